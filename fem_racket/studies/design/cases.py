"""A design's impacts stated as :class:`~fem_racket.impact.problem.ImpactProblem` s, and the
solver asked to solve them.

Every impact of a design evaluation is the stationary racket struck at the closing speed
v_in + v_r (a swing being a rigid motion of the racket, :mod:`.objectives`): the design's free
frame for e_A (:func:`free_cases`), or the frame held by the problem's hand for the handle
shock (:func:`held_cases`). Under the paper's linear law K_CB is the closing speed's K_CB(v)
(:func:`fem_racket.contact.linear.kcb_from_speed`) times the design's ``kcb_factor``, given to
each problem; any other law is the design's own (:meth:`.problem.DesignProblem.design_law`).
The method is the solver's: :func:`design_solver` makes the ``auto`` solver with the problem's
COR tolerance and no histories.
"""

from __future__ import annotations

from collections.abc import Iterable

import numpy as np

from fem_racket.contact.law import ContactLaw
from fem_racket.contact.linear import Ball, kcb_from_speed
from fem_racket.frame.model import FrameModel
from fem_racket.impact.problem import HeldRacket, Impact, ImpactProblem
from fem_racket.impact.solvers import Solver, make_solver
from fem_racket.studies.design.problem import DesignProblem

__all__ = ["closing_kcb", "design_solver", "free_cases", "held_cases"]


def design_solver(problem: DesignProblem, *, held: bool = False) -> Solver:
    """The solver of ``problem``'s impacts: ``auto`` (the exact solution under the paper's law,
    the general integrator under another), its COR tolerance, no histories; the modes kept
    (``problem.modes``, every mode when None) under the paper's law on the free racket, where
    they apply (the held racket keeps its modes by the tolerance, a law's integrator its own)."""
    options = {"tolerance": problem.tolerance, "output_step": None}
    if problem.law is None and not held:
        options["modes"] = problem.modes
    return make_solver("auto", **options)


def closing_kcb(speeds: np.ndarray, factor: np.ndarray) -> np.ndarray:
    """K_CB(v) [N/m] of each closing speed (rows: designs) times each design's ``factor``."""
    uniq, inv = np.unique(speeds, return_inverse=True)
    kcb = np.array([kcb_from_speed(v) for v in uniq])[inv].reshape(speeds.shape)
    return kcb * np.asarray(factor, dtype=float)[:, None]


def free_cases(
    problem: DesignProblem,
    model: FrameModel,
    positions: Iterable[float],
    speeds: Iterable[float],
    contact: ContactLaw | Iterable[float],
) -> list[ImpactProblem]:
    """The free racket ``model`` struck at each position x/L at each closing speed [m/s];
    ``contact``: the design's law, or K_CB [N/m] of each case under the paper's law."""
    ball = Ball(problem.ball_mass)
    if isinstance(contact, ContactLaw):
        return [
            ImpactProblem(model, Impact(x, v), ball, law=contact)
            for x, v in zip(positions, speeds, strict=True)
        ]
    return [
        ImpactProblem(model, Impact(x, v), ball, kcb=k, zeta=problem.zeta)
        for x, v, k in zip(positions, speeds, contact, strict=True)
    ]


def held_cases(
    problem: DesignProblem, model: FrameModel, positions: Iterable[float], speeds: Iterable[float]
) -> list[ImpactProblem]:
    """The racket ``model`` held by the problem's hand, struck at each position x/L at each
    closing speed [m/s] (the paper's law, K_CB(v))."""
    ball = Ball(problem.ball_mass)
    held = HeldRacket(model, problem.hand, problem.shock_window)
    return [
        ImpactProblem(held, Impact(x, v), ball, zeta=problem.zeta)
        for x, v in zip(positions, speeds, strict=True)
    ]
