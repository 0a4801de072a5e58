"""One call per command: run a design study or a sensitivity analysis and write its files.

With an output folder the study is resumable: evaluated designs are kept in
``<out>.history/`` (:mod:`fem_racket.studies.design.history`) until the results are written,
and a rerun with the same settings replays them from there (the solvers are deterministic for a
given seed).
"""

from __future__ import annotations

import json
import os
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from fem_racket.io.design_files import check_study_folder, write_study
from fem_racket.outputs import add_png_provenance, atomic_outputs, check_targets, provenance
from fem_racket.studies.design.evaluate import Evaluator
from fem_racket.studies.design.limits import check_sobol_size, check_study_size
from fem_racket.studies.design.objectives import output_names
from fem_racket.studies.design.options import ExecutionOptions, SearchOptions, check_seed
from fem_racket.studies.design.pareto import pareto_front
from fem_racket.studies.design.problem import DesignProblem
from fem_racket.studies.design.result import DesignResult
from fem_racket.studies.design.sensitivity import SobolIndices, sobol_indices
from fem_racket.studies.design.solvers import optimize
from fem_racket.studies.design.unused import METHODS, refuse_unused_sensitivity
from fem_racket.validation import InputError, check_choice, work_begins

__all__ = [
    "METHODS",
    "OptimizationRun",
    "OutputOptions",
    "SensitivityRun",
    "history_path",
    "run_optimization",
    "run_sensitivity",
]


@dataclass(frozen=True)
class OutputOptions:
    """Where a study's files go.

    Attributes
    ----------
    out : path or None
        The output (a study folder, or a PNG for the indices); nothing written when None.
    overwrite : bool
        Replace what is there.
    parameters : dict or None
        The run's settings, kept in the provenance.
    """

    out: str | os.PathLike | None = None
    overwrite: bool = False
    parameters: dict[str, Any] | None = None

    def __post_init__(self) -> None:
        if self.overwrite and self.out is None:
            raise InputError("overwrite = True is not allowed without out: nothing is written")


@dataclass(frozen=True, eq=False)
class OptimizationRun:
    """An optimisation study: the problem, how to search, where designs run, its files.

    Attributes
    ----------
    problem : DesignProblem
    search : SearchOptions
        ``nsga2`` gives a Pareto front of the problem's objectives; the others maximise the
        first.
    execution : ExecutionOptions
    files : OutputOptions
        With ``out`` the study is resumable from ``<out>.history/``.
    restart : bool
        Discard the designs an earlier run left in the history.
    """

    problem: DesignProblem
    search: SearchOptions = field(default_factory=SearchOptions)
    execution: ExecutionOptions = field(default_factory=ExecutionOptions)
    files: OutputOptions = field(default_factory=OutputOptions)
    restart: bool = False


@dataclass(frozen=True, eq=False)
class SensitivityRun:
    """A Sobol sensitivity analysis (:func:`fem_racket.studies.design.sensitivity.sobol_indices`).

    Attributes
    ----------
    problem : DesignProblem
    output : str or None
        The objective or quantity analysed (the first objective when None).
    designs : int
        About this many designs.
    seed : int
        Seed of the Sobol sample.
    execution : ExecutionOptions
    files : OutputOptions
        With ``out`` a PNG bar chart there and the indices as JSON beside it (``<out>.json``,
        with the provenance).
    """

    problem: DesignProblem
    output: str | None = None
    designs: int = 10_000
    seed: int = 1
    execution: ExecutionOptions = field(default_factory=ExecutionOptions)
    files: OutputOptions = field(default_factory=OutputOptions)


def history_path(out: str | os.PathLike) -> Path:
    """The history folder kept beside output ``out`` while a study runs."""
    out = Path(out)
    return out.with_name(out.name + ".history")


def _evaluator(problem: DesignProblem, e: ExecutionOptions, history: Path | None, restart: bool):
    return Evaluator(
        problem,
        history=history,
        backend=e.backend,
        workers=e.workers,
        scheduler=e.scheduler,
        restart=restart,
    )


