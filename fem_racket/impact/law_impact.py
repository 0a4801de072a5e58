"""One impact with any contact law: receptance, initial racket motion, histories.

Builds the impact-point :class:`~fem_racket.impact.general.Receptance` of a frame, turns an
initial racket velocity field into modal velocities, runs the general integrator (or CVODE) and
rebuilds the ball and frame histories at the output times. Every coordinate
``x = [u_B, eta_rigid, eta_flex]`` obeys ``x'' + omega^2 x = b F(t)`` (``b = [-1/m_B, a]``), so
with the integrator's piecewise-linear force each is propagated exactly over a step of length
tau from (x0, v0) with F going linearly from F0 to F1::

    x(tau) = cos(w tau) x0 + sin(w tau)/w v0 + b (F0 P0 + F1 P1)
    P1 = (tau - sin(w tau)/w) / (w^2 tau),   P0 = (1 - cos(w tau))/w^2 - P1
    v(tau) = -w sin(w tau) x0 + cos(w tau) v0 + b (F0 Q0 + F1 Q1)
    Q1 = (1 - cos(w tau)) / (w^2 tau),       Q0 = sin(w tau)/w - Q1

(w = 0: P1 = tau^2/6, P0 = tau^2/3, Q1 = Q0 = tau/2).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from fem_racket.contact.law import ContactLaw
from fem_racket.frame.model import FrameModel
from fem_racket.impact.general import (
    DEFAULT_BETA,
    DEFAULT_STEPS,
    GeneralOutcome,
    solve_general,
)
from fem_racket.impact.law_cvode import solve_law_cvode
from fem_racket.impact.receptance import Receptance
from fem_racket.impact.system import output_times
from fem_racket.validation import InputError, check_choice, check_finite

__all__ = [
    "LAW_SOLVERS",
    "LawRun",
    "law_histories",
    "modal_velocity",
    "propagate",
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
    G = np.column_stack([model.fe.point_vector(p * model.mesh.length) for p in pos])
    a = (fm.all_shapes.T @ G).T
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


def _ramp_weights(w: np.ndarray, tau: np.ndarray) -> tuple[np.ndarray, ...]:
    """cos, sin/w, -w sin, P0, P1, Q0, Q1 of :func:`propagate` (broadcast of w and tau)."""
    wt = w * tau
    c, s = np.cos(wt), np.sin(wt)
    safe_w = np.where(w > 0, w, 1.0)
    sinc = np.where(w > 0, s / safe_w, tau)
    small = wt < 1e-2
    tau_s = np.where(tau > 0, tau, 1.0)
    # (tau - sin(w tau)/w) / (w^2 tau) and (1 - cos)/w^2 with series where w tau is small
    p1 = np.where(
        small,
        tau**2 / 6 - w**2 * tau**4 / 120 + w**4 * tau**6 / 5040,
        (wt - s) / (safe_w**3 * tau_s),
    )
    one_minus_cos = np.where(
        small, tau**2 / 2 - w**2 * tau**4 / 24 + w**4 * tau**6 / 720, (1 - c) / safe_w**2
    )
    q1 = one_minus_cos / tau_s
    return c, sinc, -(w**2) * sinc, one_minus_cos - p1, p1, sinc - q1, q1


def propagate(
    omega: np.ndarray,
    b: np.ndarray,
    x0: np.ndarray,
    v0: np.ndarray,
    f0: Any,
    f1: Any,
    tau: Any,
) -> tuple[np.ndarray, np.ndarray]:
    """Exact states after ``tau`` [s] of x'' + omega^2 x = b F, F linear from f0 to f1 [N]."""
    c, sinc, msin, p0, p1, q0, q1 = _ramp_weights(omega, tau)
    x = c * x0 + sinc * v0 + b * (f0 * p0 + f1 * p1)
    v = msin * x0 + c * v0 + b * (f0 * q0 + f1 * q1)
    return x, v


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
    point; the force is the integrator's piecewise-linear one, ending at the separation value.
    """
    h = float(out.step[0])
    last, frac = int(out.last[0]), float(out.fraction[0])
    F = out.force[0, : last + 1].copy()
    F[last] = F[last - 1] + frac * (F[last] - F[last - 1])
    w = np.concatenate([[0.0], omega])
    b = np.concatenate([[-1.0 / ball_mass], a])
    x = np.zeros((last + 1, w.size))
    v = np.zeros_like(x)
    v[0, 0] = speed
    if frame_velocity is not None:
        v[0, 1:] = frame_velocity
    taus = np.full(last, h)
    taus[-1] = frac * h
    for m in range(last):
        x[m + 1], v[m + 1] = propagate(w, b, x[m], v[m], F[m], F[m + 1], taus[m])
    grid = np.concatenate([np.arange(last) * h, [(last - 1 + frac) * h]])
    k = np.clip(np.searchsorted(grid, t_out, side="right") - 1, 0, last - 1)
    tau = (t_out - grid[k])[:, None]
    span = (grid[k + 1] - grid[k])[:, None]
    f_at = F[k][:, None] + (F[k + 1] - F[k])[:, None] * tau / span
    xs, vs = propagate(w, b, x[k], v[k], F[k][:, None], f_at, tau)
    exact = np.isclose(t_out, grid[-1], rtol=0.0, atol=1e-12 * h)
    xs[exact], vs[exact] = x[-1], v[-1]
    return xs, vs


