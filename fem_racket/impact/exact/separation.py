"""Separation time, impulse and peak force of many impacts from their roots and residues.

Every signal is a sum of exponentials, x(t) = Re sum_j m w_j exp(lambda_j t) (see
:mod:`fem_racket.impact.exact.roots`): the deflection delta (w = r), the contact force
F = K_CB delta + C_CB delta' (w = (k + c lambda) r) and its integral, the impulse
J(t) = Re sum_j m w_j (exp(lambda_j t) - 1) / lambda_j, all per unit impact speed.

Separation is the first time the event function (delta, or F) falls through zero. It is found
for a whole block of cases at once: a scan on a uniform grid over windows of two eq-11 contact
times, fine enough for six points per period of every term whose weight is at least
:data:`SIGNIFICANT` of the largest (smaller terms cannot make the signal change sign except
within a hair of a real crossing), then a bracketed Newton iteration on the full sum. The grid
values come from powers of exp(lambda dt) (repeated doubling) and one batched matrix product.
"""

from __future__ import annotations

import numpy as np

from fem_racket.impact.exact.roots import RootSet

__all__ = ["SIGNIFICANT", "impulse", "peak_force", "separation_time"]

#: Terms whose weight is below this fraction of the largest are left out of the grid scan.
SIGNIFICANT = 1e-3
#: Terms at least this fraction of the largest set the grid step (the others are summed
#: but may be under-resolved: they only move a crossing of the larger terms by a hair).
RESOLVED = 1e-2
#: Grid points per period of the fastest resolved term.
PER_PERIOD = 8.0
#: Scan window [eq-11 contact times] and smallest grid.
WINDOW = 2.0
MIN_GRID = 32
#: A grid minimum of the event function before separation below this fraction of its largest
#: value marks a near-touch of zero (see :func:`separation_time`).
TOUCH = 0.02
#: Smallest grid of the peak-force search, and of its zoom on the largest value.
PEAK_GRID = 257
#: Newton/bisection iterations on the separation time, and its absolute tolerance [s] (as
#: the exact path's Brent search; 4 eps relative on top).
MAX_NEWTON = 60
TIME_TOL = 1e-15


def _powers(z: np.ndarray, start: np.ndarray, G: int) -> np.ndarray:
    """E[..., g] = start * z**g for g < G (repeated doubling: log2(G) products)."""
    E = np.empty(z.shape + (G,), complex)
    E[..., 0] = start
    filled, power = 1, z
    while filled < G:
        m = min(filled, G - filled)
        np.multiply(E[..., :m], power[..., None], out=E[..., filled : filled + m])
        filled += m
        power = power * power
    return E


def _on_grid(lam: np.ndarray, w: np.ndarray, t0: np.ndarray, dt: np.ndarray, G: int):
    """Re sum_j w_j exp(lambda_j (t0 + g dt)), g < G, per row: shape (n, G)."""
    E = _powers(np.exp(lam * dt[:, None]), np.exp(lam * t0[:, None]), G)
    return (w[:, None, :] @ E)[:, 0, :].real


def _grid_size(
    lam: np.ndarray, w: np.ndarray, span: np.ndarray, resolved: float = 0.0
) -> tuple[np.ndarray, np.ndarray]:
    """Columns of the significant terms (largest first) and grid points per row, resolving
    the terms of weight >= ``resolved`` (default :data:`RESOLVED`) of the largest."""
    resolved = resolved or RESOLVED
    aw = np.abs(w)
    order = np.argsort(-aw, axis=1)
    aw_sorted = np.take_along_axis(aw, order, axis=1)
    K = int(np.max(np.sum(aw_sorted >= SIGNIFICANT * aw_sorted[:, :1], axis=1)))
    cols = order[:, :K]
    big = np.take_along_axis(aw, cols, axis=1) >= resolved * aw_sorted[:, :1]
    fastest = np.max(np.where(big, np.abs(np.take_along_axis(lam, cols, axis=1).imag), 0.0), axis=1)
    G = np.maximum(MIN_GRID, np.ceil(span * fastest / (2.0 * np.pi) * PER_PERIOD))
    return cols, 2 ** np.ceil(np.log2(G)).astype(int)


def _value(lam, w, t):
    """Re sum w exp(lambda t) and its time derivative, per row (t shape (n,))."""
    e = np.exp(lam * t[:, None])
    we = w * e
    return we.real.sum(-1), (we * lam).real.sum(-1), e


