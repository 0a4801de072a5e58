"""Ball striking the free frame: ``simulate(...) -> ImpactResult``.

The ball (point mass m_B, speed V_B0 towards the stationary frame) meets the frame at x_i through
the linear compound ball/string spring-dashpot; the coupled system (:mod:`.system`)
is integrated until separation. The coefficient of restitution is COR = -v_B(t_c) / V_B0, the
ratio of rebound to incident speed on a free racket (Kawazoe & Kanda 1997, section 3.2).
"""

from __future__ import annotations

from dataclasses import replace
from typing import Any

from fem_racket.contact.law import ContactLaw
from fem_racket.contact.linear import Ball, LinearContact
from fem_racket.contact.presets import get_law
from fem_racket.contact.spring_dashpot import SpringDashpot
from fem_racket.frame.mesh import FrameMesh
from fem_racket.frame.model import DEFAULT_MODES, FrameModel
from fem_racket.frame.segments import Frame
from fem_racket.impact.integrators import SOLVERS, check_solver_settings, get_solver
from fem_racket.impact.law_impact import LAW_SOLVERS, solve_law_impact
from fem_racket.impact.model_cache import frame_model
from fem_racket.impact.reduction import DEFAULT_TOLERANCE, check_tolerance
from fem_racket.impact.result import ImpactResult
from fem_racket.impact.setup import Impact
from fem_racket.impact.single import engine_impact
from fem_racket.impact.swing import (
    Swing,
    add_swing,
    closing_speed,
    swing_setup,
)
from fem_racket.impact.system import SEPARATION_EVENTS, CoupledSystem, modal_system, physical_system
from fem_racket.validation import InputError, check_choice, check_integer, check_positive, show

__all__ = ["BASES", "ImpactResult", "build_system", "simulate"]

BASES = ("modal", "physical")
#: Rigid-body modes of the free frame (translation, rotation) in the modal basis.
RIGID_MODES = 2
#: Largest number of output times a simulation may be asked for.
MAX_OUTPUT_TIMES = 1e6


def _simulate_law(
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
    )
    shapes = model.modes(None).all_shapes
    return ImpactResult(
        model=model,
        impact=impact,
        ball=ball,
        contact=contact,
        solver=solver,
        separation=law.end,
        basis="modal",
        n_modes=shapes.shape[1] - RIGID_MODES,
        t=run.t,
        ball_displacement=run.ball_displacement,
        ball_velocity=run.ball_velocity,
        frame_displacement=run.modal_displacement @ shapes.T,
        frame_velocity=run.modal_velocity @ shapes.T,
        peak_force=run.peak_force,
        law=law if contact is None else None,
        law_state=run.state if contact is None else None,
    )


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


