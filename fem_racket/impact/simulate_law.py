"""An impact under any contact law, or on a racket moving as given: ``simulate_law``.

The general integrator (:mod:`fem_racket.impact.general.integrator`) or CVODE runs the ball and
every frame
mode (:func:`fem_racket.impact.law_impact.solve_law_impact`); a swing
(:mod:`fem_racket.impact.swing`) enters as the racket's initial motion about its centre of gravity,
and the paper's linear law then takes K_CB at the closing speed. The arguments are checked by
:func:`fem_racket.impact.simulate.simulate`, which calls this.
"""

from __future__ import annotations

from dataclasses import replace
from typing import Any

from fem_racket.contact.law import ContactLaw
from fem_racket.contact.linear import Ball, LinearContact
from fem_racket.contact.spring_dashpot import SpringDashpot
from fem_racket.frame.mesh import FrameMesh
from fem_racket.frame.model import FrameModel
from fem_racket.frame.segments import Frame
from fem_racket.impact.law_impact import solve_law_impact
from fem_racket.impact.model_cache import frame_model
from fem_racket.impact.ode.integrators import check_solver_settings
from fem_racket.impact.offaxis import RIGID_OFFAXIS, check_offsets, combined_modes
from fem_racket.impact.problem import Impact
from fem_racket.impact.result import ImpactResult
from fem_racket.impact.simulate_linear import RIGID_MODES
from fem_racket.impact.swing import Swing, closing_speed
from fem_racket.validation import InputError, check_positive

__all__ = ["simulate_law"]


def simulate_law(
    frame: Frame | FrameMesh | FrameModel | None,
    elements: int,
    impact: Impact,
    ball: Ball,
    contact_used: LinearContact | None,
    law: ContactLaw,
    *,
    solver: str,
    separation: str,
    kcb: float | None,
    zeta: float | None,
    frame_velocity: Any,
    swing: Swing | None,
    output_step: float | None,
    t_max: float | None,
    rtol: float,
    atol: float,
) -> ImpactResult:
    """An impact under ``law`` (``contact_used``: the paper's linear law it stands for, or None)
    by ``solver`` ("general" or "cvode"); the other arguments as
    :func:`fem_racket.impact.simulate.simulate`'s."""
    model = frame_model(frame, elements)
    check_offsets(model, impact.position, impact.offset)
    if swing is not None:  # the swing as the general integrator's moving racket
        if frame_velocity is not None:
            raise InputError("swing and frame_velocity cannot be combined: give one")
        v_r = float(swing.speed_at(impact.position * model.mesh.length))
        if contact_used is not None:  # the paper's K_CB at the closing speed
            closing = closing_speed(impact.speed, v_r)
            contact_used = LinearContact.for_speed(closing, kcb=kcb, zeta=zeta)
            law = SpringDashpot(contact_used.stiffness, contact_used.damping(ball.mass), separation)
        frame_velocity = swing.cg_motion(model.props.cg)
    if solver == "cvode":  # the general integrator has no tolerances
        check_solver_settings(solver, "modal", model.mesh.n_elements, rtol, atol)
    result = _law_result(
        model,
        impact,
        ball,
        contact_used,
        law,
        solver,
        frame_velocity,
        output_step,
        t_max,
        rtol,
        atol,
    )
    return result if swing is None else replace(result, swing=swing)


def _law_result(
    model: FrameModel,
    impact: Impact,
    ball: Ball,
    contact: LinearContact | None,
    law: ContactLaw,
    solver: str,
    frame_velocity: Any,
    output_step: float | None,
    t_max: float | None,
    rtol: float,
    atol: float,
) -> ImpactResult:
    """An impact under ``law`` by the general integrator or CVODE (all frame modes)."""
    if output_step is not None:
        check_positive("output_step", output_step, "s")
    run = solve_law_impact(
        law,
        model,
        impact.position,
        ball.mass,
        impact.speed,
        solver=solver,
        frame_velocity=frame_velocity,
        output_step=output_step,
        t_max=t_max,
        rtol=rtol,
        atol=atol,
        offset=impact.offset,
    )
    n_rigid, shapes = RIGID_MODES, model.modes(None).all_shapes
    if impact.offset != 0.0:
        n_rigid, shapes = RIGID_OFFAXIS, combined_modes(model, None).all_shapes
    q, qd = run.modal_displacement @ shapes.T, run.modal_velocity @ shapes.T
    nb = model.fe.ndof
    twist = {} if impact.offset == 0.0 else {"twist": q[:, nb:], "twist_rate": qd[:, nb:]}
    return ImpactResult(
        model=model,
        impact=impact,
        ball=ball,
        contact=contact,
        solver=solver,
        separation=law.end,
        basis="modal",
        n_modes=shapes.shape[1] - n_rigid,
        t=run.t,
        ball_displacement=run.ball_displacement,
        ball_velocity=run.ball_velocity,
        frame_displacement=q[:, :nb],
        frame_velocity=qd[:, :nb],
        peak_force=run.peak_force,
        law=law if contact is None else None,
        law_state=run.state if contact is None else None,
        **twist,
    )