def run_law(
    law: ContactLaw,
    model: FrameModel,
    position: float,
    ball_mass: float,
    speed: float,
    *,
    frame_velocity: np.ndarray | None,
    steps: int,
    beta: float | None,
    t_max: float | None,
) -> GeneralOutcome:
    """:func:`solve_general` for one impact on ``model`` (all its modes available)."""
    rec = receptance(model, position, ball_mass, None)
    fv = None if frame_velocity is None else frame_velocity[None, :]
    return solve_general(law, rec, speed, frame_velocity=fv, steps=steps, beta=beta, t_max=t_max)


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
    steps: int = DEFAULT_STEPS,
    beta: float | None = DEFAULT_BETA,
) -> LawRun:
    """One impact of the ball at ``position`` (x/L) and ``speed`` [m/s] under ``law``.

    ``solver``: ``"general"`` (:func:`~fem_racket.impact.general.solve_general`, all modes
    available, truncated by ``beta``) or ``"cvode"`` (:func:`solve_law_cvode`, all modes).
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
        if output_step is None:
            t, y = t[[0, -1]], y[[0, -1]]
        d = y[:, :n] @ np.concatenate([[1.0], -a])
        v = y[:, n : 2 * n] @ np.concatenate([[1.0], -a])
        z = y[:, -1] if law.state == "ode" else np.maximum.accumulate(d)
        peak = float(np.max(law.force(d, v, z)))
        return LawRun(t, y[:, 0], y[:, n], y[:, 1:n], y[:, n + 1 : 2 * n], z, peak)
    out = run_law(
        law,
        model,
        position,
        ball_mass,
        speed,
        frame_velocity=fv,
        steps=steps,
        beta=beta,
        t_max=t_max,
    )
    tc = float(out.contact_time[0])
    t = output_times(output_step, tc)
    x, v = law_histories(out, fm.all_omega, a, ball_mass, speed, fv, t)
    if out.coarse is not None:
        # the end state extrapolated like the scalars (each run conserves momentum, so does this)
        tcc = np.array([float(out.coarse.contact_time[0])])
        xc, vc = law_histories(out.coarse, fm.all_omega, a, ball_mass, speed, fv, tcc)
        tcf = np.array([float((out.last[0] - 1 + out.fraction[0]) * out.step[0])])
        xf, vf = law_histories(out, fm.all_omega, a, ball_mass, speed, fv, tcf)
        x[-1], v[-1] = (4.0 * xf[0] - xc[0]) / 3.0, (4.0 * vf[0] - vc[0]) / 3.0
    grid = np.arange(out.state.shape[1]) * out.step[0]
    z = np.interp(t, grid, out.state[0])
    if law.state == "memory":
        z = np.maximum(z, np.maximum.accumulate(x[:, 0] - x[:, 1:] @ a))
    return LawRun(t, x[:, 0], v[:, 0], x[:, 1:], v[:, 1:], z, float(out.peak_force[0]))
