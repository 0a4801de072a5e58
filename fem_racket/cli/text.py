"""What the CLI prints besides its results: numbers to significant digits and one-line notes.

Notes go to stderr as ``fem-racket COMMAND: note: ...`` so stdout stays the result (a table or
JSON that can be piped); they report a request the command adjusted, never an error.
"""

from __future__ import annotations

import argparse
import math
import sys
from typing import TYPE_CHECKING

if TYPE_CHECKING:
    from fem_racket.frame.model import FrameModel

__all__ = ["note", "note_modes", "significant"]


def note(args: argparse.Namespace, text: str) -> None:
    """One line on stderr, ``fem-racket COMMAND: note: text`` (stdout stays the result)."""
    print(f"fem-racket {args.command}: note: {text}", file=sys.stderr)


def note_modes(args: argparse.Namespace, model: FrameModel) -> None:
    """Say so when ``--modes`` asks for more flexible modes than the mesh has (all are kept).

    Only for a count the user chose (on the command line, or other than the default from a run
    file): the default of 80 exceeds every mesh up to 40 elements by design.
    """
    from fem_racket.frame.model import DEFAULT_MODES

    if getattr(args, "basis", "modal") != "modal":
        return
    chosen = "modes" in getattr(args, "explicit_options", ()) or args.modes != DEFAULT_MODES
    available = model.fe.ndof - 2  # minus the two rigid-body modes
    if chosen and args.modes > available:
        n = model.mesh.n_elements
        text = f"modes = {args.modes}: the {n}-element mesh has {available} flexible modes"
        if getattr(args, "offset", 0.0):  # off the axis --modes counts bending and torsion each
            torsion = model.torsion.ndof - 1  # minus the rigid roll
            note(
                args,
                f"{text} of bending and {torsion} of torsion (--modes counts each family); "
                f"using all, {available + torsion} flexible modes in all",
            )
            return
        note(args, f"{text}; using all {available}")


def significant(value: float, digits: int) -> str:
    """``value`` with ``digits`` significant digits, in plain notation from 1e-4 to 1e9
    (``significant(608.14, 4)`` is ``608.1``, ``significant(0.30412, 4)`` is ``0.3041``,
    ``significant(27400.0, 4)`` is ``27400``), in e-notation outside."""
    if not math.isfinite(value):
        return str(value)
    if value == 0:
        return f"{0.0:.{digits - 1}f}"
    value = float(f"{value:.{digits - 1}e}")  # round first: 9.99996 -> 10.000, not 9.9999
    exponent = math.floor(math.log10(abs(value)))
    if not -4 <= exponent < 9:
        return f"{value:.{digits - 1}e}"
    return f"{value:.{max(digits - 1 - exponent, 0)}f}"
