"""``fem-racket simulate``: one impact; prints COR, contact time, rebound speed, peak force."""

from __future__ import annotations

import argparse

from ..impact import simulate
from .common import add_impact_options, build_model, impact_kwargs, print_json


def register(sub: argparse._SubParsersAction) -> None:
    """Add the ``simulate`` command."""
    p = sub.add_parser("simulate", help="simulate one ball impact on the racket")
    add_impact_options(p)
    p.add_argument("--json", action="store_true", help="print a JSON object")
    p.set_defaults(func=run)


def run(args: argparse.Namespace) -> int:
    """Simulate and print the result."""
    result = simulate(build_model(args), **impact_kwargs(args))
    summary = result.summary()
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
    return 0
