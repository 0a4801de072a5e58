"""Options of the design commands (``optimize``, ``sensitivity``): the design problem and where
its designs run. A run file's ``[design]`` (optimize) or ``[sensitivity]`` table takes the same
keys (``--ei-bounds`` -> ``ei_bounds``); the starting racket comes from the frame options or the
``[frame]`` table."""

from __future__ import annotations

import argparse
from typing import Any

from fem_racket.cli.common import add_frame_options, frame_from_args, run_parameters
from fem_racket.cli.laws import add_law_options, law_from_args
from fem_racket.cli.lists import number_list
from fem_racket.frame.hand import GRIPS
from fem_racket.impact.held_shock import DEFAULT_WINDOW
from fem_racket.studies.design.build import ZONES, design_problem
from fem_racket.studies.design.problem import DesignProblem
from fem_racket.studies.design.variables import MINIMISED, OBJECTIVES
from fem_racket.studies.executors import BACKENDS

__all__ = [
    "add_design_options",
    "add_progress_option",
    "add_run_options",
    "problem_from_args",
    "run_options",
]

#: Constraint options: dest -> (quantity, help).
CONSTRAINTS = {
    "mass_range": ("mass_kg", "total mass [kg]"),
    "balance_range": ("balance_m", "balance point from the butt [m]"),
    "swing_weight_range": ("swing_weight_kg_cm2", "swing weight about 0.10 m [kg cm^2]"),
    "f1_range": ("f1_hz", "first free-free frequency [Hz]"),
}


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


def add_design_options(parser: argparse.ArgumentParser) -> None:
    """The design problem's options (starting racket: the frame options)."""
    add_frame_options(parser)
    g = parser.add_argument_group("design variables")
    g.add_argument(
        "--boundaries",
        **number_list(),
        default=[0.3, 0.5333333333333333, 0.7666666666666667],
        metavar="X",
        help="segment boundaries x/L of the design frame (default 0.3, 0.533, 0.767: 4 segments)",
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
        help="centres x/L of added masses (20 mm strips; default none)",
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
        help="bounds x/L of every added mass's centre with --vary position (default 0,1)",
    )
    g.add_argument(
        "--ei-points",
        **number_list(),
        default=[],
        metavar="X",
        help="control stations x/L of a smooth EI(x) (first 0, last 1), one EI variable each, "
        "instead of one per segment (default: segments)",
    )
    g.add_argument(
        "--rhoa-points",
        **number_list(),
        default=[],
        metavar="X",
        help="control stations x/L of a smooth rhoA(x), as --ei-points (default: segments)",
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
        help="uniform zone x/L (default 0.6,0.9)",
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
        help="standard deviation of the node zone x/L (default 0.05)",
    )
    z.add_argument(
        "--speeds",
        **number_list(),
        default=[20.0, 30.0, 40.0],
        metavar="M_S",
        help="incoming ball speeds [m/s] (default 20 30 40)",
    )
    z.add_argument(
        "--ball-mass",
        type=float,
        default=None,
        metavar="KG",
        help="ball mass m_B [kg] (default 0.057)",
    )
    z.add_argument(
        "--zeta",
        type=float,
        default=None,
        help="ball/string damping ratio (default from the clamped COR 0.83)",
    )
    z.add_argument(
        "--racket-speed",
        type=float,
        default=None,
        metavar="M_S",
        help="swing: speed of the reference point towards the ball with the starting "
        "racket [m/s]; slower for heavier swings, ~I^-0.27 (Cross & Bower 2006) "
        "(default: a stationary racket)",
    )
    z.add_argument(
        "--reference",
        type=float,
        default=0.75,
        metavar="X",
        help="reference point of --racket-speed x/L (default 0.75)",
    )
    z.add_argument(
        "--pivot",
        type=float,
        default=0.10,
        metavar="M",
        help="swing pivot (hand) from the butt [m] (default 0.10)",
    )
    z.add_argument(
        "--swing-exponent",
        type=float,
        default=-0.27,
        help="swing speed ~ I^exponent (default -0.27; 0: same swing for any racket)",
    )
    o = parser.add_argument_group("objectives and constraints")
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
        help="power region: where v_out >= F * its maximum (default 0.9)",
    )
    o.add_argument(
        "--stiffness-cost",
        type=float,
        default=0.0,
        metavar="PER_N_M2",
        help="subtracted from the objectives per N m^2 of EI_1 (default 0)",
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
    for dest, (_, text) in CONSTRAINTS.items():
        o.add_argument(
            "--" + dest.replace("_", "-"),
            type=_bounds,
            default=None,
            metavar="LOW,HIGH",
            help=f"{text}: LOW,HIGH or 'start' (keep the starting racket's) (default: free)",
        )
    add_law_options(parser)


def add_run_options(parser: argparse.ArgumentParser) -> None:
    """Where designs run: --backend, --workers, --scheduler, --seed."""
    g = parser.add_argument_group("execution")
    g.add_argument(
        "--backend",
        choices=BACKENDS,
        default=None,
        help="serial, processes or dask (default: processes for batches of 8+ designs)",
    )
    g.add_argument("--workers", type=int, default=None, help="processes (default: all cores)")
    g.add_argument(
        "--scheduler",
        default=None,
        metavar="ADDRESS",
        help="Dask scheduler tcp://HOST:PORT (default none)",
    )
    g.add_argument("--seed", type=int, default=1, help="random seed (default 1)")


def add_progress_option(group: argparse._ArgumentGroup) -> None:
    """--progress / --no-progress, in the command's output group."""
    group.add_argument(
        "--progress",
        action=argparse.BooleanOptionalAction,
        default=None,
        help="progress bar on stderr (default: when stderr is a terminal)",
    )


def run_options(args: argparse.Namespace) -> dict[str, Any]:
    """Keywords of the design studies from the run and progress options: backend, workers,
    scheduler, seed, progress and the run parameters (provenance)."""
    return {
        "backend": args.backend,
        "workers": args.workers,
        "scheduler": args.scheduler,
        "seed": args.seed,
        "progress": args.progress,
        "parameters": run_parameters(args),
    }


def problem_from_args(args: argparse.Namespace) -> DesignProblem:
    """The design problem the options describe."""
    kwargs: dict[str, Any] = {
        "objectives": args.objective,
        "boundaries": args.boundaries,
        "vary": args.vary,
        "link_ei": args.link_ei,
        "ei_bounds": args.ei_bounds,
        "rhoa_bounds": args.rhoa_bounds,
        "mass_positions": args.mass_positions,
        "mass_bounds": args.mass_bounds,
        "mass_start": args.mass_start,
        "position_bounds": args.position_bounds,
        "ei_points": args.ei_points,
        "rhoa_points": args.rhoa_points,
        "interpolation": args.interpolation,
        "law": law_from_args(args),
        "string_bounds": args.string_bounds,
        "cubic_bounds": args.cubic_bounds,
        "zone": args.zone,
        "zone_range": args.zone_range,
        "zone_points": args.zone_points,
        "zone_sigma": args.zone_sigma,
        "speeds": args.speeds,
        "racket_speed": args.racket_speed,
        "reference": args.reference,
        "pivot": args.pivot,
        "swing_exponent": args.swing_exponent,
        "constraints": {q: getattr(args, dest) for dest, (q, _) in CONSTRAINTS.items()},
        "stiffness_cost": args.stiffness_cost,
        "power_fraction": args.power_fraction,
        "ball_mass": args.ball_mass,
        "zeta": args.zeta,
        "elements": args.elements,
        "grip": args.grip,
        "shock_window": args.shock_window,
    }
    return design_problem(frame_from_args(args), **kwargs)
