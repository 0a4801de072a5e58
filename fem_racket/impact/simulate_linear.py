"""An impact under the paper's linear law on a racket at rest or swinging: ``simulate_linear``.

The exact solver without output times, or with a COR tolerance, runs the batched engine
(:mod:`fem_racket.impact.exact`, through :func:`fem_racket.impact.exact.single.engine_impact`)
at the closing speed and superposes the swing; with output times and no tolerance (every mode)
its eigen-solution (:mod:`fem_racket.impact.exact.closed_form`); otherwise the coupled
ball + frame ODE (:func:`build_system`, :mod:`fem_racket.impact.system`) in modal or physical
coordinates goes to the solver (:mod:`fem_racket.impact.ode.integrators`), a swing entering
as its initial velocity field. The solvers of :mod:`fem_racket.impact.solvers` check the
problem and the options and call this.
"""

from __future__ import annotations

from dataclasses import dataclass, replace
from typing import Any

from fem_racket.contact.linear import Ball, LinearContact
from fem_racket.frame.model import DEFAULT_MODES, FrameModel
from fem_racket.impact.exact.single import engine_impact
from fem_racket.impact.ode.integrators import check_solver_settings, get_solver
from fem_racket.impact.offaxis import RIGID_OFFAXIS, combined_modes, combined_point_vector
from fem_racket.impact.problem import Impact, ImpactProblem
from fem_racket.impact.result import ImpactResult
from fem_racket.impact.settings import BASES, Settings
from fem_racket.impact.swing import add_swing, swing_setup
from fem_racket.impact.system import (
    MAX_OUTPUT_TIMES,
    CoupledSystem,
    Integration,
    check_output_count,
    modal_system,
    physical_system,
)
from fem_racket.validation import InputError, check_choice, show

__all__ = ["BASES", "build_system", "simulate_linear"]

#: Rigid-body modes of the free frame (translation, rotation) in the modal basis.
RIGID_MODES = 2


def build_system(
    model: FrameModel,
    impact: Impact,
    ball: Ball,
    contact: LinearContact,
    *,
    basis: str = "modal",
    modes: int | None = DEFAULT_MODES,
    offset: float = 0.0,
) -> CoupledSystem:
    """The coupled ball + frame ODE for one impact (``offset`` [m] off the long axis: bending
    and torsion modes, :mod:`fem_racket.impact.offaxis`)."""
    check_choice("basis", basis, BASES)
    fe = model.fe
    g = fe.point_vector(impact.position * fe.mesh.length)
    ccb = contact.damping(ball.mass)
    if offset != 0.0:
        if basis != "modal":
            raise InputError(
                f"basis = {show(basis)} is not allowed with offset = {show(offset)} m: "
                "must be 'modal'"
            )
        cm = combined_modes(model, modes)
        g = combined_point_vector(model, impact.position * fe.mesh.length, offset)
        return modal_system(
            cm.all_omega, cm.all_shapes, g, ball.mass, contact.stiffness, ccb, impact.speed
        )
    if basis == "modal":
        fm = model.modes(modes)
        return modal_system(
            fm.all_omega, fm.all_shapes, g, ball.mass, contact.stiffness, ccb, impact.speed
        )
    props = model.props
    d = impact.position * fe.mesh.length - props.cg
    rc = 1.0 / props.mass + d * d / props.inertia
    return physical_system(fe.K, fe.M, g, ball.mass, contact.stiffness, ccb, impact.speed, rc)


def _check_output_count(
    output_step: float, t_est: float, kcb: float | None, ball_mass: float
) -> None:
    """Refuse more than MAX_OUTPUT_TIMES output times over twice the contact's eq 11 duration
    ``t_est`` [s] (from K_CB and m_B), naming what makes them so many: a kcb given, else the
    output step."""
    span = 2.0 * t_est
    if span / output_step <= MAX_OUTPUT_TIMES:
        return
    limit = f"at most {MAX_OUTPUT_TIMES:.0e} output times of output_step = {show(output_step)} s"
    if kcb is not None:
        raise InputError(
            f"kcb = {show(kcb)} N/m is not allowed with {limit}: the contact would last about "
            f"{t_est:.3g} s (eq 11, pi sqrt(m_B / K_CB)); give a larger output_step or none",
            parameter="kcb",
            value=kcb,
        )
    what = (
        f"twice the contact's {t_est:.3g} s (eq 11, pi sqrt(m_B / K_CB), "
        f"m_B = {show(ball_mass)} kg)"
    )
    check_output_count(output_step, span, what)


