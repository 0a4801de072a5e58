"""``simulate_oblique(frame, incidence=..., speed=..., clamped=...)``: an oblique, spinning ball on
the free racket (an :class:`~fem_racket.impact.problem.ImpactProblem` with an incidence, solved
by any solver, :func:`fem_racket.impact.oblique.solve.solve_oblique`) or on a clamped head
(eqs 1-3, :func:`fem_racket.impact.oblique.solve.clamped_normal`); and :func:`normal_impact`, the
normal impact alone, which sweeps and strokes share across spins and frictions.
"""

from __future__ import annotations

from typing import Any

from fem_racket.impact.incidence import Incidence
from fem_racket.impact.incidence_idle import refuse_idle_incidence
from fem_racket.impact.oblique.solve import (
    NormalImpact,
    ObliqueResult,
    clamped_normal,
    free_normal,
    held_normal,
    oblique_on,
)
from fem_racket.impact.problem import ImpactProblem
from fem_racket.impact.settings import SolverOptions
from fem_racket.impact.simulate import simulate
from fem_racket.impact.solvers import make_solver
from fem_racket.validation import InputError, check_positive

__all__ = ["normal_impact", "simulate_oblique"]


def simulate_oblique(
    frame: Any = None,
    *,
    incidence: Incidence,
    speed: float = 20.0,
    clamped: bool = False,
    **kwargs: Any,
) -> ObliqueResult:
    """Simulate an oblique, spinning ball striking the free racket or a clamped head.

    Parameters
    ----------
    frame : Frame, FrameMesh or FrameModel, optional
        The racket (as :func:`fem_racket.impact.simulate.simulate`); not with ``clamped``.
    incidence : Incidence
        Angle from the face normal, spin, friction, ball inertia and radius, eta^2.
    speed : float
        Incident ball speed V [m/s]; the normal impact runs at V cos(angle).
    clamped : bool
        A rigid, immovable head (eqs 1-3): takes only ``ball_mass``, ``kcb``, ``zeta`` and
        ``separation``.
    **kwargs
        The other options of :func:`~fem_racket.impact.simulate.simulate` (``output_step``, 1e-5
        s by default, must not be None: the tangential contact needs the normal force history).

    Returns
    -------
    ObliqueResult
    """
    if not isinstance(incidence, Incidence):
        raise InputError(f"incidence = {incidence!r} is not allowed: must be an Incidence")
    refuse_idle_incidence(incidence)
    v = check_positive("speed", speed, "m/s")
    if clamped:
        return oblique_on(clamped_normal(frame, incidence.components(v)[0], kwargs), incidence, v)
    return simulate(frame, speed=v, incidence=incidence, **kwargs)


def normal_impact(
    frame: Any = None, normal_speed: float = 20.0, *, clamped: bool = False, **kwargs: Any
) -> NormalImpact:
    """The normal impact at ``normal_speed`` [m/s] with its force history: the free or
    hand-held racket by :func:`~fem_racket.impact.simulate.simulate`'s problem and solver
    (``kwargs``), or a clamped head by eqs 1-3 (``kwargs``: only ``ball_mass``, ``kcb``,
    ``zeta``, ``separation``)."""
    if clamped:
        return clamped_normal(frame, normal_speed, kwargs)
    if kwargs.get("hand") is None:
        return free_normal(simulate(frame, speed=normal_speed, **kwargs))
    given = {k: kwargs.pop(k) for k in SolverOptions.names() if k in kwargs}
    solver = make_solver(kwargs.pop("solver", "auto"), **given)
    problem = ImpactProblem.build(frame, speed=normal_speed, **kwargs)
    return held_normal(solver.solve(problem), problem)
