"""The impact zone, the ball and the player's swing of a design study on the command line
(``optimize``, ``sensitivity``): the fields of
:class:`fem_racket.studies.design.options.ZoneOptions`."""

from __future__ import annotations

import argparse

from fem_racket.cli.options.lists import add_options, number_list
from fem_racket.impact.constants import DEFAULT_REFERENCE
from fem_racket.studies.design.zone_kinds import ZONES

__all__ = ["add_zone_options"]

#: (name, default, metavar, help) of the number options, in the order --help shows them.
BALL = (
    ("ball_mass", None, "KG", "ball mass m_B [kg] (default 0.057)"),
    ("zeta", None, None, "ball/string damping ratio [-] (default from the clamped COR 0.83)"),
    ("racket_speed", None, "M_S", "swing: speed of the reference point towards the ball with "
     "the starting racket [m/s]; slower for heavier swings, ~I^-0.27 (Cross & Bower 2006) "
     "(default: a stationary racket)"),
    ("reference", None, "X", "reference point of --racket-speed x/L [-] "
     f"(default {DEFAULT_REFERENCE} with --racket-speed; refused without it)"),
    ("pivot", 0.10, "M", "swing pivot (hand) from the butt [m] (default 0.10)"),
    ("swing_exponent", -0.27, None, "swing speed ~ I^exponent, the exponent [-] "
     "(default -0.27; 0: same swing for any racket)"),
)  # fmt: skip


def add_zone_options(parser: argparse.ArgumentParser) -> None:
    """The "impact zone, ball and swing" option group."""
    z = parser.add_argument_group("impact zone, ball and swing")
    z.add_argument(
        "--zone",
        choices=ZONES,
        default="uniform",
        help="uniform over --zone-range, or a Gaussian about the starting racket's "
        "mode-1 node (Hatze 1994) (default uniform)",
    )
    z.add_argument(
        "--zone-range",
        **number_list(),
        default=[0.6, 0.9],
        metavar="LOW,HIGH",
        help="uniform zone x/L [-] (default 0.6,0.9)",
    )
    z.add_argument(
        "--zone-points",
        type=int,
        default=20,
        metavar="N",
        help="impact points in the zone (default 20)",
    )
    z.add_argument(
        "--zone-sigma",
        type=float,
        default=0.05,
        metavar="X",
        help="standard deviation of the node zone x/L [-] (default 0.05)",
    )
    z.add_argument(
        "--speeds",
        "--speed",
        **number_list(),
        default=[20.0, 30.0, 40.0],
        metavar="M_S",
        help="incoming ball speeds [m/s] (default 20 30 40)",
    )
    add_options(z, BALL, type=float)
