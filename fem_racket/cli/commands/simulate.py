"""``fem-racket simulate``: one impact; prints COR, contact time, rebound speed, peak force.

Without ``--out`` no time histories are computed (the exact solver's batched engine gives the
summary, to ``--tolerance`` in COR).

``--out result.json`` also writes the summary, the time histories (spaced ``--output-step``) and
the provenance (package version, every parameter, solver and tolerances, date) to a JSON file;
``--out result.csv`` writes the time histories as CSV (units in the column names) with the
summary and the provenance in the sidecar ``result.csv.json``. Other suffixes are refused before
the run.

A hand on the grip (``--grip loose|firm`` or any hand parameter, :mod:`fem_racket.frame.hand`)
runs the hand-held racket (:func:`fem_racket.impact.held.run.held_impact`): the exact held
solution by default, ``--solver cvode|bdf`` the integrators; it also prints the grip force's
peak and its vibration RMS over ``--shock-window``, and ``--out`` writes the contact and grip
force histories over that window, the hand in the provenance's ``"used"``.
"""

from __future__ import annotations

import argparse
from functools import partial
from pathlib import Path
from typing import TYPE_CHECKING, Any

from fem_racket.cli.common import (
    add_config_option,
    add_impact_options,
    add_output_options,
    add_output_step_option,
    add_swing_options,
    build_model,
    check_output_step,
    impact_kwargs,
    note_modes,
    run_parameters,
    significant,
    swing_from_args,
)
from fem_racket.cli.options.impact import add_hand_options, hand_from_args, racket_speed_named
from fem_racket.cli.options.oblique import add_oblique_options, incidence_from_args, run_oblique
from fem_racket.cli.options.output import (
    core_rows,
    offset_rows,
    print_result,
    write_result_files,
)
from fem_racket.cli.options.runfile import given_options, option_name
from fem_racket.cli.options.strings import add_strings_options, run_strung, strings_from_args
from fem_racket.cli.options.strings_oblique import run_strung_oblique
from fem_racket.outputs import (
    Target,
    check_output_path,
    check_targets,
    sidecar_path,
)
from fem_racket.validation import InputError, show, show_path

if TYPE_CHECKING:
    from fem_racket.frame.hand import Hand

#: Suffixes --out takes (case-insensitive) and what each writes.
OUT_SUFFIXES = (".json", ".csv")


def add_arguments(p: argparse.ArgumentParser) -> None:
    """The ``simulate`` command's options."""
    add_impact_options(p)
    add_swing_options(p)
    add_hand_options(p)
    add_oblique_options(p)
    add_strings_options(p)
    p.add_argument("--json", action="store_true", help="print a JSON object")
    g = add_output_options(
        p,
        what="output file: .json (summary, histories, provenance) or .csv (histories; summary "
        "and provenance in FILE.json)",
    )
    add_output_step_option(g)
    add_config_option(p)


def _check_out(args: argparse.Namespace) -> list[Path]:
    """The files --out will write (a CSV's sidecar too), checked before the run."""
    path = Path(args.out)
    if path.suffix.lower() not in OUT_SUFFIXES:
        check_output_path(path, overwrite=True)  # a folder or a bad path says so first
        raise InputError(
            f"out = {show_path(path)} is not allowed: must end in {' or '.join(OUT_SUFFIXES)}"
        )
    files = [path, sidecar_path(path)] if path.suffix.lower() == ".csv" else [path]
    check_targets([Target(f) for f in files], overwrite=args.overwrite)
    return files


def _histories(result) -> dict[str, Any]:
    """Time histories, units in the names (the JSON "history" keys and the CSV columns)."""
    return {
        "time [s]": result.t,
        "ball displacement [m]": result.ball_displacement,
        "ball velocity [m/s]": result.ball_velocity,
        "impact point displacement [m]": result.impact_point_displacement,
        "contact force [N]": result.force,
    }


def _write(
    args: argparse.Namespace, result, summary: dict[str, Any], files: list[Path], history
) -> None:
    """Write --out: JSON, or CSV and its sidecar as one set (both or neither)."""
    from fem_racket.io.impact_provenance import impact_provenance

    meta = impact_provenance(result, run_parameters(args))
    write_result_files(args, meta, summary, files, history)


