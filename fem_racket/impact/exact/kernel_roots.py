"""The batched engine's poles and roots of one case, compiled (numba).

The same equations as :mod:`fem_racket.impact.reduction` (the modes kept below beta x omega_c
and the residual pseudo-mode) and :mod:`fem_racket.impact.exact.roots` (undamped starting roots
from a two-pole model of the secular function, the simultaneous Newton/Aberth iteration on
f_p(s) = (d_p + s^2) h(s), residues 1/P'(lambda) checked by the sum rules), written per case:
every case is computed on its own, so its bits do not depend on the batch it is in. Scalar
loops instead of the numpy path's batched matrix products (the same operations, the iteration's
sums reordered as :data:`_FAST` allows). Imported only where a batch runs
(:mod:`fem_racket.impact.exact.batch`).

numba's disk cache keys a compiled function on its own file only; the case loop calls this
module and :mod:`fem_racket.impact.exact.kernel_events`, so
:func:`fem_racket.impact.kernel_cache.guard` removes the room's cached code whenever any of the
three files changed, before anything compiles.
"""

from __future__ import annotations

import math

import numpy as np
from numba import njit

from fem_racket.impact.exact.roots import MAX_ITERATIONS, STEP_TOL, SUM_RULE_TOL
from fem_racket.impact.kernel_cache import KERNEL_OPTIONS

__all__ = ["case_poles", "case_roots"]

#: The root iteration's sums may be reordered (vectorised; ~15 % of the engine's time, roots
#: within ~1e-14 of the sums in order): the same bits on a machine for a case, whatever the
#: batch; NaN and infinity keep their meaning (no "nnan"/"ninf").
_FAST = {"reassoc", "contract", "arcp"}


@njit(**KERNEL_OPTIONS)
def case_poles(omega, values, mu0, omega_c, beta, flex, mass, d, v):
    """Poles d = [0, omega_kept^2, omega_p^2] and weights v = [mu0, a_kept^2, a_p^2] of one
    case into ``d``, ``v``; returns (poles, modes kept) (the pseudo-mode only where something
    is dropped: :func:`fem_racket.impact.reduction.split_modes`)."""
    m = omega.size
    kept = 0
    for j in range(m):
        if omega[j] < beta * omega_c:
            kept += 1
    tail_f, tail_m = 0.0, 0.0  # sums over the dropped tail, from the end (as its cumsum)
    for j in range(m - 1, kept - 1, -1):
        a2 = values[j] * values[j]
        tail_f += a2 / (omega[j] * omega[j])
        tail_m += a2
    tail_f += flex
    tail_m += mass
    d[0], v[0] = 0.0, mu0
    for j in range(kept):
        d[1 + j] = omega[j] * omega[j]
        v[1 + j] = values[j] * values[j]
    R = kept + 1
    if tail_f > 0.0 and tail_m > 0.0:
        d[R], v[R] = tail_m / tail_f, tail_m
        R += 1
    return R, kept


@njit(**KERNEL_OPTIONS)
def _initial(d, v, R, k, om2):
    """Undamped Omega_j^2 from the two-pole model of each interval (roots._initial_roots)."""
    top = d[R - 1]
    total = 0.0
    for i in range(R):
        total += v[i]
    top += k * total
    g0 = (d[1] if R > 1 else top) - d[0]
    for j in range(R):
        hi = d[j + 1] if j < R - 1 else top
        mid = 0.5 * (d[j] + hi)
        C = 1.0 / k
        for i in range(R):
            if i != j and i != j + 1:
                C += v[i] / (d[i] - mid)
        a = v[j]
        b = v[j + 1] if j < R - 1 else 0.0
        g = hi - d[j]
        B = C * g + a + b
        disc = math.sqrt(max(B * B - 4.0 * C * a * g, 0.0))
        if j == R - 1:
            y = a / C  # last interval: no upper pole
        elif B > 0.0:
            y = 2.0 * a * g / (B + disc)
        else:
            y = (B - disc) / (2.0 * C)
        if math.isnan(y):
            y = 0.5 * g0
        om2[j] = d[j] + min(max(y, 1e-9 * g), g * (1.0 - 1e-9))


