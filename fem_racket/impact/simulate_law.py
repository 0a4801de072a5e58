"""An impact under any contact law, or on a racket moving as given: ``simulate_law``.

The general integrator (:mod:`fem_racket.impact.general`) or CVODE runs the ball and every frame
mode (:func:`fem_racket.impact.law_impact.solve_law_impact`); a swing
(:mod:`fem_racket.impact.swing`) enters as the racket's initial motion about its centre of
gravity, and the paper's linear law then takes K_CB at the closing speed. The solvers of
:mod:`fem_racket.impact.solvers` check the problem and the options and call this.
"""

from __future__ import annotations

from fem_racket.impact.law_impact import LawOptions, solve_law_impact
from fem_racket.impact.ode.integrators import check_solver_settings
from fem_racket.impact.offaxis import RIGID_OFFAXIS, combined_modes
from fem_racket.impact.problem import ImpactProblem
from fem_racket.impact.result import ImpactResult
from fem_racket.impact.settings import Settings
from fem_racket.impact.simulate_linear import RIGID_MODES
from fem_racket.impact.system import check_output_count

__all__ = ["simulate_law"]


def simulate_law(problem: ImpactProblem, solver: str, settings: Settings) -> ImpactResult:
    """An impact of ``problem`` (any contact law, a racket at rest, swinging or moving as given)
    by ``solver`` ("general" or "cvode") with ``settings``, checked by the solver. The paper's
    linear law runs at the closing speed."""
    model = problem.model
    law, contact = problem.law, None
    if law is None:  # the paper's K_CB at the closing speed
        law = contact = problem.contact()
    frame_velocity = problem.frame_velocity
    if problem.swing is not None:  # the swing as the general integrator's moving racket
        frame_velocity = problem.swing.cg_motion(model.props.cg)
    s = settings
    if solver == "cvode":  # the general integrator has no tolerances
        check_solver_settings(solver, "modal", model.mesh.n_elements, s.rtol, s.atol)
    if s.output_step is not None and s.t_max is None:  # the histories' size (a t_max given:
        # checked by the solver, fem_racket.impact.settings.check_time_limit)
        span = 2 * float(law.contact_time_estimate(problem.ball.mass, problem.closing_speed))
        check_output_count(s.output_step, span, f"twice the law's {span:.3g} s of contact")
    options = LawOptions(solver, s.output_step, s.t_max, s.rtol, s.atol, s.tolerance)
    run = solve_law_impact(
        law,
        model,
        problem.impact.position,
        problem.ball.mass,
        problem.impact.speed,
        frame_velocity=frame_velocity,
        offset=problem.offset,
        options=options,
    )
    n_rigid, shapes = RIGID_MODES, model.modes(None).all_shapes
    if problem.offset != 0.0:  # bending then torsion DOFs (fem_racket.impact.offaxis)
        n_rigid, shapes = RIGID_OFFAXIS, combined_modes(model, None).all_shapes
    q, qd = run.modal_displacement @ shapes.T, run.modal_velocity @ shapes.T
    nb = model.fe.ndof
    twist = {}
    if problem.offset != 0.0:
        twist = {"offset": problem.offset, "twist": q[:, nb:], "twist_rate": qd[:, nb:]}
    return ImpactResult(
        model=model,
        impact=problem.impact,
        ball=problem.ball,
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
        swing=problem.swing,
        rtol=s.rtol if solver == "cvode" else None,
        atol=s.atol if solver == "cvode" else None,
        tolerance=s.tolerance if solver == "general" else None,
        **twist,
    )
