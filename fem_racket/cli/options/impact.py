"""One impact on the command line: ball, contact law, swing, solver and output-step options, and
their translation to the keyword arguments of :func:`fem_racket.simulate` (the hand's options:
:mod:`fem_racket.cli.options.hand`, named here too)."""

from __future__ import annotations

import argparse
import functools
import math
from collections.abc import Callable
from typing import TYPE_CHECKING, Any

from fem_racket.cli.options.frame import add_frame_options
from fem_racket.cli.options.hand import HAND_OPTIONS, add_hand_options, hand_from_args
from fem_racket.cli.options.laws import add_law_options, law_from_args
from fem_racket.cli.options.lists import add_options
from fem_racket.contact.constants import DEFAULT_BALL_MASS
from fem_racket.frame.constants import DEFAULT_MODES
from fem_racket.impact.constants import (
    BASES,
    DEFAULT_REFERENCE,
    DEFAULT_TOLERANCE,
    SEPARATION_EVENTS,
    SOLVER_NAMES,
)
from fem_racket.io.config_defaults import DEFAULTS as SIMULATE_DEFAULTS
from fem_racket.io.config_defaults import PLAY_DEFAULTS
from fem_racket.validation import InputError, check_range, show

if TYPE_CHECKING:
    from fem_racket.impact.swing import Swing

__all__ = [
    "DEFAULT_OUTPUT_STEP",
    "HAND_OPTIONS",
    "add_ball_options",
    "add_hand_options",
    "add_impact_options",
    "add_output_step_option",
    "add_separation_option",
    "add_solver_options",
    "add_speed_option",
    "add_swing_options",
    "check_output_step",
    "check_swing_options",
    "hand_from_args",
    "impact_kwargs",
    "racket_speed_named",
    "swing_from_args",
    "swing_kwargs",
]

#: (name, default, metavar, help) of the paper's linear ball/string law's options.
LINEAR_LAW = (
    ("kcb", None, "N_M", "ball/string stiffness K_CB [N/m] (default: from the speed; allowed "
     "[100, 1e+07])"),
    ("zeta", None, "ZETA", "ball/string damping ratio [-], 0..1 (default 0.0592, clamped COR "
     "0.83)"),
)  # fmt: skip

#: (name, default, metavar, help) of the racket's motion before impact (:func:`add_swing_options`).
SWING = (
    ("racket_speed", PLAY_DEFAULTS["racket_speed"], "M_S", "racket speed towards the ball before "
     "impact [m/s] at the --reference point (default 0: a racket at rest)"),
    ("reference", PLAY_DEFAULTS["reference"], "X_OVER_L", f"point x/L [-] whose speed "
     f"--racket-speed gives (default {DEFAULT_REFERENCE}, the string centre)"),
    ("pivot", PLAY_DEFAULTS["pivot"], "M", "the racket turns about this point [m from the butt; "
     "negative beyond it, e.g. a shoulder], so the impact point moves at V (x_i - P)/(x_ref - P) "
     "(default: none, the racket translates at V)"),
)  # fmt: skip


def add_impact_options(parser: argparse.ArgumentParser) -> None:
    """Frame options plus the ball, the ball/string law, the impact and the solver."""
    add_frame_options(parser)
    g = parser.add_argument_group("impact")
    add_speed_option(g)
    g.add_argument(
        "--position",
        type=float,
        default=0.75,
        metavar="X_OVER_L",
        help="impact point x/L [-] from the grip end, 0..1 (default 0.75)",
    )
    g.add_argument(
        "--offset",
        type=float,
        default=0.0,
        metavar="M",
        help="lateral offset [m] of the impact point from the long axis, on the head outline "
        "(100 in^2 ellipse, 0.326 x 0.252 m): the frame also twists (default 0: on the axis)",
    )
    add_ball_options(g)
    add_law_options(parser)
    add_solver_options(parser)


def add_speed_option(
    group: argparse._ArgumentGroup, text: str = "incident ball speed V_B0 [m/s] (default 20)"
) -> None:
    """--speed M_S: the ball's speed before impact [m/s], 20 by default; ``text`` its help."""
    speed = PLAY_DEFAULTS["speed"]
    group.add_argument("--speed", type=float, default=speed, metavar="M_S", help=text)


