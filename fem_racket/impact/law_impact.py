"""One impact with any contact law: receptance, initial racket motion, histories.

Builds the impact-point :class:`~fem_racket.impact.general.receptance.Receptance` of a frame, turns
an initial racket velocity field into modal velocities, runs the general integrator (or CVODE) and
rebuilds the ball and frame histories at the output times. Every coordinate
``x = [u_B, eta_rigid, eta_flex]`` obeys ``x'' + omega^2 x = b F(t)`` (``b = [-1/m_B, a]``) with
the integrator's piecewise-cubic force (:mod:`fem_racket.impact.general.cubic_force`), so each is
propagated exactly: with y = x' + i omega x, over step k (t = t_k + h s)::

    y(t_k + h s) = e^{i theta s} (y_k + b h sum_r F_r sum_q c_rq conj(M_q(theta, s)))
    (omega = 0)  x' = x'_k + b h sum_r F_r sum_q c_rq s^{q+1}/(q+1)
                 x  = x_k + x'_k h s + b h^2 sum_r F_r sum_q c_rq s^{q+2}/((q+1)(q+2))

(theta = omega h, c_rq the step's Lagrange coefficients); the node states follow by a
cumulative sum, y_k = e^{i theta k} (y_0 + b h sum_{j<k} e^{-i theta j} g_j). The states are then
as accurate as the force (fourth order), which is what the energy balance of the tests checks.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from fem_racket.contact.law import ContactLaw
from fem_racket.frame.model import FrameModel
from fem_racket.impact.general.cubic_force import ORDER, STENCILS, moments, step_stencil
from fem_racket.impact.general.integrator import GeneralOutcome, solve_general
from fem_racket.impact.general.receptance import Receptance
from fem_racket.impact.ode.law_cvode import solve_law_cvode
from fem_racket.impact.reduction import DEFAULT_TOLERANCE
from fem_racket.impact.system import output_times
from fem_racket.validation import AccuracyError, InputError, check_choice, check_finite

__all__ = [
    "LAW_SOLVERS",
    "LawRun",
    "law_histories",
    "modal_velocity",
    "ode_state_at",
    "receptance",
    "solve_law_impact",
]

#: Integrators of an impact under any contact law.
LAW_SOLVERS = ("general", "cvode")


def receptance(
    model: FrameModel, positions: Any, ball_mass: Any, modes: int | None = None
) -> Receptance:
    """The frame's modal shapes at impact points ``positions`` (x/L), one case each."""
    fm = model.modes(modes)
    pos = np.atleast_1d(np.asarray(positions, dtype=float))
    # point by point, so a point's values do not depend on the others asked with it
    a = np.array([fm.all_shapes.T @ model.fe.point_vector(p * model.mesh.length) for p in pos])
    mb = np.broadcast_to(np.asarray(ball_mass, dtype=float), pos.shape).copy()
    return Receptance(fm.omega, a[:, 2:], a[:, :2], mb)


def modal_velocity(model: FrameModel, frame_velocity: Any, modes: int | None = None) -> np.ndarray:
    """Initial modal velocities [sqrt(kg) m/s] of the frame, rigid modes first.

    Parameters
    ----------
    frame_velocity : (v, omega) or array
        ``(v, omega)``: the racket moving rigidly, its centre of gravity at v [m/s] and turning at
        omega [rad/s] about it (positive v along the ball's travel, positive omega turning the tip
        that way); or the modal velocities themselves, 2 rigid + the flexible modes kept.
    """
    fm = model.modes(modes)
    n = 2 + fm.omega.size
    arr = np.asarray(frame_velocity, dtype=float)
    if arr.shape == (2,):
        v = check_finite("frame_velocity v", arr[0], "m/s")
        w = check_finite("frame_velocity omega", arr[1], "rad/s")
        qd = model.fe.rigid_motion(v, w, about=fm.props.cg)
        return fm.all_shapes.T @ (model.fe.M @ qd)
    if arr.shape != (n,) or not np.all(np.isfinite(arr)):
        raise InputError(
            f"frame_velocity of shape {arr.shape} is not allowed: must be (v [m/s], omega "
            f"[rad/s]) or {n} finite modal velocities (2 rigid + {n - 2} flexible)"
        )
    return arr


def _step_parts(omega: np.ndarray, h: float, k: np.ndarray, s: np.ndarray):
    """Per (step k, fraction s) and coordinate: the forced parts of y (omega > 0) and of x', x
    (omega = 0) per unit b h F_r, shape (4 nodes r, T, n), and the phase e^{i theta s}."""
    theta = omega * h
    M = np.conj(moments(theta[None, :], s[:, None]))  # (4, T, n)
    q = np.arange(ORDER)[:, None, None]
    rig_v = s[None, :, None] ** (q + 1) / (q + 1)
    rig_x = h * s[None, :, None] ** (q + 2) / ((q + 1) * (q + 2))
    kind = np.minimum(k, 2)  # the stencils: forward on steps 0 and 1, backward after
    coef = STENCILS[np.array([1, 2, 0])[kind]]  # (T, 4 nodes, 4 powers)
    py = np.einsum("trq,qtn->trn", coef, M)
    pv = np.einsum("trq,qt->tr", coef, rig_v[:, :, 0])
    px = np.einsum("trq,qt->tr", coef, rig_x[:, :, 0])
    return py, pv, px, np.exp(1j * theta[None, :] * s[:, None])


