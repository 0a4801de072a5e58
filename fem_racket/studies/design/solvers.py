"""Solvers of a design problem: scipy.optimize (local SLSQP / trust-constr, global differential
evolution) for the first objective, pymoo NSGA-II for a Pareto front of several.

All search the unit box u in [0, 1]^n (EI variables on a log scale, :class:`.problem.Variable`)
and hand whole batches to the :class:`.evaluate.Evaluator`:

- local methods get the objective, the constraints and their forward-difference gradients from
  one batch per iterate (the point and its n neighbours at step ``step`` in u);
- differential evolution runs ``vectorized`` (one batch per generation) with the constraints as
  a vectorised :class:`scipy.optimize.NonlinearConstraint`; its best design is then polished by
  the local method (``polish``);
- NSGA-II (Deb et al. 2002, pymoo) evaluates a generation per batch, constraints as
  ``G <= 0`` (normalised violations).

Objectives are maximised: the solvers minimise ``-f / |f(start)|``. A constraint
``low <= q <= high`` enters as ``(q - low) / s >= 0`` and ``(high - q) / s >= 0`` (``s`` its
scale), or ``(q - low) / s = 0`` when low = high. Every solver is deterministic for a given seed,
so a rerun replays its designs from the evaluator's history (resume).
"""

from __future__ import annotations

import logging
import sys
import warnings
from dataclasses import dataclass, field
from typing import Any

import numpy as np

from fem_racket.studies.design.evaluate import Evaluator
from fem_racket.studies.design.problem import QUANTITIES, DesignProblem
from fem_racket.validation import InputError, check_choice, check_integer

__all__ = [
    "GLOBAL_METHODS",
    "LOCAL_METHODS",
    "DesignResult",
    "optimize",
    "pareto_front",
]

log = logging.getLogger(__name__)

LOCAL_METHODS = ("SLSQP", "trust-constr")
GLOBAL_METHODS = ("differential-evolution",)


@dataclass
class DesignResult:
    """The outcome of a design study.

    Attributes
    ----------
    problem : DesignProblem
    method : str
    x, x_start : ndarray
        Best and starting design variables [SI].
    outputs, start_outputs : dict
        Every quantity and objective of the best and starting designs.
    success : bool
    message : str
    iterations : int
    evaluator : Evaluator
        Its history holds every evaluated design.
    pareto_x, pareto_f : ndarray, optional
        Non-dominated designs [SI] and their objectives (multi-objective runs).
    """

    problem: DesignProblem
    method: str
    x: np.ndarray
    x_start: np.ndarray
    outputs: dict[str, float]
    start_outputs: dict[str, float]
    success: bool
    message: str
    iterations: int
    evaluator: Evaluator
    pareto_x: np.ndarray | None = None
    pareto_f: np.ndarray | None = None
    extra: dict[str, Any] = field(default_factory=dict)

    @property
    def objective(self) -> float:
        """The first objective at the best design."""
        return self.outputs[self.problem.objectives[0]]

    @property
    def start_objective(self) -> float:
        """The first objective at the starting design."""
        return self.start_outputs[self.problem.objectives[0]]

    def constraints(self) -> list[dict[str, Any]]:
        """Each constraint at the best design: name, value, bounds, tolerance, whether it holds."""
        out = []
        for c in self.problem.constraints:
            value = self.outputs[c.name]
            out.append(
                {
                    "name": c.name,
                    "label": QUANTITIES[c.name][0],
                    "value": value,
                    "low": c.low,
                    "high": c.high,
                    "tolerance": c.tolerance,
                    "holds": c.holds(value),
                }
            )
        return out