def add_ball_options(
    group: argparse._ArgumentGroup, ball_mass: float | None = DEFAULT_BALL_MASS
) -> None:
    """--ball-mass and the paper's linear ball/string law (--kcb, --zeta) of the commands of
    one impact and refine; ``ball_mass`` the default of --ball-mass (None: the study's own)."""
    text = f"ball mass m_B [kg] (default {DEFAULT_BALL_MASS}; not stated in the paper)"
    add_options(group, [("ball_mass", ball_mass, "KG", text), *LINEAR_LAW], type=float)


def add_separation_option(group: argparse._ArgumentGroup) -> None:
    """--separation: the event that ends the contact (the paper's: the spring's deflection)."""
    group.add_argument(
        "--separation",
        default="displacement",
        choices=SEPARATION_EVENTS,
        help="end of contact: spring deflection or force back to zero "
        "(default displacement, the paper's)",
    )


def add_swing_options(parser: argparse.ArgumentParser) -> None:
    """--racket-speed, --reference, --pivot: the racket's motion before impact (every command
    that takes a swing: simulate, sweep, map); read them with :func:`swing_from_args`."""
    g = parser.add_argument_group("swing (racket motion before impact)")
    add_options(g, SWING, type=float)


def check_swing_options(
    args: argparse.Namespace, *, pivot_at_rest: bool = False, at_reference: bool = True
) -> None:
    """Refuse a ``--racket-speed`` beyond :data:`MAX_RACKET_SPEED`, or (``at_reference``: where
    studies build the swing; simulate's impact point is the library's, :func:`racket_speed_named`)
    one whose closing speed with ``--speed`` at the reference point leaves the paper's K_CB
    range (K_CB from the speed: no --kcb, no --law); and a swing's ``--reference`` (and
    ``--pivot`` unless ``pivot_at_rest``: the maps' centre of percussion) given, on the command
    line or in a run file, without a swing (``--racket-speed`` 0): the racket at rest would drop
    them. Left out, both are None (a run file's reference at its default too); the swing's
    reference point is then its default (:meth:`~fem_racket.impact.swing.Swing.from_speed`)."""
    from fem_racket.impact.closing import check_kcb_closing
    from fem_racket.impact.swing import check_racket_speed
    from fem_racket.studies.map_options import check_at_rest

    v_r = args.racket_speed
    check_racket_speed(v_r)  # before the closing speed: Swing.from_speed's bound, no racket yet
    closing = getattr(args, "speed", 0.0) + v_r
    linear = getattr(args, "kcb", None) is None and getattr(args, "law", None) in (None, "linear")
    if at_reference and v_r != 0.0 and linear and math.isfinite(closing):
        check_kcb_closing(args.speed, v_r, closing, "racket_speed")
    if args.reference is not None:
        check_range("reference", args.reference, 0.0, 1.0, unit="x/L")  # as the swing's check
    check_at_rest(v_r, args.reference, None if pivot_at_rest else args.pivot)


def racket_speed_named(command: Callable[[argparse.Namespace], int]) -> Callable[..., int]:
    """Decorate a ``command``: the library's refusal of the racket's speed at the impact point
    (:func:`fem_racket.impact.problem_checks.check_swing`) named as ``racket_speed`` when it is
    that option's value (a translation), as a run file names its key
    (:func:`fem_racket.io.config_named.named_by_key`)."""

    @functools.wraps(command)
    def run(args: argparse.Namespace) -> int:
        from fem_racket.io.config_named import named_by_key

        try:
            return command(args)
        except InputError as exc:
            raise named_by_key(exc, {"racket_speed": "racket_speed"}, vars(args), None) from None

    return run


def swing_kwargs(args: argparse.Namespace) -> dict[str, Any]:
    """The swing's options as the keywords ``racket_speed``, ``reference`` and ``pivot`` of the
    maps (:func:`fem_racket.studies.racket_map.racket_map`, ``face_map``) and of compare's
    ``Play``, which build the swing themselves; ``--reference`` without a swing refused
    (``--pivot`` sets the maps' centre of percussion at rest too)."""
    check_swing_options(args, pivot_at_rest=True, at_reference=False)  # the maps' points: theirs
    return {name: getattr(args, name) for name, *_ in SWING}


