"""Solvers of a design problem's first objective: scipy.optimize's local SLSQP / trust-constr and
global differential evolution (several objectives: :mod:`.pareto`).

All search the unit box u in [0, 1]^n (EI variables on a log scale, :class:`.variables.Variable`)
through :class:`.scaling.ScaledProblem` and hand whole batches to the :class:`.evaluate.Evaluator`:

- local methods get the objective, the constraints and their forward-difference gradients from
  one batch per iterate (the point and its n neighbours at step ``step`` in u);
- differential evolution runs ``vectorized`` (one batch per generation) with the constraints as
  a vectorised :class:`scipy.optimize.NonlinearConstraint`; its best design is then polished by
  the local method (``polish``).

Every solver is deterministic for a given seed,
so a rerun replays its designs from the evaluator's history (resume).
"""

from __future__ import annotations

import logging
import warnings
from typing import Any

import numpy as np

from fem_racket.studies.design.evaluate import Evaluator
from fem_racket.studies.design.methods import GLOBAL_METHODS, LOCAL_METHODS
from fem_racket.studies.design.options import SearchOptions
from fem_racket.studies.design.problem import DesignProblem
from fem_racket.studies.design.result import DesignResult
from fem_racket.studies.design.scaling import ScaledProblem, progress_bar
from fem_racket.validation import InputError, check_choice, check_integer

__all__ = ["GLOBAL_METHODS", "LOCAL_METHODS", "optimize"]

log = logging.getLogger(__name__)


def _local(
    problem: DesignProblem,
    evaluator: Evaluator,
    u0: np.ndarray,
    method: str,
    maxiter: int,
    tol: float,
    step: float,
    bar: Any,
) -> tuple[np.ndarray, bool, str, int]:
    from scipy.optimize import Bounds, NonlinearConstraint, minimize

    s = ScaledProblem(problem, evaluator, step, bar)
    bounds = Bounds(np.zeros(problem.n_var), np.ones(problem.n_var))
    s._evaluate(u0)
    has_ineq, has_eq = s.ineq.size > 0, s.eq.size > 0
    if method == "SLSQP":
        cons = []
        if has_ineq:
            cons.append(
                {
                    "type": "ineq",
                    "fun": lambda u: (s._evaluate(u), s.ineq)[1],
                    "jac": lambda u: (s._evaluate(u), s.dineq)[1],
                }
            )
        if has_eq:
            cons.append(
                {
                    "type": "eq",
                    "fun": lambda u: (s._evaluate(u), s.eq)[1],
                    "jac": lambda u: (s._evaluate(u), s.deq)[1],
                }
            )
        options = {"maxiter": maxiter, "ftol": tol}
        callback = _settled(s, tol)
    else:
        cons = []
        if has_ineq:
            cons.append(
                NonlinearConstraint(
                    lambda u: (s._evaluate(u), s.ineq)[1],
                    0.0,
                    np.inf,
                    jac=lambda u: (s._evaluate(u), s.dineq)[1],
                )
            )
        if has_eq:
            cons.append(
                NonlinearConstraint(
                    lambda u: (s._evaluate(u), s.eq)[1],
                    0.0,
                    0.0,
                    jac=lambda u: (s._evaluate(u), s.deq)[1],
                )
            )
        options = {"maxiter": maxiter, "gtol": tol, "xtol": tol}
        callback = None
    with warnings.catch_warnings():
        # trust-constr's quasi-Newton update warns when an iterate repeats (delta_grad == 0),
        # e.g. on a linear constraint: informational, the step is skipped.
        warnings.filterwarnings("ignore", "delta_grad == 0.0", UserWarning)
        res = minimize(
            s.fun,
            u0,
            jac=s.jac,
            bounds=bounds,
            constraints=cons,
            method=method,
            options=options,
            callback=callback,
        )
    if callback is not None and callback.settled:
        return np.clip(res.x, 0.0, 1.0), True, SETTLED, int(res.nit)
    return np.clip(res.x, 0.0, 1.0), bool(res.success), str(res.message), int(res.nit)


#: Message of an SLSQP run stopped by :func:`_settled`.
SETTLED = (
    "Optimization terminated successfully: the objective settled (change <= tol) with every "
    "constraint within its tolerance"
)


def _settled(s: ScaledProblem, tol: float) -> Any:
    """SLSQP's callback: stop once an iteration changes the scaled objective by at most ``tol``
    and the design meets every constraint to its tolerance. SLSQP's own test asks the
    constraints to hold to ``tol`` in scaled units too: an active bound met to 4e-6 Hz of an
    f1 limit of 200 Hz (2e-8 scaled, 1e-3 Hz tolerance) kept it iterating to ``maxiter``."""

    def callback(u: np.ndarray) -> None:
        s._evaluate(u)
        last, callback.last = callback.last, float(s.f)
        if last is not None and abs(last - s.f) <= tol and s.feasible():
            callback.settled = True
            raise StopIteration

    callback.last, callback.settled = None, False
    return callback


