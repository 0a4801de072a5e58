"""Hunt-Crossley contact law: a power-law spring with deflection-weighted damping.

    F = k delta^n (1 + alpha delta'),   delta > 0;   F = 0 otherwise

(Hunt & Crossley 1975, J. Appl. Mech. 42; lambda = alpha k is the damping coefficient of
F = k delta^n + lambda delta^n delta'). The force starts and ends at zero, so the contact ends when
delta falls back through 0. For an impact at relative speed v0 the coefficient of restitution e
fixes alpha through one of two published relations:

- Lankarani & Nikravesh 1990 (J. Mech. Des. 112): ``alpha = 3 (1 - e^2) / (4 v0)``, derived for
  e near 1;
- Flores, Machado, Silva & Martins 2011 (Multibody Syst. Dyn. 25): ``alpha = 8 (1 - e) / (5 e v0)``,
  valid over the whole range of e.

With one alpha for every speed the COR falls with speed (to first order 1 - e = 2 alpha v0 / 3,
Hunt & Crossley), as a tennis ball's does on a rigid surface (Haake, Carre & Goodwill 2003). A
single power law stiffens with speed only through n: the equivalent linear stiffness of a clamped
impact grows as v0^(2(n-1)/(n+1)), so the paper's 3.04x from 20 to 40 m/s needs n near 9.
Typical tennis values: n = 1.5 (Hertz) to ~2 for a ball on a rigid surface; k of order
1e5-1e6 N/m^n; see the calibrated presets in :mod:`fem_racket.contact.presets`.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Any, ClassVar

import numpy as np

from fem_racket.contact import power_law
from fem_racket.contact.law import ContactLaw, deflection_condition, power_contact_time
from fem_racket.contact.parameters import LawFit, LawParameter
from fem_racket.validation import check_choice, check_positive, check_range

__all__ = ["COR_RELATIONS", "HuntCrossley", "damping_from_cor"]

COR_RELATIONS = ("lankarani-nikravesh", "flores")


def damping_from_cor(cor: float, speed: float, relation: str = "flores") -> float:
    """alpha = lambda / k [s/m] giving restitution ``cor`` at relative speed ``speed`` [m/s].

    ``"lankarani-nikravesh"``: 3 (1 - e^2) / (4 v0); ``"flores"``: 8 (1 - e) / (5 e v0).
    """
    e = check_range("cor", cor, 0.0, 1.0, include_low=False)
    v0 = check_positive("speed", speed, "m/s")
    check_choice("relation", relation, COR_RELATIONS)
    if relation == "lankarani-nikravesh":
        return 3.0 * (1.0 - e * e) / (4.0 * v0)
    return 8.0 * (1.0 - e) / (5.0 * e * v0)


@dataclass(frozen=True, eq=False)
class HuntCrossley(ContactLaw):
    """F = k delta^n (1 + alpha delta') for delta > 0.

    Parameters
    ----------
    stiffness : float or ndarray
        k [N/m^n].
    exponent : float or ndarray
        n [-], >= 1.
    alpha : float or ndarray
        alpha = lambda / k [s/m], >= 0 (0: elastic).
    """

    name: ClassVar[str] = "hunt-crossley"
    declared: ClassVar[tuple[LawParameter, ...]] = (
        power_law.stiffness(
            name="hc_stiffness",
            field="stiffness",
            default=2.978e24,
            help="Hunt-Crossley stiffness k of F = k delta^n (1 + alpha delta')",
        ),
        power_law.exponent(
            name="hc_exponent",
            default=14.87,
            help="Hunt-Crossley exponent n",
            why="1: a linear spring, 1.5: Hertz; the paper's K_CB(V) needs n ~ 9-15",
        ),
        LawParameter(
            name="hc_alpha",
            field="alpha",
            unit="s/m",
            default=0.009905,
            low=0.0,
            high=10.0,
            help="Hunt-Crossley damping alpha = lambda / k",
            why="0: elastic; alpha = 8 (1 - e) / (5 e v0) (Flores et al. 2011): 10 s/m is "
            "e ~ 0.14 at 1 m/s, below any ball",
        ),
    )
    conditions = (
        deflection_condition(lambda v, f: (f / v["hc_stiffness"]) ** (1.0 / v["hc_exponent"])),
    )
    fit = LawFit(
        names=("k [N/m^n]", "n [-]", "alpha [s/m]"),
        build=lambda p: HuntCrossley(p[0], p[1], p[2]),
        low=(power_law.STIFFNESS_RANGE[0], power_law.EXPONENT_RANGE[0], 1e-5),
        high=(power_law.STIFFNESS_RANGE[1], power_law.EXPONENT_RANGE[1], 5.0),
        starts={"kawazoe-1997": (1e17, 9.0, 0.01), "itf": (3e5, 1.5, 0.05)},
    )
    stiffness: Any
    exponent: Any = 1.5
    alpha: Any = 0.0

    @classmethod
    def from_cor(
        cls,
        stiffness: float,
        exponent: float,
        cor: float,
        speed: float,
        relation: str = "flores",
    ) -> HuntCrossley:
        """The law whose damping gives ``cor`` at ``speed`` [m/s] (see :func:`damping_from_cor`)."""
        return cls(stiffness, exponent, damping_from_cor(cor, speed, relation))

    def elastic(self) -> HuntCrossley:
        """alpha = 0."""
        return replace(self, alpha=0.0)

    def force(self, d: Any, v: Any, z: Any) -> Any:
        dp = np.maximum(d, 0.0)
        return self.stiffness * dp**self.exponent * (1.0 + self.alpha * v)

    def partials(self, d: Any, v: Any, z: Any) -> tuple[Any, Any, Any]:
        dp = np.maximum(d, 0.0)
        spring = self.stiffness * dp**self.exponent
        slope = self.exponent * self.stiffness * dp ** (self.exponent - 1.0)
        return slope * (1.0 + self.alpha * v), self.alpha * spring, 0.0 * dp

    def contact_time_estimate(self, mass: Any, speed: Any) -> Any:
        """The elastic power law's contact time (:func:`power_contact_time`) [s]."""
        return power_contact_time(self.stiffness, self.exponent, mass, speed)
