"""The oblique impact's options of ``fem-racket simulate`` (``--angle``, ``--spin``,
``--friction``, ..., ``--clamped``, ``--face-angle``, ``--path-angle``): the run they ask for
(:func:`fem_racket.impact.simulate_oblique.simulate_oblique` or
:func:`fem_racket.impact.simulate_stroke.simulate_stroke`), its histories and its printed rows.

Without any of these options ``simulate`` runs today's head-on impact, unchanged.
"""

from __future__ import annotations

import argparse
from typing import TYPE_CHECKING, Any

from fem_racket.cli.common import (
    build_model,
    impact_kwargs,
    run_parameters,
    significant,
    swing_from_args,
)
from fem_racket.cli.options.incidence_checks import check_normal_speed, refuse_idle_options
from fem_racket.cli.options.output import print_result, write_result_files
from fem_racket.cli.options.runfile import given_options, option_name
from fem_racket.impact.incidence import (
    DEFAULT_BALL_INERTIA,
    DEFAULT_BALL_RADIUS,
    DEFAULT_COMPLIANCE_RATIO,
    DEFAULT_FRICTION,
    MAX_COMPLIANCE_RATIO,
    MAX_FRICTION,
    Incidence,
)
from fem_racket.outputs import provenance
from fem_racket.validation import InputError

if TYPE_CHECKING:
    from fem_racket.impact.oblique.stroke import Stroke

__all__ = [
    "add_oblique_options",
    "incidence_from_args",
    "oblique_from_args",
    "oblique_histories",
    "oblique_rows",
    "run_oblique",
    "stroke_from_args",
    "write_oblique",
]

#: argparse dest -> (option, Incidence field, metavar, help).
OBLIQUE_OPTIONS = {
    "angle": ("--angle", "angle", "DEG", "angle of the ball's path from the face normal, in the "
              "plane of the racket's long axis [deg], 0..90 (default 0)"),
    "spin": ("--spin", "spin", "RPM", "incoming spin [rpm]: positive = topspin (the ball's "
             "surface on the strings' side moving backward, the sense of rolling along them), "
             "negative = backspin (default 0)"),
    "friction": ("--friction", "friction", "MU", "sliding friction ball/strings [-], "
                 f"0..{MAX_FRICTION:g} "
                 f"(default {DEFAULT_FRICTION:g}, Cross 2003)"),
    "ball_inertia": ("--ball-inertia", "ball_inertia", "I_OVER_MR2", "ball's moment of inertia "
                     f"I/(m R^2) [-], 0..2/3 (default {DEFAULT_BALL_INERTIA:g}: a thick shell)"),
    "ball_radius": ("--ball-radius", "radius", "M", "ball radius R [m] (default "
                    f"{DEFAULT_BALL_RADIUS:g})"),
    "compliance_ratio": ("--compliance-ratio", "compliance_ratio", "ETA2", "normal over "
                         "tangential contact stiffness eta^2 = k_n/k_t [-], "
                         f"0..{MAX_COMPLIANCE_RATIO:g} (default "
                         f"{DEFAULT_COMPLIANCE_RATIO:g}, fitted to clamped-head spins; 0: rigid)"),
    "side_angle": ("--side-angle", "side_angle", "DEG", "angle of the ball's path from the plane "
                   "of the long axis and the face normal [deg], -90..90, positive toward the "
                   "side of a positive --offset (default 0)"),
    "side_spin": ("--side-spin", "side_spin", "RPM", "incoming side spin [rpm], about the long "
                  "axis's direction: positive = the ball's surface on the strings' side moving "
                  "toward the negative side, the sense of rolling toward the positive side "
                  "(default 0)"),
}  # fmt: skip

#: argparse dest -> (option, Stroke field, help): a stroke's geometry.
STROKE_OPTIONS = {
    "face_angle": ("--face-angle", "face_angle", "string plane to the horizontal [deg] with the "
                   "ball arriving horizontally (90: vertical; a forehand ~80, Kwon et al. 2017; "
                   "default 90 with --path-angle, else no stroke)"),
    "path_angle": ("--path-angle", "path_angle", "the racket's path above the horizontal [deg] "
                   "(needs --racket-speed, the speed along it; a forehand ~19; default 0)"),
}  # fmt: skip

#: Options a clamped head takes (besides the oblique ones and the output options; its histories
#: come from the closed form at 400 times over the contact, so --output-step is refused).
CLAMPED_TAKES = {"speed", "ball_mass", "kcb", "zeta", "separation", "json", "out", "overwrite",
                 "config", "clamped", "face_angle", *OBLIQUE_OPTIONS}  # fmt: skip


