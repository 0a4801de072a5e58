"""A ball striking a hand-held racket: the frame with a hand on its grip, and the grip force.

The held structure (:mod:`fem_racket.frame.hand`: frame DOFs plus the hand's translation and
rotation, the grip layer's stiffness in K and damping in C) meets the ball through the paper's
linear spring-dashpot. The grip's damping is not modal, so the exact solver does not apply: the
full system in physical coordinates goes to the BDF integrators (CVODE, or scipy's BDF) with the
grip damping added to the state matrix.

The grip force on the hand is ``F_h(t) = int_a^b (k' s + c' s') dx`` (s the layer's stretch),
which is also m_h u_h'' (nothing else acts on the hand). Its *rigid part* is the force that
would carry the hand along with a rigid racket + hand pushed by the contact force F(t):
``m_h F (1/M_t + (x_i - x_G)(x_h - x_G)/I_t)`` (M_t, x_G, I_t of frame + hand); the rest is the
*vibration part*: what the frame's bending and the hand's own motion on the grip layer add.

All three forces are linear in the state, so their extrema are root-found by the integrator on
its dense solution, as the free racket's peak force is (:class:`~fem_racket.impact.ode.
integrators.Watched`): the peaks do not depend on the output times.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np

from fem_racket.frame.hand import HeldFrame, held_frame
from fem_racket.frame.model import FrameModel
from fem_racket.impact.held.flow import flow_energy
from fem_racket.impact.ode.integrators import INTEGRATORS, Watched
from fem_racket.impact.problem import HeldRacket, ImpactProblem
from fem_racket.impact.system import CoupledSystem, Integration, physical_system
from fem_racket.validation import InputError, check_choice, show

__all__ = ["HeldImpact", "simulate_held"]

#: Integrators that take the grip's (non-modal) damping.
HELD_SOLVERS = ("cvode", "bdf")


@dataclass(frozen=True, eq=False)
class _HeldSystem(CoupledSystem):
    """A physical-coordinate system with the grip layer's damping C [N s/m] (frame + hand)."""

    grip_damping: np.ndarray | None = None

    @cached_property
    def state_matrix(self) -> np.ndarray:  # type: ignore[override]
        """y' = A y with the ball/string dashpot and the grip damping."""
        A = super().state_matrix.copy()
        n = self.size
        c = np.zeros((n, n))
        c[1:, 1:] = self.grip_damping
        A[n:, n:] -= np.linalg.solve(self.mass.toarray(), c)
        return A


@dataclass(frozen=True, eq=False)
class HeldImpact:
    """Outcome and histories of an impact on a hand-held racket.

    Attributes
    ----------
    t : ndarray
        Output times [s]; the last is the contact time.
    ball_velocity, hand_velocity : ndarray
        v_B and the hand's u_h' [m/s] (positive along the ball's travel).
    contact_force, grip_force, grip_force_rigid : ndarray
        Contact force F [N], force of the grip on the hand F_h [N] (positive along the ball's
        travel) and its rigid part [N] (module docstring).
    peak_force, peak_grip_force, peak_grip_vibration : float
        Largest F, |F_h| and |F_h - rigid part| during contact [N], root-found between the
        output times (module docstring).
    grip_vibration_energy : float
        int_0^t_c (F_h - rigid part)^2 dt [N^2 s] from the integrator's states, exact between
        them (:func:`~fem_racket.impact.held.flow.flow_energy`).
    speed : float
        Incident ball speed [m/s].
    racket_speed : float
        v_r: speed of the impact point towards the ball before impact [m/s] (0 at rest).
    state : ndarray
        Frame + hand displacements then velocities at t_c (frame DOFs, u_h, theta_h).
    """

    t: np.ndarray
    ball_velocity: np.ndarray
    hand_velocity: np.ndarray
    contact_force: np.ndarray
    grip_force: np.ndarray
    grip_force_rigid: np.ndarray
    peak_force: float
    peak_grip_force: float
    peak_grip_vibration: float
    grip_vibration_energy: float
    speed: float
    racket_speed: float = 0.0
    state: np.ndarray | None = None

    @property
    def cor(self) -> float:
        """The apparent COR e_A = (v_out - v_r) / (v_in + v_r), v_out = -v_B(t_c) (on a racket
        at rest -v_B(t_c) / V_B0)."""
        v_r = self.racket_speed
        return (-float(self.ball_velocity[-1]) - v_r) / (self.speed + v_r)

    @property
    def contact_time(self) -> float:
        """t_c [s]."""
        return float(self.t[-1])

    @property
    def grip_vibration(self) -> np.ndarray:
        """Vibration part of the grip force [N]: F_h less its rigid part."""
        return self.grip_force - self.grip_force_rigid

    def summary(self) -> dict[str, float]:
        """JSON-ready scalars, units in the keys."""
        return {
            "cor": self.cor,
            "contact_time_s": self.contact_time,
            "peak_grip_force_n": self.peak_grip_force,
            "peak_grip_vibration_n": self.peak_grip_vibration,
        }