def run_optimization(run: OptimizationRun) -> DesignResult:
    """Optimise ``run.problem`` with its search method (:data:`METHODS`) and write the study.

    See :func:`fem_racket.studies.design.solvers.optimize`,
    :func:`fem_racket.studies.design.pareto.pareto_front` and
    :func:`fem_racket.io.design_files.write_study`.
    """
    problem, s, files = run.problem, run.search, run.files
    check_choice("method", s.method, METHODS)
    sizes = {"maxiter": s.maxiter, "popsize": s.popsize, "pop_size": s.pop_size}
    check_study_size(problem, s.method, generations=s.generations, **sizes)
    if files.out is None and run.restart:
        raise InputError("restart = True is not allowed without out: no history is kept")
    if files.out is not None:
        check_study_folder(files.out, overwrite=files.overwrite)
    work_begins()
    history = None if files.out is None else history_path(files.out)
    ev = _evaluator(problem, run.execution, history, run.restart)
    common = {"evaluator": ev, "progress": run.execution.progress}
    # the search refused what its method does not use: the global methods' own options only
    de = {"popsize": s.popsize, "seed": s.seed} if s.method == "differential-evolution" else {}
    try:
        if s.method == "nsga2":
            result = pareto_front(
                problem, pop_size=s.pop_size, generations=s.generations, seed=s.seed, **common
            )
        else:
            result = optimize(problem, method=s.method, maxiter=s.maxiter, **de, **common)
        if files.out is not None:
            write_study(result, files.out, overwrite=files.overwrite, parameters=files.parameters)
            ev.history.remove()
    except BaseException as exc:
        kept = len(ev.history.rows)
        if ev.history.folder is not None and kept and ev.history.folder.exists():
            exc.add_note(
                f"the history '{ev.history.folder}' holds {kept} designs: rerun the same "
                "command to resume"
            )
        raise
    finally:
        ev.history.close()
    return result


def run_sensitivity(run: SensitivityRun) -> SobolIndices:
    """Sobol indices of ``run.output`` (:func:`fem_racket.studies.design.sensitivity.
    sobol_indices`); with an output file a PNG bar chart there and the indices as JSON beside
    it (``<out>.json``, with the provenance)."""
    from fem_racket.io.design_plots import plot_sobol

    problem, out, files = run.problem, run.files.out, run.files
    names = output_names(problem)
    check_choice(
        "output", problem.objectives[0] if run.output is None else run.output, tuple(names)
    )
    refuse_unused_sensitivity(problem, problem.objectives[0] if run.output is None else run.output)
    check_sobol_size(problem, run.designs)
    check_seed(run.seed)
    if out is not None:
        check_targets([Path(out), Path(str(out) + ".json")], overwrite=files.overwrite)
    work_begins()
    ev = _evaluator(problem, run.execution, None, False)
    s = sobol_indices(
        problem,
        output=run.output,
        designs=run.designs,
        seed=run.seed,
        evaluator=ev,
        progress=run.execution.progress,
    )
    if out is not None:  # the chart and its JSON as one set: both or neither
        meta = provenance(files.parameters)
        targets = [Path(out), Path(str(out) + ".json")]
        with atomic_outputs(targets, overwrite=files.overwrite) as (png, side):
            plot_sobol(s, png)
            add_png_provenance(png, meta)
            side.write_text(json.dumps({**sobol_json(s), "provenance": meta}, indent=2) + "\n")
    return s


def sobol_json(s: SobolIndices) -> dict[str, Any]:
    """The indices as a JSON-able dict."""
    return {
        "output": s.output,
        "designs": s.designs,
        "mean": s.mean,
        "std": s.std,
        "indices": {
            n: {"S1": float(a), "S1_conf": float(b), "ST": float(c), "ST_conf": float(d)}
            for n, a, b, c, d in zip(s.names, s.s1, s.s1_conf, s.st, s.st_conf, strict=True)
        },
    }
