"""An impact under the paper's linear law on a racket at rest or swinging: ``simulate_linear``.

The exact solver without output times runs the batched engine
(:mod:`fem_racket.impact.exact.engine`,
through :func:`fem_racket.impact.exact.single.engine_impact`) at the closing speed and superposes
the
swing; otherwise the coupled ball + frame ODE (:func:`build_system`,
:mod:`fem_racket.impact.system`) in modal or
physical coordinates goes to the solver (:mod:`fem_racket.impact.ode.integrators`), a swing
entering as its initial
velocity field. The arguments are checked by :func:`fem_racket.impact.simulate.simulate`, which
calls this.
"""

from __future__ import annotations

from dataclasses import replace

from fem_racket.contact.linear import Ball, LinearContact
from fem_racket.frame.mesh import FrameMesh
from fem_racket.frame.model import DEFAULT_MODES, FrameModel
from fem_racket.frame.segments import Frame
from fem_racket.impact.exact.single import engine_impact
from fem_racket.impact.model_cache import frame_model
from fem_racket.impact.ode.integrators import check_solver_settings, get_solver
from fem_racket.impact.offaxis import (
    RIGID_OFFAXIS,
    check_offsets,
    combined_modes,
    combined_point_vector,
)
from fem_racket.impact.problem import Impact
from fem_racket.impact.result import ImpactResult
from fem_racket.impact.swing import Swing, add_swing, closing_speed, swing_setup
from fem_racket.impact.system import CoupledSystem, modal_system, physical_system
from fem_racket.validation import InputError, check_choice, show

__all__ = ["BASES", "build_system", "simulate_linear"]

BASES = ("modal", "physical")
#: Rigid-body modes of the free frame (translation, rotation) in the modal basis.
RIGID_MODES = 2
#: Largest number of output times a simulation may be asked for.
MAX_OUTPUT_TIMES = 1e6


def build_system(
    model: FrameModel,
    impact: Impact,
    ball: Ball,
    contact: LinearContact,
    *,
    basis: str = "modal",
    modes: int | None = DEFAULT_MODES,
) -> CoupledSystem:
    """The coupled ball + frame ODE for one impact."""
    check_choice("basis", basis, BASES)
    fe = model.fe
    g = fe.point_vector(impact.position * fe.mesh.length)
    ccb = contact.damping(ball.mass)
    if impact.offset != 0.0:  # bending and torsion (fem_racket.impact.offaxis)
        if basis != "modal":
            raise InputError(
                f"basis = {show(basis)} is not allowed with offset = {impact.offset!r} m: "
                "must be 'modal'"
            )
        cm = combined_modes(model, modes)
        g = combined_point_vector(model, impact.position * fe.mesh.length, impact.offset)
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
    output_step: float, t_max: float | None, t_est: float, kcb: float | None, ball_mass: float
) -> None:
    """Refuse more than MAX_OUTPUT_TIMES output times, naming what makes them so many: the
    user's t_max, else the contact itself (its eq 11 duration from K_CB and m_B)."""
    span = 2.0 * t_est if t_max is None else t_max
    if span / output_step <= MAX_OUTPUT_TIMES:
        return
    limit = f"at most {MAX_OUTPUT_TIMES:.0e} output times of output_step = {output_step!r} s"
    if t_max is not None:
        raise InputError(
            f"t_max = {show(t_max)} s is not allowed: {limit}, so t_max <= "
            f"{MAX_OUTPUT_TIMES * output_step:.3g} s (or a larger output_step)"
        )
    what = f"kcb = {kcb!r} N/m" if kcb is not None else f"ball_mass = {ball_mass!r} kg"
    raise InputError(
        f"{what} is not allowed with {limit}: the contact would last about {t_est:.3g} s "
        "(eq 11, pi sqrt(m_B / K_CB)); give a larger output_step or none"
    )