def _global(
    problem: DesignProblem,
    evaluator: Evaluator,
    popsize: int,
    maxiter: int,
    seed: int,
    bar: Any,
) -> tuple[np.ndarray, bool, str, int]:
    from scipy.optimize import NonlinearConstraint, differential_evolution

    s = ScaledProblem(problem, evaluator, 1e-4, bar)
    cache: dict[bytes, np.ndarray] = {}

    def rows(u: np.ndarray) -> np.ndarray:  # u: (n, S)
        key = u.tobytes()
        if key not in cache:
            cache.clear()
            cache[key] = evaluator(problem.from_unit(u.T))
            bar.update(1)
        return cache[key]

    def fun(u: np.ndarray) -> np.ndarray:
        return s.objective_values(rows(u))

    def cons(u: np.ndarray) -> np.ndarray:
        ineq, eq = s.constraint_values(rows(u))
        return np.concatenate([ineq, eq, -eq], axis=-1).T

    constraints = ()
    if problem.constraints:
        # equalities as two-sided bands of the constraint's tolerance (DE cannot hit them exactly)
        tol = []
        for c in problem.constraints:
            if c.low == c.high:
                tol.append(c.tolerance / c.scale)
        t = np.array(tol)
        n_ineq = s.constraint_values(np.zeros(len(evaluator.names)))[0].size
        lb = np.concatenate([np.zeros(n_ineq), -t, -t])
        constraints = (NonlinearConstraint(cons, lb, np.inf),)
    res = differential_evolution(
        fun,
        [(0.0, 1.0)] * problem.n_var,
        popsize=popsize,
        maxiter=maxiter,
        seed=seed,
        x0=problem.to_unit(problem.x_start),
        vectorized=True,
        constraints=constraints,
        polish=False,
        tol=1e-8,
        updating="deferred",
    )
    return np.clip(res.x, 0.0, 1.0), bool(res.success), str(res.message), int(res.nit)


def optimize(
    problem: DesignProblem,
    *,
    method: str = "SLSQP",
    evaluator: Evaluator | None = None,
    maxiter: int = 100,
    tol: float = 1e-9,
    step: float = 1e-4,
    popsize: int | None = None,
    seed: int | None = None,
    polish: bool | None = None,
    progress: bool | None = None,
) -> DesignResult:
    """Maximise the problem's first objective subject to its constraints.

    Parameters
    ----------
    problem : DesignProblem
    method : {"SLSQP", "trust-constr", "differential-evolution"}
        Local constrained methods start from the starting racket; differential evolution is
        global (the starting racket is in its first population).
    evaluator : Evaluator, optional
        Where designs run and are remembered (history, executors); serial in memory when None.
    maxiter : int
        Iterations (local) or generations (differential evolution).
    tol : float
        Convergence tolerance of the local method (on the scaled objective).
    step : float
        Forward-difference step in the unit box.
    popsize : int, optional
        Differential evolution: population = popsize x number of variables (default 10).
    seed : int, optional
        Random seed of differential evolution (default 1).
    polish : bool, optional
        Differential evolution: finish with SLSQP from its best design (default True).
        ``popsize``, ``seed`` and ``polish`` are differential evolution's: given (at any
        value) with a local method, they are refused.
    progress : bool, optional
        Progress bar on stderr (iterations, best objective); None: only on a terminal.

    Returns
    -------
    DesignResult
    """
    check_choice("method", method, LOCAL_METHODS + GLOBAL_METHODS)
    check_integer("maxiter", maxiter)
    told = {k: v for k, v in (("popsize", popsize), ("seed", seed)) if v is not None}
    SearchOptions(method=method, maxiter=maxiter, **told, given=frozenset(told))  # refuses unused
    if polish is not None and method in LOCAL_METHODS:
        raise InputError(
            f"polish = {polish} is not allowed with method {method!r}: only "
            "differential-evolution is polished"
        )
    popsize = SearchOptions.popsize if popsize is None else popsize
    seed = SearchOptions.seed if seed is None else seed
    polish = True if polish is None else polish
    evaluator = Evaluator(problem) if evaluator is None else evaluator
    u0 = problem.to_unit(problem.x_start)
    with progress_bar(progress, method, None) as bar:
        if method in LOCAL_METHODS:
            u, ok, msg, nit = _local(problem, evaluator, u0, method, maxiter, tol, step, bar)
        else:
            check_integer("popsize", popsize, minimum=4)
            u, ok, msg, nit = _global(problem, evaluator, popsize, maxiter, seed, bar)
            if polish:
                u, ok, msg, more = _local(problem, evaluator, u, "SLSQP", maxiter, tol, step, bar)
                nit += more
    names = evaluator.names
    x = problem.from_unit(u)
    y = evaluator(np.vstack([x, problem.x_start]))
    result = DesignResult(
        problem=problem,
        method=method,
        x=x,
        x_start=problem.x_start,
        outputs=dict(zip(names, map(float, y[0]), strict=True)),
        start_outputs=dict(zip(names, map(float, y[1]), strict=True)),
        success=ok,
        message=msg,
        iterations=nit,
        evaluator=evaluator,
    )
    bad = [c["name"] for c in result.constraints() if not c["holds"]]
    if bad:
        log.warning("the best design found violates %s", ", ".join(bad))
    return result
