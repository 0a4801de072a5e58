"""Separation time, impulse and peak force of one case from its roots, compiled (numba).

The same search as :mod:`fem_racket.impact.exact.separation`, per case: a scan of the event
function's significant terms on a uniform grid (windows of two eq-11 contact times, grid
points from powers of exp(lambda dt) by repeated doubling), the near-touch check, then the
bracketed Newton iteration on the full sum; the impulse J(t) in closed form; the peak force on
a grid over [0, t_c], a zoom on its largest value and Newton on dF/dt = 0. Every case uses only
its own terms (which are significant, how fine its grid), so its bits do not depend on the
batch it is in. Imported only where a batch runs (:mod:`fem_racket.impact.exact.batch`).
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from fem_racket.impact.exact.separation import (
    MAX_NEWTON,
    MIN_GRID,
    PEAK_GRID,
    PER_PERIOD,
    SIGNIFICANT,
    TIME_TOL,
    TOUCH,
)
from fem_racket.impact.kernel_cache import KERNEL_OPTIONS

__all__ = ["cexp", "grid_size", "impulse", "peak_force", "peak_points", "separation_time"]

_EPS4 = 4.0 * np.finfo(np.float64).eps


@njit(**KERNEL_OPTIONS)
def cexp(z):
    """exp(z) of a complex z from the real exp, cos and sin (numba's own adds branches for
    infinite parts, which never occur here)."""
    e = math.exp(z.real)
    return complex(e * math.cos(z.imag), e * math.sin(z.imag))


@njit(**KERNEL_OPTIONS)
def grid_size(lam, w, R, span, resolved, use):
    """Grid points (a power of two >= MIN_GRID) resolving the terms of weight >= ``resolved``
    of the largest; marks in ``use`` the terms of weight >= SIGNIFICANT of it."""
    big = 0.0
    for j in range(R):
        big = max(big, abs(w[j]))
    fastest = 0.0
    for j in range(R):
        aw = abs(w[j])
        use[j] = aw >= SIGNIFICANT * big
        if aw >= resolved * big:
            fastest = max(fastest, abs(lam[j].imag))
    G = max(float(MIN_GRID), math.ceil(span * fastest / (2.0 * np.pi) * PER_PERIOD))
    return int(2.0 ** math.ceil(math.log2(G)))


@njit(**KERNEL_OPTIONS)
def _on_grid(lam, w, R, use, t0, dt, G, vals, buf):
    """vals[g] = Re sum_j w_j exp(lambda_j (t0 + g dt)) over the terms ``use``, g < G."""
    for g in range(G):
        vals[g] = 0.0
    for j in range(R):
        if not use[j]:
            continue
        buf[0] = w[j] * cexp(lam[j] * t0)
        power = cexp(lam[j] * dt)
        filled = 1
        while filled < G:
            m = min(filled, G - filled)
            for g in range(m):
                buf[filled + g] = buf[g] * power
            filled += m
            power = power * power
        for g in range(G):
            vals[g] += buf[g].real


@njit(**KERNEL_OPTIONS)
def _value(lam, w, R, t):
    """Re sum w exp(lambda t) and its time derivative."""
    f = df = 0.0
    for j in range(R):
        we = w[j] * cexp(lam[j] * t)
        f += we.real
        df += (we * lam[j]).real
    return f, df


@njit(**KERNEL_OPTIONS)
def _refine(lam, w, R, lo, hi):
    """The fall through zero of the full sum near [lo, hi] (separation._refine, one case)."""
    dt = hi - lo
    f_lo = f_hi = 0.0
    for _ in range(4):
        f_lo = _value(lam, w, R, lo)[0]
        f_hi = _value(lam, w, R, hi)[0]
        if f_lo <= 0.0:
            lo, hi = lo - dt, lo
        elif f_hi > 0.0:
            lo, hi = hi, hi + dt
        else:
            break
    t = lo + (hi - lo) * f_lo / (f_lo - f_hi)
    if not (t > lo and t < hi):
        t = 0.5 * (lo + hi)
    for _ in range(MAX_NEWTON):
        f, df = _value(lam, w, R, t)
        if f > 0.0:
            lo = t
        elif f <= 0.0:
            hi = t
        tn = t - f / df
        bisect = not (tn >= lo and tn <= hi)
        if bisect:
            tn = 0.5 * (lo + hi)
        tol = TIME_TOL + _EPS4 * t
        done = (not bisect and abs(tn - t) <= tol) or hi - lo <= tol or f == 0.0
        t = tn
        if done:
            break
    return t


@njit(**KERNEL_OPTIONS)
def separation_time(lam, w, R, t_est, t_max, G, scratch):
    """First fall of Re sum w exp(lambda t) through zero after t = 0 [s] (NaN: none by
    ``t_max``) and whether a grid minimum before it came within TOUCH of zero, on the grid of
    G points per window (:func:`grid_size` with RESOLVED, which also marks the terms used);
    ``scratch`` = (use, vals, buf, ...) holds them."""
    use, vals, buf = scratch[0], scratch[1], scratch[2]
    span = 2.0 * t_est
    dt = span / (G - 1)
    t0 = 0.0
    first = 1  # the first window starts at delta(0) = 0
    while True:
        _on_grid(lam, w, R, use, t0, dt, G, vals, buf)
        i = -1
        for g in range(first, G - 1):
            if vals[g] > 0.0 and vals[g + 1] <= 0.0:
                i = g
                break
        if i >= 0:
            top = 0.0
            for g in range(G):
                top = max(top, abs(vals[g]))
            touch = False
            for g in range(1, i):
                if vals[g] <= vals[g - 1] and vals[g] <= vals[g + 1] and vals[g] < TOUCH * top:
                    touch = True
            lo = t0 + i * dt
            return _refine(lam, w, R, lo, lo + dt), touch
        t0 += (G - 1) * dt
        if not t0 < t_max:
            return np.nan, False
        first = 0


@njit(**KERNEL_OPTIONS)
def peak_points(lam, fw, R, tc, use):
    """Grid points of the peak force's first scan: at least PEAK_GRID, resolving every term of
    weight >= SIGNIFICANT of the largest."""
    return max(grid_size(lam, fw, R, tc, SIGNIFICANT, use) + 1, PEAK_GRID)


@njit(**KERNEL_OPTIONS)
def impulse(lam, fw, R, mult, t):
    """J(t) per unit impact speed [N s per m/s] (numpy's complex expm1, term by term)."""
    J = 0.0
    for j in range(R):
        x, y = (lam[j] * t).real, (lam[j] * t).imag
        a = math.sin(0.5 * y)
        em1 = complex(math.expm1(x) * math.cos(y) - 2.0 * a * a, math.exp(x) * math.sin(y))
        J += (fw[j] * em1 / lam[j]).real
    return mult * J


@njit(**KERNEL_OPTIONS)
def _argmax(vals, n):
    """``np.argmax(vals[:n])`` (n >= 1) as numba computes it: the first NaN, else the first
    largest value. Written out: numba's own lives in ``numba.np.arraymath``, which a process
    loading the cached kernels then imports, and with it scipy.linalg (~0.15 s CPU)."""
    top = vals[0]
    at = 0
    if math.isnan(top):
        return 0
    for g in range(n):
        if math.isnan(vals[g]):
            return g
        if vals[g] > top:
            top = vals[g]
            at = g
    return at


@njit(**KERNEL_OPTIONS)
def peak_force(lam, fw, R, mult, tc, G, scratch):
    """Largest contact force on [0, t_c] per unit speed [N per m/s] (separation.peak_force):
    every term on G points (:func:`peak_points`), PEAK_GRID points over the four steps around
    the largest value, then Newton on dF/dt = 0 between its neighbours (kept if it improves on
    it). ``scratch`` = (use, vals, buf, ...) holds max(G, PEAK_GRID) points."""
    use, vals, buf = scratch[0], scratch[1], scratch[2]
    for j in range(R):
        use[j] = True
    dt = tc / (G - 1)
    _on_grid(lam, fw, R, use, 0.0, dt, G, vals, buf)
    i = _argmax(vals, G)
    t0 = max(i - 2, 0) * dt
    dt = (min(i + 2, G - 1) * dt - t0) / (PEAK_GRID - 1)
    _on_grid(lam, fw, R, use, t0, dt, PEAK_GRID, vals, buf)
    i = _argmax(vals, PEAK_GRID)
    t = t0 + i * dt
    best = mult * vals[i]
    lo, hi = t - dt, t + dt
    for _ in range(6):
        d1 = d2 = 0.0
        for j in range(R):
            we = fw[j] * lam[j] * cexp(lam[j] * t)
            d1 += we.real
            d2 += (we * lam[j]).real
        tn = t - d1 / d2
        if math.isfinite(tn):
            t = tn
        t = min(max(t, lo), hi)
    f = mult * _value(lam, fw, R, t)[0]
    if math.isfinite(f) and f > best:
        best = f
    return best