def law_histories(
    out: GeneralOutcome,
    omega: np.ndarray,
    a: np.ndarray,
    ball_mass: float,
    speed: float,
    frame_velocity: np.ndarray | None,
    t_out: np.ndarray,
) -> tuple[np.ndarray, np.ndarray]:
    """States [u_B, eta] and rates at times ``t_out`` (within contact) of case 0 of ``out``.

    ``omega`` and ``a``: every frame coordinate (rigid ones as 0) and its shape at the impact
    point; the force is the integrator's piecewise cubic, up to the separation time.
    """
    h = float(out.step[0])
    last, frac = int(out.last[0]), float(out.fraction[0])
    F = out.force[0, : last + 1]
    w = np.concatenate([[0.0], omega])
    b = np.concatenate([[-1.0 / ball_mass], a])
    flex = w > 0
    v0 = np.zeros(w.size)
    v0[0] = speed
    if frame_velocity is not None:
        v0[1:] = frame_velocity
    # node states: one whole-step increment per step 0 .. last - 2
    ks = np.arange(last - 1)
    nodes = np.array([[k + o for o in step_stencil(int(k))] for k in ks]).reshape(-1, ORDER)
    py, pv, px = _step_parts(w, h, ks, np.ones(ks.size))[:3]
    g_y = h * np.einsum("kr,krn->kn", F[nodes], py)  # per unit b
    g_v = h * np.einsum("kr,kr->k", F[nodes], pv)
    g_x = h * np.einsum("kr,kr->k", F[nodes], px)
    rot = np.exp(-1j * np.outer(np.arange(last), w * h))  # e^{-i theta j}
    y0 = v0.astype(complex)
    acc = np.concatenate([np.zeros((1, w.size)), np.cumsum(rot[:-1] * g_y, axis=0)])
    y_nodes = np.conj(rot) * (y0 + b * acc)  # (last, n): nodes 0 .. last - 1
    v_rig = v0 + b * np.concatenate([[0.0], np.cumsum(g_v)])[:, None]
    x_rig = np.concatenate(
        [np.zeros((1, w.size)), np.cumsum(h * v_rig[:-1] + b * g_x[:, None], axis=0)]
    )
    # outputs: from the node before each time, over the step's fraction
    t_end = (last - 1 + frac) * h
    k = np.clip(np.floor(t_out / h).astype(int), 0, last - 1)
    s = np.clip(t_out / h - k, 0.0, 1.0)
    py, pv, px, ph = _step_parts(w, h, k, s)
    idx = np.array([[kk + o for o in step_stencil(int(kk))] for kk in k]).reshape(-1, ORDER)
    Fk = F[idx]  # (T, 4)
    y = ph * (y_nodes[k] + b * h * np.einsum("tr,trn->tn", Fk, py))
    vr = v_rig[k] + b * h * np.sum(Fk * pv, axis=1)[:, None]
    xr = x_rig[k] + v_rig[k] * (h * s)[:, None] + b * h * np.sum(Fk * px, axis=1)[:, None]
    x = np.where(flex, y.imag / np.where(flex, w, 1.0), xr)
    v = np.where(flex, y.real, vr)
    if np.any(t_out > t_end * (1 + 1e-12)):
        raise ValueError("output times beyond the contact")
    return x, v


def run_law(
    law: ContactLaw,
    model: FrameModel,
    position: float,
    ball_mass: float,
    speed: float,
    *,
    frame_velocity: np.ndarray | None,
    tolerance: float | None,
    steps: int | None,
    beta: float | None,
    t_max: float | None,
) -> GeneralOutcome:
    """:func:`solve_general` for one impact on ``model`` (all its modes available)."""
    rec = receptance(model, position, ball_mass, None)
    fv = None if frame_velocity is None else frame_velocity[None, :]
    try:
        return solve_general(
            law, rec, speed, frame_velocity=fv, tolerance=tolerance, steps=steps, beta=beta,
            t_max=t_max,
        )  # fmt: skip
    except RuntimeError as err:  # a step's Newton iteration diverged: one line naming the case
        raise AccuracyError(
            f"law {law.label()} at {speed:g} m/s, x/L = {position:g}: the general integrator "
            f"failed ({err}); solver 'cvode' may succeed"
        ) from None


