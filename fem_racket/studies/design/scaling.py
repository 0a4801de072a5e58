"""A design problem as the solvers see it: the unit box, a minimised scaled objective,
constraints as ``>= 0`` / ``= 0`` functions with forward-difference gradients from one batch.

Objectives are maximised (minimised: those in :data:`.variables.MINIMISED`): the solvers
minimise ``-s f / |f(start)|`` (s = +1, or -1 for a minimised one). A constraint
``low <= q <= high`` enters as ``(q - low) / s >= 0`` and ``(high - q) / s >= 0`` (``s`` its
scale), or ``(q - low) / s = 0`` when low = high.
"""

from __future__ import annotations

import sys
from typing import Any

import numpy as np

from fem_racket.studies.design.evaluate import Evaluator
from fem_racket.studies.design.problem import DesignProblem
from fem_racket.studies.design.variables import sense

__all__ = ["NoBar", "ScaledProblem", "progress_bar"]


class ScaledProblem:
    """Objective and constraints of the unit box, from one evaluator batch per iterate."""

    def __init__(self, problem: DesignProblem, evaluator: Evaluator, step: float, bar: Any):
        self.problem, self.evaluator, self.step, self.bar = problem, evaluator, step, bar
        self.k_obj = evaluator.column(problem.objectives[0])
        self.sense = sense(problem.objectives[0])
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

    def feasible(self) -> bool:
        """Whether the last evaluated design meets every constraint to its tolerance
        (:meth:`Constraint.satisfied`, here on the scaled values of :meth:`constraint_values`)."""
        ineq_tol, eq_tol = [], []
        for c in self.problem.constraints:
            if c.low == c.high:
                eq_tol.append(c.tolerance / c.scale)
            else:
                ineq_tol += [c.tolerance / c.scale] * (
                    int(np.isfinite(c.low)) + int(np.isfinite(c.high))
                )
        return bool(np.all(self.ineq >= -np.array(ineq_tol)) and np.all(np.abs(self.eq) <= eq_tol))

    def objective_values(self, y: np.ndarray) -> np.ndarray:
        """-s f / |f(start)| (minimised; module docstring)."""
        return -self.sense * y[..., self.k_obj] / self.f_scale

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
        self.bar.set_postfix_str(f"{self.problem.objectives[0]} {y[0, self.k_obj]:.6g}")

    def fun(self, u: np.ndarray) -> float:
        self._evaluate(u)
        return float(self.f)

    def jac(self, u: np.ndarray) -> np.ndarray:
        self._evaluate(u)
        return self.df


def progress_bar(enabled: bool | None, desc: str, total: int | None, unit: str = "batch") -> Any:
    """A tqdm bar on stderr (None: only when stderr is a terminal), without tqdm's monitor
    thread: a process with a second thread starts its pools by forkserver, not fork (slower;
    :mod:`fem_racket.studies.executors`)."""
    from tqdm import tqdm

    class Bar(tqdm):
        monitor_interval = 0

    if enabled is None:
        enabled = sys.stderr.isatty()
    return Bar(total=total, desc=desc, unit=unit, disable=not enabled, file=sys.stderr)


class NoBar:
    """A progress bar that shows nothing."""

    def update(self, n: int) -> None:
        """Nothing."""

    def set_postfix_str(self, text: str) -> None:
        """Nothing."""