def simulate(
    frame: Frame | FrameMesh | FrameModel | None = None,
    *,
    position: float = 0.75,
    speed: float = 20.0,
    ball_mass: float | None = None,
    kcb: float | None = None,
    zeta: float | None = None,
    elements: int = 20,
    solver: str = "exact",
    separation: str = "displacement",
    basis: str = "modal",
    modes: int | None = DEFAULT_MODES,
    output_step: float | None = 1e-5,
    t_max: float | None = None,
    rtol: float = 1e-10,
    atol: float = 1e-12,
    law: ContactLaw | str | None = None,
    frame_velocity: Any = None,
    tolerance: float | None = DEFAULT_TOLERANCE,
    swing: Swing | None = None,
) -> ImpactResult:
    """Simulate a ball striking the free frame, at rest or swinging (``swing``, or any initial
    motion ``frame_velocity``).

    Parameters
    ----------
    frame : Frame, FrameMesh or FrameModel, optional
        The racket; the paper's standard racket (EI1 = 146 N m^2) when None. A Frame or
        FrameMesh is assembled once per process (:mod:`.model_cache`) and its modes reused by
        the next calls; a :class:`FrameModel` keeps its own.
    position : float
        Impact point x/L from the grip end, in [0, 1].
    speed : float
        Incident ball speed V_B0 [m/s], > 0.
    ball_mass : float, optional
        m_B [kg]; 0.057 by default (the paper does not state it).
    kcb : float, optional
        K_CB [N/m]; from the speed through the paper's three points when None.
    zeta : float, optional
        Damping ratio in [0, 1); from the clamped-frame COR 0.83 (0.0592) when None.
    elements : int
        Cells when meshing a :class:`Frame`.
    solver : {"exact", "cvode", "bdf", "general"}
        Integrator (see :mod:`fem_racket.impact.integrators`); ``"general"`` is the fast
        integrator for any contact law (:mod:`fem_racket.impact.general`). With a contact law
        other than the paper's only ``"general"`` (chosen when ``solver`` is ``"exact"``) and
        ``"cvode"`` apply.
    separation : {"displacement", "force"}
        End of contact: delta back to 0 (the paper's) or contact force back to 0.
    basis : {"modal", "physical"}
        Frame coordinates: free-free modes (truncated to ``modes``) or all FE DOFs (BDF only).
    modes : int or None
        Flexible modes kept in the modal basis; None keeps all.
    output_step : float or None
        Spacing of the output times [s]; None keeps only t = 0 and t = t_c, and the exact
        solver then runs the batched engine (:mod:`fem_racket.impact.engine`) on the ``modes``
        modes, dropping those ``tolerance`` does not need.
    t_max : float, optional
        Give up if the ball has not separated by then [s]; 20 x the eq 11 estimate by default.
    rtol, atol : float
        Tolerances of the BDF integrators.
    law : ContactLaw or str, optional
        The ball/string law: a :class:`~fem_racket.contact.law.ContactLaw` or the name of one
        with its default or preset parameters (:data:`fem_racket.contact.presets.LAW_NAMES`);
        None or ``"linear"``: the paper's spring-dashpot from ``kcb`` and ``zeta``. Under any
        other law (or ``solver="general"``, or a moving racket) every frame mode is available:
        ``"general"`` keeps those the engine's rule keeps for the default COR tolerance (with the
        law's contact frequency, :func:`fem_racket.impact.general.settings`) plus a residual
        pseudo-mode,
        ``"cvode"`` all of them, so ``basis`` and ``modes`` do not apply; the law's own end
        condition replaces ``separation`` (which still applies to the linear law).
    frame_velocity : (v, omega) or array, optional
        Initial racket motion: its centre of gravity moving at v [m/s] along the ball's travel
        and turning at omega [rad/s] about it (positive turns the tip along the ball's travel),
        or initial velocities of the free-free modes [sqrt(kg) m/s], 2 rigid (translation,
        rotation about the CG) then every flexible mode of the model. A moving racket is
        integrated by the general integrator (or CVODE); ``speed`` stays the ball's speed (and
        sets the paper's K_CB unless ``kcb`` is given: pass the K_CB of the relative speed).
    tolerance : float or None
        COR tolerance of the engine (output_step None, solver "exact"; default 1e-6): the
        modes far above the contact frequency are replaced by one residual pseudo-mode, and the
        frame state at t_c treats them quasi-statically. None or 0: every mode of ``modes``.
    swing : Swing, optional
        The racket's rigid motion before impact (:mod:`fem_racket.impact.swing`); at rest when
        None. K_CB then follows the closing speed ``speed + v_r``; the exact solver superposes
        the swing on the stationary impact, the BDF solvers start from its velocity field.

    Returns
    -------
    ImpactResult
    """
    impact = Impact(position, speed)
    ball = Ball() if ball_mass is None else Ball(ball_mass)
    contact = LinearContact.for_speed(impact.speed, kcb=kcb, zeta=zeta)
    check_choice("solver", solver, (*SOLVERS, *LAW_SOLVERS))
    law = get_law(law) if isinstance(law, str) else law
    if law is not None or solver == "general" or frame_velocity is not None:
        # any contact law, or a racket moving as given: the general integrator (or CVODE)
        if law is None:
            law = SpringDashpot(contact.stiffness, contact.damping(ball.mass), separation)
            contact_used: LinearContact | None = contact
        else:
            contact_used = None
        if solver == "exact":
            solver = "general"
        if solver not in LAW_SOLVERS:
            raise InputError(
                f"solver = {show(solver)} is not allowed with contact law {show(law.name)} or a "
                f"moving racket: must be one of {LAW_SOLVERS}"
            )
        if t_max is not None:
            check_positive("t_max", t_max, "s")
        model = frame_model(frame, elements)
        if swing is not None:  # the swing as the general integrator's moving racket
            if frame_velocity is not None:
                raise InputError("swing and frame_velocity cannot be combined: give one")
            v_r = float(swing.speed_at(impact.position * model.mesh.length))
            if contact_used is not None:  # the paper's K_CB at the closing speed
                closing = closing_speed(impact.speed, v_r)
                contact_used = LinearContact.for_speed(closing, kcb=kcb, zeta=zeta)
                law = SpringDashpot(
                    contact_used.stiffness, contact_used.damping(ball.mass), separation
                )
            frame_velocity = swing.cg_motion(model.props.cg)
        if solver == "cvode":  # the general integrator has no tolerances
            check_solver_settings(solver, "modal", model.mesh.n_elements, rtol, atol)
        result = _simulate_law(
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
    check_choice("separation", separation, SEPARATION_EVENTS)
    check_choice("basis", basis, BASES)
    if output_step is not None:
        check_positive("output_step", output_step, "s")
    if t_max is not None:
        check_positive("t_max", t_max, "s")
    check_positive("rtol", rtol)
    check_positive("atol", atol)
    if modes is not None:
        check_integer("modes", modes)
    if solver == "exact" and basis != "modal":
        raise InputError(
            f"basis = {show(basis)} is not allowed with solver 'exact': must be 'modal'"
        )
    tolerance = check_tolerance(tolerance)
    model = frame_model(frame, elements)
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
    n_modes = (system.size - 1 - RIGID_MODES) if basis == "modal" else None
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
    )
