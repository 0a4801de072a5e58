"""``fem-racket calibrate``: fit a contact law family to a target set, report and save it.

Prints the fitted parameters and, per target, the target, the model's value and whether it is
within tolerance. With ``--out DIR`` writes ``<family>-<targets>.toml`` (the law as a run file's
``[contact]`` table: ``fem-racket simulate --config`` takes it), ``<family>-<targets>.json``
(parameters, the fit table, provenance) and ``<family>-<targets>.png`` (force-deflection loops
and force histories on a rigid support at each target speed).
"""

from __future__ import annotations

import argparse

from fem_racket.cli.common import (
    add_config_option,
    add_output_options,
    print_json,
    print_written,
    run_parameters,
    significant,
)
from fem_racket.cli.options.output import overwrite_of
from fem_racket.outputs import Target, check_targets
from fem_racket.studies.calibration_targets import FAMILIES, TARGET_SETS


def add_arguments(p: argparse.ArgumentParser) -> None:
    """The ``calibrate`` command's options."""
    p.add_argument(
        "--family",
        default="hysteretic",
        choices=sorted(FAMILIES),
        help="law family to fit (default hysteretic)",
    )
    p.add_argument(
        "--targets",
        default="kawazoe-1997",
        choices=sorted(TARGET_SETS),
        help="kawazoe-1997: the paper's clamped contact times and COR at 20-40 m/s; itf: a "
        "ball on a rigid surface (ITF rules) (default kawazoe-1997)",
    )
    p.add_argument(
        "--ball-mass",
        type=float,
        default=0.057,
        metavar="KG",
        help="ball mass [kg] (default 0.057)",
    )
    p.add_argument("--json", action="store_true", help="print a JSON object")
    add_output_options(p, what="output folder (writes FAMILY-TARGETS .toml, .json and .png)")
    add_config_option(p)


def run(args: argparse.Namespace) -> int:
    """Fit, print the table, write the files."""
    from fem_racket.io.calibration_files import (
        calibration_files,
        calibration_summary,
        write_calibration,
    )
    from fem_racket.studies.calibrate import calibrate

    overwrite_of(args, bool(args.out))
    files = []
    if args.out:  # the three files are checked now and written as one set
        files = calibration_files(args.out, args.family, args.targets)
        check_targets([Target(f) for f in files], overwrite=args.overwrite)
    cal = calibrate(args.family, args.targets, ball_mass=args.ball_mass)
    summary = calibration_summary(cal)
    if args.out:
        parameters, overwrite = run_parameters(args), args.overwrite
        write_calibration(cal, files, parameters, ball_mass=args.ball_mass, overwrite=overwrite)
    if args.json:
        print_json(summary)
        return 0
    print(f"{cal.family} fitted to {cal.target_set}: meets every target: {cal.meets_targets}")
    for key, value in cal.law.describe().items():
        print(f"  {key:<24} {value if key == 'law' else significant(value, 5)}")
    print(f"  {'target':<20} {'at':>8} {'target':>10} {'model':>10} {'tol':>7}  ok")
    for row in cal.table():
        print(
            f"  {row['quantity']:<20} {significant(row['condition'], 4):>8} "
            f"{significant(row['target'], 4):>10} {significant(row['model'], 4):>10} "
            f"{significant(row['tolerance'], 2):>7}  {'yes' if row['within'] else 'NO'}"
        )
    print_written(files)
    return 0
