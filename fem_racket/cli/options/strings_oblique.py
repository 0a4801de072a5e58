"""``fem-racket simulate`` with an incidence and a string bed: the oblique impact on the bed.

The oblique options (:mod:`fem_racket.cli.options.oblique`) with any string option run the ball's
own law on the bed for the normal impact (:func:`fem_racket.cli.options.strings.strung_from_args`)
and the tangential contact over its force history (:func:`fem_racket.impact.oblique.solve.
solve_oblique`, called unchanged); printed and written as the oblique impact's, with the bed's
rows. The strung racket is free and at rest, so ``--clamped`` and a stroke's face and path angles
are refused in one line, as is a hand.
"""

from __future__ import annotations

import argparse
from typing import TYPE_CHECKING, Any

from fem_racket.cli.options.oblique import oblique_rows, write_oblique
from fem_racket.cli.options.output import print_result
from fem_racket.cli.options.runfile_named import where_set
from fem_racket.cli.options.strings import STRING_DESTS, strung_from_args
from fem_racket.cli.text import significant
from fem_racket.validation import InputError

if TYPE_CHECKING:
    from fem_racket.impact.incidence import Incidence
    from fem_racket.strings.bed import StringBed

__all__ = ["run_strung_oblique"]

#: Oblique options the strung racket (free, at rest) does not take.
REFUSED = ("clamped", "face_angle", "path_angle")


def run_strung_oblique(
    args: argparse.Namespace, strings: StringBed, incidence: Incidence, hand: Any, model, files
) -> int:
    """The oblique impact of ``incidence`` on ``strings`` and the frame ``model``: run, write
    ``--out`` (``files``: list of Path), print."""
    if hand is not None:
        raise InputError("a hand is not allowed with a string bed: give one of them")
    for dest in REFUSED:
        if getattr(args, dest, None):
            raise InputError(
                f"{where_set(args, dest)} is not allowed with {_bed(args)}: the strung racket "
                "is free and at rest"
            )
    result = strung_from_args(args, strings, model, incidence)
    summary = {
        **result.summary(),
        "ball_law": "kawazoe-1997-ball" if args.law == "linear" else args.law,
    }
    if args.out:
        write_oblique(args, result, summary, files)
    return print_result(args, summary, _rows, files)


def _bed(args: argparse.Namespace) -> str:
    """The string bed, for a message: named by its first key when a run file set it
    (``the string bed of strings.tension_n (run.toml)``)."""
    files = getattr(args, "file_options", {})
    keys = [d for d in STRING_DESTS if d in files and getattr(args, d, None) is not None]
    return f"the string bed of {where_set(args, keys[0])}" if keys else "a string bed"


def _rows(summary: dict[str, Any]) -> list[tuple[str, str, str]]:
    """The oblique impact's rows, then the bed's."""
    return [
        *oblique_rows(summary),
        ("string bed", f"{summary['pattern']} {summary['string']}", ""),
        ("string tension", significant(summary["string_tension_n"], 4), "N"),
        ("stringbed stiffness", significant(summary["stringbed_stiffness_n_m"], 4), "N/m"),
        ("ball law", summary["ball_law"], ""),
        ("solver", summary["solver"], ""),
    ]
