"""The stiffness k and exponent n of a power law F = k delta^n, declared once for every law that
has one (:mod:`fem_racket.contact.hunt_crossley`, :mod:`fem_racket.contact.hysteretic`).

k's unit, N/m^n, depends on n, so its bounds cannot be physical by themselves: they are the
calibration's search range for n = 1-20 (:mod:`fem_racket.studies.calibrate`), and the physical
bound is the law's deflection under 1 kN (:func:`fem_racket.contact.law.deflection_condition`).
"""

from __future__ import annotations

from fem_racket.contact.parameters import LawParameter

__all__ = ["EXPONENT_RANGE", "STIFFNESS_RANGE", "STIFFNESS_WHY", "exponent", "stiffness"]

#: Bounds of a power law's stiffness k [N/m^n] (and the calibration's search range of k).
STIFFNESS_RANGE = (1e2, 1e40)
#: Bounds of a power law's exponent n [-] (and the calibration's search range of n).
EXPONENT_RANGE = (1.0, 20.0)
#: Why :data:`STIFFNESS_RANGE` (a stiffness declaration's ``why``).
STIFFNESS_WHY = (
    "its unit depends on n: the calibration's search range for n = 1-20; the physical bound is "
    "the deflection under 1 kN (a condition)"
)
#: What every power law's stiffness declares alike: its unit and bounds.
_STIFFNESS = {"unit": "N/m^n", "low": STIFFNESS_RANGE[0], "high": STIFFNESS_RANGE[1]}
#: What every power law's exponent declares alike: its field, unit and bounds.
_EXPONENT = {"field": "exponent", "unit": "-", "low": EXPONENT_RANGE[0], "high": EXPONENT_RANGE[1]}


def stiffness(
    name: str, default: float, help: str, why: str = STIFFNESS_WHY, field: str | None = None
) -> LawParameter:
    """A power law's stiffness k [N/m^n] within :data:`STIFFNESS_RANGE`, run-file key
    ``<name>_n_m_n`` (the unit's suffix).

    Parameters
    ----------
    name : str
        Its name (option, sweep axis).
    default : float
        The family's default [N/m^n].
    help, why : str
        One line for ``--help``; the reasoning of the bounds.
    field : str, optional
        The law's dataclass attribute holding it; the name when None.
    """
    return LawParameter(name=name, field=field, default=default, help=help, why=why, **_STIFFNESS)


def exponent(name: str, default: float, help: str, why: str) -> LawParameter:
    """A power law's exponent n [-] within :data:`EXPONENT_RANGE`, held in the law's field
    ``exponent``; its run-file key is its name (no unit).

    Parameters
    ----------
    name : str
        Its name (option, sweep axis, run-file key).
    default : float
        The family's default [-].
    help, why : str
        One line for ``--help``; the reasoning of the bounds.
    """
    return LawParameter(name=name, default=default, help=help, why=why, **_EXPONENT)
