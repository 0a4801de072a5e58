"""``fem-racket closest``: the listed rackets nearest a target, and the least lead for each.

Rank the rackets of a CSV list (name, length_m, mass_kg, balance_m, swing_weight_kg_cm2; optional
twist_weight_kg_cm2, stiffness_ra, f1_hz) by their distance to the targets (each a value or
LOW:HIGH) and find the least lead bringing each of the nearest to the mass, balance, swing-weight
and twistweight targets. Example: fem-racket closest meshes/rackets.csv --swing-weight 330
--balance 0.32

The list is read by :mod:`fem_racket.io.racket_table`; the distance is scaled per target, and each
racket's least customisation with lead at ``--places`` comes from
:mod:`fem_racket.studies.closest`.
"""

from __future__ import annotations

import argparse

from fem_racket.cli.common import add_config_option, print_json, significant
from fem_racket.cli.options.targets import (
    add_target_options,
    places_of,
    target_summary,
    targets_from_args,
)


def add_arguments(p: argparse.ArgumentParser) -> None:
    """The ``closest`` command's options."""
    p.add_argument(
        "rackets", nargs="?", default=None, metavar="CSV", help="the racket list (a CSV file)"
    )
    add_target_options(p, ranked=True)
    p.add_argument("--count", type=int, default=3, metavar="N", help="rackets to show (default 3)")
    p.add_argument("--json", action="store_true", help="print a JSON object (default: a table)")
    add_config_option(p, requires=("rackets",))


def run(args: argparse.Namespace) -> int:
    """Rank, customise and print."""
    from fem_racket.io.racket_table import read_rackets
    from fem_racket.studies.closest import closest
    from fem_racket.validation import InputError, work_begins

    if args.rackets is None:
        work_begins()  # a run file cannot name the list: its checks end here
        raise InputError("rackets = none is not allowed: give the racket list, a CSV file")
    targets = targets_from_args(args)
    rackets = read_rackets(args.rackets)
    work_begins()
    matches = closest(rackets, targets, places_of(args), args.count)
    if args.json:
        print_json({"targets": target_summary(targets), "rackets": [m.summary() for m in matches]})
        return 0
    for rank, m in enumerate(matches, start=1):
        s = m.summary()
        print(f"{rank}. {m.listed.name}  (distance {significant(m.distance, 3)})")
        if m.added is None:
            print(f"   unreachable with lead: {m.reason}")
            continue
        where = ", ".join(f"{g:.1f} g at {p}" for p, g in s["placement_g"].items() if g > 0)
        print(f"   add {s['added_mass_g']:.1f} g{': ' + where if where else ''}")
        after = s["after"]
        print(
            f"   then {after['mass_kg'] * 1e3:.1f} g, balance {after['balance_m'] * 1e2:.2f} cm, "
            f"swing weight {after['swing_weight_kg_cm2']:.1f} kg cm^2"
        )
    return 0
