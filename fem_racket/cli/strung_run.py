"""``fem-racket simulate`` with a string bed: the ball's law on the membrane bed and the frame.

Runs :func:`fem_racket.impact.strung_impact.simulate_strung` and prints the outcome with the
bed's stiffness and first frequencies, the peak deflections of the bed and the ball and the
energy the bed returns and the ball loses. Options that belong to the paper's lumped spring or to
paths the strung racket does not take are refused in one line.
"""

from __future__ import annotations

import argparse
import csv
import json
from pathlib import Path
from typing import Any

from fem_racket.cli.laws import law_from_args
from fem_racket.cli.output import print_json, run_parameters, write_json
from fem_racket.cli.text import significant
from fem_racket.impact.strung_impact import StrungImpact, simulate_strung
from fem_racket.outputs import Target, atomic_outputs, provenance
from fem_racket.strings.bed import StringBed
from fem_racket.validation import InputError

__all__ = ["run_strung"]

#: Options of the lumped spring or of other paths, refused with a string bed (dest -> why).
REFUSED = {
    "kcb": "the string bed replaces the lumped K_CB (the ball's law acts on the bed)",
    "zeta": "the string bed replaces the lumped K_CB's damping (the ball's law has its own)",
    "separation": "the ball's law ends contact by its own condition",
    "basis": "the strung racket runs in modal coordinates",
    "modes": "the strung racket uses every frame mode",
    "t_max": "the strung racket's integrators set their own span",
    "output_step": "the strung racket's histories have 801 points over the contact",
    "racket_speed": "the strung racket is struck at rest",
    "reference": "the strung racket is struck at rest",
    "pivot": "the strung racket is struck at rest",
}
#: --solver values the strung racket takes (exact: the general integrator under a law other
#: than the linear kawazoe-1997-ball, as ``simulate`` does).
STRUNG_CLI_SOLVERS = ("exact", "general", "cvode")


def _check(args: argparse.Namespace) -> None:
    given = set(getattr(args, "explicit_options", ()))
    for dest, why in REFUSED.items():
        if dest in given:
            raise InputError(f"--{dest.replace('_', '-')} is not allowed with a string bed: {why}")
    if args.solver not in STRUNG_CLI_SOLVERS:
        raise InputError(
            f"solver = {args.solver!r} is not allowed with a string bed: must be one of "
            f"{', '.join(STRUNG_CLI_SOLVERS)}"
        )


def _histories(result: StrungImpact) -> dict[str, Any]:
    return {
        "time [s]": result.t,
        "ball deflection [m]": result.ball_deflection,
        "bed deflection [m]": result.bed_deflection,
        "contact force [N]": result.force,
    }


def _write(args: argparse.Namespace, result: StrungImpact, summary: dict, files: list) -> None:
    meta = provenance(run_parameters(args))
    meta["used"] = summary
    history = _histories(result)
    if len(files) == 1:
        data = {"provenance": meta, "summary": summary}
        history = {k: v.tolist() for k, v in history.items()}
        write_json(args.out, {**data, "history": history}, overwrite=args.overwrite)
        return
    with atomic_outputs([Target(f) for f in files], overwrite=args.overwrite) as (tmp, side):
        with open(tmp, "w", newline="", encoding="utf-8") as f:
            w = csv.writer(f)
            w.writerow(history)
            for row in zip(*history.values(), strict=True):
                w.writerow([repr(float(v)) for v in row])
        text = json.dumps({**meta, "summary": summary}, indent=2, default=str)
        side.write_text(text + "\n", encoding="utf-8")


def _rows(s: dict[str, Any]) -> list[tuple[str, str, str]]:
    freqs = ", ".join(f"{f:.0f}" for f in s["stringbed_frequencies_hz"])
    return [
        ("coefficient of restitution", significant(s["cor"], 6), "-"),
        ("contact time", significant(s["contact_time_s"] * 1e3, 5), "ms"),
        ("rebound speed", significant(s["rebound_speed_m_s"], 5), "m/s"),
        ("peak force", significant(s["peak_force_n"], 4), "N"),
        ("impact point", significant(s["position_x_over_l"], 4), "x/L"),
        ("impact speed", significant(s["speed_m_s"], 5), "m/s"),
        ("string bed", f"{s['pattern']} {s['string']}", ""),
        ("string tension", significant(s["string_tension_n"], 4), "N"),
        ("head area", significant(s["head_area_cm2"], 4), "cm^2"),
        ("stringbed stiffness", significant(s["stringbed_stiffness_n_m"], 4), "N/m"),
        ("stringbed frequencies", freqs, "Hz"),
        ("peak bed deflection", significant(s["peak_bed_deflection_m"] * 1e3, 4), "mm"),
        ("peak ball deflection", significant(s["peak_ball_deflection_m"] * 1e3, 4), "mm"),
        ("energy returned by the bed", significant(s["bed_energy_returned_j"], 4), "J"),
        ("energy lost in the ball", significant(s["energy_lost_in_ball_j"], 4), "J"),
        ("ball law", s["ball_law"], ""),
        ("solver", f"{s['solver']} (modal, {s['elements']} elements + bed)", ""),
    ]


def run_strung(args: argparse.Namespace, strings: StringBed, model, files: list[Path]) -> int:
    """Simulate the ball on ``strings`` and the frame ``model``; print, write."""
    _check(args)
    law = law_from_args(args)
    solver = "general" if args.solver == "exact" and law is not None else args.solver
    result = simulate_strung(
        model,
        strings,
        position=args.position,
        speed=args.speed,
        ball_mass=args.ball_mass,
        law=law,
        solver=solver,
        tolerance=args.tolerance or None,
        rtol=args.rtol,
        atol=args.atol,
    )
    summary = {
        **result.summary(),
        "ball_law": "kawazoe-1997-ball" if law is None else args.law,
        "elements": model.mesh.n_elements,
    }
    if args.out:
        _write(args, result, summary, files)
    if args.json:
        print_json(summary)
        return 0
    for name, value, unit in _rows(summary):
        print(f"{name:<28} {value:>14} {unit}".rstrip())
    for f in files:
        print(f"{'written':<28} {f}")
    return 0
