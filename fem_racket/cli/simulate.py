"""``fem-racket simulate``: one impact; prints COR, contact time, rebound speed, peak force.

``--out result.json`` also writes the summary, the time histories and the provenance (package
version, every parameter, solver and tolerances, date) to a JSON file.
"""

from __future__ import annotations

import argparse

from ..impact import simulate
from ..outputs import check_output_path, provenance
from .common import (
    add_config_option,
    add_impact_options,
    add_output_options,
    build_model,
    impact_kwargs,
    print_json,
    run_parameters,
    write_json,
)


def register(sub: argparse._SubParsersAction) -> None:
    """Add the ``simulate`` command."""
    p = sub.add_parser("simulate", help="simulate one ball impact on the racket")
    add_impact_options(p)
    p.add_argument("--json", action="store_true", help="print a JSON object")
    add_output_options(p)
    add_config_option(p)
    p.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    """Simulate and print the result (and write it with ``--out``)."""
    if args.out:
        check_output_path(args.out, overwrite=args.overwrite)
    result = simulate(build_model(args), **impact_kwargs(args))
    summary = result.summary()
    if args.out:
        history = {
            "time [s]": result.t.tolist(),
            "ball displacement [m]": result.ball_displacement.tolist(),
            "ball velocity [m/s]": result.ball_velocity.tolist(),
            "impact point displacement [m]": result.impact_point_displacement.tolist(),
            "contact force [N]": result.force.tolist(),
        }
        data = {"provenance": provenance(run_parameters(args)), "summary": summary}
        write_json(args.out, {**data, "history": history}, overwrite=args.overwrite)
    if args.json:
        print_json(summary)
        return 0
    rows = [
        ("coefficient of restitution", f"{summary['cor']:.6f}", "-"),
        ("contact time", f"{summary['contact_time_s'] * 1e3:.4f}", "ms"),
        ("rebound speed", f"{summary['rebound_speed_m_s']:.4f}", "m/s"),
        ("peak force", f"{summary['peak_force_n']:.1f}", "N"),
        ("impact point", f"{summary['position_x_over_l']:.4f}", "x/L"),
        ("impact speed", f"{summary['speed_m_s']:.3f}", "m/s"),
        ("K_CB", f"{summary['kcb_n_m']:.4g}", "N/m"),
        ("zeta", f"{summary['zeta']:.4f}", "-"),
        ("solver", f"{summary['solver']} ({summary['basis']}, {summary['elements']} elements)", ""),
    ]
    for name, value, unit in rows:
        print(f"{name:<28} {value:>14} {unit}")
    if args.out:
        print(f"{'written':<28} {args.out}")
    return 0
