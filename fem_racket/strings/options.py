"""The string bed from its options, as the command line and a run file's ``[strings]`` table give
them: tension per string, pattern, head size, string, edge and stretch (each None when not given).

The head: ``head_length`` and ``head_width`` set the ellipse's axes; ``head_area`` scales the
default head (0.326 m x 0.252 m, 645 cm^2) keeping its shape, or, with one axis given, sets the
other; all three together are refused. Any option given makes a bed; none: no bed (the paper's
lumped K_CB stays).
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

from fem_racket.strings.bed import HEAD_AXIS_RANGE, StringBed, parse_pattern
from fem_racket.validation import InputError, check_positive, check_range, show

__all__ = ["MAX_STRING_TENSION_N", "STRING_OPTIONS", "bed_from_options", "check_tension"]

#: Largest string tension [N] the options take: rackets are strung at about 180-300 N (40-65
#: lb), and tennis strings break at a few hundred N (an assumption of this bound: about 500-700
#: N for a 1.25-1.35 mm string); 2000 N is far beyond any strung racket. The library's
#: :class:`StringBed` takes more, to check that a very stiff bed tends to the paper's model.
MAX_STRING_TENSION_N = 2000.0

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
    """The head's axes [m] from the options (see the module docstring); an axis the area sets
    outside :data:`~fem_racket.strings.bed.HEAD_AXIS_RANGE` refused naming the area."""
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
            "--head-width: give two of the three",
            parameter="head area",
            value=area,
        )
    low, high = HEAD_AXIS_RANGE
    if length is not None:
        axes = float(length), a / check_range("head length", length, low, high, unit="m")
    elif width is not None:
        axes = a / check_range("head width", width, low, high, unit="m"), float(width)
    else:
        s = math.sqrt(a / (d.head_length_m * d.head_width_m))
        axes = d.head_length_m * s, d.head_width_m * s
    for name, value in zip(("length", "width"), axes, strict=True):
        if not low <= value <= high:  # the axis the area sets
            raise InputError(
                f"head area = {show(area)} cm^2 is not allowed: it makes the head {value:.4g} m "
                f"{'long' if name == 'length' else 'wide'}, outside [{low:g}, {high:g}] m",
                parameter="head area",
                value=area,
            )
    return axes


def check_tension(name: str, value: Any, beds: Sequence[StringBed] = ()) -> float:
    """A string tension [N] named ``name`` (``--string-tension``, a run file's or a sweep's),
    refused beyond :data:`MAX_STRING_TENSION_N` and below the least tension of each of ``beds``
    (:meth:`StringBed.check_soft`: a bed softer than a string bed)."""
    number = check_range(name, value, 1.0, MAX_STRING_TENSION_N, unit="N")
    for bed in beds:
        bed.check_soft(name, value)
    return number


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
    tension = values["string_tension"]
    return StringBed(
        tension_n=d.tension_n if tension is None else check_tension("string tension", tension),
        mains=mains,
        crosses=crosses,
        head_length_m=length,
        head_width_m=width,
        string=d.string if values["string_material"] is None else values["string_material"],
        edge=d.edge if values["bed_edge"] is None else values["bed_edge"],
        stretch=bool(values["string_stretch"]),
    )
