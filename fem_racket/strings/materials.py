"""String materials: linear density and axial rigidity of a tennis string, by name.

Only two numbers of a string enter the bed: its linear density mu [kg/m] (the bed's mass per
area, with the pattern) and its axial rigidity EA [N] (the tension's rise when the bed stretches
at large deflection, :mod:`fem_racket.strings.stiffening`). Both are *typical* values for the
common 1.25-1.30 mm gauges, not measurements of one product:

- mu: nylon ~1.1 g/m, polyester ~1.3 g/m (``DESIGN.md`` section 10, typical values; a solid
  1.30 mm nylon monofilament of density 1.14 g/cm^3 would be 1.5 g/m, multifilament nylon with its
  voids is lighter).
- EA: Young's modulus x cross-section, E ~ 4 GPa for nylon and ~ 8 GPa for polyester (order of the
  tensile moduli of textile nylon 6 and PET monofilament; an assumption, not a measurement) over
  a 1.30 / 1.25 mm gauge. Yang, Fafitis & Wiezel (2012, J. Mech. Sci. Technol. 26(2)) found the
  strings' axial rigidity hardly changes dwell time and rebound; here it changes only the
  stiffening estimate.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from fem_racket.validation import check_choice, check_positive

__all__ = ["STRINGS", "StringMaterial", "get_string"]


@dataclass(frozen=True)
class StringMaterial:
    """One string: its name, linear density and axial rigidity.

    Parameters
    ----------
    name : str
        Name used on the command line and in run files.
    linear_density_kg_m : float
        Mass per length mu [kg/m].
    axial_rigidity_n : float
        EA [N].
    gauge_m : float
        Diameter [m] (for the record; EA already includes it).
    """

    name: str
    linear_density_kg_m: float
    axial_rigidity_n: float
    gauge_m: float

    def __post_init__(self) -> None:
        check_positive("string linear density", self.linear_density_kg_m, "kg/m")
        check_positive("string axial rigidity", self.axial_rigidity_n, "N")
        check_positive("string gauge", self.gauge_m, "m")


def _area(d: float) -> float:
    return math.pi * d * d / 4.0


#: The string presets (typical values, see the module docstring).
STRINGS: dict[str, StringMaterial] = {
    "nylon": StringMaterial("nylon", 1.1e-3, 4.0e9 * _area(1.30e-3), 1.30e-3),
    "polyester": StringMaterial("polyester", 1.3e-3, 8.0e9 * _area(1.25e-3), 1.25e-3),
}


def get_string(name: str) -> StringMaterial:
    """The string preset ``name`` (one of :data:`STRINGS`)."""
    return STRINGS[check_choice("string", name, tuple(STRINGS))]
