"""Ball striking the free frame: ``simulate(...) -> ImpactResult``.

The ball (point mass m_B, speed V_B0 towards the stationary frame) meets the frame at x_i through
the linear compound ball/string spring-dashpot; the coupled system (:mod:`fem_racket.impact.system`)
is integrated until separation. The coefficient of restitution is COR = -v_B(t_c) / V_B0, the
ratio of rebound to incident speed on a free racket (Kawazoe & Kanda 1997, section 3.2).

``simulate`` checks its arguments and runs one of two paths: the paper's linear law on a racket
at rest or swinging (:mod:`fem_racket.impact.simulate_linear`), or any other contact law,
``solver="general"`` or a
racket moving as given (:mod:`fem_racket.impact.simulate_law`).
"""

from __future__ import annotations

from typing import Any

from fem_racket.contact.law import ContactLaw
from fem_racket.contact.linear import Ball, LinearContact
from fem_racket.contact.presets import get_law
from fem_racket.contact.spring_dashpot import SpringDashpot
from fem_racket.frame.mesh import FrameMesh
from fem_racket.frame.model import DEFAULT_MODES, FrameModel
from fem_racket.frame.segments import Frame
from fem_racket.impact.law_impact import LAW_SOLVERS
from fem_racket.impact.ode.integrators import SOLVERS
from fem_racket.impact.problem import Impact
from fem_racket.impact.reduction import DEFAULT_TOLERANCE, check_tolerance
from fem_racket.impact.result import ImpactResult
from fem_racket.impact.simulate_law import simulate_law
from fem_racket.impact.simulate_linear import BASES, simulate_linear
from fem_racket.impact.swing import Swing
from fem_racket.impact.system import SEPARATION_EVENTS
from fem_racket.validation import InputError, check_choice, check_integer, check_positive, show

__all__ = ["ImpactResult", "simulate"]


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
    offset: float = 0.0,
) -> ImpactResult:
    """Simulate a ball striking the free frame, at rest or swinging (``swing``, or any initial
    motion ``frame_velocity``).

    Parameters
    ----------
    frame : Frame, FrameMesh or FrameModel, optional
        The racket; the paper's standard racket (EI1 = 146 N m^2) when None. A Frame or
        FrameMesh is assembled once per process (:mod:`fem_racket.impact.model_cache`) and its
        modes reused by
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
        Integrator (see :mod:`fem_racket.impact.ode.integrators`); ``"general"`` is the fast
        integrator for any contact law (:mod:`fem_racket.impact.general.integrator`). With a
        contact law
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
        solver then runs the batched engine (:mod:`fem_racket.impact.exact.engine`) on the ``modes``
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
        law's contact frequency, :func:`fem_racket.impact.general.integrator.settings`) plus a
        residual
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
    offset : float
        Lateral distance of the impact point from the long axis [m], on the head outline
        (:mod:`fem_racket.impact.offaxis`); the frame then twists too (every solver, modal
        basis). 0: on the axis.

    Returns
    -------
    ImpactResult
    """
    impact = Impact(position, speed, offset)
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
        return simulate_law(
            frame,
            elements,
            impact,
            ball,
            contact_used,
            law,
            solver=solver,
            separation=separation,
            kcb=kcb,
            zeta=zeta,
            frame_velocity=frame_velocity,
            swing=swing,
            output_step=output_step,
            t_max=t_max,
            rtol=rtol,
            atol=atol,
        )
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
    return simulate_linear(
        frame,
        elements,
        impact,
        ball,
        kcb=kcb,
        zeta=zeta,
        solver=solver,
        separation=separation,
        basis=basis,
        modes=modes,
        output_step=output_step,
        t_max=t_max,
        rtol=rtol,
        atol=atol,
        tolerance=tolerance,
        swing=swing,
    )