def _law_rows(summary: dict[str, Any]) -> list[tuple[str, str, str]]:
    """K_CB and zeta for the paper's law; else the law's name and parameters."""
    from fem_racket.contact.presets import FILE_KEYS

    if summary["law"] == "linear":
        return [
            ("K_CB", significant(summary["kcb_n_m"], 4), "N/m"),
            ("zeta", significant(summary["zeta"], 3), "-"),
        ]
    params = {k: v for k, v in summary.items() if k in FILE_KEYS.values()}
    return [("contact law", summary["law"], "")] + [
        (k, significant(v, 4), "") for k, v in params.items()
    ]


def _swing_rows(summary: dict[str, Any], swinging: bool) -> list[tuple[str, str, str]]:
    """Table rows of a swing: the ball's speed out and the racket's speed at the impact point."""
    if not swinging:
        return []
    return [
        ("ball speed out", significant(summary["ball_speed_out_m_s"], 5), "m/s"),
        ("racket speed at impact", significant(summary["racket_speed_at_impact_m_s"], 5), "m/s"),
    ]


def _check_hand(args: argparse.Namespace) -> None:
    """Refuse, before the run, the options the hand-held racket does not take, named as the
    user gave them - on the command line or in the run file (the library refuses the rest: a
    law, the general solver)."""
    from fem_racket.io.config_run import NOT_WITH_HAND

    given = given_options(args)
    for dest in NOT_WITH_HAND:
        if dest in given:
            raise InputError(
                f"{option_name(args, dest)} is not allowed with a hand: the held racket keeps "
                "its modes by --tolerance (exact) or all its DOFs (cvode, bdf) and ends contact "
                "by the spring deflection"
            )


def _run_held(args: argparse.Namespace, hand: Hand, files: list[Path]) -> int:
    """The hand-held racket: simulate, print, write."""
    from fem_racket.impact.held.shock import DEFAULT_WINDOW
    from fem_racket.impact.simulate import simulate

    _check_hand(args)
    _check_unwritten(args, "output_step")
    model = build_model(args)
    window = DEFAULT_WINDOW if args.hand_shock_window is None else args.hand_shock_window
    result = simulate(
        model,
        hand=hand,
        shock_window=args.hand_shock_window,
        swing=swing_from_args(args, model.mesh.length),
        output_step=args.output_step if args.out else None,
        **impact_kwargs(args),
    )
    summary = result.summary()
    if args.out:
        _write(args, result, summary, files, result.histories)
    return print_result(args, summary, partial(_held_rows, window=window), files)


def _held_rows(summary: dict[str, Any], window: float) -> list[tuple[str, str, str]]:
    """The held racket's rows: the outcome, the grip force over ``window`` [s], the hand."""
    h = summary["hand"]
    exact = summary["solver"] == "exact"
    modes = f"{summary['modes']} modes" if exact else f"{summary['modes']} DOFs"
    return [
        *_outcome_rows(summary, summary["racket_speed_at_impact_m_s"] != 0.0),
        ("peak grip force", significant(summary["peak_grip_force_n"], 4), "N"),
        (
            "grip vibration RMS",
            significant(summary["grip_vibration_rms_n"], 4),
            f"N (over {significant(window * 1e3, 4)} ms)",
        ),
        ("hand", f"{h['grip']} grip", ""),
        ("hand mass", significant(h["mass_kg"], 4), "kg"),
        ("grip", f"{h['grip_start_m']:g}-{h['grip_end_m']:g}", "m from the butt"),
        ("grip stiffness", significant(h["stiffness_n_m2"], 4), "N/m per m"),
        ("grip damping", significant(h["damping_n_s_m2"], 4), "N s/m per m"),
        ("K_CB", significant(summary["kcb_n_m"], 4), "N/m"),
        ("zeta", significant(summary["zeta"], 3), "-"),
        ("solver", f"{summary['solver']} (held, {summary['elements']} elements, {modes})", ""),
    ]