def separation_time(
    roots: RootSet, w: np.ndarray, t_est: np.ndarray, t_max: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """First time [s] the signal with weights ``w`` falls through zero after t = 0, per row,
    and whether the signal came close to zero before it (a grid minimum below :data:`TOUCH` of
    its largest value in that window: whether it crosses there is then decided by details a
    reduced model may miss).

    NaN where it has not by ``t_max``.
    """
    lam = roots.lam
    n = lam.shape[0]
    span = WINDOW * t_est
    cols, G = _grid_size(lam, w, span)
    lo = np.full(n, np.nan)
    dt_row = np.empty(n)
    touch = np.zeros(n, dtype=bool)
    for g in np.unique(G):
        rows = np.flatnonzero(G == g)
        dt = span[rows] / (g - 1)
        lam_s = np.take_along_axis(lam[rows], cols[rows], axis=1)
        w_s = np.take_along_axis(w[rows], cols[rows], axis=1)
        t0 = np.zeros(rows.size)
        todo = np.arange(rows.size)
        first = 1  # the first window starts at delta(0) = 0: look from its second point on
        while todo.size:
            vals = _on_grid(lam_s[todo], w_s[todo], t0[todo], dt[todo], g)
            falls = (vals[:, first:-1] > 0.0) & (vals[:, first + 1 :] <= 0.0)
            has = falls.any(axis=1)
            i = np.argmax(falls, axis=1) + first
            hit = todo[has]
            before = np.arange(g)[None, 1:-1] < i[has, None]
            v = vals[has]
            dips = (v[:, 1:-1] <= v[:, :-2]) & (v[:, 1:-1] <= v[:, 2:]) & before
            low = v[:, 1:-1] < TOUCH * np.max(np.abs(v), axis=1, keepdims=True)
            touch[rows[hit]] = np.any(dips & low, axis=1)
            lo[rows[hit]] = t0[hit] + i[has] * dt[hit]
            dt_row[rows[hit]] = dt[hit]
            todo = todo[~has]
            t0[todo] += (g - 1) * dt[todo]
            todo = todo[t0[todo] < t_max[rows[todo]]]
            first = 0
    found = np.flatnonzero(np.isfinite(lo))
    t = np.full(n, np.nan)
    if found.size:
        t[found] = _refine(lam[found], w[found], lo[found], lo[found] + dt_row[found])
    return t, touch


def _refine(lam: np.ndarray, w: np.ndarray, lo: np.ndarray, hi: np.ndarray) -> np.ndarray:
    """The fall through zero of the full sum near the bracket [lo, hi] from the scan.

    The terms left out of the scan may move the crossing by a hair: the bracket is first
    shifted by whole steps until the full sum is > 0 at ``lo`` and <= 0 at ``hi``; then Newton
    steps from the secant point, replaced by bisection whenever they leave the bracket, until
    a step or the bracket is below :data:`TIME_TOL` (absolute) plus 4 eps t.
    """
    dt = hi - lo
    for _ in range(4):
        f_lo = _value(lam, w, lo)[0]
        f_hi = _value(lam, w, hi)[0]
        early = f_lo <= 0.0
        late = f_hi > 0.0
        if not (early.any() or late.any()):
            break
        lo, hi = (
            np.where(early, lo - dt, np.where(late, hi, lo)),
            np.where(early, lo, np.where(late, hi + dt, hi)),
        )
    with np.errstate(divide="ignore", invalid="ignore"):
        t = lo + (hi - lo) * f_lo / (f_lo - f_hi)
    t = np.where((t > lo) & (t < hi), t, 0.5 * (lo + hi))
    active = np.arange(t.size)
    for _ in range(MAX_NEWTON):
        f, df, _ = _value(lam[active], w[active], t[active])
        ta, la, ha = t[active], lo[active], hi[active]
        la = np.where(f > 0.0, ta, la)
        ha = np.where(f <= 0.0, ta, ha)
        lo[active], hi[active] = la, ha
        with np.errstate(divide="ignore", invalid="ignore"):
            tn = ta - f / df
        bisect = ~((tn >= la) & (tn <= ha))
        tn = np.where(bisect, 0.5 * (la + ha), tn)
        t[active] = tn
        tol = TIME_TOL + 4.0 * np.finfo(float).eps * ta
        done = (~bisect & (np.abs(tn - ta) <= tol)) | (ha - la <= tol) | (f == 0.0)
        active = active[~done]
        if active.size == 0:
            break
    return t


def impulse(roots: RootSet, fw: np.ndarray, t: np.ndarray) -> np.ndarray:
    """J(t) = int_0^t F dt per unit impact speed [N s per m/s], per row."""
    lt = roots.lam * t[:, None]
    return roots.mult * (fw * np.expm1(lt) / roots.lam).real.sum(-1)


def peak_force(roots: RootSet, fw: np.ndarray, tc: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Largest contact force on [0, t_c] per unit impact speed [N per m/s] and its time [s].

    Every term on a grid over [0, t_c] of at least 257 points resolving all terms of weight
    >= :data:`SIGNIFICANT`, then 257 points over the four steps around the largest value (as
    :func:`fem_racket.impact.exact.outcome.exact_outcome`: steps finer than the high modes'
    ripple), then Newton on dF/dt = 0 within the neighbours of the best of those (kept only if
    it improves on it).
    """
    lam = roots.lam
    n = lam.shape[0]
    _, G = _grid_size(lam, fw, tc, SIGNIFICANT)
    G = np.maximum(G + 1, PEAK_GRID)
    best = np.empty(n)
    t_best = np.empty(n)
    zero = np.zeros(n)
    for g in np.unique(G):
        rows = np.flatnonzero(G == g)
        r = np.arange(rows.size)
        L, W = lam[rows], fw[rows]
        dt = tc[rows] / (g - 1)
        i = np.argmax(_on_grid(L, W, zero[rows], dt, g), axis=1)
        t0 = np.maximum(i - 2, 0) * dt
        dt = (np.minimum(i + 2, g - 1) * dt - t0) / (PEAK_GRID - 1)
        vals = _on_grid(L, W, t0, dt, PEAK_GRID)
        i = np.argmax(vals, axis=1)
        t = t0 + i * dt
        best[rows], t_best[rows] = roots.mult * vals[r, i], t
        lo, hi = t - dt, t + dt
        for _ in range(6):
            d1, d2, _ = _value(L, W * L, t)
            with np.errstate(divide="ignore", invalid="ignore"):
                tn = t - d1 / d2
            t = np.clip(np.where(np.isfinite(tn), tn, t), lo, hi)
        f = roots.mult * _value(L, W, t)[0]
        better = np.isfinite(f) & (f > best[rows])
        best[rows] = np.where(better, f, best[rows])
        t_best[rows] = np.where(better, t, t_best[rows])
    return best, t_best
