"""One call per command: run a design study or a sensitivity analysis and write its files.

With an output folder the study is resumable: evaluated designs are kept in
``<out>.history/`` (:mod:`fem_racket.studies.design.history`) until the results are written,
and a rerun with the same settings replays them from there (the solvers are deterministic for a
given seed).
"""

from __future__ import annotations

import json
import os
from pathlib import Path
from typing import Any

from fem_racket.io.design_files import check_study_folder, write_study
from fem_racket.outputs import add_png_provenance, atomic_output, check_output_path, provenance
from fem_racket.studies.design.evaluate import Evaluator
from fem_racket.studies.design.pareto import pareto_front
from fem_racket.studies.design.problem import DesignProblem
from fem_racket.studies.design.result import DesignResult
from fem_racket.studies.design.sensitivity import SobolIndices, sobol_indices
from fem_racket.studies.design.solvers import optimize
from fem_racket.validation import InputError, check_choice

__all__ = ["METHODS", "history_path", "run_optimization", "run_sensitivity"]

#: Solvers by name: scipy.optimize's local and global methods, pymoo's NSGA-II.
METHODS = ("SLSQP", "trust-constr", "differential-evolution", "nsga2")


def history_path(out: str | os.PathLike) -> Path:
    """The history folder kept beside output ``out`` while a study runs."""
    out = Path(out)
    return out.with_name(out.name + ".history")


def _evaluator(problem, out, restart, backend, workers, scheduler) -> Evaluator:
    history = None
    if out is not None:
        history = history_path(out)
        if restart and history.exists():
            import shutil

            shutil.rmtree(history)
    return Evaluator(
        problem, history=history, backend=backend, workers=workers, scheduler=scheduler
    )


def run_optimization(
    problem: DesignProblem,
    *,
    method: str = "SLSQP",
    out: str | os.PathLike | None = None,
    overwrite: bool = False,
    restart: bool = False,
    backend: str | None = None,
    workers: int | None = None,
    scheduler: str | None = None,
    maxiter: int = 100,
    popsize: int = 10,
    pop_size: int = 50,
    generations: int = 100,
    seed: int = 1,
    progress: bool | None = None,
    parameters: dict[str, Any] | None = None,
) -> DesignResult:
    """Optimise ``problem`` with ``method`` (:data:`METHODS`) and write the study to ``out``.

    ``nsga2`` gives a Pareto front of the problem's objectives; the others maximise the first.
    See :func:`fem_racket.studies.design.solvers.optimize`,
    :func:`fem_racket.studies.design.pareto.pareto_front` and
    :func:`fem_racket.io.design_files.write_study`.
    """
    check_choice("method", method, METHODS)
    if method == "nsga2" and len(problem.objectives) < 2:
        raise InputError(
            f"objectives = {list(problem.objectives)} is not allowed with nsga2: give 2 or 3"
        )
    if out is not None:
        check_study_folder(out, overwrite=overwrite)
    ev = _evaluator(problem, out, restart, backend, workers, scheduler)
    if method == "nsga2":
        result = pareto_front(
            problem,
            evaluator=ev,
            pop_size=pop_size,
            generations=generations,
            seed=seed,
            progress=progress,
        )
    else:
        result = optimize(
            problem,
            method=method,
            evaluator=ev,
            maxiter=maxiter,
            popsize=popsize,
            seed=seed,
            progress=progress,
        )
    if out is not None:
        write_study(result, out, overwrite=overwrite, parameters=parameters)
        ev.history.remove()
    return result


def run_sensitivity(
    problem: DesignProblem,
    *,
    output: str | None = None,
    designs: int = 10_000,
    seed: int = 1,
    out: str | os.PathLike | None = None,
    overwrite: bool = False,
    backend: str | None = None,
    workers: int | None = None,
    scheduler: str | None = None,
    progress: bool | None = None,
    parameters: dict[str, Any] | None = None,
) -> SobolIndices:
    """Sobol indices of ``output`` (:func:`fem_racket.studies.design.sensitivity.sobol_indices`);
    with ``out`` a PNG bar chart there and the indices as JSON beside it (``<out>.json``, with
    the provenance)."""
    from fem_racket.io.design_plots import plot_sobol

    if out is not None:
        out = check_output_path(out, overwrite=overwrite)
        check_output_path(Path(str(out) + ".json"), overwrite=overwrite)
    ev = Evaluator(problem, backend=backend, workers=workers, scheduler=scheduler)
    s = sobol_indices(
        problem, output=output, designs=designs, seed=seed, evaluator=ev, progress=progress
    )
    if out is not None:
        meta = provenance(parameters)
        with atomic_output(out, overwrite=overwrite) as tmp:
            plot_sobol(s, tmp)
            add_png_provenance(tmp, meta)
        data = sobol_json(s)
        with atomic_output(Path(str(out) + ".json"), overwrite=overwrite) as tmp:
            tmp.write_text(json.dumps({**data, "provenance": meta}, indent=2) + "\n")
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
