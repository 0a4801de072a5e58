"""The design variables on the command line (``optimize``, ``sensitivity``): the segments, the
parameter groups to vary (:data:`fem_racket.studies.design.variable_groups.VARY`) and their
bounds, added masses, smooth profiles and the string bed."""

from __future__ import annotations

import argparse

from fem_racket.cli.options.lists import number_list

__all__ = ["add_variable_options"]


def add_variable_options(parser: argparse.ArgumentParser) -> None:
    """The "design variables" option group."""
    g = parser.add_argument_group("design variables")
    g.add_argument(
        "--boundaries",
        **number_list(),
        default=[0.3, 0.5333333333333333, 0.7666666666666667],
        metavar="X",
        help="segment boundaries x/L [-] of the design frame "
        "(default 0.3, 0.533, 0.767: 4 segments)",
    )
    g.add_argument(
        "--vary",
        **number_list(str),
        default=["ei", "rhoa"],
        metavar="LIST",
        help="free parameter groups, comma list of ei, rhoa, mass, position, string, "
        "string_cubic (default ei,rhoa)",
    )
    g.add_argument(
        "--link-ei",
        action="store_true",
        help="one EI variable (EI_1), the others keeping the starting ratios",
    )
    g.add_argument(
        "--ei-bounds",
        **number_list(),
        default=[50.0, 3000.0],
        metavar="LOW,HIGH",
        help="bounds of every EI [N m^2] (default 50,3000: Fig 13's range)",
    )
    g.add_argument(
        "--rhoa-bounds",
        **number_list(),
        default=[0.2, 1.2],
        metavar="LOW,HIGH",
        help="bounds of every rhoA [kg/m] (default 0.2,1.2)",
    )
    g.add_argument(
        "--mass-positions",
        **number_list(),
        default=[],
        metavar="X",
        help="centres x/L [-] of added masses (20 mm strips; default none)",
    )
    g.add_argument(
        "--mass-bounds",
        **number_list(),
        default=[0.0, 0.03],
        metavar="LOW,HIGH",
        help="bounds of every added mass [kg] (default 0,0.03)",
    )
    g.add_argument(
        "--mass-start",
        type=float,
        default=0.0,
        metavar="KG",
        help="starting value of every added mass [kg] (default 0)",
    )
    g.add_argument(
        "--position-bounds",
        **number_list(),
        default=[0.0, 1.0],
        metavar="LOW,HIGH",
        help="bounds x/L [-] of every added mass's centre with --vary position (default 0,1)",
    )
    g.add_argument(
        "--ei-points",
        **number_list(),
        default=[],
        metavar="X",
        help="control stations x/L [-] of a smooth EI(x) (first 0, last 1), one EI variable each, "
        "instead of one per segment (default: segments)",
    )
    g.add_argument(
        "--rhoa-points",
        **number_list(),
        default=[],
        metavar="X",
        help="control stations x/L [-] of a smooth rhoA(x), as --ei-points (default: segments)",
    )
    g.add_argument(
        "--interpolation",
        choices=("pchip", "linear"),
        default="pchip",
        help="profile between control points: monotone cubic (PCHIP) or linear (default pchip)",
    )
    g.add_argument(
        "--string-bounds",
        **number_list(),
        default=None,
        metavar="LOW,HIGH",
        help="with --vary string: bounds of the factor on K_CB (linear law) or of k_s [N/m] "
        "(--law series) (default 0.5-2 x the start)",
    )
    g.add_argument(
        "--cubic-bounds",
        **number_list(),
        default=None,
        metavar="LOW,HIGH",
        help="with --vary string_cubic (--law series): bounds of k_3 [N/m^3] "
        "(default 0-2 x the start)",
    )