def _rigid_factor(model: FrameModel, held: HeldFrame, x_i: float) -> float:
    """m_h (1/M_t + (x_i - x_G)(x_h - x_G)/I_t): the rigid hand force per newton of contact."""
    p, h = model.props, held.hand
    m_t = p.mass + h.mass
    x_g = (p.mass * p.cg + h.mass * h.centre) / m_t
    i_t = p.inertia + p.mass * (p.cg - x_g) ** 2 + h.rotary_inertia + h.mass * (h.centre - x_g) ** 2
    return h.mass * (1.0 / m_t + (x_i - x_g) * (h.centre - x_g) / i_t)


def simulate_held(
    problem: ImpactProblem,
    *,
    solver: str = "cvode",
    output_step: float = 1e-5,
    rtol: float = 1e-10,
    atol: float = 1e-12,
) -> HeldImpact:
    """A ball striking the racket held in a hand, at rest or swinging, by an integrator.

    Parameters
    ----------
    problem : ImpactProblem
        Its structure a :class:`~fem_racket.impact.problem.HeldRacket` (the frame and the hand),
        the paper's linear law. A swing (:mod:`fem_racket.impact.swing`) moves racket and hand
        rigidly: the integration starts from its velocity field (the hand moving with the
        handle), the ball at the problem's speed; K_CB follows the closing speed unless given.
        The grip layer is not stretched by a rigid motion, so the grip force is that of the
        racket at rest struck at the closing speed.
    solver : {"cvode", "bdf"}
        The integrator (the exact solver needs modal damping, which the grip is not).
    output_step : float
        Spacing of the output times [s].
    rtol, atol : float
        Tolerances of the integrator.

    Returns
    -------
    HeldImpact
    """
    check_choice("solver", solver, HELD_SOLVERS)
    if not isinstance(problem.structure, HeldRacket):
        raise InputError("simulate_held takes a problem whose structure is a HeldRacket")
    model, hand = problem.model, problem.structure.hand
    ball, swing, speed = problem.ball, problem.swing, problem.impact.speed
    x_i = problem.impact.position * model.mesh.length
    v_r = problem.racket_speed
    law = problem.contact()
    if not output_step > 0.0:
        raise InputError(f"output_step = {show(output_step)} s is not allowed: must be > 0")
    import scipy.sparse as sp

    held = held_frame(model.fe, hand)
    g = np.concatenate([model.fe.point_vector(x_i), [0.0, 0.0]])
    ccb = law.damping(ball.mass)
    props = model.props
    rc = 1.0 / props.mass + (x_i - props.cg) ** 2 / props.inertia
    base = physical_system(
        sp.csr_matrix(held.K), sp.csr_matrix(held.M), g, ball.mass, law.stiffness, ccb, speed, rc
    )
    fields = {f: getattr(base, f) for f in base.__dataclass_fields__}
    if swing is not None:  # the swing's rigid field, the hand moving with the handle
        hand_speed = float(swing.speed_at(hand.centre))
        frame = model.fe.rigid_motion(-swing.velocity, -swing.omega)
        fields["frame_velocity0"] = np.concatenate([frame, [-hand_speed, -swing.omega]])
    system = _HeldSystem(**fields, grip_damping=held.C)
    # Force of the grip layer on the hand's translation: -(k' G x + c' G x')[u_h] (G symmetric).
    row = held.grip[held.n_frame]
    factor = _rigid_factor(model, held, x_i)
    rows = _force_rows(system, -hand.stiffness * row, -hand.damping * row, factor)
    run = Integration(output_step=output_step, rtol=rtol, atol=atol)
    # the contact force's maxima, the grip forces' extrema of either sign; an output identically
    # 0 (no grip layer) has none (and CVODE would warn of it)
    on = [i for i, c in enumerate(rows) if np.any(c)]
    out = INTEGRATORS[solver](system, run, Watched(rows[on], tuple((-1, 0, 0)[i] for i in on)))
    extrema = dict(zip(on, out.extrema, strict=True))
    n = system.size
    traj_x, traj_v = out.y[:, :n], out.y[:, n:]
    x, v = traj_x[:, 1:], traj_v[:, 1:]
    f_hand = -(hand.stiffness * (x @ row) + hand.damping * (v @ row))
    force = law.stiffness * (traj_x @ system.h) + ccb * (traj_v @ system.h)
    rigid = factor * force
    state = np.concatenate([x[-1], v[-1]])
    none = np.zeros((0, out.y.shape[1]))
    peaks = [np.vstack([out.y, extrema.get(i, none)]) @ c for i, c in enumerate(rows)]
    return HeldImpact(
        out.t,
        traj_v[:, 0],
        v[:, held.n_frame],
        force,
        f_hand,
        rigid,
        float(np.max(peaks[0])),
        float(np.max(np.abs(peaks[1]))),
        float(np.max(np.abs(peaks[2]))),
        flow_energy(system.state_matrix, rows[2], out.t, out.y),
        speed,
        v_r,
        state,
    )


def _force_rows(system: CoupledSystem, kx: np.ndarray, cv: np.ndarray, factor: float):
    """Rows of the contact force F, the grip force F_h and its vibration part F_h - factor F on
    the state [x, x'] (ball first); ``kx`` and ``cv`` give F_h = kx @ x_held + cv @ x_held'."""
    n = system.size
    force = system.event_vector("force")
    grip = np.zeros(2 * n)
    grip[1:n], grip[n + 1 :] = kx, cv
    return np.vstack([force, grip, grip - factor * force])