def simulate_linear(
    frame: Frame | FrameMesh | FrameModel | None,
    elements: int,
    impact: Impact,
    ball: Ball,
    *,
    kcb: float | None,
    zeta: float | None,
    solver: str,
    separation: str,
    basis: str,
    modes: int | None,
    output_step: float | None,
    t_max: float | None,
    rtol: float,
    atol: float,
    tolerance: float | None,
    swing: Swing | None,
) -> ImpactResult:
    """An impact under the paper's linear law (K_CB from ``kcb`` or the closing speed, ``zeta``)
    by ``solver``; the arguments as :func:`fem_racket.impact.simulate.simulate`'s, checked."""
    model = frame_model(frame, elements)
    check_offsets(model, impact.position, impact.offset)
    check_solver_settings(solver, basis, model.mesh.n_elements, rtol, atol)
    x_i = impact.position * model.mesh.length
    v_r = 0.0 if swing is None else float(swing.speed_at(x_i))
    closing = closing_speed(impact.speed, v_r)
    contact = LinearContact.for_speed(closing, kcb=kcb, zeta=zeta)
    if solver == "exact" and output_step is None:
        traj, frame_map, kept = engine_impact(
            model,
            impact if swing is None else replace(impact, speed=closing),
            ball,
            contact,
            separation=separation,
            modes=modes,
            tolerance=tolerance,
            t_max=t_max,
        )
        if swing is not None:  # the stationary impact at the closing speed, plus the swing
            traj = add_swing(traj, frame_map, model, swing, v_r)
        return _result(
            model, impact, ball, contact, solver, separation, basis, kept, traj, frame_map,
            swing=swing, tolerance=tolerance,
        )  # fmt: skip
    system = build_system(model, impact, ball, contact, basis=basis, modes=modes)
    to_lab = None
    if swing is not None:
        system, to_lab = swing_setup(system, model, swing, x_i, direct=solver != "exact")
    if output_step is not None:
        _check_output_count(output_step, t_max, system.contact_time_estimate(), kcb, ball.mass)
    traj = get_solver(solver)(
        system, separation=separation, output_step=output_step, t_max=t_max, rtol=rtol, atol=atol
    )
    if to_lab is not None:
        traj = to_lab(traj)
    n_rigid = RIGID_MODES if impact.offset == 0.0 else RIGID_OFFAXIS
    n_modes = (system.size - 1 - n_rigid) if basis == "modal" else None
    return _result(
        model, impact, ball, contact, solver, separation, basis, n_modes, traj, system.frame_map,
        swing=swing, rtol=rtol, atol=atol,
    )  # fmt: skip


def _result(
    model, impact, ball, contact, solver, separation, basis, n_modes, traj, frame_map,
    *, swing=None, rtol=None, atol=None, tolerance=None,
):  # fmt: skip
    """The :class:`ImpactResult` of a linear-law run from its trajectory in the solver's
    coordinates (``frame_map`` takes them to the frame's Hermite DOFs, None: they are those)."""
    if frame_map is None:
        q, qd = traj.x[:, 1:], traj.v[:, 1:]
    else:
        q, qd = traj.x[:, 1:] @ frame_map.T, traj.v[:, 1:] @ frame_map.T
    nb = model.fe.ndof
    twist = {} if impact.offset == 0.0 else {"twist": q[:, nb:], "twist_rate": qd[:, nb:]}
    q, qd = q[:, :nb], qd[:, :nb]
    return ImpactResult(
        model=model,
        impact=impact,
        ball=ball,
        contact=contact,
        solver=solver,
        separation=separation,
        basis=basis,
        n_modes=n_modes,
        t=traj.t,
        ball_displacement=traj.x[:, 0],
        ball_velocity=traj.v[:, 0],
        frame_displacement=q,
        frame_velocity=qd,
        peak_force=traj.peak_force,
        rtol=None if solver == "exact" else rtol,
        atol=None if solver == "exact" else atol,
        tolerance=tolerance,
        swing=swing,
        **twist,
    )
