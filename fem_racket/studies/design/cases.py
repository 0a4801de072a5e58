"""A design's impacts as :class:`~fem_racket.impact.problem.ImpactProblem` s
(:class:`DesignCases`), and the solver asked to solve them.

Every impact of a design evaluation is the stationary racket struck at the closing speed
v_in + v_r (a swing being a rigid motion of the racket, :mod:`.objectives`): the design's free
frame for e_A (:func:`free_cases`), or the frame held by the problem's hand for the handle
shock (:func:`held_cases`). Under the paper's linear law K_CB is the closing speed's K_CB(v)
(:func:`fem_racket.contact.linear.kcb_from_speed`) times the design's ``kcb_factor``, given to
each problem; any other law is the design's own (:meth:`.problem.DesignProblem.design_law`).
The method is the solver's: :func:`design_solver` makes the ``auto`` solver with the problem's
COR tolerance and no histories.

A design has ~60 impacts and a batch thousands: each problem is made (and validated, ~25 us)
when it is read, so the batch (:mod:`.impacts`: one
:class:`~fem_racket.impact.problem_batch.ProblemBatch` of every design's cases) pays for one
problem per design.
"""

from __future__ import annotations

from collections.abc import Iterator, Sequence
from dataclasses import dataclass

import numpy as np

from fem_racket.contact.law import ContactLaw
from fem_racket.contact.linear import Ball, kcb_from_speed
from fem_racket.frame.model import FrameModel
from fem_racket.impact.problem import HeldRacket, Impact, ImpactProblem
from fem_racket.impact.solvers import Solver, make_solver
from fem_racket.studies.design.problem import DesignProblem
from fem_racket.validation import InputError

__all__ = ["DesignCases", "closing_kcb", "design_solver", "free_cases", "held_cases"]


@dataclass(frozen=True, eq=False)
class DesignCases(Sequence[ImpactProblem]):
    """Impacts on one structure at many (point, speed) cases: a sequence of ImpactProblems,
    each made when read.

    Attributes
    ----------
    structure : FrameModel or HeldRacket
    positions, speeds : ndarray
        Impact points x/L and closing speeds [m/s], one per case.
    ball : Ball
    law : ContactLaw or None
        The contact law (None: the paper's, with ``kcb`` and ``zeta``).
    kcb : ndarray or None
        K_CB [N/m] per case (None: K_CB(v) of each speed).
    zeta : float or None
        Damping ratio of the paper's law.
    """

    structure: FrameModel | HeldRacket
    positions: np.ndarray
    speeds: np.ndarray
    ball: Ball
    law: ContactLaw | None = None
    kcb: np.ndarray | None = None
    zeta: float | None = None

    def __post_init__(self) -> None:
        n = self.positions.shape
        if len(n) != 1 or self.speeds.shape != n or (self.kcb is not None and self.kcb.shape != n):
            raise InputError(
                f"design cases of shapes {n}, {self.speeds.shape}: need one position, speed "
                "(and K_CB) per case"
            )

    def __len__(self) -> int:
        return self.positions.size

    def __getitem__(self, i):  # type: ignore[override]
        if isinstance(i, slice):
            return [self[k] for k in range(*i.indices(len(self)))]
        return ImpactProblem(
            self.structure,
            Impact(float(self.positions[i]), float(self.speeds[i])),
            self.ball,
            law=self.law,
            kcb=None if self.kcb is None else float(self.kcb[i]),
            zeta=self.zeta,
        )

    def __iter__(self) -> Iterator[ImpactProblem]:
        return (self[k] for k in range(len(self)))


def design_solver(
    problem: DesignProblem, *, held: bool = False, flexible: int | None = None
) -> Solver:
    """The solver of ``problem``'s impacts: ``auto`` (the exact solution under the paper's law,
    the general integrator under another), its COR tolerance, no histories; under the paper's
    law on the free racket the modes kept, ``problem.modes`` or, when None, every one of the
    ``flexible`` modes of the designs' frames (the tolerance then drops those it does not need;
    when ``flexible`` is None too the engine's own choice, static totals for the modes above
    its cut-off). The held racket keeps its modes by the tolerance, a law's integrator its own.
    """
    options = {"tolerance": problem.tolerance, "output_step": None}
    if problem.law is None and not held:
        options["modes"] = flexible if problem.modes is None else problem.modes
    return make_solver("auto", **options)


def closing_kcb(speeds: np.ndarray, factor: np.ndarray) -> np.ndarray:
    """K_CB(v) [N/m] of each closing speed (rows: designs) times each design's ``factor``."""
    uniq, inv = np.unique(speeds, return_inverse=True)
    kcb = np.array([kcb_from_speed(v) for v in uniq])[inv].reshape(speeds.shape)
    return kcb * np.asarray(factor, dtype=float)[:, None]


def free_cases(
    problem: DesignProblem,
    model: FrameModel,
    positions: np.ndarray,
    speeds: np.ndarray,
    contact: ContactLaw | np.ndarray,
) -> DesignCases:
    """The free racket ``model`` struck at each position x/L at each closing speed [m/s];
    ``contact``: the design's law, or K_CB [N/m] of each case under the paper's law."""
    x, v = np.asarray(positions, dtype=float), np.asarray(speeds, dtype=float)
    ball = Ball(problem.ball_mass)
    if isinstance(contact, ContactLaw):
        return DesignCases(model, x, v, ball, law=contact)
    kcb = np.asarray(contact, dtype=float)
    return DesignCases(model, x, v, ball, kcb=kcb, zeta=problem.zeta)


def held_cases(
    problem: DesignProblem, model: FrameModel, positions: np.ndarray, speeds: np.ndarray
) -> DesignCases:
    """The racket ``model`` held by the problem's hand, struck at each position x/L at each
    closing speed [m/s] (the paper's law, K_CB(v))."""
    held = HeldRacket(model, problem.hand, problem.shock_window)
    x, v = np.asarray(positions, dtype=float), np.asarray(speeds, dtype=float)
    return DesignCases(held, x, v, Ball(problem.ball_mass), zeta=problem.zeta)
