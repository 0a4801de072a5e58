"""The histories of an impact the general integrator solved: ball and frame at any time.

From the nodal forces of a :class:`~fem_racket.impact.general.march.GeneralOutcome`, the ball
and every frame mode at the output times, and the law's state between nodes. Every coordinate
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

import numpy as np

from fem_racket.contact.law import ContactLaw
from fem_racket.impact.general.cubic_force import ORDER, STENCILS, moments, step_stencil
from fem_racket.impact.general.march import GeneralOutcome
from fem_racket.impact.general.step import hermite_value, turn_max

__all__ = ["law_histories", "memory_at", "ode_state_at"]


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


def ode_state_at(law: ContactLaw, out: GeneralOutcome, t: np.ndarray) -> np.ndarray:
    """An ODE state at times ``t``: cubic Hermite through its nodal values and rates [m]."""
    h, n = float(out.step[0]), int(out.last[0]) + 1
    d, v, z = out.deflection[0, :n], out.rate[0, :n], out.state[0, :n]
    g = h * np.asarray(law.rate(d, v, z))
    k = np.clip(np.floor(t / h).astype(int), 0, n - 2)
    return hermite_value(np.clip(t / h - k, 0.0, 1.0), z[k], g[k], z[k + 1], g[k + 1])


def memory_at(out: GeneralOutcome, t: np.ndarray, d: np.ndarray, v: np.ndarray) -> np.ndarray:
    """The largest deflection up to each time: the integrator's value at the node before it and
    the maximum of the cubic Hermite interpolant of delta from that node to t [m]."""
    h, n = float(out.step[0]), int(out.last[0]) + 1
    k = np.clip(np.floor(t / h).astype(int), 0, n - 2)
    D, V, Z = out.deflection[0], out.rate[0], out.state[0]
    tau = np.maximum(t - k * h, 1e-300)
    return np.maximum.accumulate(np.maximum(Z[k], turn_max(D[k], V[k], d, v, tau)))
