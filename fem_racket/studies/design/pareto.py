"""Pareto front of several objectives by NSGA-II (Deb et al. 2002, pymoo).

A generation is one evaluator batch (:mod:`.evaluate`); constraints enter as ``G <= 0`` (the
normalised violations of :class:`.scaling.ScaledProblem`, an equality as a band of its tolerance).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from fem_racket.extras import require
from fem_racket.studies.design.evaluate import Evaluator
from fem_racket.studies.design.options import check_seed
from fem_racket.studies.design.problem import DesignProblem
from fem_racket.studies.design.result import DesignResult
from fem_racket.studies.design.scaling import NoBar, ScaledProblem, progress_bar
from fem_racket.studies.design.variables import sense
from fem_racket.validation import InputError, check_integer

__all__ = ["pareto_front"]


def pareto_front(
    problem: DesignProblem,
    *,
    evaluator: Evaluator | None = None,
    pop_size: int = 50,
    generations: int = 100,
    seed: int = 1,
    progress: bool | None = None,
) -> DesignResult:
    """Pareto front of the problem's objectives (maximised, or minimised for those in
    :data:`.variables.MINIMISED`) by NSGA-II (pymoo).

    Returns a :class:`DesignResult` whose ``pareto_x``/``pareto_f`` hold the non-dominated
    feasible designs, best first in the first objective; ``x`` is the one best in it.
    """
    require("pymoo", "the nsga2 method (a Pareto front)")
    from pymoo.algorithms.moo.nsga2 import NSGA2
    from pymoo.core.callback import Callback
    from pymoo.core.problem import Problem
    from pymoo.optimize import minimize

    if len(problem.objectives) < 2:
        raise InputError(
            f"objectives = {list(problem.objectives)} is not allowed for a Pareto front: "
            "give 2 or 3"
        )
    check_integer("pop_size", pop_size, minimum=4)
    check_integer("generations", generations)
    check_seed(seed)
    evaluator = Evaluator(problem) if evaluator is None else evaluator
    s = ScaledProblem(problem, evaluator, 1e-4, NoBar())
    k = [evaluator.column(o) for o in problem.objectives]
    signs = np.array([sense(o) for o in problem.objectives])
    n_g = sum(
        1 if c.low == c.high else int(np.isfinite(c.low)) + int(np.isfinite(c.high))
        for c in problem.constraints
    )

    class _P(Problem):
        def __init__(self) -> None:
            super().__init__(n_var=problem.n_var, n_obj=len(k), n_ieq_constr=n_g, xl=0.0, xu=1.0)

        def _evaluate(self, u: np.ndarray, out: dict, *args: Any, **kwargs: Any) -> None:
            y = evaluator(problem.from_unit(u))
            out["F"] = -signs * y[:, k]
            if n_g:
                ineq, eq = s.constraint_values(y)
                tol = np.array(
                    [c.tolerance / c.scale for c in problem.constraints if c.low == c.high]
                )
                out["G"] = np.concatenate([-ineq, np.abs(eq) - tol], axis=1)

    with progress_bar(progress, "NSGA-II", generations) as bar:

        class _Bar(Callback):
            def notify(self, algorithm: Any) -> None:
                bar.update(1)

        res = minimize(
            _P(),
            NSGA2(pop_size=pop_size),
            ("n_gen", generations),
            seed=seed,
            callback=_Bar(),
            verbose=False,
        )
    if res.X is None:
        raise InputError(
            f"generations = {generations} is not enough: no design met every constraint; add "
            "generations or widen the constraints (an equality such as --mass-range start is "
            "hard for NSGA-II: give a window, e.g. --mass-range 0.355,0.365)"
        )
    u = np.atleast_2d(res.X)
    x = problem.from_unit(u)
    f = -signs * np.atleast_2d(res.F)
    order = np.argsort(-signs[0] * f[:, 0])
    x, f = x[order], f[order]
    names = evaluator.names
    y = evaluator(np.vstack([x[0], problem.x_start]))
    return DesignResult(
        problem=problem,
        method="NSGA-II",
        x=x[0],
        x_start=problem.x_start,
        outputs=dict(zip(names, map(float, y[0]), strict=True)),
        start_outputs=dict(zip(names, map(float, y[1]), strict=True)),
        success=True,
        message=f"{len(x)} non-dominated designs after {generations} generations",
        iterations=generations,
        evaluator=evaluator,
        pareto_x=x,
        pareto_f=f,
    )
