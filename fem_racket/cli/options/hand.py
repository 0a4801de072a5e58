"""The hand-held racket on the command line: ``--grip`` and the hand's parameters
(:mod:`fem_racket.frame.hand`), ``--shock-window``; :func:`hand_from_args` reads them."""

from __future__ import annotations

import argparse
import dataclasses

from fem_racket.frame.grips import GRIPS, Hand
from fem_racket.impact.constants import DEFAULT_WINDOW
from fem_racket.validation import InputError, show

__all__ = ["HAND_OPTIONS", "add_hand_options", "hand_from_args"]


#: Hand options: argparse dest -> (option, Hand field, unit, help).
HAND_OPTIONS = {
    "hand_mass": ("--hand-mass", "mass", "KG", "hand mass m_h [kg]"),
    "grip_start": ("--grip-start", "grip_start", "M", "start of the grip from the butt [m]"),
    "grip_end": ("--grip-end", "grip_end", "M", "end of the grip from the butt [m]"),
    "grip_stiffness": (
        "--grip-stiffness",
        "stiffness",
        "N_M2",
        "stiffness k' of the grip layer [N/m per m of handle], >= 0",
    ),
    "grip_damping": (
        "--grip-damping",
        "damping",
        "N_S_M2",
        "damping c' of the grip layer [N s/m per m of handle], >= 0",
    ),
    "hand_inertia": (
        "--hand-inertia",
        "inertia",
        "KG_M2",
        "hand's inertia about its centre [kg m^2], a uniform rod over the grip unless given",
    ),
}


def add_hand_options(parser: argparse.ArgumentParser) -> None:
    """--grip and the hand's parameters (a hand-held racket, :mod:`fem_racket.frame.hand`), and
    --shock-window; read them with :func:`hand_from_args`."""
    g = parser.add_argument_group(
        "hand (a hand-held racket: any of these holds the racket in a hand)"
    )
    g.add_argument(
        "--grip",
        dest="hand_grip",
        choices=tuple(GRIPS),
        default=None,
        help="an illustrative loose or firm grip (assumptions, fem_racket.frame.hand); the "
        "options below change its values (default: no hand; loose when only they are given)",
    )
    loose, firm = GRIPS["loose"], GRIPS["firm"]
    for dest, (option, name, metavar, text) in HAND_OPTIONS.items():
        a, b = getattr(loose, name), getattr(firm, name)
        default = "the grip's" if a is None else f"the grip's: {a:g} loose, {b:g} firm"
        g.add_argument(
            option, dest=dest, type=float, default=None, metavar=metavar,
            help=f"{text} (default {default})",
        )  # fmt: skip
    g.add_argument(
        "--shock-window",
        dest="hand_shock_window",
        type=float,
        default=None,
        metavar="S",
        help="window of the grip force's peak and vibration RMS from the start of contact [s] "
        f"(default {DEFAULT_WINDOW:g})",
    )


def hand_from_args(args: argparse.Namespace) -> Hand | None:
    """The hand the options give (a --grip preset with the given parameters replaced); None when
    no hand option is given."""
    given = {
        name: getattr(args, dest)
        for dest, (_, name, _, _) in HAND_OPTIONS.items()
        if getattr(args, dest) is not None
    }
    if args.hand_grip is None and not given:
        if args.hand_shock_window is not None:
            raise InputError(
                f"shock_window = {show(args.hand_shock_window)} s is not allowed without a hand: "
                "give --grip or a hand parameter",
                parameter="shock_window",
                value=args.hand_shock_window,
            )
        return None
    return dataclasses.replace(GRIPS[args.hand_grip or "loose"], **given)