def _outcome_rows(summary: dict[str, Any], swinging: bool) -> list[tuple[str, str, str]]:
    """COR, contact time, rebound speed, peak force, impact point, swing and speed."""
    rebound = "m/s"
    if summary["rebound_speed_m_s"] < 0:  # COR < 0, or a racket receding faster than the
        why = "COR < 0" if summary["cor"] < 0 else "the racket recedes faster than it rebounds"
        rebound += f" (negative: the ball keeps moving forward, {why})"  # ball rebounds from it
    return [
        *core_rows(summary, rebound),
        *_twist_rows(summary),
        *_swing_rows(summary, swinging),
        ("impact speed", significant(summary["speed_m_s"], 5), "m/s"),
    ]


def _twist_rows(summary: dict[str, Any]) -> list[tuple[str, str, str]]:
    """Off axis: the offset, the racket's roll rate and the energy left in torsion."""
    if "offset_m" not in summary:
        return []
    return [
        *offset_rows(summary),
        (
            "lost energy in torsion",
            significant(100 * summary["torsion_energy_share"], 3),
            "% (roll and torsion vibration)",
        ),
    ]


def _check_unwritten(args: argparse.Namespace, dest: str) -> None:
    """Refuse ``--output-step`` (the head-on and held impacts compute histories only to write
    them) or ``--overwrite`` given on the command line without ``--out``: nothing would use it;
    so is the run file's ``[simulate] output_step`` or ``overwrite`` (also ``[output]
    overwrite``; at other than its default, as every run-file key) with no output in the file
    either (the Python method's line, :func:`fem_racket.io.config_run.unwritten`)."""
    if args.out:
        return
    name = None
    if dest in getattr(args, "explicit_options", ()):
        value = "" if dest == "overwrite" else f" {show(getattr(args, dest))}"
        name = f"--{dest.replace('_', '-')}{value}"
    elif getattr(args, "file_options", {}).get(dest, "").startswith(("simulate.", "output.")):
        from fem_racket.io.config_run import unwritten

        raise InputError(unwritten(option_name(args, dest)))
    if name is not None:
        raise InputError(
            f"{name} is not allowed without --out: it sets the histories or files written, and "
            "none are"
        )


@racket_speed_named  # a swing's closing speed: the library's check, named as the option
def run(args: argparse.Namespace) -> int:
    """Simulate and print the result (and write it with ``--out``)."""
    from fem_racket.impact.simulate import simulate

    check_output_step(args.output_step)
    _check_unwritten(args, "overwrite")
    hand = hand_from_args(args)
    files = _check_out(args) if args.out else []
    incidence, strings = incidence_from_args(args), strings_from_args(args)
    if incidence is not None:  # an oblique impact (fem_racket.cli.options.oblique)
        if strings is not None:  # on the bed (fem_racket.cli.options.strings_oblique)
            return run_strung_oblique(args, strings, incidence, hand, build_model(args), files)
        return run_oblique(args, incidence, hand, files)
    if strings is not None:
        if hand is not None:
            raise InputError("a hand is not allowed with a string bed: give one of them")
        return run_strung(args, strings, build_model(args), files)
    if hand is not None:
        return _run_held(args, hand, files)
    _check_unwritten(args, "output_step")
    model = build_model(args)
    # Histories only when written: the printed summary needs t = 0 and t_c alone, which the
    # exact solver gets from the batched engine (to --tolerance in COR).
    step = args.output_step if args.out else None
    swing = swing_from_args(args, model.mesh.length)
    result = simulate(model, output_step=step, swing=swing, **impact_kwargs(args))
    note_modes(args, model)
    summary = result.summary()
    if args.out:
        _write(args, result, summary, files, _histories(result))
    return print_result(args, summary, partial(_head_on_rows, swinging=swing is not None), files)


def _head_on_rows(summary: dict[str, Any], swinging: bool) -> list[tuple[str, str, str]]:
    """The head-on impact's rows: the outcome, the law and the solver."""
    return [
        *_outcome_rows(summary, swinging),
        *_law_rows(summary),
        ("solver", f"{summary['solver']} ({summary['basis']}, {summary['elements']} elements)", ""),
    ]
