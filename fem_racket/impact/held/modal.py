"""Exact impacts on a hand-held racket: modes of frame + hand, then the eigen-solution.

The held structure (:mod:`fem_racket.frame.hand`) meets the ball through the paper's linear
spring-dashpot, so the whole system is linear. Its undamped modes (K_held, M_held), mass
normalised, are two rigid-body modes of frame + hand (the grip layer is not stretched) and
flexible modes omega_f; the grip damping becomes a full matrix D = Phi_f^T C_held Phi_f (not
modal: no mode is a damped mode), which acts on no rigid mode. Eliminating the rigid modes
through the spring deflection delta as :mod:`fem_racket.impact.exact.closed_form` does::

    delta'' = -mu F + sum_f a_f (omega_f^2 eta_f + (D eta_f')_f),   mu = 1/m_B + sum_k a_k^2
    eta_f'' = -omega_f^2 eta_f - (D eta_f')_f + a_f F,              F = K_CB delta + C_CB delta'

(a: mode values at the impact point). z = [delta, eta_f, delta', eta_f'] obeys z' = A z with a
constant A, solved by its complex eigen-decomposition, z(t) = Re sum_j Z_j exp(lambda_j t).
Separation is the paper's criterion (delta falls through 0), found as the free racket's exact
path finds it. Modes are kept by the engine's rule (:mod:`fem_racket.impact.reduction`): the
flexible modes below beta x omega_c, the rest replaced by one undamped pseudo-mode with their
static flexibility and mass at the impact point (and no share in the hand's motion).

The grip force on the hand is F_h = m_h u_h'' (nothing else acts on it), u_h = sum p eta with p
the modes' values at the hand's translation. Its rigid part m_h F sum_r p_r a_r is the
``_rigid_factor`` of :mod:`fem_racket.impact.held.grip`; the vibration part is m_h sum_f p_f
eta_f''. After separation the racket and hand vibrate freely (ball gone): y = [eta_f, eta_f'] obeys
y' = B y, B = [[0, I], [-Omega^2, -D]], again a sum of exponentials from the state at t_c.
Shock measures: :mod:`fem_racket.impact.held.shock`.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from fem_racket.contact.linear import Ball, LinearContact
from fem_racket.impact.exact.closed_form import (
    ModalClosedForm,
    reduced_matrix,
    separation_time,
)
from fem_racket.impact.held.basis import HeldBasis
from fem_racket.impact.reduction import DEFAULT_TOLERANCE, cutoff_factor
from fem_racket.validation import InputError, check_range

__all__ = ["HeldContact", "held_contact", "held_contacts"]


class _HeldClosedForm(ModalClosedForm):
    """The closed form of :mod:`fem_racket.impact.exact.closed_form` on the held racket's reduced
    state matrix (with the grip damping); amplitudes from the eigenvectors."""

    def __init__(self, A: np.ndarray, n: int, mb: float, v0: float, k: float, c: float):
        self.lam, V = np.linalg.eig(A)
        z0 = np.zeros(2 * n)
        z0[n] = v0
        self.Z = V[:n] * np.linalg.solve(V, z0)
        self.fvec = (k + c * self.lam) * self.Z[0]
        self.k, self.c, self.mb, self.v0 = k, c, mb, v0


@dataclass(frozen=True, eq=False)
class HeldContact:
    """One impact on the held racket as sums of exponentials (module docstring).

    Attributes
    ----------
    speed : float
        Incident ball speed V_B0 [m/s].
    contact_time : float
        t_c [s].
    rebound_velocity : float
        Ball velocity at separation [m/s] (negative: rebounding).
    lam, vib, rigid : ndarray
        During contact: eigenvalues [1/s] and weights [N] of the grip force's vibration and
        rigid parts, F = Re sum_j w_j exp(lambda_j t).
    mu, free : ndarray
        After separation: eigenvalues [1/s] and weights [N] of the grip force (all vibration),
        F = Re sum_j w_j exp(mu_j (t - t_c)).
    modes : int
        Flexible modes kept (plus the pseudo-mode when any is dropped).
    force : ndarray
        Weights [N] of the contact force on ``lam``, F = Re sum_j w_j exp(lambda_j t).
    """

    speed: float
    contact_time: float
    rebound_velocity: float
    lam: np.ndarray
    vib: np.ndarray
    rigid: np.ndarray
    mu: np.ndarray
    free: np.ndarray
    modes: int
    force: np.ndarray

    @property
    def cor(self) -> float:
        """-v_B(t_c) / V_B0."""
        return -self.rebound_velocity / self.speed

    def contact_force(self, t: np.ndarray) -> np.ndarray:
        """Contact force F [N] at times ``t`` >= 0 [s] (zero after separation)."""
        t = np.atleast_1d(np.asarray(t, dtype=float))
        out = np.zeros_like(t)
        on = t <= self.contact_time
        out[on] = np.real(np.exp(np.multiply.outer(t[on], self.lam)) @ self.force)
        return out

    def grip_force(self, t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Grip force on the hand F_h and its rigid part [N] at times ``t`` >= 0 [s]."""
        t = np.atleast_1d(np.asarray(t, dtype=float))
        total, rigid = np.zeros_like(t), np.zeros_like(t)
        on = t <= self.contact_time
        E = np.exp(np.multiply.outer(t[on], self.lam))
        rigid[on] = np.real(E @ self.rigid)
        total[on] = rigid[on] + np.real(E @ self.vib)
        E = np.exp(np.multiply.outer(t[~on] - self.contact_time, self.mu))
        total[~on] = np.real(E @ self.free)
        return total, rigid


