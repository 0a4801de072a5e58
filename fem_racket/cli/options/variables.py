"""The design variables on the command line (``optimize``, ``sensitivity``): the segments, the
parameter groups to vary (:data:`fem_racket.studies.design.variable_groups.VARY`) and their
bounds, added masses, smooth profiles and the string bed (the fields of
:class:`fem_racket.studies.design.options.VariableOptions`)."""

from __future__ import annotations

import argparse

from fem_racket.cli.options.lists import add_options, number_list

__all__ = ["add_variable_options"]

#: (name, default, metavar, help) of the list options, in the order --help shows them.
SEGMENTS = (
    (
        "boundaries",
        [0.3, 0.5333333333333333, 0.7666666666666667],
        "X",
        "segment boundaries x/L [-] of the design frame (default 0.3, 0.533, 0.767: 4 segments)",
    ),
)
BOUNDS = (
    ("ei_bounds", [50.0, 3000.0], "LOW,HIGH", "bounds of every EI [N m^2] (default 50,3000: "
     "Fig 13's range)"),
    ("rhoa_bounds", [0.2, 1.2], "LOW,HIGH", "bounds of every rhoA [kg/m] (default 0.2,1.2)"),
    ("mass_positions", [], "X", "centres x/L [-] of added masses (20 mm strips; default none)"),
    ("mass_bounds", [0.0, 0.03], "LOW,HIGH", "bounds of every added mass [kg] (default 0,0.03)"),
)  # fmt: skip
PROFILES = (
    ("position_bounds", [0.0, 1.0], "LOW,HIGH", "bounds x/L [-] of every added mass's centre "
     "with --vary position (default 0,1)"),
    ("ei_points", [], "X", "control stations x/L [-] of a smooth EI(x) (first 0, last 1), one EI "
     "variable each, instead of one per segment (default: segments)"),
    ("rhoa_points", [], "X", "control stations x/L [-] of a smooth rhoA(x), as --ei-points "
     "(default: segments)"),
)  # fmt: skip
STRINGS = (
    ("string_bounds", None, "LOW,HIGH", "with --vary string: bounds of the factor on K_CB "
     "(linear law) or of k_s [N/m] (--law series) (default 0.5-2 x the start)"),
    ("cubic_bounds", None, "LOW,HIGH", "with --vary string_cubic (--law series): bounds of k_3 "
     "[N/m^3] (default 0-2 x the start)"),
)  # fmt: skip


def add_variable_options(parser: argparse.ArgumentParser) -> None:
    """The "design variables" option group."""
    g = parser.add_argument_group("design variables")
    add_options(g, SEGMENTS, **number_list())
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
    add_options(g, BOUNDS, **number_list())
    g.add_argument(
        "--mass-start",
        type=float,
        default=0.0,
        metavar="KG",
        help="starting value of every added mass [kg] (default 0)",
    )
    add_options(g, PROFILES, **number_list())
    g.add_argument(
        "--interpolation",
        choices=("pchip", "linear"),
        default="pchip",
        help="profile between control points: monotone cubic (PCHIP) or linear (default pchip)",
    )
    add_options(g, STRINGS, **number_list())
