"""The string bed from its options, as the command line and a run file's ``[strings]`` table give
them: tension per string, pattern, head size, string, edge and stretch (each None when not given).

The head: ``head_length`` and ``head_width`` set the ellipse's axes; ``head_area`` scales the
default head (0.326 m x 0.252 m, 645 cm^2) keeping its shape, or, with one axis given, sets the
other; all three together are refused. Any option given makes a bed; none: no bed (the paper's
lumped K_CB stays).
"""

from __future__ import annotations

import math
from typing import Any

from fem_racket.strings.bed import StringBed, parse_pattern
from fem_racket.validation import InputError, check_positive, show

__all__ = ["STRING_OPTIONS", "bed_from_options"]

#: The names of the string-bed options (argparse destinations and run-file destinations alike).
STRING_OPTIONS = (
    "string_tension",
    "pattern",
    "head_area",
    "head_length",
    "head_width",
    "string_material",
    "bed_edge",
    "string_stretch",
)


def _axes(area: Any, length: Any, width: Any) -> tuple[float, float]:
    """The head's axes [m] from the options (see the module docstring)."""
    d = StringBed()
    if area is None:
        return (
            d.head_length_m if length is None else check_positive("head length", length, "m"),
            d.head_width_m if width is None else check_positive("head width", width, "m"),
        )
    a = check_positive("head area", area, "cm^2") * 1e-4 * 4.0 / math.pi  # L W [m^2]
    if length is not None and width is not None:
        raise InputError(
            f"head area = {show(area)} cm^2 is not allowed with both --head-length and "
            "--head-width: give two of the three"
        )
    if length is not None:
        return float(length), a / check_positive("head length", length, "m")
    if width is not None:
        return a / check_positive("head width", width, "m"), float(width)
    s = math.sqrt(a / (d.head_length_m * d.head_width_m))
    return d.head_length_m * s, d.head_width_m * s


def bed_from_options(values: dict[str, Any]) -> StringBed | None:
    """The string bed ``values`` (:data:`STRING_OPTIONS` -> value or None) ask for, or None
    when none is given."""
    values = {k: values.get(k) for k in STRING_OPTIONS}
    if all(v is None for v in values.values()):
        return None
    d = StringBed()
    length, width = _axes(values["head_area"], values["head_length"], values["head_width"])
    mains, crosses = (
        (d.mains, d.crosses) if values["pattern"] is None else parse_pattern(values["pattern"])
    )
    return StringBed(
        tension_n=d.tension_n if values["string_tension"] is None else values["string_tension"],
        mains=mains,
        crosses=crosses,
        head_length_m=length,
        head_width_m=width,
        string=d.string if values["string_material"] is None else values["string_material"],
        edge=d.edge if values["bed_edge"] is None else values["bed_edge"],
        stretch=bool(values["string_stretch"]),
    )
