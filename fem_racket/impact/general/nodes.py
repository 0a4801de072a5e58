"""The general integrator's equations solved at every node at once (few cases, no ODE state).

The march (:mod:`fem_racket.impact.general.march`) solves the nodes one after another, which
costs ~40 small numpy calls per node and Newton iteration: ~10 ms for one impact in Python. The
same discrete equations, all nodes together::

    R(F) = F - law(delta_free - Wd F, delta'_free - Wv F, z) = 0,
    J = I + diag(dF/d delta) Wd + diag(dF/d delta') Wv + diag(dF/dz) dz/dF

are one Newton iteration over arrays of length N per step: W is lower triangular (causal) apart
from the 3 x 3 block of the starting nodes, so J is solved by that block and one triangular
solve. A memory state z_m = max(z_{m-1}, the step's Hermite maximum) enters J through the
deflection at the node where the maximum was reached (the in-step refinement is left to the
iteration, a contraction of O(h^2)). Nodes after the contact has ended do not act on earlier
ones (causality), so convergence is required only up to the separation step. The result is
the march's to round-off (tested); an iteration that does not converge returns None and the
caller marches instead.
"""

from __future__ import annotations

import numpy as np

from fem_racket.contact.law import ContactLaw
from fem_racket.impact.general.cubic_force import ORDER
from fem_racket.impact.general.receptance import Kernels
from fem_racket.impact.general.step import turn_max

__all__ = ["full_weights", "solve_all"]

_ITER = 40


def full_weights(T: np.ndarray, S: np.ndarray) -> np.ndarray:
    """W[c, m, j] = T[c, m - j] (j <= m) + S[c, m, j] (j <= 3), shape (C, N, N)."""
    from numpy.lib.stride_tricks import sliding_window_view

    ncase, n = T.shape
    # row m is T[m], T[m-1], ..., T[0], 0, ...: a window of T reversed and padded with zeros
    rev = np.concatenate([T[:, ::-1], np.zeros((ncase, n - 1))], axis=1)
    W = sliding_window_view(rev, n, axis=1)[:, ::-1].copy()
    W[:, :, :ORDER] += S
    return W


def _solve_block(J: np.ndarray, rhs: np.ndarray) -> np.ndarray:
    """J x = rhs for J lower triangular but for its leading 3 x 3 block (unknowns 1..N-1)."""
    from scipy.linalg.lapack import dtrtrs

    b = ORDER - 1
    x = np.empty_like(rhs)
    x[:b] = np.linalg.solve(J[:b, :b], rhs[:b])
    x[b:], info = dtrtrs(J[b:, b:], rhs[b:] - J[b:, :b] @ x[:b], lower=1)
    if info != 0:
        x[b:] = np.nan
    return x


def solve_all(
    law: ContactLaw,
    K: Kernels,
    dfree: np.ndarray,
    vfree: np.ndarray,
    guess: np.ndarray,
    h: float,
    scale: np.ndarray,
    ends,
) -> tuple[np.ndarray, ...] | None:
    """Nodal F, delta, delta', z (C, N) by Newton on all nodes; None if it does not converge.

    ``guess`` (C, N): starting forces (column 0 is the exact F at t = 0); ``ends(F, D, V, Z)``
    gives each case's separation step (N - 1 when not yet separated), up to which the
    residual must vanish.
    """
    memory = law.state == "memory"
    Wd_all, Wv_all = full_weights(K.Td, K.Sd), full_weights(K.Tv, K.Sv)
    F = guess.copy()
    ncase, n = F.shape
    live_n = n
    for _ in range(_ITER):
        # causality: the nodes up to a little past every case's separation decide the answer
        Wd, Wv = Wd_all[:, :live_n, :live_n], Wv_all[:, :live_n, :live_n]
        f = F[:, :live_n]
        D = dfree[:, :live_n] - (Wd @ f[:, :, None])[:, :, 0]
        V = vfree[:, :live_n] - (Wv @ f[:, :, None])[:, :, 0]
        Z = np.zeros_like(D)
        at = None
        if memory:
            tm = turn_max(D[:, :-1], V[:, :-1], D[:, 1:], V[:, 1:], h)
            Z = np.maximum.accumulate(np.concatenate([D[:, :1], tm], 1), axis=1)
            idx = np.arange(live_n)
            at = np.maximum.accumulate(np.where(np.concatenate([D[:, :1], tm], 1) >= Z, idx, 0), 1)
        R = f - law.force(D, V, Z)
        last = ends(f, D, V, Z)
        live = np.arange(live_n)[None, :] <= np.minimum(last + 1, live_n - 1)[:, None]
        err = np.abs(np.where(live, R, 0.0)) / (np.abs(f) + scale[:, None])
        if np.all(err <= 1e-12):
            return f, D, V, Z
        fd, fv, fz = (np.broadcast_to(x, D.shape) for x in law.partials(D, V, Z))
        for c in range(ncase):
            J = fd[c, :, None] * Wd[c]
            if np.any(fv[c]):
                J += fv[c, :, None] * Wv[c]
            if memory and np.any(fz[c]):
                J += fz[c, :, None] * Wd[c, at[c]]
            J[np.arange(live_n), np.arange(live_n)] += 1.0
            dF = _solve_block(J[1:, 1:], -R[c, 1:])
            cap = 2.0 * (np.abs(f[c, 1:]) + scale[c])
            step = np.maximum(np.minimum(dF, cap), -cap)
            F[c, 1:live_n] += np.where(np.isfinite(step), step, 0.0)
        if np.all(err <= 1e-3):  # near the answer: its separation steps are known
            live_n = min(live_n, int(np.max(last)) + max(8, int(np.max(last)) // 8))
    return None
