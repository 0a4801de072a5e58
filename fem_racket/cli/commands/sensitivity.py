"""``fem-racket sensitivity``: Sobol indices of a design objective to each design variable."""

from __future__ import annotations

import argparse

from fem_racket.cli.options.design import add_design_options, add_study_tail, problem_from_args
from fem_racket.cli.options.execution import execution_from_args
from fem_racket.cli.options.output import overwrite_of
from fem_racket.extras import check_installed


def add_arguments(p: argparse.ArgumentParser) -> None:
    """The ``sensitivity`` command's options."""
    add_design_options(p, constraints=False)  # the sample constrains nothing
    s = p.add_argument_group("sensitivity")
    s.add_argument(
        "--output",
        default=None,
        help="objective or quantity analysed (default: the first --objective)",
    )
    s.add_argument(
        "--designs",
        type=int,
        default=10_000,
        help="about this many designs, N (D + 2) with N a power of two (default 10000)",
    )
    out = {
        "default": None,
        "metavar": "PNG",
        "help": "PNG file: bar chart of the indices, PNG.json beside it (default: print only)",
    }
    help_of = {"overwrite": "replace the output files", "json": "print the indices as JSON"}
    add_study_tail(p, out, help_of)


def run(args: argparse.Namespace) -> int:
    """Compute and print the indices."""
    from fem_racket.cli.common import print_json, print_written, run_parameters
    from fem_racket.cli.options.runfile import given_options
    from fem_racket.io.design_study import (
        OutputOptions,
        SensitivityRun,
        run_sensitivity,
        sobol_json,
    )
    from fem_racket.studies.design.unused import refuse_power_fraction

    check_installed("SALib", "fem-racket sensitivity")  # imported where the indices are computed

    files = OutputOptions(args.out, overwrite_of(args, bool(args.out)), run_parameters(args))
    problem = problem_from_args(args)
    if "power_fraction" in given_options(args):  # given at any value, as the problem's other
        refuse_power_fraction(args.power_fraction, args.output or problem.objectives[0])
    run = SensitivityRun(
        problem,
        args.output,
        args.designs,
        args.seed,
        execution_from_args(args),
        files,
    )
    s = run_sensitivity(run)
    if args.json:
        print_json(sobol_json(s))
        return 0
    print(
        f"Sobol indices of {s.output} ({s.designs} designs; mean {s.mean:.6g}, "
        f"std {s.std:.3g}; +- are 95 % confidence half-widths)"
    )
    print(s.table())
    if args.out:
        print_written([args.out, f"{args.out}.json"])
    return 0
