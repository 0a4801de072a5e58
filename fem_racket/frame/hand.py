"""A hand on the grip: a rigid hand joined to the handle by a distributed spring-dashpot.

The hand is a rigid body of mass m_h and inertia I_h about its centre x_h (translation u_h and
rotation theta_h in the swing plane), free otherwise (no arm). Over the grip [a, b] a layer of
stiffness k' [N/m per m of handle] and damping c' [N s/m per m] joins it to the frame; the
layer's stretch is ``s(x) = w(x) - u_h - theta_h (x - x_h)``, so with Hermite shape functions N
and R = [1, x - x_h]::

    G = int_a^b B^T B dx,   B = [N, -R]        (4-point Gauss per cell, exact for the cubics)
    K_held = diag(K, 0) + k' G,   M_held = diag(M, m_h, I_h),   C_held = c' G

Parameters are assumptions, not measurements: the hand mass 0.45 kg is the middle of the
anthropometric 0.4-0.5 kg (DESIGN section 8); its inertia that of a uniform 0.10 m rod; the
grip spans 0.02-0.12 m from the butt. No published grip stiffness or damping was found: the two
presets, :data:`LOOSE_GRIP` and :data:`FIRM_GRIP`, are illustrative values for which the
held racket shows the measured trends (Chadefaux et al.: a firmer grip lowers the first
frequency and raises its damping). The trend is not monotonic in k' and c' in this model (hand
resonances on the grip layer cross the frame's first mode), so treat other values with care.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from fem_racket.frame.fe import FrameFE
from fem_racket.frame.grips import FIRM_GRIP, GRIPS, LOOSE_GRIP, Hand
from fem_racket.validation import InputError, show

__all__ = [
    "FIRM_GRIP",
    "GRIPS",
    "LOOSE_GRIP",
    "Hand",
    "HeldFrame",
    "check_grip",
    "held_frame",
    "held_modes",
]


@dataclass(frozen=True, eq=False)
class HeldFrame:
    """Frame + hand: dense K [N/m], M [kg], C [N s/m] over the frame DOFs then (u_h, theta_h),
    and ``grip`` = G / (layer coefficient) to rebuild the grip force."""

    K: np.ndarray
    M: np.ndarray
    C: np.ndarray
    grip: np.ndarray
    hand: Hand
    n_frame: int


def check_grip(hand: Hand, length: float) -> None:
    """Refuse a grip that reaches beyond a frame ``length`` [m] long."""
    if hand.grip_end > length:
        raise InputError(
            f"grip_end = {show(hand.grip_end)} m is not allowed: beyond the frame ({length:g} m)",
            parameter="grip_end",
            value=hand.grip_end,
        )


def _grip_matrix(fe: FrameFE, hand: Hand) -> np.ndarray:
    a, b = hand.grip_start, hand.grip_end
    p = fe.mesh.points
    check_grip(hand, p[-1])
    xg, wg = np.polynomial.legendre.leggauss(4)
    xs, ws = [], []
    for x0, x1 in zip(p[:-1], p[1:], strict=True):
        lo, hi = max(x0, a), min(x1, b)
        if hi > lo:
            xs.append(0.5 * (lo + hi) + 0.5 * (hi - lo) * xg)
            ws.append(0.5 * (hi - lo) * wg)
    x, w = np.concatenate(xs), np.concatenate(ws)
    B = np.hstack(
        [fe.field_matrix(x, 0).toarray(), -np.column_stack([np.ones_like(x), x - hand.centre])]
    )
    return B.T @ (w[:, None] * B)


def held_frame(fe: FrameFE, hand: Hand) -> HeldFrame:
    """The frame with the hand on its grip (module docstring)."""
    n = fe.ndof
    G = _grip_matrix(fe, hand)
    K = np.zeros((n + 2, n + 2))
    K[:n, :n] = fe.K.toarray()
    M = np.zeros_like(K)
    M[:n, :n] = fe.M.toarray()
    M[n, n], M[n + 1, n + 1] = hand.mass, hand.rotary_inertia
    return HeldFrame(K + hand.stiffness * G, M, hand.damping * G, G, hand, n)


def held_modes(held: HeldFrame) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Damped modes of the held racket, ascending: frequency [Hz], damping ratio and the share
    of each mode's strain energy in the frame's bending (1: pure bending; the hand's rocking on
    the grip layer has a small share). From the eigenvalues of the first-order system."""
    n = held.K.shape[0]
    minv = np.linalg.inv(held.M)
    A = np.zeros((2 * n, 2 * n))
    A[:n, n:] = np.eye(n)
    A[n:, :n], A[n:, n:] = -minv @ held.K, -minv @ held.C
    lam, vec = np.linalg.eig(A)
    keep = lam.imag > 1e-6 * np.abs(lam).max()
    lam, vec = lam[keep], vec[:n, keep]
    order = np.argsort(np.abs(lam))
    lam, vec = lam[order], vec[:, order]
    kf = np.zeros_like(held.K)
    kf[: held.n_frame, : held.n_frame] = (held.K - held.hand.stiffness * held.grip)[
        : held.n_frame, : held.n_frame
    ]
    total = np.real(np.einsum("ij,ik,kj->j", vec.conj(), held.K, vec))
    share = np.real(np.einsum("ij,ik,kj->j", vec.conj(), kf, vec)) / total
    return np.abs(lam) / (2 * np.pi), -lam.real / np.abs(lam), share