def swing_from_args(args: argparse.Namespace, length: float) -> Swing | None:
    """The swing the options give for a racket of ``length`` [m]; None for a racket at rest
    (the options checked by :func:`check_swing_options`)."""
    from fem_racket.impact.swing import Swing

    check_swing_options(args, at_reference=False)  # the impact point's: the library's
    if args.racket_speed == 0.0:
        Swing.from_speed(0.0, length, reference=args.reference, pivot=args.pivot)  # checks
        return None
    return Swing.from_speed(args.racket_speed, length, reference=args.reference, pivot=args.pivot)


def add_solver_options(parser: argparse.ArgumentParser, *, t_max: bool = True) -> None:
    """--solver, --separation, --basis, --modes, --rtol, --atol and (optionally) --t-max."""
    s = parser.add_argument_group("solver")
    s.add_argument(
        "--solver",
        default="auto",
        choices=SOLVER_NAMES,
        help="integrator: exact (the paper's linear law, closed-form modal solution), general "
        "(any contact law or racket motion), cvode, bdf, or auto: exact for the paper's law, "
        "general otherwise (default auto)",
    )
    add_separation_option(s)
    s.add_argument(
        "--basis",
        default="modal",
        choices=BASES,
        help="frame coordinates for the BDF solvers; exact needs modal (default modal)",
    )
    s.add_argument(
        "--modes",
        type=int,
        default=DEFAULT_MODES,
        metavar="N",
        help=f"flexible frame modes kept in the modal basis (default {DEFAULT_MODES}; "
        "a mesh of n elements has 2n, all kept when fewer; off the long axis N of bending "
        "and N of torsion)",
    )
    if t_max:
        s.add_argument(
            "--t-max",
            type=float,
            default=None,
            metavar="S",
            help="give up if the ball has not separated by then [s] (default 20 x the eq 11 "
            "contact time)",
        )
    s.add_argument(
        "--tolerance",
        type=float,
        default=DEFAULT_TOLERANCE,
        metavar="COR",
        help="COR error [-] the exact solver may make: modes far above the contact frequency "
        f"become one residual mode (default {DEFAULT_TOLERANCE:g}, but histories keep every "
        "mode unless it is given; 0: every mode)",
    )
    s.add_argument(
        "--rtol",
        type=float,
        default=1e-10,
        help="relative tolerance of cvode/bdf [-] (default 1e-10)",
    )
    s.add_argument(
        "--atol",
        type=float,
        default=1e-12,
        help="absolute tolerance of cvode/bdf [state units: m, rad, m/s, rad/s] (default 1e-12)",
    )


#: Default spacing of the output times of an impact's histories [s].
DEFAULT_OUTPUT_STEP = 1e-5


def add_output_step_option(group: argparse._ArgumentGroup) -> None:
    """--output-step S: spacing of the simulation's output times [s] (simulate, export-vtk,
    animate); check it with :func:`check_output_step`."""
    group.add_argument(
        "--output-step",
        type=float,
        default=DEFAULT_OUTPUT_STEP,
        metavar="S",
        help="spacing of the simulation's output times [s], > 0 (default 1e-5); the end of "
        "contact is always the last output time",
    )


def check_output_step(value: float) -> float:
    """``value`` if it is a finite number > 0, else :class:`InputError`."""
    if not 0 < value < math.inf:  # also catches NaN
        raise InputError(
            f"output_step = {show(value)} s is not allowed: must be a finite number > 0"
        )
    return value


def impact_kwargs(args: argparse.Namespace) -> dict[str, Any]:
    """Keyword arguments of :func:`fem_racket.simulate` from the parsed options: the impact
    point, speed and law, and every other option given (on the command line or in a run file)."""
    from fem_racket.impact.solvers import auto_method

    given = set(getattr(args, "explicit_options", ()))
    law = law_from_args(args)
    if getattr(args, "solver", "auto") == "auto":  # as the library's auto picks it, and the
        args.solver = auto_method(law is None)  # provenance records the method that ran
    kwargs: dict[str, Any] = {"position": args.position, "speed": args.speed}
    for key, default in SIMULATE_DEFAULTS.items():
        value = getattr(args, key, default)
        if key in given or value != default:
            kwargs[key] = value
    if law is not None:
        kwargs["law"] = law
    return kwargs
