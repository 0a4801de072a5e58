"""The contact laws and the in-step roots of the general integrator, compiled (numba).

Each function is the scalar form of the numpy expression it mirrors, so the compiled march
(:mod:`fem_racket.impact.general.kernel`) solves the same discrete equations as
:mod:`fem_racket.impact.general.march` (tested to round-off): the laws of
:mod:`fem_racket.contact` by number (:data:`LAW_IDS`, parameters in one row per case, in the
order of :func:`fem_racket.impact.general.compiled.kernel_law`), and
:func:`~fem_racket.impact.general.step.turn_max`,
:func:`~fem_racket.impact.general.step.hermite_root` and
:func:`~fem_racket.impact.general.step.cubic_root`. Imported only where a kernel runs (numba
is heavy); compiled code is cached on disk. The functions a node calls (scalars and tuples only)
are inlined into the march's node loop.
"""

from __future__ import annotations

import math

from fem_racket.impact.general.jit import njit
from fem_racket.impact.kernel_cache import KERNEL_OPTIONS

__all__ = [
    "LAW_IDS",
    "cubic_root",
    "end_value",
    "force",
    "force_partials",
    "hermite_root",
    "power",
    "rate",
    "rate_partials",
    "turn_max",
]

#: Law number per family name: linear (k, c), hunt-crossley (k, n, alpha), hysteretic
#: (k1, k2, n, (k1/k2)^(1/n)), series (K_b, C_b, k_s, k_3).
LAW_IDS = {"linear": 0, "hunt-crossley": 1, "hysteretic": 2, "series": 3}


@njit(inline="always", **KERNEL_OPTIONS)
def end_value(law, p, z):
    """The deflection whose downward crossing ends a "displacement" contact [m]."""
    if law == 2:
        return z * (1.0 - p[3])
    return 0.0 * z


@njit(**KERNEL_OPTIONS)
def force(law, p, d, v, z):
    """F(delta, delta', z) [N]."""
    if law == 0:
        return p[0] * d + p[1] * v
    if law == 1:
        return p[0] * max(d, 0.0) ** p[1] * (1.0 + p[2] * v)
    if law == 2:
        if d >= z:
            return p[0] * max(d, 0.0) ** p[2]
        return p[1] * max(d - end_value(law, p, z), 0.0) ** p[2]
    return p[2] * z + p[3] * (z * (z * z))


@njit(inline="always", **KERNEL_OPTIONS)
def power(base, a, near):
    """base^a [-]; from ``near`` = (b0, b0^a) by its Taylor series in e = base / b0 - 1 where
    |e| (|a| + 4) <= 1e-4 (four terms: the rest < 1e-18 relative, below round-off), else by
    ``pow``. A node's Newton iteration evaluates its law twice; the second time the deflection
    moved by the first update alone, so one ``pow`` per node is enough."""
    b0, s0 = near
    if b0 > 0.0:
        e = (base - b0) / b0
        if abs(e) * (abs(a) + 4.0) <= 1e-4:
            c4 = e * (a - 3.0) * 0.25
            c3 = e * (a - 2.0) * (1.0 / 3.0) * (1.0 + c4)
            c2 = e * (a - 1.0) * 0.5 * (1.0 + c3)
            return s0 * (1.0 + e * a * (1.0 + c2))
    return base**a


@njit(inline="always", **KERNEL_OPTIONS)
def force_partials(law, p, d, v, z, near):
    """(F, dF/d delta, dF/d delta', dF/dz, (base, base^(n - 1))) of a power law at most one
    power per call (x^n = x^(n-1) x; :func:`power` from ``near``, the last call's base and
    power, or (0, 0)); other laws return ``near`` as it was."""
    if law == 0:
        return p[0] * d + p[1] * v, p[0], p[1], 0.0, near
    if law == 1:
        dp = max(d, 0.0)
        s = power(dp, p[1] - 1.0, near)
        spring = p[0] * (s * dp)
        fd = p[1] * p[0] * s * (1.0 + p[2] * v)
        return spring * (1.0 + p[2] * v), fd, p[2] * spring, 0.0, (dp, s)
    if law == 2:
        n = p[2]
        if d >= z:
            base = max(d, 0.0)
            s = power(base, n - 1.0, near)
            return p[0] * (s * base), n * p[0] * s, 0.0, 0.0, (base, s)
        base = max(d - end_value(law, p, z), 0.0)
        s = power(base, n - 1.0, near)
        unload = n * p[1] * s
        return p[1] * (s * base), unload, 0.0, -unload * (1.0 - p[3]), (base, s)
    cubic = p[2] * z + p[3] * (z * (z * z))
    return cubic, 0.0, 0.0, p[2] + 3.0 * p[3] * (z * z), near


