"""The frame seen from the impact point: modal receptance and the integrator's kernels.

The frame is linear, so with the contact force F(t) the only unknown, the deflection at the
contact is a Volterra integral of F (free-free modal superposition)::

    delta(t)  = delta_free(t)  - int_0^t K(t - s) F(s) ds
    K(tau)    = mu0 tau + sum_j a_j^2 sin(omega_j tau) / omega_j,   mu0 = 1/m_B + sum_rigid a_r^2

(a_j: mass-normalised mode shapes at the impact point; delta_free: the ball's and the frame's
motion without contact) and delta' likewise with K'. With F the piecewise cubic of
:mod:`fem_racket.impact.general.cubic_force` on a grid of step h, the deflection at node m is a
weighted sum of the nodal forces, exactly for every mode::

    delta_m = delta_free(t_m) - sum_j W[m, j] F_j,   W[m, j] = T[m - j] + S[m, j]

T is a Toeplitz table (the backward stencil everywhere, nodes before 0 taken as zero) and S the
correction of the two starting steps (forward stencil), nonzero for j <= 3 only. The weight of
node r of a step at lag L = m - k >= 1 (per unit a^2; rigid part per unit mu0)::

    displacement   h/omega Im(e^{i theta L} G_r),   rigid h^2 sum_q c_rq (L/(q+1) - 1/(q+2))
    velocity       h Re(e^{i theta L} G_r),         rigid h sum_q c_rq / (q+1)
    G_r = sum_q c_rq conj(M_q(theta, 1)),           theta = omega h

Modes above the cut-off of :mod:`fem_racket.impact.reduction` enter through one residual
pseudo-mode per case. Used by :mod:`fem_racket.impact.general.integrator`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from fem_racket.impact.general.cubic_force import ORDER, STENCILS, lagrange, moments
from fem_racket.impact.reduction import split_modes

__all__ = ["Kernels", "Receptance", "free_motion", "kernels", "stencil_quadrature"]


@dataclass(frozen=True, eq=False)
class Receptance:
    """The frame at the impact points of a batch of cases, in free-free modal terms.

    Attributes
    ----------
    omega : ndarray, shape (n,) or (C, n)
        Flexible angular frequencies [rad/s], shared by the batch or one row per case (a batch
        spanning frames, :mod:`fem_racket.impact.general.batches`; the compiled march only).
    a : ndarray, shape (C, n)
        Mass-normalised flexible mode shapes at each case's impact point [1/sqrt(kg)].
    rigid : ndarray, shape (C, 2)
        Rigid-mode shapes (translation, rotation about the CG) at the impact point [1/sqrt(kg)].
    ball_mass : ndarray, shape (C,)
        m_B [kg].
    """

    omega: np.ndarray
    a: np.ndarray
    rigid: np.ndarray
    ball_mass: np.ndarray

    @property
    def compliance(self) -> np.ndarray:
        """1/m_B + sum a_r^2 [1/kg]: the ball's and the rigid frame's acceleration per newton."""
        return 1.0 / self.ball_mass + np.sum(self.rigid**2, axis=1)

    @property
    def clamped(self) -> bool:
        """True when there is no frame (a ball on a rigid support)."""
        return self.a.shape[1] == 0 and not np.any(self.rigid)


@dataclass(frozen=True, eq=False)
class Kernels:
    """W[m, j] = T[m - j] + S[m, j] for displacement (d) and velocity (v), see module docstring.

    Attributes
    ----------
    Td, Tv : ndarray, shape (C, N)
        Toeplitz weights by lag m - j [m/N], [m/(N s)].
    Sd, Sv : ndarray, shape (C, N, 4)
        Starting corrections for nodes j = 0..3 at each node m.
    kept : ndarray of int, shape (C,)
        Flexible modes kept per case (the others: one pseudo-mode).
    """

    Td: np.ndarray
    Tv: np.ndarray
    Sd: np.ndarray
    Sv: np.ndarray
    kept: np.ndarray


def stencil_quadrature(offsets: tuple[int, ...], s: float = 1.0) -> np.ndarray:
    """Weights per unit h of int_0^s (step's cubic) d sigma for the nodes ``offsets``."""
    return lagrange(offsets) @ (s ** np.arange(1, ORDER + 1) / np.arange(1, ORDER + 1))


def _tables(
    rec: Receptance, kept: np.ndarray, w2p: np.ndarray, a2p: np.ndarray, h: float, nlag: int
) -> tuple[np.ndarray, np.ndarray]:
    """Weights (C, 12, nlag) of the 4 nodes of the backward and the two forward stencils
    (in that order) at lags 0 .. nlag - 1, displacement and velocity."""
    coef = STENCILS.reshape(3 * ORDER, ORDER)
    lag = np.arange(nlag, dtype=float)
    nk = int(kept.max(initial=0))
    w = rec.omega[:nk]
    a2 = rec.a[:, :nk] ** 2 * (np.arange(nk)[None, :] < kept[:, None])
    # rigid part: h^2 sum_q c_q (L/(q+1) - 1/(q+2)) and h sum_q c_q/(q+1), times mu0
    q = np.arange(ORDER)
    c1, c2 = coef @ (1.0 / (q + 1)), coef @ (1.0 / (q + 2))
    mu0 = rec.compliance[:, None, None]
    Td = mu0 * (h * h * (c1[:, None] * lag - c2[:, None]))[None]
    Tv = mu0 * np.broadcast_to(h * c1[:, None], (c1.size, nlag))[None]
    if nk:
        G = coef @ np.conj(moments(w * h))  # (12, nk)
        phase = np.outer(w * h, lag)
        cs, sn = np.cos(phase), np.sin(phase)
        ad, av = (a2 / w)[:, None, :], a2[:, None, :]  # (C, 1, nk)
        Td = Td + h * ((ad * G.imag) @ cs + (ad * G.real) @ sn)
        Tv = Tv + h * ((av * G.real) @ cs - (av * G.imag) @ sn)
    if np.any(a2p > 0):
        wp = np.sqrt(np.where(a2p > 0, w2p, 1.0))
        Gp = (coef @ np.conj(moments(wp * h))).T[:, :, None]  # (C, 12, 1)
        phase = (wp * h)[:, None] * lag
        cs, sn = np.cos(phase)[:, None, :], np.sin(phase)[:, None, :]
        Td = Td + (h * a2p / wp)[:, None, None] * (Gp.imag * cs + Gp.real * sn)
        Tv = Tv + (h * a2p)[:, None, None] * (Gp.real * cs - Gp.imag * sn)
    return Td, Tv


def kernels(rec: Receptance, omega_c: np.ndarray, beta: float, h: float, nsteps: int) -> Kernels:
    """The weight tables of a grid of ``nsteps`` nodes of step ``h`` [s].

    Flexible modes below ``beta`` x ``omega_c`` (per case [rad/s]) are kept, the others
    replaced by one pseudo-mode (:func:`fem_racket.impact.reduction.split_modes`).
    """
    kept, w2p, a2p = split_modes(rec.omega, rec.a, omega_c, beta)
    tab_d, tab_v = _tables(rec, kept, w2p, a2p, h, nsteps + 1)
    (Td, Sd), (Tv, Sv) = _assemble(tab_d, nsteps), _assemble(tab_v, nsteps)
    return Kernels(Td, Tv, Sd, Sv, kept)


def _assemble(tab: np.ndarray, nsteps: int) -> tuple[np.ndarray, np.ndarray]:
    """T (C, N) and S (C, N, 4) from the stencils' weights by lag (:func:`_tables`)."""
    ncase = tab.shape[0]
    D = tab[:, :ORDER].copy()  # the backward stencil's node r at lag L >= 1
    D[:, :, 0] = 0.0
    T = np.zeros((ncase, nsteps))
    for r in range(ORDER):  # T[n] = sum_r D_r[n - 2 + r] (nodes before 0 count as zero)
        shift = r - 2
        if shift < 0:
            T[:, -shift:] += D[:, r, : nsteps + shift]
        else:
            T += D[:, r, shift : nsteps + shift]
    # starting corrections: node 0 is also the last node of a phantom step -1 (lag m + 1),
    # and steps 0 and 1 use the forward stencil instead of the backward one
    S = np.zeros((ncase, nsteps, ORDER))
    S[:, :, 0] -= D[:, 3, 1:]
    for k in (0, 1):
        m = np.arange(k + 1, nsteps)
        fwd = tab[:, ORDER * (k + 1) : ORDER * (k + 2)]
        for j in range(ORDER):
            S[:, m, j] += fwd[:, j, m - k]
            r = j - k + 2
            if r < ORDER:
                S[:, m, j] -= D[:, r, m - k]
    return T, S


def free_motion(
    rec: Receptance, speed: np.ndarray, frame_velocity: np.ndarray | None, t: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """delta and delta' without contact: ball at ``speed``, frame with initial modal velocities."""
    d = speed[:, None] * t[None, :]
    v = np.broadcast_to(speed[:, None], d.shape).copy()
    if frame_velocity is not None:
        rig, flex = frame_velocity[:, :2], frame_velocity[:, 2:]
        wr = np.sum(rec.rigid * rig, axis=1)
        d -= wr[:, None] * t
        v -= wr[:, None]
        w = rec.omega
        amp = rec.a * flex
        d -= (amp / w) @ np.sin(np.outer(w, t))
        v -= amp @ np.cos(np.outer(w, t))
    return d, v