@njit(**KERNEL_OPTIONS)
def _inverse(z):
    """1/z as conj(z)/|z|^2 (no overflow at the sizes here: |z|^2 < ~1e30)."""
    inv = 1.0 / (z.real * z.real + z.imag * z.imag)
    return complex(z.real * inv, -z.imag * inv)


@njit(**KERNEL_OPTIONS, fastmath=_FAST)
def case_roots(d, v, R, k, c, lam, res, work, scratch):
    """Damped upper-half-plane roots ``lam`` and residues ``res`` (first R entries) of one
    case; returns whether it converged and its sum rules hold. ``work`` (float) and
    ``scratch`` = (step, dfl (complex), pole (int)) hold at least R entries."""
    step, dfl, pole = scratch
    _initial(d, v, R, k, work)
    for j in range(R):
        lam[j] = complex(0.0, math.sqrt(work[j]))
        upper = d[j + 1] if j < R - 1 else np.inf
        pole[j] = j + 1 if (j < R - 1 and upper - work[j] < work[j] - d[j]) else j
    converged = False
    for j in range(R):
        work[j] = 1.0  # still moving
    for _ in range(MAX_ITERATIONS):
        for j in range(R):
            if work[j] == 0.0:
                step[j] = 0.0
                continue
            s = lam[j]
            s2 = s * s
            s2r, s2i = s2.real, s2.imag
            p = pole[j]
            # S0 = sum v_i x_i, S1 = sum x_i, S2 = sum v_i x_i^2 with x_i = 1/(d_i + s^2), i != p
            # (real arithmetic: v_i and d_i are real)
            a0 = b0 = a1 = b1 = a2 = b2 = 0.0
            for i in range(R):
                if i != p:
                    zr = d[i] + s2r
                    inv = 1.0 / (zr * zr + s2i * s2i)
                    xr, xi = zr * inv, -s2i * inv
                    vi = v[i]
                    a0 += vi * xr
                    b0 += vi * xi
                    a1 += xr
                    b1 += xi
                    a2 += vi * (xr * xr - xi * xi)
                    b2 += vi * (2.0 * xr * xi)
            S0, S1, S2 = complex(a0, b0), complex(a1, b1), complex(a2, b2)
            ikcs = _inverse(k + c * s)
            q = ikcs + S0
            e = d[p] + s2
            f = v[p] + e * q
            df = 2.0 * s * q - e * (c * ikcs * ikcs + 2.0 * s * S2)
            # Aberth: the other poles of f_p, minus the conjugate root and the neighbours
            corr = 2.0 * s * S1 + c * ikcs + complex(0.0, 0.5 / s.imag)
            if j > 0:
                u = s - lam[j - 1].real
                corr -= 2.0 * u * _inverse(u * u + lam[j - 1].imag ** 2)
            if j < R - 1:
                u = s - lam[j + 1].real
                corr -= 2.0 * u * _inverse(u * u + lam[j + 1].imag ** 2)
            step[j] = f * _inverse(df + f * corr)
            dfl[j] = df
        done = True
        for j in range(R):
            lam[j] -= step[j]
            if abs(step[j]) <= STEP_TOL * abs(lam[j]):
                work[j] = 0.0  # converged: it stays (its neighbours still see it)
            else:
                done = False
        if done:
            converged = True
            break
    # residues at the final roots (df from one negligible step before), then the sum rules
    ok = converged
    r0 = r1 = a0 = a1 = 0.0
    for j in range(R):
        s = lam[j]
        s2 = s * s
        res[j] = (d[pole[j]] + s2) / (s2 * (k + c * s) * dfl[j])
        r = res[j]
        if not (math.isfinite(r.real) and math.isfinite(r.imag)):
            ok = False
        if not s.real <= 1e-12 * abs(s):
            ok = False
        lr = s * r
        r0 += r.real
        a0 += abs(r)
        r1 += lr.real
        a1 += abs(lr)
    ok = ok and abs(2.0 * r0) <= SUM_RULE_TOL * 2.0 * a0
    return ok and abs(2.0 * r1 - 1.0) <= SUM_RULE_TOL * 2.0 * a1
