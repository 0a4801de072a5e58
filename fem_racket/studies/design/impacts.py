"""The one place design evaluation has its impact problems solved: a stand-in for
``solver.solve_many(problems)``.

:meth:`fem_racket.impact.solvers.Solver.solve_many` on ``main`` still solves one problem at a
time (an eigen-solution or an engine call per impact, milliseconds each, and a full
:class:`~fem_racket.impact.result.ImpactResult`), where a design batch has thousands of impacts
and needs only e_A or the grip measures. Until the batched engine stands behind
``ExactSolver.solve_many`` and the law batch behind ``GeneralSolver.solve_many``, the two
functions here take a solver and the problems (each structure's
:class:`~.cases.DesignCases`), let the solver check them, and run the method it stands for on
every structure's cases at once:

- :func:`apparent_cor`, the free racket: under the paper's law the batched engine
  (:func:`fem_racket.impact.exact.engine.modal_impacts`) on each structure's modes kept by the
  solver (every mode when it keeps all), structures with equal mode counts in one call; under
  another law the general integrator (:func:`fem_racket.impact.general.integrator.
  solve_general`), every structure's cases in one call, each on its frame's receptance;
- :func:`grip_shock`, the hand-held racket: the exact modal path
  (:mod:`fem_racket.impact.held.modal`), the modes of frame + hand once per structure.

Switching to ``solve_many`` changes these two bodies only (``solver.solve_many(chain(*runs))``).
The runs are of one kind (one design problem's); the cases of one structure differ only in
their impact point and speed (checked in bulk by the engine), which no solver refuses, so the
first of each is checked as a problem.
"""

from __future__ import annotations

from collections import OrderedDict
from collections.abc import Sequence
from typing import Any

import numpy as np

from fem_racket.frame.model import FrameModel
from fem_racket.impact.exact.engine import EngineOptions, modal_impacts
from fem_racket.impact.general.batches import stack_laws, stack_receptances
from fem_racket.impact.general.integrator import solve_general
from fem_racket.impact.held.basis import held_basis
from fem_racket.impact.held.modal import held_contacts
from fem_racket.impact.held.shock import grip_peak, vibration_rms
from fem_racket.impact.law_impact import receptance
from fem_racket.impact.solvers import Solver
from fem_racket.studies.design.cases import DesignCases

__all__ = ["apparent_cor", "grip_shock"]

#: Hermite point vectors at impact points, per node set (designs on one mesh share them).
_FIELDS: OrderedDict[bytes, Any] = OrderedDict()
_FIELDS_KEPT = 8


def _field(model: FrameModel, positions: np.ndarray) -> Any:
    """Sparse (points, ndof) matrix of the deflection at ``positions`` (x/L), cached."""
    key = model.mesh.points.tobytes() + b"|" + positions.tobytes()
    g = _FIELDS.get(key)
    if g is None:
        g = model.fe.field_matrix(positions * model.mesh.length, 0)
        _FIELDS[key] = g
        if len(_FIELDS) > _FIELDS_KEPT:
            _FIELDS.popitem(last=False)
    return g


def _checked(solver: Solver, runs: Sequence[DesignCases]) -> list[DesignCases]:
    """The non-empty ``runs``, the first problem of each checked by the method ``solver``
    stands for (``auto`` picks it on the first problem: the runs are of one kind)."""
    runs = [run for run in runs if len(run)]
    if runs and hasattr(solver, "pick"):
        solver = solver.pick(runs[0][0])
    for run in runs:
        solver.check(run[0])
    return runs


def apparent_cor(solver: Solver, runs: Sequence[DesignCases]) -> np.ndarray:
    """e_A = -v_B(t_c) / V_B0 of each problem of ``runs`` in order (a free racket at rest
    struck at V_B0), as ``[r.cor for r in solver.solve_many(chain(*runs))]`` (module
    docstring); the solver's ``modes`` and ``tolerance`` apply (NaN: no separation)."""
    runs = _checked(solver, runs)
    if not runs:
        return np.empty(0)
    settings = solver.options.settings()
    if runs[0].law is not None:
        return _law_cor(runs, settings.modes, settings.tolerance)
    data = []
    for run in runs:
        modes = run.structure.modes(settings.modes)
        g = _field(run.structure, run.positions)
        rigid = (np.asarray(g @ modes.rigid) ** 2).sum(axis=1)
        data.append((modes.omega, np.asarray(g @ modes.shapes), rigid, run.speeds, run))
    cor = [np.empty(0)] * len(data)
    counts = np.array([d[0].size for d in data])
    for m in np.unique(counts):
        group = [data[i] for i in np.flatnonzero(counts == m)]
        n = [d[3].size for d in group]
        batch = modal_impacts(
            np.concatenate([np.broadcast_to(d[0], (k, m)) for d, k in zip(group, n, strict=True)]),
            np.concatenate([d[1] for d in group]),
            np.concatenate([d[2] for d in group]),
            speed=np.concatenate([d[3] for d in group]),
            kcb=np.concatenate([d[4].kcb for d in group]),
            zeta=np.concatenate([np.full(k, d[4].zeta) for d, k in zip(group, n, strict=True)]),
            ball_mass=np.concatenate(
                [np.full(k, d[4].ball.mass) for d, k in zip(group, n, strict=True)]
            ),
            options=EngineOptions(tolerance=settings.tolerance),
        )
        parts = np.split(batch.cor, np.cumsum(n)[:-1])
        for i, part in zip(np.flatnonzero(counts == m), parts, strict=True):
            cor[i] = part
    return np.concatenate(cor)


def _law_cor(runs: list[DesignCases], modes: int | None, tolerance: float | None) -> np.ndarray:
    """e_A of every run's cases under its law: one call of the general integrator."""
    rec = stack_receptances(
        [receptance(run.structure, run.positions, run.ball.mass, modes) for run in runs]
    )
    law = stack_laws([run.law for run in runs], [len(run) for run in runs])
    speed = np.concatenate([run.speeds for run in runs])
    out = solve_general(law, rec, speed, tolerance=tolerance)
    return -out.ball_velocity / speed


def grip_shock(
    solver: Solver, runs: Sequence[DesignCases], *, peak: bool = True
) -> tuple[np.ndarray, np.ndarray | None]:
    """Vibration RMS and peak of the grip force [N] over each problem's shock window, the
    racket held in a hand (:mod:`fem_racket.impact.held.shock`), as ``solver.solve_many``
    would give them (module docstring).

    Parameters
    ----------
    solver : Solver
    runs : sequence of DesignCases
        Hand-held rackets at rest under the paper's law.
    peak : bool
        Compute the peaks too (about half again the cost).

    Returns
    -------
    rms, peak : ndarray
        One per problem (peak None unless asked for).
    """
    tolerance = solver.options.settings().tolerance
    rms, peaks = [], []
    for run in _checked(solver, runs):
        held = run.structure
        window = held.shock_window
        contacts = held_contacts(
            held_basis(held.model.fe, held.hand),
            run.positions,
            run.speeds,
            ball_mass=run.ball.mass,
            zeta=run.zeta,
            tolerance=tolerance,
        )
        rms += [vibration_rms(c, window) for c in contacts]
        if peak:
            peaks += [grip_peak(c, window) for c in contacts]
    return np.array(rms), (np.array(peaks) if peak else None)
