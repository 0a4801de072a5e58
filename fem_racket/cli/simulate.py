"""``fem-racket simulate``: one impact; prints COR, contact time, rebound speed, peak force.

Without ``--out`` no time histories are computed (the exact solver's batched engine gives the
summary, to ``--tolerance`` in COR).

``--out result.json`` also writes the summary, the time histories (spaced ``--output-step``) and
the provenance (package version, every parameter, solver and tolerances, date) to a JSON file;
``--out result.csv`` writes the time histories as CSV (units in the column names) with the
summary and the provenance in the sidecar ``result.csv.json``. Other suffixes are refused before
the run.
"""

from __future__ import annotations

import argparse
import csv
from pathlib import Path
from typing import Any

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
    print_json,
    run_parameters,
    significant,
    swing_from_args,
    write_json,
)
from fem_racket.impact.simulate import simulate
from fem_racket.outputs import (
    atomic_output,
    check_output_path,
    provenance,
    sidecar_path,
    write_sidecar,
)
from fem_racket.validation import InputError

#: Suffixes --out takes (case-insensitive) and what each writes.
OUT_SUFFIXES = (".json", ".csv")


def register(sub: argparse._SubParsersAction) -> None:
    """Add the ``simulate`` command."""
    p = sub.add_parser("simulate", help="simulate one ball impact on the racket")
    add_impact_options(p)
    add_swing_options(p)
    p.add_argument("--json", action="store_true", help="print a JSON object")
    g = add_output_options(
        p,
        what="output file: .json (summary, histories, provenance) or .csv (histories; summary "
        "and provenance in FILE.json)",
    )
    add_output_step_option(g)
    add_config_option(p)
    p.set_defaults(func=run)


def _check_out(args: argparse.Namespace) -> list[Path]:
    """The files --out will write, checked before the run."""
    path = Path(args.out)
    suffix = path.suffix.lower()
    if path.is_dir():
        check_output_path(path)  # says it is a folder, not a file
    if suffix not in OUT_SUFFIXES:
        raise InputError(
            f"output = '{path}' is not allowed: must end in {' or '.join(OUT_SUFFIXES)}"
        )
    files = [path, sidecar_path(path)] if suffix == ".csv" else [path]
    for f in files:
        check_output_path(f, overwrite=args.overwrite)
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


def _write(args: argparse.Namespace, result, summary: dict[str, Any]) -> None:
    history = _histories(result)
    meta = provenance(run_parameters(args))
    if Path(args.out).suffix.lower() == ".json":
        data = {"provenance": meta, "summary": summary}
        history = {k: v.tolist() for k, v in history.items()}
        write_json(args.out, {**data, "history": history}, overwrite=args.overwrite)
        return
    with atomic_output(args.out, overwrite=args.overwrite) as tmp:
        with open(tmp, "w", newline="", encoding="utf-8") as f:
            w = csv.writer(f)
            w.writerow(history)
            for row in zip(*history.values(), strict=True):
                w.writerow([repr(float(v)) for v in row])
    write_sidecar(args.out, {**meta, "summary": summary}, overwrite=args.overwrite)


def _swing_rows(summary: dict[str, Any], swinging: bool) -> list[tuple[str, str, str]]:
    """Table rows of a swing: the ball's speed out and the racket's speed at the impact point."""
    if not swinging:
        return []
    return [
        ("ball speed out", significant(summary["ball_speed_out_m_s"], 5), "m/s"),
        ("racket speed at impact", significant(summary["racket_speed_at_impact_m_s"], 5), "m/s"),
    ]


def run(args: argparse.Namespace) -> int:
    """Simulate and print the result (and write it with ``--out``)."""
    check_output_step(args.output_step)
    files = _check_out(args) if args.out else []
    model = build_model(args)
    # Histories only when written: the printed summary needs t = 0 and t_c alone, which the
    # exact solver gets from the batched engine (to --tolerance in COR).
    step = args.output_step if args.out else None
    swing = swing_from_args(args, model.mesh.length)
    result = simulate(model, output_step=step, swing=swing, **impact_kwargs(args))
    note_modes(args, model)
    summary = result.summary()
    if args.out:
        _write(args, result, summary)
    if args.json:
        print_json(summary)
        return 0
    rebound = "m/s"
    if summary["rebound_speed_m_s"] < 0:
        rebound += " (negative: the ball keeps moving forward, COR < 0)"
    rows = [
        ("coefficient of restitution", significant(summary["cor"], 6), "-"),
        ("contact time", significant(summary["contact_time_s"] * 1e3, 5), "ms"),
        ("rebound speed", significant(summary["rebound_speed_m_s"], 5), rebound),
        ("peak force", significant(summary["peak_force_n"], 4), "N"),
        ("impact point", significant(summary["position_x_over_l"], 4), "x/L"),
        *_swing_rows(summary, swing is not None),
        ("impact speed", significant(summary["speed_m_s"], 5), "m/s"),
        ("K_CB", significant(summary["kcb_n_m"], 4), "N/m"),
        ("zeta", significant(summary["zeta"], 3), "-"),
        ("solver", f"{summary['solver']} ({summary['basis']}, {summary['elements']} elements)", ""),
    ]
    for name, value, unit in rows:
        print(f"{name:<28} {value:>14} {unit}".rstrip())
    for f in files:
        print(f"{'written':<28} {f}")
    return 0