class _Scaled:
    """Objective and constraints of the unit box, from one evaluator batch per iterate."""

    def __init__(self, problem: DesignProblem, evaluator: Evaluator, step: float, bar: Any):
        self.problem, self.evaluator, self.step, self.bar = problem, evaluator, step, bar
        self.k_obj = evaluator.column(problem.objectives[0])
        y0 = evaluator(problem.x_start)[0]
        self.f_scale = max(abs(float(y0[self.k_obj])), 1e-12)
        self._u: np.ndarray | None = None
        self.best: tuple[float, np.ndarray] | None = None

    def constraint_values(self, y: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """(inequalities >= 0, equalities = 0) from output rows ``y`` (..., n_out)."""
        ineq, eq = [], []
        for c in self.problem.constraints:
            q = y[..., self.evaluator.column(c.name)]
            if c.low == c.high:
                eq.append((q - c.low) / c.scale)
                continue
            if np.isfinite(c.low):
                ineq.append((q - c.low) / c.scale)
            if np.isfinite(c.high):
                ineq.append((c.high - q) / c.scale)
        shape = y.shape[:-1]
        as_array = lambda v: np.stack(v, -1) if v else np.zeros((*shape, 0))  # noqa: E731
        return as_array(ineq), as_array(eq)

    def objective_values(self, y: np.ndarray) -> np.ndarray:
        """-f / |f(start)| (minimised)."""
        return -y[..., self.k_obj] / self.f_scale

    def _evaluate(self, u: np.ndarray) -> None:
        if self._u is not None and np.array_equal(u, self._u):
            return
        n = u.size
        pts = np.repeat(u[None, :], n + 1, axis=0)
        h = np.where(u + self.step <= 1.0, self.step, -self.step)
        pts[np.arange(1, n + 1), np.arange(n)] += h
        y = self.evaluator(self.problem.from_unit(pts))
        f = self.objective_values(y)
        ineq, eq = self.constraint_values(y)
        self._u = u.copy()
        self.f, self.df = f[0], (f[1:] - f[0]) / h
        self.ineq, self.dineq = ineq[0], ((ineq[1:] - ineq[0]) / h[:, None]).T
        self.eq, self.deq = eq[0], ((eq[1:] - eq[0]) / h[:, None]).T
        self.bar.update(1)
        self.bar.set_postfix_str(f"{self.problem.objectives[0]} {-f[0] * self.f_scale:.6g}")

    def fun(self, u: np.ndarray) -> float:
        self._evaluate(u)
        return float(self.f)

    def jac(self, u: np.ndarray) -> np.ndarray:
        self._evaluate(u)
        return self.df


def _progress(enabled: bool | None, desc: str, total: int | None) -> Any:
    from tqdm import tqdm

    if enabled is None:
        enabled = sys.stderr.isatty()
    return tqdm(total=total, desc=desc, unit="batch", disable=not enabled, file=sys.stderr)


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

    s = _Scaled(problem, evaluator, step, bar)
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
    with warnings.catch_warnings():
        # trust-constr's quasi-Newton update warns when an iterate repeats (delta_grad == 0),
        # e.g. on a linear constraint: informational, the step is skipped.
        warnings.filterwarnings("ignore", "delta_grad == 0.0", UserWarning)
        res = minimize(
            s.fun, u0, jac=s.jac, bounds=bounds, constraints=cons, method=method, options=options
        )
    return np.clip(res.x, 0.0, 1.0), bool(res.success), str(res.message), int(res.nit)


def _global(
    problem: DesignProblem,
    evaluator: Evaluator,
    popsize: int,
    maxiter: int,
    seed: int,
    bar: Any,
) -> tuple[np.ndarray, bool, str, int]:
    from scipy.optimize import NonlinearConstraint, differential_evolution

    s = _Scaled(problem, evaluator, 1e-4, bar)
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
    popsize: int = 10,
    seed: int = 1,
    polish: bool = True,
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
    popsize : int
        Differential evolution: population = popsize x number of variables.
    seed : int
        Random seed of differential evolution.
    polish : bool
        Differential evolution: finish with SLSQP from its best design.
    progress : bool, optional
        Progress bar on stderr (iterations, best objective); None: only on a terminal.

    Returns
    -------
    DesignResult
    """
    check_choice("method", method, LOCAL_METHODS + GLOBAL_METHODS)
    check_integer("maxiter", maxiter)
    evaluator = Evaluator(problem) if evaluator is None else evaluator
    u0 = problem.to_unit(problem.x_start)
    with _progress(progress, method, None) as bar:
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


def pareto_front(
    problem: DesignProblem,
    *,
    evaluator: Evaluator | None = None,
    pop_size: int = 50,
    generations: int = 100,
    seed: int = 1,
    progress: bool | None = None,
) -> DesignResult:
    """Pareto front of the problem's objectives (all maximised) by NSGA-II (pymoo).

    Returns a :class:`DesignResult` whose ``pareto_x``/``pareto_f`` hold the non-dominated
    feasible designs, sorted by the first objective; ``x`` is the one best in the first objective.
    """
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
    evaluator = Evaluator(problem) if evaluator is None else evaluator
    s = _Scaled(problem, evaluator, 1e-4, _NoBar())
    k = [evaluator.column(o) for o in problem.objectives]
    n_g = sum(
        1 if c.low == c.high else int(np.isfinite(c.low)) + int(np.isfinite(c.high))
        for c in problem.constraints
    )

    class _P(Problem):
        def __init__(self) -> None:
            super().__init__(n_var=problem.n_var, n_obj=len(k), n_ieq_constr=n_g, xl=0.0, xu=1.0)

        def _evaluate(self, u: np.ndarray, out: dict, *args: Any, **kwargs: Any) -> None:
            y = evaluator(problem.from_unit(u))
            out["F"] = -y[:, k]
            if n_g:
                ineq, eq = s.constraint_values(y)
                tol = np.array(
                    [c.tolerance / c.scale for c in problem.constraints if c.low == c.high]
                )
                out["G"] = np.concatenate([-ineq, np.abs(eq) - tol], axis=1)

    with _progress(progress, "NSGA-II", generations) as bar:

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
    f = -np.atleast_2d(res.F)
    order = np.argsort(-f[:, 0])
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


class _NoBar:
    def update(self, n: int) -> None:
        pass

    def set_postfix_str(self, text: str) -> None:
        pass
