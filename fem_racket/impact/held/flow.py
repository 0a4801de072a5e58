"""A linear output's energy and extrema between samples of a linear flow, without the samples'
grid error: what the integrators' path of the hand-held racket takes its shock measures from.

Between two samples y_k (at t_k) and the next, a linear system y' = A y moves exactly as
y(t_k + s) = exp(A s) y_k. For an output F = q @ y:

- its energy over the interval is y_k^T G(h) y_k, G(h) = int_0^h exp(A^T s) q q^T exp(A s) ds,
  computed by Van Loan's block exponential (Van Loan 1978, IEEE Trans. Autom. Control 23) on
  h / 2^m, then doubled: G(2 h) = G(h) + exp(A h)^T G(h) exp(A h), each term a Gramian, so no
  growing exponential is subtracted from another (the block's exp(-A^T h) grows with the grip's
  damping);
- its extrema are where dF/dt = (A^T q) @ y (:func:`~fem_racket.impact.ode.integrators.
  peak_rates`, as the integrators root-find them) changes sign, found on a grid of the flow
  and root-found on it (brentq on exp(A s) y_k) wherever the extremum could be the largest:
  |F| there is at most the grid's |F| + max |F''| h^2 / 2 (F'' = (A^T A^T q) @ y), with max |F''|
  over the interval taken as twice its larger end value. (A's eigenvectors would be cheaper but
  its rigid-body modes are a defective zero eigenvalue: they cost 1e-7 of the force.)

With exact samples (the free vibration after contact) both are exact; with an integrator's
samples the energy carries its error only, not a quadrature's.
"""

from __future__ import annotations

import numpy as np

from fem_racket.impact.ode.integrators import peak_rates

__all__ = ["flow_energy", "flow_extrema", "gramian"]

#: Interval lengths within this fraction of each other share one Gramian (the samples' uniform
#: steps differ by round-off only; the energy's error from it is below this fraction).
SAME_STEP = 1e-9


def gramian(A: np.ndarray, q: np.ndarray, tau: float) -> np.ndarray:
    """G(tau) = int_0^tau exp(A^T s) q q^T exp(A s) ds (module docstring), symmetric."""
    from scipy.linalg import expm

    n = A.shape[0]
    scale = float(np.max(np.sum(np.abs(A), axis=0))) * tau
    m = max(int(np.ceil(np.log2(scale))), 0) if scale > 1.0 else 0
    h = tau / 2.0**m
    block = np.zeros((2 * n, 2 * n))
    block[:n, :n], block[:n, n:], block[n:, n:] = -A.T, np.outer(q, q), A
    E = expm(block * h)
    P = E[n:, n:]
    G = P.T @ E[:n, n:]
    for _ in range(m):
        G = G + P.T @ G @ P
        P = P @ P
    return 0.5 * (G + G.T)


def flow_energy(A: np.ndarray, q: np.ndarray, t: np.ndarray, y: np.ndarray) -> float:
    """int (q @ y)^2 dt [output^2 s] from t[0] to t[-1], each interval from its first sample
    ``y[k]`` (module docstring); A balanced first (its physical form spans 13 decades)."""
    from scipy.linalg import matrix_balance

    Ab, (scale, _) = matrix_balance(A, permute=False, separate=True)
    z = y[:-1] / scale
    dt = np.diff(t)
    key = np.round(dt / dt[0] / SAME_STEP)
    total = 0.0
    for k in np.unique(key):
        on = key == k
        G = gramian(Ab, q * scale, float(np.mean(dt[on])))
        total += float(np.sum((z[on] @ G) * z[on]))
    return total


def flow_extrema(A: np.ndarray, q: np.ndarray, y0: np.ndarray, span: float, step: float):
    """q @ y over the flow from ``y0`` for a time ``span``: its values on a grid of about
    ``step`` and at each extremum between grid points that could exceed their largest |value|
    (module docstring)."""
    from scipy.linalg import expm
    from scipy.optimize import brentq

    num = max(int(np.ceil(span / step)), 1)
    h = span / num
    P = expm(A * h)
    Y = np.empty((num + 1, y0.size))
    Y[0] = y0
    for k in range(num):
        Y[k + 1] = P @ Y[k]
    rate = peak_rates(A, q[None, :])[0]
    F, g, curve = Y @ q, Y @ rate, Y @ peak_rates(A, rate[None, :])[0]
    # |F| at an extremum s* in [s_k, s_k + h] is at most |F(s_k)| + max |F''| h^2 / 2
    reach = np.maximum(np.abs(F[:-1]), np.abs(F[1:]))
    reach += h**2 * np.maximum(np.abs(curve[:-1]), np.abs(curve[1:]))
    found = [F]
    for k in np.flatnonzero((g[:-1] * g[1:] < 0.0) & (reach >= np.max(np.abs(F)))):

        def on_flow(s: float, w: np.ndarray, y: np.ndarray = Y[k]) -> float:
            return float(w @ (expm(A * s) @ y))

        found.append([on_flow(brentq(on_flow, 0.0, h, args=(rate,), xtol=1e-15), q)])
    return np.concatenate(found)