def held_contact(
    basis: HeldBasis,
    *,
    position: float = 0.75,
    speed: float = 20.0,
    ball_mass: float | None = None,
    kcb: float | None = None,
    zeta: float | None = None,
    tolerance: float | None = DEFAULT_TOLERANCE,
) -> HeldContact:
    """A ball striking the held racket at rest: the exact solution (module docstring).

    Parameters
    ----------
    basis : HeldBasis
        From :func:`fem_racket.impact.held.basis.held_basis`.
    position, speed, ball_mass, kcb, zeta
        As for :func:`fem_racket.impact.held.grip.simulate_held`.
    tolerance : float or None
        COR tolerance choosing the modes kept (:func:`fem_racket.impact.reduction.
        cutoff_factor`); None keeps every mode.
    """
    (c,) = held_contacts(
        basis, [position], [speed], ball_mass=ball_mass, kcb=kcb, zeta=zeta, tolerance=tolerance
    )
    return c


def held_contacts(
    basis: HeldBasis,
    positions: Sequence[float],
    speeds: Sequence[float],
    *,
    ball_mass: float | None = None,
    kcb: float | None = None,
    zeta: float | None = None,
    tolerance: float | None = DEFAULT_TOLERANCE,
) -> list[HeldContact]:
    """:func:`held_contact` for each pair of ``positions`` (x/L) and ``speeds`` [m/s]."""
    x = [check_range("position", p, 0.0, 1.0, unit="x/L") for p in positions]
    if len(x) != len(speeds):
        raise InputError(f"{len(x)} positions and {len(speeds)} speeds: need as many of each")
    ball = Ball() if ball_mass is None else Ball(ball_mass)
    fe = basis.fe
    g = fe.field_matrix(np.asarray(x) * fe.mesh.length, 0).toarray()
    a_r, a = g @ basis.rigid[: fe.ndof], g @ basis.shapes[: fe.ndof]
    beta = cutoff_factor(tolerance)
    return [
        _contact(basis, a_r[i], a[i], LinearContact.for_speed(v, kcb=kcb, zeta=zeta), ball, v, beta)
        for i, v in enumerate(speeds)
    ]


def _contact(
    basis: HeldBasis,
    a_r: np.ndarray,
    a: np.ndarray,
    law: LinearContact,
    ball: Ball,
    speed: float,
    beta: float,
) -> HeldContact:
    """One impact from the modes' values at the impact point (module docstring)."""
    k, c, mb = law.stiffness, law.damping(ball.mass), ball.mass
    j = basis.hand_row
    p = basis.shapes[j]
    mu0 = 1.0 / mb + float(a_r @ a_r)
    omega_c = math.sqrt(k * mu0)
    kept = int(np.sum(basis.omega < beta * omega_c))
    w2 = basis.omega**2
    af, wf2, pf = a[:kept], w2[:kept], p[:kept]
    D = basis.damping[:kept, :kept]
    mass, flex = float(np.sum(a[kept:] ** 2)), float(np.sum(a[kept:] ** 2 / w2[kept:]))
    if mass > 0.0 and flex > 0.0:  # pseudo-mode of the dropped modes (reduction.py)
        af = np.append(af, math.sqrt(mass))
        wf2 = np.append(wf2, mass / flex)
        pf = np.append(pf, 0.0)
        D = np.pad(D, ((0, 1), (0, 1)))
    n = af.size + 1
    A = reduced_matrix(af, wf2, mu0 + float(af @ af), k, c)
    A[n + 1 :, n + 1 :] -= D
    A[n, n + 1 :] += af @ D
    cf = _HeldClosedForm(A, n, mb, float(speed), k, c)
    tc = separation_time(cf, "displacement", math.pi / omega_c, None)
    m_h = basis.hand.mass
    vib = m_h * (pf @ cf.Z[1:]) * cf.lam**2
    rigid = m_h * float(basis.rigid[j] @ a_r) * cf.fvec
    # Free vibration from the kept flexible modes' state at t_c (the pseudo-mode has p = 0).
    e = np.exp(cf.lam * tc)
    Zk = cf.Z[1 : kept + 1]
    y = np.concatenate([np.real(Zk @ e), np.real(Zk @ (cf.lam * e))])
    mu, W, Winv = basis.free_eig(kept)
    Y = W[:kept] * (Winv @ y)
    free = m_h * (p[:kept] @ Y) * mu**2
    rebound = cf.v0 - cf.impulse(tc) / mb
    return HeldContact(float(speed), tc, rebound, cf.lam, vib, rigid, mu, free, kept, cf.fvec)
