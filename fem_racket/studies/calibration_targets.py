"""What ``fem-racket calibrate`` fits, by name: the published target sets
(:data:`TARGET_SETS`, sources in :mod:`fem_racket.studies.calibrate`'s docstring) and the law
families calibration can fit (:data:`FAMILIES`). Its parser reads them from here, with the
contact laws' registry and without the impact solvers; :mod:`fem_racket.studies.calibrate` (the
fit) imports them back.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass

from fem_racket.contact.linear import LinearContact
from fem_racket.contact.parameters import LawFit
from fem_racket.contact.registry import FAMILIES as REGISTERED
from fem_racket.contact.registry import LiveView

__all__ = ["FAMILIES", "ITF_LOAD", "ITF_SPEED", "TARGET_SETS", "Target"]

ITF_SPEED = math.sqrt(2.0 * 9.80665 * 2.54)
ITF_LOAD = 8.165 * 9.80665


@dataclass(frozen=True)
class Target:
    """One number a law should reproduce.

    Attributes
    ----------
    quantity : {"contact_time", "cor", "static_deflection"}
    condition : float
        Impact speed [m/s] (or the static load [N]).
    value : float
        Target: contact time [s], COR [-] or deflection [m].
    tolerance : float
        Relative for contact times, absolute otherwise.
    source : str
    """

    quantity: str
    condition: float
    value: float
    tolerance: float
    source: str

    def scaled_error(self, model: float) -> float:
        """(model - value) / tolerance (relative for contact times): |.| <= 1 meets it."""
        if self.quantity == "contact_time":
            return (model / self.value - 1.0) / self.tolerance
        return (model - self.value) / self.tolerance


_PAPER = "Kawazoe & Kanda 1997, sec. 2.1.1 and eq 4, m_B = 0.057 kg"
_ITF = "ITF Rules of Tennis, Appendix I"
TARGET_SETS: dict[str, tuple[Target, ...]] = {
    "kawazoe-1997": tuple(
        Target("contact_time", v, math.pi * math.sqrt(0.057 / k), 0.05, _PAPER)
        for v, k in ((20.0, 2.74e4), (30.0, 5.0e4), (40.0, 8.33e4))
    )
    + tuple(Target("cor", v, 0.83, 0.01, _PAPER) for v in (20.0, 25.0, 30.0, 35.0, 40.0)),
    "itf": (
        Target("cor", ITF_SPEED, 0.745, 0.015, _ITF + ": rebound 135-147 cm from 254 cm"),
        Target("static_deflection", ITF_LOAD, 0.0065, 0.0009, _ITF + ": 0.56-0.74 cm at 80.1 N"),
    ),
}


#: Family name -> how calibration fits it (live: the paper's linear law and every registered
#: family that declares a :class:`~fem_racket.contact.parameters.LawFit`).
FAMILIES: Mapping[str, LawFit] = LiveView(
    lambda: {
        name: cls.fit
        for name, cls in {"linear": LinearContact, **REGISTERED}.items()
        if cls.fit is not None
    }
)
