"""The string bed on the command line: tension, pattern, head size and string.

Any of these options replaces the paper's lumped K_CB by the string bed (:mod:`fem_racket.strings`,
:mod:`fem_racket.impact.strung`): the ball's own law then acts on the bed. Without them the
paper's spring stays, unchanged. (``--string-stiffness`` and ``--string-cubic`` are parameters
of the ``series`` contact law, a different, lumped model.)

The head: ``--head-length`` and ``--head-width`` set the ellipse's axes; ``--head-area`` scales
the default head (0.326 m x 0.252 m, 645 cm^2) keeping its shape, or, with one axis given, sets
the other; all three together are refused.
"""

from __future__ import annotations

import argparse
import math
from typing import Any

from fem_racket.strings.bed import StringBed, parse_pattern
from fem_racket.strings.materials import STRINGS
from fem_racket.validation import InputError, check_positive, show

__all__ = ["STRING_DESTS", "add_strings_options", "strings_from_args"]

#: The argparse destinations of the string-bed options.
STRING_DESTS = (
    "string_tension",
    "pattern",
    "head_area",
    "head_length",
    "head_width",
    "string_material",
)


def add_strings_options(parser: argparse.ArgumentParser) -> None:
    """Add the string-bed options (all default to None: the paper's K_CB)."""
    d = StringBed()
    g = parser.add_argument_group(
        "string bed (any of these replaces the paper's K_CB by a membrane bed and the ball's law)"
    )
    g.add_argument(
        "--string-tension",
        type=float,
        default=None,
        metavar="N",
        help=f"tension per string [N] (default {d.tension_n:g}, the paper's 55 lb)",
    )
    g.add_argument(
        "--pattern",
        default=None,
        metavar="MAINSxCROSSES",
        help=f"string pattern, mains along the racket x crosses (default {d.pattern})",
    )
    g.add_argument(
        "--head-area",
        type=float,
        default=None,
        metavar="CM2",
        help=f"string-bed area [cm^2] (default {d.area_m2 * 1e4:.0f}; the ellipse keeps its shape)",
    )
    g.add_argument(
        "--head-length",
        type=float,
        default=None,
        metavar="M",
        help=f"string-bed length along the racket [m] (default {d.head_length_m:g})",
    )
    g.add_argument(
        "--head-width",
        type=float,
        default=None,
        metavar="M",
        help=f"string-bed width across the racket [m] (default {d.head_width_m:g})",
    )
    g.add_argument(
        "--string-material",
        default=None,
        choices=tuple(STRINGS),
        help=f"string material (default {d.string})",
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


def strings_from_args(args: argparse.Namespace) -> StringBed | None:
    """The string bed the options ask for, or None when no string option is given."""
    values = {k: getattr(args, k, None) for k in STRING_DESTS}
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
    )
