"""The normal contact force history that drives the tangential contact.

The tangential contact is integrated alongside a normal impact computed first (any contact law,
any solver): it needs the normal force F(t), its rate F'(t) and impulse P(t) = int_0^t F, the
secant normal stiffness k_n (the force over the deflection at maximum compression; K_CB for the
paper's linear law, whose dashpot force vanishes there) and the time ``end`` up to which the
normal force presses (its first return to zero; the paper's linear law then pulls the ball for
a moment before the spring deflection returns to zero, which carries no friction).

Three histories: :class:`SampledNormal` from a solver's output times (the impulse as a cubic
Hermite spline through P and P' = F, exact at the samples); :class:`ClampedNormal`, the paper's
spring-dashpot on a clamped head in closed form (eqs 1-3); :class:`StrongeNormal`, Stronge's
piecewise-linear spring (stiffness k_n in compression, k_n / e^2 in restitution: half sines at
omega_n and omega_n / e; Stronge 2000, *Impact Mechanics*, section 5.2), whose tangential
outcomes are known in closed form (:mod:`fem_racket.impact.tangential.stronge`).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from functools import cached_property
from typing import Protocol

import numpy as np

from fem_racket.impact.tangential.release import first_release

__all__ = [
    "ClampedNormal",
    "NormalHistory",
    "SampledNormal",
    "StrongeNormal",
    "peak_force",
]


class NormalHistory(Protocol):
    """Normal force F [N], rate F' [N/s] and impulse P [N s] on the ball over [0, ``end``];
    ``stiffness`` k_n [N/m]; ``grid``: times [s] fine enough to bracket every switch of the
    tangential contact (the solver's output times)."""

    stiffness: float
    end: float
    grid: np.ndarray

    def force(self, t: np.ndarray | float) -> np.ndarray: ...

    def rate(self, t: np.ndarray | float) -> np.ndarray: ...

    def impulse(self, t: np.ndarray | float) -> np.ndarray: ...

    def slope(self, t: np.ndarray | float) -> np.ndarray: ...

    def smooth_force(self, t: np.ndarray | float) -> np.ndarray: ...


@dataclass(frozen=True, eq=False)
class SampledNormal:
    """A normal history from a solver's output times.

    Parameters
    ----------
    t : ndarray
        Output times [s], increasing from 0.
    impulse_samples : ndarray
        P(t) [N s]: the ball's normal momentum lost, m_B (V_0 - v_B(t)).
    force_samples : ndarray
        F(t) [N].
    stiffness : float
        Secant normal stiffness k_n [N/m].
    """

    t: np.ndarray
    impulse_samples: np.ndarray
    force_samples: np.ndarray
    stiffness: float
    _spline: object = field(init=False, repr=False)
    force_spline: object = field(init=False, repr=False)
    end: float = field(init=False)
    grid: np.ndarray = field(init=False, repr=False)

    def __post_init__(self) -> None:
        from scipy.interpolate import CubicHermiteSpline, CubicSpline

        t = np.asarray(self.t, dtype=float)
        # an output time repeated (the contact time on the output grid) is one sample
        keep = np.concatenate(([True], np.diff(t) > 0.0))
        t, f = t[keep], np.asarray(self.force_samples, dtype=float)[keep]
        p = np.asarray(self.impulse_samples, dtype=float)[keep]
        spline = CubicHermiteSpline(t, p, f)
        object.__setattr__(self, "_spline", spline)
        object.__setattr__(self, "force_spline", CubicSpline(t, f))
        grid, force = t, spline.derivative()
        for i in range(1, len(t)):
            if f[i - 1] > 0.0 >= f[i]:
                # P' equals the samples at the knots up to round-off only: where that leaves it
                # positive at the zero sample (~1e-27 N at the end of a slow law's long tail),
                # the force is zero there to machine precision and the sample ends the contact
                end = t[i] if force(t[i]) > 0.0 else _piece_root(force, t[i - 1], t[i])
                grid = np.append(t[:i], end)
                break
        release = first_release(spline, float(grid[-1]))
        if release is not None:  # P' dips through zero between two pressing samples
            grid = np.append(grid[grid < release], release)
        object.__setattr__(self, "end", float(grid[-1]))
        object.__setattr__(self, "grid", grid)

    def force(self, t):
        return self._spline(t, 1)

    def rate(self, t):
        return self._spline(t, 2)

    def smooth_force(self, t):
        """F [N] from a C2 cubic spline through the force samples (``force_spline``): the
        vector contact (:mod:`fem_racket.impact.tangential.plane_ode`) integrates its slides
        over it, where :meth:`force` (P' of the Hermite spline) has a corner at every sample
        that an adaptive integrator would creep through; the two differ by O(h^4)."""
        return self.force_spline(t)

    def slope(self, t):
        """F' [N/s] of :meth:`smooth_force`: continuous, where :meth:`rate` (P'' of the
        Hermite spline) jumps at the samples; the vector contact stops its slides by it (the
        jumps would switch a slider moving near zero speed at every sample)."""
        return self.force_spline(t, 1)

    def impulse(self, t):
        return self._spline(t) - self._spline(0.0)


def _piece_root(fun, a: float, b: float) -> float:
    """The root of ``fun`` in [a, b] (a sign change), to machine precision."""
    from scipy.optimize import brentq

    return float(brentq(fun, a, b, xtol=1e-15 * max(b, 1e-300), rtol=4 * np.finfo(float).eps))


@dataclass(frozen=True, eq=False)
class _ClosedFormNormal:
    """What the closed-form histories share: a ball of mass ``mass`` m [kg] on a spring of
    ``stiffness`` k [N/m] (undamped angular frequency :attr:`omega`), the event-search grid of
    ``samples`` points over [0, ``end``], and F, F' already smooth (``smooth_force`` and
    ``slope`` are exact)."""

    mass: float
    stiffness: float

    @property
    def omega(self) -> float:
        """sqrt(k / m) [rad/s]."""
        return math.sqrt(self.stiffness / self.mass)

    @cached_property
    def grid(self) -> np.ndarray:
        """Times [s] of the event search over the contact."""
        return np.linspace(0.0, self.end, self.samples)

    def slope(self, t):
        """F' [N/s] (:meth:`rate`, exact)."""
        return self.rate(t)

    def smooth_force(self, t):
        """F [N] (:meth:`force`, exact)."""
        return self.force(t)


@dataclass(frozen=True, eq=False)
class ClampedNormal(_ClosedFormNormal):
    """The paper's spring-dashpot on a clamped head (eqs 1-3), in closed form.

    delta(t) = V/omega_d exp(-zeta Omega t) sin(omega_d t); F = K delta + C delta' = -m delta''.

    Parameters
    ----------
    mass : float
        m_B [kg].
    stiffness : float
        K_CB [N/m].
    zeta : float
        Damping ratio in [0, 1).
    speed : float
        Normal speed V [m/s] towards the strings.
    samples : int
        Points of the event-search grid over the contact.
    """

    zeta: float
    speed: float
    samples: int = 400

    @cached_property
    def end(self) -> float:
        """The force's return to zero [s]: where tan(omega_d t) = -2 zeta sqrt(1 - zeta^2) /
        (1 - 2 zeta^2), in (pi/2, pi] / omega_d."""
        z = self.zeta
        wd = self.omega * math.sqrt(1.0 - z * z)
        return (math.pi - math.atan2(2.0 * z * math.sqrt(1.0 - z * z), 1.0 - 2.0 * z * z)) / wd

    def _states(self, t):
        """delta, delta' and delta'' at ``t``."""
        w, z = self.omega, self.zeta
        wd = w * math.sqrt(1.0 - z * z)
        t = np.asarray(t, dtype=float)
        env = np.exp(-z * w * t) * self.speed
        s, c = np.sin(wd * t), np.cos(wd * t)
        d = env * s / wd
        v = env * (c - z * w / wd * s)
        return d, v, -(w * w) * d - 2.0 * z * w * v

    def force(self, t):
        return -self.mass * self._states(t)[2]

    def rate(self, t):
        _, v, a = self._states(t)
        return self.stiffness * v + 2.0 * self.zeta * math.sqrt(self.stiffness * self.mass) * a

    def impulse(self, t):
        return self.mass * (self.speed - self._states(t)[1])

    def rebound_speed(self) -> float:
        """Ball speed away from the strings when the force returns to zero [m/s]."""
        return -float(self._states(self.end)[1])


@dataclass(frozen=True, eq=False)
class StrongeNormal(_ClosedFormNormal):
    """Stronge's normal spring: k_n in compression, k_n / e^2 in restitution, from rest.

    F = m V omega_n sin(phi) with phi = omega_n t up to t_c = pi / (2 omega_n), then
    phi = omega_n t / e + (pi/2)(1 - 1/e) until phi = pi at t_f = (1 + e) t_c; the ball leaves at
    e V (clamped target, beta_n = 1).

    Parameters
    ----------
    mass : float
        Ball mass m [kg].
    stiffness : float
        k_n [N/m].
    restitution : float
        e in (0, 1].
    speed : float
        Normal speed V [m/s].
    samples : int
        Points of the event-search grid.
    """

    restitution: float
    speed: float
    samples: int = 400

    @cached_property
    def end(self) -> float:
        """t_f = (1 + e) t_c [s]."""
        return (1.0 + self.restitution) * self.compression_time

    @property
    def compression_time(self) -> float:
        """t_c = pi / (2 omega_n) [s]."""
        return 0.5 * math.pi / self.omega

    def _phase(self, t):
        t = np.asarray(t, dtype=float)
        w, e = self.omega, self.restitution
        rest = w * t / e + 0.5 * math.pi * (1.0 - 1.0 / e)
        return np.where(t <= self.compression_time, w * t, rest), np.where(
            t <= self.compression_time, 1.0, 1.0 / e
        )

    def force(self, t):
        phi, _ = self._phase(t)
        return self.mass * self.speed * self.omega * np.sin(phi)

    def rate(self, t):
        phi, scale = self._phase(t)
        return self.mass * self.speed * self.omega**2 * scale * np.cos(phi)

    def impulse(self, t):
        phi, scale = self._phase(t)
        e = np.where(scale == 1.0, 1.0, self.restitution)
        return self.mass * self.speed * (1.0 - e * np.cos(phi))


def peak_force(normal: NormalHistory) -> float:
    """The largest normal force over the contact [N] (bounded search)."""
    from scipy.optimize import minimize_scalar

    res = minimize_scalar(lambda t: -normal.force(t), bounds=(0.0, normal.end), method="bounded")
    return float(-res.fun)
