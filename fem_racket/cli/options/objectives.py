"""The objectives and constraints of a design study on the command line (``optimize``,
``sensitivity``): what is maximised or minimised, the handle-shock settings, and the bounds on
mass, balance, swing weight and first frequency."""

from __future__ import annotations

import argparse
from typing import TYPE_CHECKING

from fem_racket.cli.options.fields import options_from_args
from fem_racket.cli.options.lists import number_list
from fem_racket.frame.grips import GRIPS
from fem_racket.impact.constants import DEFAULT_WINDOW
from fem_racket.io.constants import CONSTRAINTS
from fem_racket.studies.design.objective_names import MINIMISED, OBJECTIVES

if TYPE_CHECKING:
    from fem_racket.studies.design.options import ObjectiveOptions

__all__ = ["CONSTRAINTS", "add_objective_options", "objectives_from_args"]


def _bounds(text: str) -> tuple:
    """argparse type: ``start`` or ``LOW,HIGH``."""
    if str(text).strip() == "start":
        return ("start",)
    try:
        lo, hi = (float(w) for w in str(text).split(","))
    except ValueError:
        raise argparse.ArgumentTypeError(
            f"invalid range: {text!r} (give LOW,HIGH or 'start' for the starting racket's value)"
        ) from None
    return (lo, hi)


def add_objective_options(parser: argparse.ArgumentParser, *, constraints: bool = True) -> None:
    """The "objectives and constraints" option group; without ``constraints`` (sensitivity,
    which samples the variables' whole box and constrains nothing), the "objectives" group
    without the bounds on mass, balance, swing weight and first frequency."""
    o = parser.add_argument_group("objectives and constraints" if constraints else "objectives")
    o.add_argument(
        "--objective",
        **number_list(str),
        default=["cor"],
        metavar="LIST",
        help="comma list of "
        + ", ".join(OBJECTIVES)
        + " (maximised; "
        + ", ".join(sorted(MINIMISED))
        + " minimised) (default cor; nsga2 takes 2-3)",
    )
    o.add_argument(
        "--power-fraction",
        type=float,
        default=0.9,
        metavar="F",
        help="power region: where v_out >= F [-] x its maximum (default 0.9)",
    )
    o.add_argument(
        "--stiffness-cost",
        type=float,
        default=0.0,
        metavar="PER_N_M2",
        help="subtracted from the objectives per N m^2 of EI_1 [1/(N m^2)] (default 0)",
    )
    o.add_argument(
        "--grip",
        choices=tuple(GRIPS),
        default="loose",
        help="the hand of handle_shock and peak_grip_force: an illustrative loose or firm grip "
        "(assumptions, fem_racket.frame.hand) (default loose)",
    )
    o.add_argument(
        "--shock-window",
        type=float,
        default=DEFAULT_WINDOW,
        metavar="S",
        help=f"window of the handle-shock measures from the start of contact [s] "
        f"(default {DEFAULT_WINDOW:g})",
    )
    for dest, (_, text) in CONSTRAINTS.items() if constraints else ():
        o.add_argument(
            "--" + dest.replace("_", "-"),
            type=_bounds,
            default=None,
            metavar="LOW,HIGH",
            help=f"{text}: LOW,HIGH or 'start' (keep the starting racket's) (default: free)",
        )


def objectives_from_args(args: argparse.Namespace) -> ObjectiveOptions:
    """The objectives and constraints the options give."""
    from fem_racket.studies.design.options import ObjectiveOptions

    constraints = {q: getattr(args, dest, None) for dest, (q, _) in CONSTRAINTS.items()}
    return options_from_args(
        args, ObjectiveOptions, objectives=args.objective, constraints=constraints
    )
