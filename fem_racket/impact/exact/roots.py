"""Roots and residues of the linear ball + structure impact, many cases at once.

With the rigid-body modes eliminated through the spring deflection delta (see
:mod:`fem_racket.impact.exact.closed_form`), the Laplace transform of delta for an impact at unit
speed is delta(s) = 1 / P(s) with::

    P(s) = s^2 + (k + c s) G(s),   G(s) = mu0 + sum_f a_f^2 s^2 / (s^2 + omega_f^2)
    mu0  = 1/m_B + sum_r a_r^2                                  (ball + rigid modes)

(k = K_CB, c = C_CB, a = mode values at the impact point). Dividing by s^2 (k + c s) gives the
secular form h(s) = P(s) / (s^2 (k + c s))::

    h(s) = 1/(k + c s) + sum_{i=0..m} v_i / (d_i + s^2),   d = [0, omega_f^2],  v = [mu0, a_f^2]

Undamped (c = 0) its zeros are s = +-i Omega_j with Omega_j^2 the eigenvalues of the symmetric
diagonal + rank-one matrix diag(d) + k sqrt(v) sqrt(v)^T: exactly one in each interval
(d_j, d_{j+1}) and one above d_m. They start the damped iteration from a two-pole model of h on
each interval. The damped roots in the upper half-plane (the others are their conjugates) come
from a simultaneous Newton iteration on f_p(s) = (d_p + s^2) h(s) (the pole p nearest each root
divided out, so roots close to a pole, i.e. modes barely coupled to the ball, converge as well
as the others) with the Ehrlich-Aberth repulsion from the neighbouring roots and from the
conjugates, which keeps two roots near one pole from converging to the same value.

The residues are r_j = 1 / P'(lambda_j) = (d_p + lambda^2) / (lambda^2 (k + c lambda) f_p'),
so that delta(t) = 2 Re sum_j r_j exp(lambda_j t). They are checked by the initial conditions
delta(0) = 0 and delta'(0) = 1, i.e. the sum rules 2 Re sum r = 0 and 2 Re sum lambda r = 1.
A case whose iteration does not converge or whose sum rules fail (e.g. a heavily damped pair of
roots that has become real) is solved again by a general eigen-decomposition of its small
reduced state matrix, as :mod:`fem_racket.impact.exact.closed_form` does.
"""

from __future__ import annotations

import numpy as np

from fem_racket.impact.exact.closed_form import reduced_matrix

__all__ = ["SUM_RULE_TOL", "RootSet", "coupled_roots", "eigen_roots"]

#: Relative tolerance of the sum rules that check every case's residues.
SUM_RULE_TOL = 1e-9
#: Newton/Aberth steps stop below this relative size.
STEP_TOL = 1e-13
#: Iteration limit; a case still moving after it is solved by eigen-decomposition.
MAX_ITERATIONS = 12


class RootSet:
    """Roots lambda and residues r of a block of cases, delta(t) = Re sum_j m r_j e^{lambda_j t}.

    Attributes
    ----------
    lam, res : ndarray, complex, shape (n, R)
        Roots [1/s] and residues [s] (per unit impact speed).
    mult : float
        2 when only the upper half-plane is stored (conjugates implied), 1 for every root.
    """

    def __init__(self, lam: np.ndarray, res: np.ndarray, mult: float) -> None:
        self.lam, self.res, self.mult = lam, res, mult


def _initial_roots(d: np.ndarray, v: np.ndarray, k: np.ndarray) -> np.ndarray:
    """Undamped Omega_j^2, one per interval (d_j, d_{j+1}), from a two-pole model of h.

    The poles other than the interval's ends are frozen at the interval's middle; the model's
    root is the smaller root of a quadratic, written in a cancellation-free form.
    """
    n, R = d.shape
    top = d[:, -1] + k * v.sum(-1)  # the last root lies below d_m + k |v|
    hi = np.concatenate([d[:, 1:], top[:, None]], axis=1)
    mid = 0.5 * (d + hi)
    den = d[:, None, :] - mid[:, :, None]
    j = np.arange(R)
    den[:, j, j] = np.inf
    den[:, j[:-1], j[:-1] + 1] = np.inf
    C = 1.0 / k[:, None] + (v[:, None, :] / den).sum(-1)
    a = v
    b = np.concatenate([v[:, 1:], np.zeros((n, 1))], axis=1)
    g = hi - d
    # C + a/(d - x) + b/(hi - x) = 0 with y = x - d: C y^2 - (C g + a + b) y + a g = 0
    B = C * g + a + b
    disc = np.sqrt(np.maximum(B * B - 4.0 * C * a * g, 0.0))
    with np.errstate(divide="ignore", invalid="ignore"):
        y = np.where(B > 0.0, 2.0 * a * g / (B + disc), (B - disc) / (2.0 * C))
        y[:, -1] = a[:, -1] / C[:, -1]  # last interval: no upper pole
    y = np.clip(np.nan_to_num(y, nan=0.5 * g[:, :1].min()), 1e-9 * g, g * (1.0 - 1e-9))
    return d + y