def add_oblique_options(parser: argparse.ArgumentParser) -> None:
    """The oblique impact's options and ``--clamped``; read them with
    :func:`incidence_from_args`."""
    g = parser.add_argument_group(
        "oblique impact and spin (any of these runs the oblique impact; see the README)"
    )
    for dest, (option, _, metavar, text) in OBLIQUE_OPTIONS.items():
        g.add_argument(option, dest=dest, type=float, default=None, metavar=metavar, help=text)
    for dest, (option, _, text) in STROKE_OPTIONS.items():
        g.add_argument(option, dest=dest, type=float, default=None, metavar="DEG", help=text)
    g.add_argument(
        "--clamped",
        action="store_true",
        default=None,
        help="a rigid, immovable head (eqs 1-3, the paper's linear law) instead of the free racket",
    )


def incidence_from_args(args: argparse.Namespace) -> Incidence | None:
    """The incidence the options give; None when no oblique option (nor ``--clamped``) is
    given: the head-on impact, unchanged."""
    given = {
        field: getattr(args, dest)
        for dest, (_, field, _, _) in OBLIQUE_OPTIONS.items()
        if getattr(args, dest, None) is not None
    }
    stroke = any(getattr(args, d, None) is not None for d in STROKE_OPTIONS)
    if not given and not stroke and not getattr(args, "clamped", None):
        return None
    incidence = Incidence(**given)  # each value in its range first
    if not stroke:  # a stroke's face and path angles make the ball oblique
        refuse_idle_options(args, {dest: o[1] for dest, o in OBLIQUE_OPTIONS.items()})
        check_normal_speed(args, incidence)
    return incidence


def stroke_from_args(args: argparse.Namespace) -> Stroke | None:
    """The stroke ``--face-angle`` and ``--path-angle`` give (None without them)."""
    from fem_racket.impact.oblique.stroke import Stroke

    given = {
        field: getattr(args, dest)
        for dest, (_, field, _) in STROKE_OPTIONS.items()
        if getattr(args, dest, None) is not None
    }
    if not given:
        return None
    if "path_angle" in given and args.racket_speed == 0.0:
        raise InputError(
            f"path_angle = {given['path_angle']!r} deg is not allowed without a swing: give "
            "--racket-speed",
            parameter="path_angle",
            value=given["path_angle"],
        )
    return Stroke(**given)


def _check(args: argparse.Namespace, hand: Any) -> None:
    if hand is not None and args.clamped:
        raise InputError("a hand is not allowed with --clamped: give one of them")
    if args.clamped:  # on the command line or in the run file
        given = sorted(given_options(args) - CLAMPED_TAKES)
        if given:
            dest = given[0]
            name = f"--{dest.replace('_', '-')}"
            name = (
                name if dest in getattr(args, "explicit_options", ()) else option_name(args, dest)
            )
            raise InputError(
                f"{name} is not allowed with --clamped: a clamped head takes --speed, "
                "--ball-mass, --kcb, --zeta, --separation and the oblique options"
            )


def oblique_histories(result) -> dict[str, Any]:
    """The tangential contact's histories (and the normal ones on the free racket), units in
    the names."""
    out = result.histories()
    if not result.clamped and not result.held:
        n = result.normal
        out["ball normal velocity [m/s]"] = n.ball_velocity
        out["contact force [N]"] = n.force
    return out


def oblique_rows(s: dict[str, Any]) -> list[tuple[str, str, str]]:
    grips = ", ".join(f"{a * 1e3:.4g}-{b * 1e3:.4g}" for a, b in s["grip_times_s"]) or "none"
    flips = ", ".join(f"{t * 1e3:.4g}" for t in s["friction_reversal_times_s"]) or "none"
    where = (
        "clamped head"
        if s["structure"] == "clamped head"
        else (f"{s['structure']} at {significant(s['position_x_over_l'], 4)} x/L")
    )
    return [
        ("ball speed out", significant(s["ball_speed_out_m_s"], 5), "m/s"),
        ("angle out", significant(s["angle_out_deg"], 5), "deg from the face normal"),
        ("spin out", significant(s["spin_out_rpm"], 5), "rpm (positive: topspin)"),
        ("contact regime", s["contact_regime"], ""),
        ("grip", grips, "ms" if s["grip_times_s"] else ""),
        ("friction reversal", flips, "ms" if s["friction_reversal_times_s"] else ""),
        ("tangential COR", significant(s["tangential_cor"], 5), "-"),
        *_side_rows(s),
        ("normal COR", significant(s["cor"], 6), "-"),
        ("contact time", significant(s["contact_time_s"] * 1e3, 5), "ms"),
        ("normal rebound speed", significant(s["rebound_speed_m_s"], 5), "m/s"),
        ("peak force", significant(s["peak_force_n"], 4), "N"),
        ("impact speed", significant(s["speed_m_s"], 5), "m/s"),
        ("angle in", significant(s["angle_deg"], 5), "deg"),
        ("spin in", significant(s["spin_rpm"], 5), "rpm"),
        ("friction", significant(s["friction"], 4), "-"),
        ("ball inertia", significant(s["ball_inertia_i_over_mr2"], 4), "I/(m R^2)"),
        ("compliance ratio", significant(s["compliance_ratio_eta2"], 4), "eta^2 = k_n/k_t"),
        ("structure", where, ""),
        *_offset_rows(s),
        *_stroke_rows(s),
    ]


