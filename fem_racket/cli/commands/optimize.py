"""``fem-racket optimize``: search a racket design (stiffness and mass distribution, added
masses) maximising the ball's rebound or speed (or minimising the handle shock) over an impact
zone, within a mass, balance, swing-weight and frequency budget; writes the optimum, its report,
the history and figures."""

from __future__ import annotations

import argparse

from fem_racket.cli.options.design import add_design_options, add_study_tail, problem_from_args
from fem_racket.cli.options.execution import execution_from_args
from fem_racket.cli.options.lists import add_options
from fem_racket.cli.options.output import print_written_folder
from fem_racket.cli.options.rerun import replace_own
from fem_racket.cli.options.runfile import given_options
from fem_racket.extras import require

#: Where the study goes unless --out is given.
DEFAULT_OUTPUT = "output/design"

#: (name, default, metavar, help) of the search budget's options.
BUDGET = (
    ("maxiter", 100, None, "iterations (local) or generations (differential evolution) "
     "(default 100)"),
    ("popsize", 10, None, "differential evolution: population per variable (default 10)"),
    ("pop_size", 50, None, "nsga2: population (default 50)"),
    ("generations", 100, None, "nsga2: generations (default 100)"),
)  # fmt: skip


def add_arguments(p: argparse.ArgumentParser) -> None:
    """The ``optimize`` command's options."""
    from fem_racket.studies.design.methods import METHODS

    add_design_options(p)
    s = p.add_argument_group("solver")
    s.add_argument(
        "--method",
        choices=METHODS,
        default="SLSQP",
        help="SLSQP or trust-constr (local, from the starting racket), "
        "differential-evolution (global, then SLSQP), nsga2 (Pareto front of the "
        "objectives) (default SLSQP)",
    )
    add_options(s, BUDGET, type=int)
    out = {
        "default": DEFAULT_OUTPUT,
        "metavar": "DIR",
        "help": "output folder: optimum.vtu, start.vtu, result.json, history.nc, PNGs "
        f"(default {DEFAULT_OUTPUT}, replacing the study an earlier run wrote there); designs "
        "are kept in DIR.history/ until it is written, so a rerun resumes",
    }
    help_of = {
        "overwrite": "replace the output folder",
        "restart": "discard DIR.history/ and start afresh",
        "json": "print result.json's summary as JSON",
    }
    add_study_tail(p, out, help_of)


def run(args: argparse.Namespace) -> int:
    """Run the study and print its summary."""
    from fem_racket.cli.common import print_json, run_parameters
    from fem_racket.io.design_study import OptimizationRun, OutputOptions, run_optimization
    from fem_racket.studies.design.options import SearchOptions

    if args.method == "nsga2":
        require("pymoo", "fem-racket optimize --method nsga2")
    problem = problem_from_args(args)
    search = SearchOptions(
        **{k: getattr(args, k) for k in ("method", "maxiter", "popsize", "pop_size")},
        generations=args.generations,
        seed=args.seed,
        given=frozenset(given_options(args)),  # refused where unused, even at the default
    )
    files = OutputOptions(
        args.out,
        replace_own(args, args.out == DEFAULT_OUTPUT, [args.out]),
        run_parameters(args),
    )
    r = run_optimization(
        OptimizationRun(problem, search, execution_from_args(args), files, args.restart)
    )
    summary = {
        "objective_name": problem.objectives[0],
        "objective": r.objective,
        "start_objective": r.start_objective,
        "variables": dict(zip(problem.names, map(float, r.x), strict=True)),
        "constraints": r.constraints(),
        "success": r.success,
        "message": r.message,
        "out": args.out,
    }
    if args.json:
        print_json(summary)
        return 0
    name = problem.objectives[0]
    print(f"{r.method}: {r.message}")
    print(
        f"{name:<24} {r.start_objective:>12.6g} -> {r.objective:.6g} "
        f"({r.objective - r.start_objective:+.4g})"
    )
    for v, x, x0 in zip(problem.variables, r.x, r.x_start, strict=True):
        print(f"{v.name + ' [' + v.unit + ']':<24} {x0:>12.6g} -> {x:.6g}")
    for c in r.constraints():
        ok = "ok" if c["holds"] else "VIOLATED"
        print(f"{c['label']:<40} {c['value']:>12.6g} in [{c['low']:g}, {c['high']:g}] {ok}")
    if r.pareto_f is not None:
        print(f"Pareto front: {len(r.pareto_f)} designs (pareto.png, result.json)")
    print_written_folder(args.out)
    return 0
