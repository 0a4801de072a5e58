"""Design evaluation's impact problems, solved by ``solver.solve_many``.

A design batch has thousands of impacts and needs only e_A or the grip measures of each. The
two functions here take a solver and the problems (each structure's :class:`~.cases.
DesignCases`), state them as one :class:`~fem_racket.impact.problem_batch.ProblemBatch` (every
structure's frame in it, the cases in order) and let the solver answer it
(:meth:`fem_racket.impact.solvers.Solver.solve_many`, which checks the batch and chooses how):

- :func:`apparent_cor`, the free racket: under the paper's law the exact solver's batched
  engine, one call per design's frame; under another law the general integrator, every case in
  one call, each on its own frame's receptance;
- :func:`grip_shock`, the hand-held racket: the exact solver's held modal path
  (:mod:`fem_racket.impact.held.batch`), the modes of frame + hand once per frame.

Every case is a problem :meth:`ProblemBatch.problem` would state exactly as its DesignCases
does, so the numbers are those of ``solver.solve_many(chain(*runs))``, one problem at a time
(checked in ``tests/studies/design/test_design_impacts.py``).
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np

from fem_racket.impact.general.batches import stack_laws
from fem_racket.impact.problem_batch import ProblemBatch
from fem_racket.impact.solvers import Solver
from fem_racket.studies.design.cases import DesignCases
from fem_racket.validation import InputError

__all__ = ["apparent_cor", "grip_shock"]


def _batch(runs: list[DesignCases], **fields: Any) -> ProblemBatch:
    """The cases of ``runs`` (of one design problem: one ball, law class, zeta and hand) as a
    ProblemBatch, run i on frame i."""
    first = runs[0]
    counts = [len(run) for run in runs]
    models = tuple(run.structure.model if fields.get("hand") else run.structure for run in runs)
    if first.law is not None:
        fields["law"] = stack_laws([run.law for run in runs], counts)
    elif first.kcb is not None:
        fields["kcb"] = np.concatenate([run.kcb for run in runs])
    if first.law is None and first.zeta is not None:
        fields["zeta"] = first.zeta
    return ProblemBatch(
        models,
        frame=np.repeat(np.arange(len(runs)), counts),
        position=np.concatenate([run.positions for run in runs]),
        speed=np.concatenate([run.speeds for run in runs]),
        ball_mass=first.ball.mass,
        **fields,
    )


def apparent_cor(solver: Solver, runs: Sequence[DesignCases]) -> np.ndarray:
    """e_A = -v_B(t_c) / V_B0 of each problem of ``runs`` in order (a free racket at rest
    struck at V_B0), by ``solver.solve_many``; the solver's ``modes`` and ``tolerance`` apply
    (NaN: no separation)."""
    runs = [run for run in runs if len(run)]
    if not runs:
        return np.empty(0)
    return solver.solve_many(_batch(runs)).cor


def grip_shock(
    solver: Solver, runs: Sequence[DesignCases], *, peak: bool = True
) -> tuple[np.ndarray, np.ndarray | None]:
    """Vibration RMS and peak of the grip force [N] over each problem's shock window, the
    racket held in a hand (:mod:`fem_racket.impact.held.shock`), by ``solver.solve_many``.

    Parameters
    ----------
    solver : Solver
    runs : sequence of DesignCases
        Hand-held rackets at rest under the paper's law, in one hand with one shock window.
    peak : bool
        Compute the peaks too (about half again the cost).

    Returns
    -------
    rms, peak : ndarray
        One per problem (peak None unless asked for).
    """
    runs = [run for run in runs if len(run)]
    if not runs:
        return np.empty(0), (np.empty(0) if peak else None)
    held = runs[0].structure
    if any((r.structure.hand, r.structure.shock_window) != (held.hand, held.shock_window)
           for r in runs):  # fmt: skip
        raise InputError("grip_shock takes runs in one hand with one shock window")
    batch = _batch(runs, hand=held.hand, shock_window=held.shock_window, peak_force=peak)
    extra = solver.solve_many(batch).extra
    return extra["grip_vibration_rms_n"], (extra["peak_grip_force_n"] if peak else None)