def _side_rows(s: dict[str, Any]) -> list[tuple[str, str, str]]:
    """Across the face: shown when anything crosses it (else the rows of the plane only)."""
    keys = ("side_angle_deg", "side_spin_rpm", "side_spin_out_rpm", "side_angle_out_deg")
    if not any(s[k] for k in keys):
        return []
    return [
        (
            "side angle out",
            significant(s["side_angle_out_deg"], 5),
            "deg from the long axis' plane",
        ),
        ("side spin out", significant(s["side_spin_out_rpm"], 5), "rpm (positive: rolling to +y)"),
        ("racket yaw rate", significant(s["racket_yaw_rate_rad_s"], 5), "rad/s"),
        ("side angle in", significant(s["side_angle_deg"], 5), "deg"),
        ("side spin in", significant(s["side_spin_rpm"], 5), "rpm"),
    ]


def _offset_rows(s: dict[str, Any]) -> list[tuple[str, str, str]]:
    """Off the axis: the offset and the racket's roll rate (from the normal impact)."""
    if not s.get("offset_m"):
        return []
    return [
        ("offset from the axis", significant(s["offset_m"], 4), "m"),
        ("roll rate", significant(s["roll_rate_rad_s"], 5), "rad/s"),
    ]


def _stroke_rows(s: dict[str, Any]) -> list[tuple[str, str, str]]:
    if "face_angle_deg" not in s:
        return []
    return [
        ("launch angle", significant(s["launch_angle_deg"], 4), "deg above the horizontal"),
        ("face angle", significant(s["face_angle_deg"], 4), "deg to the horizontal"),
        ("path angle", significant(s["path_angle_deg"], 4), "deg above the horizontal"),
        ("racket speed on its path", significant(s["racket_path_speed_m_s"], 5), "m/s"),
    ]


def oblique_from_args(args: argparse.Namespace, incidence: Incidence, hand: Any):
    """Check the options against the oblique impact and run it: an ``ObliqueResult``."""
    from fem_racket.impact.simulate_oblique import simulate_oblique
    from fem_racket.impact.simulate_stroke import simulate_stroke

    _check(args, hand)
    stroke = stroke_from_args(args)
    if args.clamped:
        kw = {k: getattr(args, k) for k in ("ball_mass", "kcb", "zeta", "separation")}
        kw.update(incidence=incidence, speed=args.speed, clamped=True)
        return simulate_stroke(stroke=stroke, **kw) if stroke else simulate_oblique(**kw)
    model = build_model(args)
    kw = impact_kwargs(args)
    kw.update(incidence=incidence, output_step=args.output_step)
    swing = swing_from_args(args, model.mesh.length)
    if hand is not None:
        kw.update(hand=hand, shock_window=args.hand_shock_window)
    if stroke:
        return simulate_stroke(model, stroke=stroke, swing=swing, **kw)
    return simulate_oblique(model, swing=swing, **kw)


def write_oblique(args: argparse.Namespace, result, summary: dict[str, Any], files: list) -> None:
    """Write ``--out`` (``files``) of an oblique impact: its histories, ``summary`` and the
    provenance with the summary as its ``"results"``."""
    meta = {**provenance(run_parameters(args)), "results": summary}
    write_result_files(args, meta, summary, files, oblique_histories(result))


def run_oblique(args: argparse.Namespace, incidence: Incidence, hand: Any, files: list) -> int:
    """``simulate``'s oblique impact: run, write ``--out`` (``files``), print."""
    result = oblique_from_args(args, incidence, hand)
    summary = result.summary()
    if args.out:
        write_oblique(args, result, summary, files)
    return print_result(args, summary, oblique_rows, files)
