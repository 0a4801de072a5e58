"""``fem-racket compare A B [C ...]``: set-ups side by side, and each minus the first.

Compare set-ups (presets, mesh files or run files with their own strings and ball;
SOURCE+LOCATION:GRAMS adds lead) played alike: specs, e_A and v_out maps with their differences,
sweet spots, power region, handle shock and contact time. Example: fem-racket compare standard
standard+12:10 --out cmp.png cmp.nc

A set-up is read by :mod:`fem_racket.io.setups`; ``--add-mass`` adds lead to every one. Prints a
table (or ``--json``: ``rackets`` with each one's values, ``differences`` with each later one
minus the first) and writes the one-page figure (.png, .svg, .pdf) and/or netCDF of the maps
(.nc), as one set. At the default ``--out`` an earlier compare's figure is replaced; anything
else only with ``--overwrite``. A swing's closing speed is the library's to check, at the impact
points (:func:`fem_racket.studies.compare.check_compare`).
"""

from __future__ import annotations

import argparse
from pathlib import Path

from fem_racket.cli.common import (
    add_config_option,
    add_elements_option,
    add_speed_option,
    add_swing_options,
    print_json,
    print_written,
    run_parameters,
)
from fem_racket.cli.options.impact import check_swing_options, racket_speed_named
from fem_racket.cli.options.lead import add_lead_option, leads_of
from fem_racket.cli.options.output import add_overwrite_json
from fem_racket.cli.options.rerun import replace_own

#: Where the figure goes unless --out is given.
DEFAULT_OUTPUT = Path("output") / "compare.png"


def add_arguments(p: argparse.ArgumentParser) -> None:
    """The ``compare`` command's options."""
    p.add_argument(
        "rackets",
        nargs="*",
        metavar="RACKET",
        help="preset (standard, rigid), mesh file or .toml run file, each optionally "
        "+LOCATION:GRAMS (lead); at least two",
    )
    r = p.add_argument_group("rackets")
    add_elements_option(r, "beam elements of presets and segment frames (default 20)")
    add_lead_option(r)
    g = p.add_argument_group("play (the same for every racket)")
    add_speed_option(g, "ball speed [m/s] (default 20)")
    g.add_argument(
        "--point",
        type=float,
        default=0.75,
        metavar="X_OVER_L",
        help="impact point of the contact time and handle shock [x/L] (default 0.75)",
    )
    g.add_argument(
        "--positions",
        "--position",
        dest="positions",
        default="0.5:1.0:200",
        metavar="VALUES",
        help="impact points of the maps [x/L]: start:stop:num or a comma list "
        "(default 0.5:1.0:200)",
    )
    g.add_argument(
        "--offsets",
        default=None,
        metavar="VALUES",
        help="lateral offsets y [m] (start:stop:num or a comma list): also map the whole face "
        "over (x, y), with its power area and the difference maps (default: the axis only)",
    )
    g.add_argument(
        "--grip",
        choices=("firm", "loose"),
        default="firm",
        help="the hand holding the racket for the handle shock (default firm)",
    )
    add_swing_options(p)
    o = p.add_argument_group("output")
    o.add_argument(
        "--out",
        nargs="+",
        default=None,
        metavar="FILE",
        help=f"file(s): a figure .png/.svg/.pdf and/or maps .nc (default {DEFAULT_OUTPUT}, "
        "replacing an earlier compare's figure there)",
    )
    add_overwrite_json(o, "a JSON object")
    add_config_option(p, private=("out",), requires=("rackets",))


@racket_speed_named  # a swing's closing speed: the library's check, named as the option
def run(args: argparse.Namespace) -> int:
    """Read the set-ups, compare, write the files and print."""
    from fem_racket.io.compare_files import check_compare_outputs, table_rows, write_compare
    from fem_racket.io.setups import compare_play, read_setups
    from fem_racket.studies.compare import check_compare, compare, differences
    from fem_racket.studies.grid_values import value_count
    from fem_racket.studies.map_options import check_map_points
    from fem_racket.validation import InputError, work_begins

    if len(args.rackets) < 2:
        work_begins()  # a run file cannot name the rackets: its checks end here
        raise InputError(f"rackets = {len(args.rackets)} given is not allowed: need at least 2")
    # compare shows no centre of percussion: --pivot needs a swing; the closing speed is the
    # library's to check, at the impact points
    check_swing_options(args, at_reference=False)
    check_map_points(
        value_count(args.positions), 1 if args.offsets is None else value_count(args.offsets)
    )
    outs = [Path(p) for p in (args.out or [DEFAULT_OUTPUT])]
    overwrite = replace_own(args, outs == [DEFAULT_OUTPUT], outs)
    check_compare_outputs(outs, overwrite=overwrite)
    setups = read_setups(args.rackets, elements=args.elements, leads=leads_of(args))
    names = [s.name for s in setups]
    play = compare_play(vars(args))
    check_compare(setups, play)  # a swing at the impact points: the library's check
    work_begins()
    reports = compare(setups, play)
    diffs = differences(reports)
    write_compare(reports, diffs, outs, overwrite=overwrite, parameters=run_parameters(args))
    if args.json:
        arrays = ("curve", "face")
        scalar = {
            n: {k: v for k, v in d.items() if not any(a in k for a in arrays)}
            for n, d in diffs.items()
        }
        print_json(
            {
                "rackets": [{"name": r.map.name, **r.values()} for r in reports],
                "differences": scalar,
                "files": [str(p) for p in outs],
            }
        )
        return 0
    head = ["", *names, *(f"{n} - {names[0]}" for n in diffs)]
    rows = [head, *table_rows(reports, diffs)]
    width = [max(len(str(row[k])) for row in rows) for k in range(len(head))]
    for row in rows:
        cells = [f"{row[0]:<{width[0]}}"] + [
            f"{c:>{w}}" for c, w in zip(row[1:], width[1:], strict=True)
        ]
        print("  ".join(cells))
    print_written(outs)
    return 0