@njit(inline="always", **KERNEL_OPTIONS)
def rate(law, p, d, v, z):
    """z' of an ODE state (the series law's string bed) [m/s]."""
    return v - (p[2] * z + p[3] * (z * (z * z)) - p[0] * (d - z)) / p[1]


@njit(inline="always", **KERNEL_OPTIONS)
def rate_partials(law, p, d, v, z):
    """(dz'/d delta, dz'/d delta', dz'/dz)."""
    c = p[1]
    ds = p[2] + 3.0 * p[3] * (z * z)
    return p[0] / c, 1.0, -(ds + p[0]) / c


@njit(inline="always", **KERNEL_OPTIONS)
def hermite_value(s, p0, m0, p1, m1):
    """Cubic Hermite interpolant at fraction s (values p, slopes m per step)."""
    s2, s3 = s * s, s * s * s
    ends = (2 * s3 - 3 * s2 + 1) * p0 + (-2 * s3 + 3 * s2) * p1
    return ends + (s3 - 2 * s2 + s) * m0 + (s3 - s2) * m1


@njit(inline="always", **KERNEL_OPTIONS)
def turn_max(d0, v0, d1, v1, h):
    """Largest delta on the step (cubic Hermite through the ends' delta and delta')."""
    top = max(d0, d1)
    if not (v0 > 0 and v1 <= 0):
        return top
    m0, m1, dd = h * v0, h * v1, d0 - d1
    qa = 6.0 * dd + 3.0 * m0 + 3.0 * m1
    qb = -6.0 * dd - 4.0 * m0 - 2.0 * m1
    disc = math.sqrt(max(qb * qb - 4.0 * qa * m0, 0.0))  # numba's x ** 0.5, as interpreted
    den = -qb + disc
    s = min(max(2.0 * m0 / (den if den > 0 else 1.0), 0.0), 1.0)
    return max(hermite_value(s, d0, m0, d1, m1), top)


@njit(**KERNEL_OPTIONS)
def hermite_root(d0, v0, d1, v1, end, h):
    """Fraction s in (0, 1] where the cubic Hermite interpolant of delta reaches ``end``."""
    p0, p1, m0, m1 = d0 - end, d1 - end, h * v0, h * v1
    if p1 >= 0:
        return 1.0
    s = min(max(p0 / (p0 - p1 if p0 - p1 > 0 else 1.0), 0.0), 1.0)
    for _ in range(8):
        f = hermite_value(s, p0, m0, p1, m1)
        s2 = s * s
        df = (6 * s2 - 6 * s) * (p0 - p1) + (3 * s2 - 4 * s + 1) * m0 + (3 * s2 - 2 * s) * m1
        s = min(max(s - f / (df if df != 0 else -1.0), 0.0), 1.0)
    return s


@njit(**KERNEL_OPTIONS)
def cubic_root(coef, p0, p1):
    """Fraction s in (0, 1] where the step's cubic (coefficients of sigma^q) falls through 0."""
    if p1 > 0:
        return 1.0
    s = min(max(p0 / (p0 - p1 if p0 - p1 > 0 else 1.0), 0.0), 1.0)
    for _ in range(8):
        f = coef[0] + s * (coef[1] + s * (coef[2] + s * coef[3]))
        df = coef[1] + s * (2 * coef[2] + 3 * s * coef[3])
        s = min(max(s - f / (df if df != 0 else -1.0), 0.0), 1.0)
    return s