def _aberth(d: np.ndarray, v: np.ndarray, k: np.ndarray, c: np.ndarray) -> tuple:
    """Damped upper-half-plane roots and residues (see the module docstring).

    Returns lam, res, ok (per case: converged and its sum rules hold). A case stops moving once
    its own steps are below STEP_TOL and leaves the arrays, so its result does not depend on
    the other cases of the block (sweeps give the same bits however they are chunked).
    """
    n, R = d.shape
    om2 = _initial_roots(d, v, k)
    s = 1j * np.sqrt(om2)
    upper = np.concatenate([d[:, 1:], np.full((n, 1), np.inf)], axis=1)
    p = np.arange(R)[None, :] + ((upper - om2 < om2 - d) & (np.arange(R) < R - 1))
    dp = np.take_along_axis(d, p, axis=1)
    vp = np.take_along_axis(v, p, axis=1)
    dm = np.where(np.arange(R)[None, None, :] == p[:, :, None], np.inf, d[:, None, :])
    W = np.stack([v, np.ones_like(v)], axis=-1).astype(complex)
    kk, cc = k[:, None], c[:, None]
    lam = s.copy()
    df_last = np.empty((n, R), complex)
    rows = np.arange(n)  # the cases still moving
    with np.errstate(all="ignore"):
        for _ in range(MAX_ITERATIONS):
            s2 = s * s
            X = dm + s2[:, :, None]
            np.divide(1.0, X, out=X)
            S = X @ W  # sum_i v_i / (d_i + s^2), sum_i 1 / (d_i + s^2)
            X *= X
            S2 = (X @ W[:, :, :1])[..., 0]
            ikcs = 1.0 / (kk + cc * s)
            q = ikcs + S[..., 0]
            e = dp + s2
            f = vp + e * q
            df = 2.0 * s * q - e * (cc * ikcs * ikcs + 2.0 * s * S2)
            # Aberth: poles of f_p (the other d_i, -k/c) minus the other roots: the conjugate
            # (1/(s - conj s) = -i/(2 Im s)) and the neighbours with theirs (far roots barely
            # move a root and would cost R^2 more).
            y = s.imag
            corr = 2.0 * s * S[..., 1] + cc * ikcs + 0.5j / y
            if R > 1:
                x = s.real
                u = s[:, 1:] - x[:, :-1]
                corr[:, 1:] -= 2.0 * u / (u * u + y[:, :-1] ** 2)
                u = s[:, :-1] - x[:, 1:]
                corr[:, :-1] -= 2.0 * u / (u * u + y[:, 1:] ** 2)
            step = f / (df + f * corr)
            s = s - step
            lam[rows], df_last[rows] = s, df
            done = np.all(np.abs(step) <= STEP_TOL * np.abs(s), axis=1)
            if done.all():
                rows = rows[:0]
                break
            if done.any():
                live = ~done
                rows, s, dm, W = rows[live], s[live], dm[live], W[live]
                dp, vp, kk, cc = dp[live], vp[live], kk[live], cc[live]
        # Residues at the final roots: df was evaluated one (negligible) step before.
        e = np.take_along_axis(d, p, axis=1) + lam * lam
        res = e / (lam * lam * (k[:, None] + c[:, None] * lam) * df_last)
        ok = np.all(np.isfinite(res), axis=1) & np.all(lam.real <= 1e-12 * np.abs(lam), axis=1)
        ok[rows] = False
        ok &= _sum_rules(lam, res, 2.0)
    return lam, res, ok


def _sum_rules(lam: np.ndarray, res: np.ndarray, mult: float) -> np.ndarray:
    """delta(0) = 0 and delta'(0) = 1 from the residues, per case, to SUM_RULE_TOL."""
    r0 = np.abs(mult * res.real.sum(-1)) <= SUM_RULE_TOL * mult * np.abs(res).sum(-1)
    lr = lam * res
    r1 = np.abs(mult * lr.real.sum(-1) - 1.0) <= SUM_RULE_TOL * mult * np.abs(lr).sum(-1)
    return r0 & r1


def eigen_roots(d: np.ndarray, v: np.ndarray, k: float, c: float) -> tuple[np.ndarray, np.ndarray]:
    """Every root and delta-residue of one case from the eigenvectors of the reduced state matrix
    (:func:`fem_racket.impact.exact.closed_form.reduced_matrix`).

    State z = [delta, eta_f, delta', eta_f'] with delta'' = -mu F + sum a_f w_f^2 eta_f,
    eta_f'' = -w_f^2 eta_f + a_f F, F = k delta + c delta', mu = sum v (signs of a_f do not
    change delta, so a_f = sqrt(v_f)).
    """
    af, w2 = np.sqrt(v[1:]), d[1:]
    m = af.size + 1
    mu = float(v.sum())
    lam, V = np.linalg.eig(reduced_matrix(af, w2, mu, k, c))
    z0 = np.zeros(2 * m)
    z0[m] = 1.0
    return lam, V[0] * np.linalg.solve(V, z0)


def coupled_roots(
    d: np.ndarray, v: np.ndarray, k: np.ndarray, c: np.ndarray
) -> list[tuple[np.ndarray, RootSet]]:
    """Roots and residues of a block of cases with the same number of poles.

    Parameters
    ----------
    d : ndarray, shape (n, R)
        Poles [0, omega_1^2, ...] [rad^2/s^2], ascending along each row.
    v : ndarray, shape (n, R)
        Weights [mu0, a_1^2, ...] [1/kg].
    k, c : ndarray, shape (n,)
        K_CB [N/m] and C_CB [N s/m].

    Returns
    -------
    list of (rows, RootSet)
        The fast path's cases (upper half-plane roots), then, if any case needed it, those
        solved by eigen-decomposition (every root). Rows index the block.
    """
    lam, res, ok = _aberth(d, v, k, c)
    out = [(np.flatnonzero(ok), RootSet(lam[ok], res[ok], 2.0))]
    bad = np.flatnonzero(~ok)
    if bad.size:
        R2 = 2 * d.shape[1]
        L = np.empty((bad.size, R2), complex)
        Z = np.empty((bad.size, R2), complex)
        for row, i in enumerate(bad):
            L[row], Z[row] = eigen_roots(d[i], v[i], float(k[i]), float(c[i]))
        out.append((bad, RootSet(L, Z, 1.0)))
    return out