def simulate_linear(problem: ImpactProblem, solver: str, settings: Settings) -> ImpactResult:
    """An impact of ``problem`` (the paper's linear law on a free racket, at rest or swinging)
    by ``solver`` ("exact", "cvode" or "bdf") with ``settings``, checked by the solver."""
    model = problem.model
    impact, ball, swing = problem.impact, problem.ball, problem.swing
    separation = problem.separation or "displacement"
    s = settings
    check_solver_settings(solver, s.basis, model.mesh.n_elements, s.rtol, s.atol)
    x_i = impact.position * model.mesh.length
    v_r = problem.racket_speed
    contact = problem.contact()
    if solver == "exact" and (s.output_step is None or s.tolerance is not None):
        traj, frame_map, kept = engine_impact(
            model,
            impact if swing is None else replace(impact, speed=problem.closing_speed),
            ball,
            contact,
            separation=separation,
            modes=s.modes,
            tolerance=s.tolerance,
            t_max=s.t_max,
            offset=problem.offset,
            output_step=s.output_step,
        )
        if swing is not None:  # the stationary impact at the closing speed, plus the swing
            traj = add_swing(traj, frame_map, model, swing, v_r)
        run = _Run(solver, separation, s.basis, kept, traj, frame_map)
        return _result(problem, contact, run, tolerance=s.tolerance)
    system = build_system(
        model, impact, ball, contact, basis=s.basis, modes=s.modes, offset=problem.offset
    )
    to_lab = None
    if swing is not None:
        system, to_lab = swing_setup(system, model, swing, x_i, direct=solver != "exact")
    if s.output_step is not None and s.t_max is None:  # a t_max given: the solver has checked
        # t_max / output_step <= MAX_OUTPUT_TIMES (fem_racket.impact.settings.check_time_limit)
        _check_output_count(s.output_step, system.contact_time_estimate(), problem.kcb, ball.mass)
    how = Integration(separation, s.output_step, s.t_max, s.rtol, s.atol)
    traj = get_solver(solver)(system, how)
    if to_lab is not None:
        traj = to_lab(traj)
    n_rigid = RIGID_MODES if problem.offset == 0.0 else RIGID_OFFAXIS
    n_modes = (system.size - 1 - n_rigid) if s.basis == "modal" else None
    run = _Run(solver, separation, s.basis, n_modes, traj, system.frame_map)
    tols = {} if solver == "exact" else {"rtol": s.rtol, "atol": s.atol}
    return _result(problem, contact, run, **tols)


@dataclass(frozen=True)
class _Run:
    """How a linear-law run went: the solver, its trajectory in the solver's coordinates and the
    map taking them to the frame's Hermite DOFs (None: they are those)."""

    solver: str
    separation: str
    basis: str
    n_modes: int | None
    traj: Any
    frame_map: Any


def _result(
    problem: ImpactProblem,
    contact: LinearContact,
    run: _Run,
    *,
    rtol: float | None = None,
    atol: float | None = None,
    tolerance: float | None = None,
) -> ImpactResult:
    """The :class:`ImpactResult` of a linear-law ``run`` of ``problem``."""
    traj, frame_map = run.traj, run.frame_map
    if frame_map is None:
        q, qd = traj.x[:, 1:], traj.v[:, 1:]
    else:
        q, qd = traj.x[:, 1:] @ frame_map.T, traj.v[:, 1:] @ frame_map.T
    nb = problem.model.fe.ndof  # off axis the torsion DOFs follow the Hermite ones
    twist = {}
    if problem.offset != 0.0:
        twist = {"offset": problem.offset, "twist": q[:, nb:], "twist_rate": qd[:, nb:]}
    q, qd = q[:, :nb], qd[:, :nb]
    return ImpactResult(
        model=problem.model,
        impact=problem.impact,
        ball=problem.ball,
        contact=contact,
        solver=run.solver,
        separation=run.separation,
        basis=run.basis,
        n_modes=run.n_modes,
        t=traj.t,
        ball_displacement=traj.x[:, 0],
        ball_velocity=traj.v[:, 0],
        frame_displacement=q,
        frame_velocity=qd,
        peak_force=traj.peak_force,
        rtol=rtol,
        atol=atol,
        tolerance=tolerance,
        swing=problem.swing,
        **twist,
    )