def ode_state_at(law: ContactLaw, out: GeneralOutcome, t: np.ndarray) -> np.ndarray:
    """An ODE state at times ``t``: cubic Hermite through its nodal values and rates [m]."""
    from fem_racket.impact.general.step import hermite_value

    h, n = float(out.step[0]), int(out.last[0]) + 1
    d, v, z = out.deflection[0, :n], out.rate[0, :n], out.state[0, :n]
    g = h * np.asarray(law.rate(d, v, z))
    k = np.clip(np.floor(t / h).astype(int), 0, n - 2)
    return hermite_value(np.clip(t / h - k, 0.0, 1.0), z[k], g[k], z[k + 1], g[k + 1])


def _memory_at(out: GeneralOutcome, t: np.ndarray, d: np.ndarray, v: np.ndarray) -> np.ndarray:
    """The largest deflection up to each time: the integrator's value at the node before it and
    the maximum of the cubic Hermite interpolant of delta from that node to t [m]."""
    from fem_racket.impact.general.step import turn_max

    h, n = float(out.step[0]), int(out.last[0]) + 1
    k = np.clip(np.floor(t / h).astype(int), 0, n - 2)
    D, V, Z = out.deflection[0], out.rate[0], out.state[0]
    tau = np.maximum(t - k * h, 1e-300)
    return np.maximum.accumulate(np.maximum(Z[k], turn_max(D[k], V[k], d, v, tau)))


@dataclass(frozen=True, eq=False)
class LawRun:
    """Histories of one impact under a contact law, in modal frame coordinates.

    Attributes
    ----------
    t : ndarray, shape (nt,)
        Output times [s], the last the contact time.
    ball_displacement, ball_velocity : ndarray, shape (nt,)
        u_B [m], v_B [m/s].
    modal_displacement, modal_velocity : ndarray, shape (nt, 2 + n)
        Frame coordinates (rigid modes first) and rates.
    state : ndarray, shape (nt,)
        The law's internal state [m] (zeros for a law without one).
    peak_force : float
        Largest contact force [N].
    """

    t: np.ndarray
    ball_displacement: np.ndarray
    ball_velocity: np.ndarray
    modal_displacement: np.ndarray
    modal_velocity: np.ndarray
    state: np.ndarray
    peak_force: float


def solve_law_impact(
    law: ContactLaw,
    model: FrameModel,
    position: float,
    ball_mass: float,
    speed: float,
    *,
    solver: str = "general",
    frame_velocity: Any = None,
    output_step: float | None = 1e-5,
    t_max: float | None = None,
    rtol: float = 1e-10,
    atol: float = 1e-12,
    tolerance: float | None = DEFAULT_TOLERANCE,
    steps: int | None = None,
    beta: float | None = None,
) -> LawRun:
    """One impact of the ball at ``position`` (x/L) and ``speed`` [m/s] under ``law``.

    ``solver``: ``"general"`` (:func:`~fem_racket.impact.general.integrator.solve_general`, all
    modes available, truncated and stepped for the COR ``tolerance`` unless ``steps``/``beta`` are
    given) or ``"cvode"`` (:func:`solve_law_cvode`, all modes, ``rtol``/``atol``).
    ``frame_velocity``: see :func:`modal_velocity`.
    """
    check_choice("solver", solver, LAW_SOLVERS)
    fm = model.modes(None)
    a = fm.all_shapes.T @ model.fe.point_vector(position * model.mesh.length)
    fv = None if frame_velocity is None else modal_velocity(model, frame_velocity)
    if solver == "cvode":
        tr = solve_law_cvode(
            law,
            fm.all_omega,
            a,
            ball_mass,
            speed,
            frame_velocity=fv,
            rtol=rtol,
            atol=atol,
            t_max=t_max,
            output_step=output_step,
        )
        n = tr.n
        t, y = tr.t, tr.y
        d = y[:, :n] @ np.concatenate([[1.0], -a])
        v = y[:, n : 2 * n] @ np.concatenate([[1.0], -a])
        z = y[:, -1] if law.state == "ode" else np.maximum.accumulate(d)
        peak = float(np.max(law.force(d, v, z)))  # on CVODE's output grid (sampled)
        if output_step is None:
            t, y, z = t[[0, -1]], y[[0, -1]], z[[0, -1]]
        return LawRun(t, y[:, 0], y[:, n], y[:, 1:n], y[:, n + 1 : 2 * n], z, peak)
    out = run_law(
        law,
        model,
        position,
        ball_mass,
        speed,
        frame_velocity=fv,
        tolerance=tolerance,
        steps=steps,
        beta=beta,
        t_max=t_max,
    )
    tc = float(out.contact_time[0])
    t = output_times(output_step, tc)
    x, v = law_histories(out, fm.all_omega, a, ball_mass, speed, fv, t)
    z = np.zeros_like(t)
    if law.state == "memory":
        z = _memory_at(out, t, x[:, 0] - x[:, 1:] @ a, v[:, 0] - v[:, 1:] @ a)
    elif law.state == "ode":
        z = ode_state_at(law, out, t)
    return LawRun(t, x[:, 0], v[:, 0], x[:, 1:], v[:, 1:], z, float(out.peak_force[0]))
