"""The outcome of a design study: best design, its outputs and the starting racket's, the
constraints at the best design, and for multi-objective runs the Pareto front."""

from __future__ import annotations

from dataclasses import dataclass, field
from typing import Any

import numpy as np

from fem_racket.studies.design.evaluate import Evaluator
from fem_racket.studies.design.problem import DesignProblem
from fem_racket.studies.design.variables import QUANTITIES
from fem_racket.studies.views import DesignView

__all__ = ["DesignResult"]


@dataclass(repr=False)
class DesignResult(DesignView):
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
