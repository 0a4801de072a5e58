"""Hysteretic ball/string law: a loading and a stiffer unloading branch (Cross 2000).

Cross (2000, Sports Eng. 3, "The coefficient of restitution for collisions of happy balls, unhappy
balls, and tennis balls"; also Am. J. Phys. 67, 1999) models a tennis ball's hysteresis loop with
stiffness k1 in compression and k2 > k1 in restitution; for linear branches the energy returned
over the energy stored is k1/k2, so on a rigid support e^2 = k1/k2. Here both branches are power
laws of one exponent n (n = 1: Cross's linear branches)::

    loading   (delta >= z):  F = k1 delta^n
    unloading (delta <  z):  F = k2 (delta - delta_0)^n,   delta_0 = z (1 - (k1/k2)^(1/n))

where z is the largest deflection reached so far (a memory state) and delta_0 the permanent set at
which the unloading branch reaches zero force; F is continuous at the turning point. The energy
returned over the energy stored is (k1/k2)^(1/n) whatever the speed, so on a rigid support
``e^2 = (k1/k2)^(1/n)``: a speed-independent COR, like the paper's clamped e = 0.83, with a contact
time that shortens with speed as v0^(-(n-1)/(n+1)). The contact ends when delta falls through
delta_0 (the force is back to zero). Typical tennis values: e = 0.73-0.76 on a rigid surface at
low speed (ITF rules), 0.83 for ball on strings (the paper); n = 1 with k1 ~ 2-3e4 N/m for a ball
alone (Cross 1999); the calibrated preset ``kawazoe-1997-nonlinear`` uses n near 9.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Any, ClassVar

import numpy as np

from fem_racket.contact import power_law
from fem_racket.contact.law import ContactLaw, deflection_condition, power_contact_time
from fem_racket.contact.parameters import LawCondition, LawFit, LawParameter
from fem_racket.validation import check_range

__all__ = ["MIN_RIGID_COR", "Hysteretic"]

#: Smallest rigid-support COR a hysteretic law may have [-] (the calibration's lower bound).
MIN_RIGID_COR = 0.05


@dataclass(frozen=True, eq=False)
class Hysteretic(ContactLaw):
    """Power-law loading branch k1 delta^n and unloading branch k2 (delta - delta_0)^n.

    Parameters
    ----------
    k1 : float or ndarray
        Loading stiffness [N/m^n].
    k2 : float or ndarray
        Unloading stiffness [N/m^n], >= k1 (k1 = k2: elastic).
    exponent : float or ndarray
        n [-], >= 1.
    """

    name: ClassVar[str] = "hysteretic"
    state: ClassVar[str | None] = "memory"
    declared: ClassVar[tuple[LawParameter, ...]] = (
        power_law.stiffness(
            name="k1",
            default=3.182e15,
            help="hysteretic loading stiffness k1 (F = k1 delta^n)",
        ),
        power_law.stiffness(
            name="k2",
            default=8.816e16,
            help="hysteretic unloading stiffness k2",
            why="as k1; k2 >= k1 and the rigid COR are conditions",
        ),
        power_law.exponent(
            name="hyst_exponent",
            default=8.913,
            help="hysteretic exponent n",
            why="1: Cross's linear branches; the paper's K_CB(V) needs n ~ 9",
        ),
    )
    conditions = (
        LawCondition(
            "k2 >= k1",
            lambda v: v["k2"] >= v["k1"],
            "a softer unloading branch returns more energy than it stores",
        ),
        LawCondition(
            f"rigid COR (k1/k2)^(1/(2n)) >= {MIN_RIGID_COR:g}",
            lambda v: (v["k1"] / v["k2"]) ** (0.5 / v["hyst_exponent"]) >= MIN_RIGID_COR,
            "a ball returning under 5 % of its speed from a rigid support is putty, not a ball; "
            "tennis balls return 73-76 %, ITF",
        ),
        deflection_condition(lambda v, f: (f / v["k1"]) ** (1.0 / v["hyst_exponent"])),
    )
    fit = LawFit(
        names=("k1 [N/m^n]", "n [-]", "rigid COR [-]"),
        build=lambda p: Hysteretic.from_cor(p[0], min(p[2], 0.999), p[1]),
        low=(power_law.STIFFNESS_RANGE[0], power_law.EXPONENT_RANGE[0], MIN_RIGID_COR),
        high=(power_law.STIFFNESS_RANGE[1], power_law.EXPONENT_RANGE[1], 0.999),
        starts={"kawazoe-1997": (1e17, 9.0, 0.83), "itf": (2e4, 1.0, 0.745)},
    )
    k1: Any
    k2: Any
    exponent: Any = 1.0

    @classmethod
    def from_cor(cls, k1: float, cor: float, exponent: float = 1.0) -> Hysteretic:
        """The law with restitution ``cor`` on a rigid support: k2 = k1 / e^(2 n)."""
        e = check_range("cor", cor, 0.0, 1.0, include_low=False)
        return cls(k1, k1 / e ** (2.0 * exponent), exponent)

    @property
    def rigid_cor(self) -> Any:
        """e = (k1/k2)^(1/(2n)) on a rigid support [-]."""
        return (self.k1 / self.k2) ** (0.5 / self.exponent)

    def _ratio(self) -> Any:
        return (self.k1 / self.k2) ** (1.0 / self.exponent)

    def end_deflection(self, z: Any) -> Any:
        """Permanent set delta_0 = z (1 - (k1/k2)^(1/n)) [m]."""
        return np.asarray(z) * (1.0 - self._ratio())

    def elastic(self) -> Hysteretic:
        """k2 = k1: the loading branch both ways."""
        return replace(self, k2=self.k1)

    def force(self, d: Any, v: Any, z: Any) -> Any:
        d = np.asarray(d, dtype=float)
        load = self.k1 * np.maximum(d, 0.0) ** self.exponent
        unload = self.k2 * np.maximum(d - self.end_deflection(z), 0.0) ** self.exponent
        return np.where(d >= z, load, unload)

    def partials(self, d: Any, v: Any, z: Any) -> tuple[Any, Any, Any]:
        d = np.asarray(d, dtype=float)
        n = self.exponent
        load = n * self.k1 * np.maximum(d, 0.0) ** (n - 1.0)
        unload = n * self.k2 * np.maximum(d - self.end_deflection(z), 0.0) ** (n - 1.0)
        fd = np.where(d >= z, load, unload)
        fz = np.where(d >= z, 0.0, -unload * (1.0 - self._ratio()))
        return fd, 0.0 * d, fz

    def contact_time_estimate(self, mass: Any, speed: Any) -> Any:
        """Loading half of the k1 power law's time, times (1 + e): unloading spans e^2 of the
        peak deflection at e times the speed, so it lasts e times as long [s]."""
        return (
            0.5 * power_contact_time(self.k1, self.exponent, mass, speed) * (1.0 + self.rigid_cor)
        )
