"""A Kelvin-Voigt ball in series with a hardening string bed (Goodwill & Haake 2001).

Goodwill & Haake (2001, Proc. IMechE C 215, "Spring damper model of an impact between a tennis ball
and racket") model the ball as a spring K_b and dashpot C_b in parallel (Kelvin-Voigt), in series
with the string bed, and validate it on head-clamped and pinned rackets; Cross (2000, Sports Eng.
3) likewise puts a ball spring in series with a string spring. The string bed here may harden,
``s(x) = k_s x + k_3 x^3`` (a stretched membrane stiffens with its deflection). The string bed is
massless, so its deflection x is an internal state of the law (delta = ball compression + x)::

    F = s(x) = K_b (delta - x) + C_b (delta' - x')
    x' = delta' - (s(x) - K_b (delta - x)) / C_b

The contact ends when the string bed returns to its plane (x falls through 0, where the force
does too; with a soft linear term the force touches zero almost tangentially, x does not).
Typical values (assumptions, to be calibrated): string-bed stiffness k_s ~ 2-4e4 N/m for a
tensioned bed (Cross 2000; Brody, Cross & Lindsey 2002, ch. 8); ball stiffness K_b ~ 1e5 N/m at
impact deflections and C_b set by the ball's own restitution (~0.75 on a rigid surface).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any, ClassVar

import numpy as np

from fem_racket.contact.law import ContactLaw, deflection_condition
from fem_racket.contact.parameters import LawFit, LawParameter

__all__ = ["SeriesBallString"]


def _string_deflection(k_s: Any, k_3: Any, load: float) -> Any:
    """x [m] with k_s x + k_3 x^3 = load [N] (bisection, elementwise: s rises with x)."""
    low = np.zeros(np.shape(k_s + k_3))
    high = load / k_s + low
    for _ in range(80):
        x = 0.5 * (low + high)
        below = k_s * x + k_3 * x**3 < load
        low, high = np.where(below, x, low), np.where(below, high, x)
    return high


@dataclass(frozen=True, eq=False)
class SeriesBallString(ContactLaw):
    """Kelvin-Voigt ball (K_b, C_b) in series with a string bed k_s x + k_3 x^3.

    Parameters
    ----------
    ball_stiffness : float or ndarray
        K_b [N/m].
    ball_damping : float or ndarray
        C_b [N s/m], > 0.
    string_stiffness : float or ndarray
        k_s [N/m].
    string_cubic : float or ndarray
        k_3 [N/m^3], >= 0.
    """

    name: ClassVar[str] = "series"
    state: ClassVar[str | None] = "ode"
    end: ClassVar[str] = "state"
    declared: ClassVar[tuple[LawParameter, ...]] = (
        LawParameter(
            name="ball_stiffness",
            unit="N/m",
            default=9.823e4,
            low=1e3,
            high=1e8,
            help="series law: ball stiffness K_b",
            why="a tennis ball ~1e5 N/m (Goodwill & Haake 2001); 1e8 is a ball as rigid as a "
            "steel face; below 1e3 a ball flattens under its own impact",
        ),
        LawParameter(
            name="ball_damping",
            unit="N s/m",
            default=17.06,
            low=1e-2,
            high=1e3,
            help="series law: ball damping C_b",
            why="C_b = 2 zeta_b sqrt(m K_b): tennis ~10-20 N s/m; the calibration's range",
        ),
        LawParameter(
            name="string_stiffness",
            unit="N/m",
            default=1559.0,
            low=1.0,
            high=1e7,
            help="series law: string-bed stiffness k_s",
            why="a tensioned bed 2-4e4 N/m (Cross 2000); a soft linear term under a hardening "
            "cubic down to 1 N/m; 1e7: a rigid face",
        ),
        LawParameter(
            name="string_cubic",
            unit="N/m^3",
            default=8.317e8,
            low=0.0,
            high=1e15,
            help="series law: string-bed cubic stiffness k_3",
            why="0: a linear bed; 1e15 N/m^3 stiffens to 1e9 N/m at 0.5 mm",
        ),
    )
    conditions = (
        deflection_condition(
            lambda v, f: (
                _string_deflection(v["string_stiffness"], v["string_cubic"], f)
                + f / v["ball_stiffness"]
            )
        ),
    )
    fit = LawFit(
        names=("ball K_b [N/m]", "ball C_b [N s/m]", "string k_s [N/m]", "string k_3 [N/m^3]"),
        build=lambda p: SeriesBallString(p[0], p[1], p[2], p[3]),
        low=(1e3, 1e-2, 1e3, 1e-3),
        high=(1e8, 1e3, 1e7, 1e14),
        # itf: a ball on a rigid surface, the bed at the top of its range
        starts={"kawazoe-1997": (2e5, 10.0, 2e4, 3e8), "itf": (2e4, 3.0, 1e7, 1.0)},
    )
    ball_stiffness: Any
    ball_damping: Any
    string_stiffness: Any
    string_cubic: Any = 0.0

    def string_force(self, x: Any) -> Any:
        """s(x) = k_s x + k_3 x^3 [N]."""
        return self.string_stiffness * x + self.string_cubic * x**3

    def force(self, d: Any, v: Any, z: Any) -> Any:
        return self.string_force(z)

    def partials(self, d: Any, v: Any, z: Any) -> tuple[Any, Any, Any]:
        zero = 0.0 * np.asarray(d)
        return zero, zero, self.string_stiffness + 3.0 * self.string_cubic * z**2 + zero

    def rate(self, d: Any, v: Any, z: Any) -> Any:
        return v - (self.string_force(z) - self.ball_stiffness * (d - z)) / self.ball_damping

    def rate_partials(self, d: Any, v: Any, z: Any) -> tuple[Any, Any, Any]:
        c = self.ball_damping
        ds = self.string_stiffness + 3.0 * self.string_cubic * z**2
        return self.ball_stiffness / c + 0.0 * z, 1.0 + 0.0 * z, -(ds + self.ball_stiffness) / c

    def static_deflection(self, load: float) -> float:
        """Ball compression load / K_b plus the string bed's x with s(x) = load [m]."""
        from scipy.optimize import brentq

        def excess(x: float) -> float:
            return float(self.string_force(x)) - load

        high = load / self.string_stiffness  # s(x) >= k_s x: the root lies below
        # a cubic term too small to move the root leaves s(high) = load to rounding
        x = high if excess(high) <= 0.0 else brentq(excess, 0.0, high)
        return float(x + load / self.ball_stiffness)

    def contact_time_estimate(self, mass: Any, speed: Any) -> Any:
        """pi sqrt(m / k_sec) [s], k_sec the secant stiffness F/delta at the static deflection
        storing the impact energy m v^2 / 2 (k_s x^2/2 + k_3 x^4/4 + s(x)^2 / (2 K_b))."""
        energy = 0.5 * np.asarray(mass) * np.asarray(speed) ** 2
        low = np.zeros_like(energy)
        high = np.sqrt(2.0 * energy / self.string_stiffness) + 0.0 * low
        for _ in range(60):  # bisection: the stored energy rises with x
            x = 0.5 * (low + high)
            s = self.string_force(x)
            stored = 0.5 * self.string_stiffness * x**2 + 0.25 * self.string_cubic * x**4
            stored = stored + s**2 / (2.0 * self.ball_stiffness)
            low, high = np.where(stored < energy, x, low), np.where(stored < energy, high, x)
        s = self.string_force(high)
        k_sec = s / (high + s / self.ball_stiffness)
        return math.pi * np.sqrt(np.asarray(mass) / k_sec)
