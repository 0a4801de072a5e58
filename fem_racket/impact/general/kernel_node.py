"""One node of the compiled march (numba): the contact equation, the end of contact.

At node m the force solves ``F_m = law(delta_m, delta'_m, z_m)`` with delta_m, delta'_m affine in
F_m (:func:`newton`, as :func:`fem_racket.impact.general.step.solve_step` does for one case);
:func:`node_base` gathers what it needs of the earlier nodes and :func:`solve_node` returns the
node's values; :func:`ended` and :func:`fraction` find the end of contact in a step on the law's
own end condition; :func:`integrals` integrates the outcome from the histories. A case's
histories are the rows of one array (:data:`F` ... :data:`G`). The
functions a node calls take and return scalars only: an array passed to a compiled function
(or an inlined one's alias of it) costs two atomic reference counts per call, which were a
third of a node's time. Used by :mod:`fem_racket.impact.general.kernel`.
"""

from __future__ import annotations

import numpy as np

from fem_racket.impact.general import kernel_laws as kl
from fem_racket.impact.general.jit import njit
from fem_racket.impact.kernel_cache import KERNEL_OPTIONS

__all__ = [
    "D",
    "F",
    "G",
    "NEWTON_ITER",
    "V",
    "Z",
    "ended",
    "fraction",
    "integrals",
    "newton",
    "node_base",
    "solve_node",
]

#: Newton iterations at most.
NEWTON_ITER = 40
#: Rows of a case's histories: F, delta, delta', z, z'.
F, D, V, Z, G = range(5)


@njit(inline="always", **KERNEL_OPTIONS)
def newton(kind, p, lin, guess, prev, step):
    """F and z at a node (as step.solve_step for one case); ok False if not converged.

    ``kind`` = (law, state, ...), ``lin`` = (A, B, kd0, kv0): delta = A - kd0 F, delta' = B -
    kv0 F; ``prev`` = (z at the previous node, the ODE state's base and weight, delta and
    delta' at the previous node); ``step`` = (h, force scale).
    """
    law, state = kind[0], kind[1]
    A, B, kd0, kv0 = lin
    zp, zb, zc, d0, v0 = prev
    h, scale = step
    F, z = guess, zp
    near = (0.0, 0.0)
    for _ in range(NEWTON_ITER):
        d, v = A - kd0 * F, B - kv0 * F
        if state == 1:
            z = max(zp, kl.turn_max(d0, v0, d, v, h))
        f, fd, fv, fz, near = kl.force_partials(law, p, d, v, z, near)
        r1 = F - f
        tol = 1e-12 * (abs(F) + scale)
        if state == 2:
            r2 = z - zb - zc * kl.rate(law, p, d, v, z)
            if abs(r1) <= tol and abs(r2) <= 1e-12 * (abs(z) + 1e-9):
                return F, z, True
            gd, gv, gz = kl.rate_partials(law, p, d, v, z)
            j11 = 1.0 + fd * kd0 + fv * kv0
            j21 = zc * (gd * kd0 + gv * kv0)
            j22 = 1.0 - zc * gz
            det = j11 * j22 + fz * j21
            dF = -(r1 * j22 + fz * r2) / det
            z = z - (j11 * r2 - j21 * r1) / det
        else:
            if abs(r1) <= tol:
                return F, z, True
            dF = -r1 / (1.0 + fd * kd0 + fv * kv0)
        cap = 2.0 * (abs(F) + scale)
        F = F + max(min(dF, cap), -cap)
    return F, z, False


@njit(inline="always", **KERNEL_OPTIONS)
def ended(kind, p, prev, now):
    """True where the contact ends in the step from node m - 1 to node m (``prev``, ``now``:
    F, delta and z at each, scalars: no array passes through a node's calls)."""
    law, end = kind[0], kind[2]
    if end == 1:
        return prev[0] > 0 and now[0] <= 0
    if end == 2:
        return prev[2] > 0 and now[2] <= 0
    e0, e1 = kl.end_value(law, p, prev[2]), kl.end_value(law, p, now[2])
    return prev[1] - e0 > 0 and now[1] - e1 <= 0


@njit(**KERNEL_OPTIONS)
def fraction(kind, p, H, at, h, cs):
    """Where in step m - 1 (``at`` = (m, its stencil's first node b, stencil s)) the contact
    ended (0-1]."""
    law, end = kind[0], kind[2]
    m, b, s = at
    if end == 1:
        coef = np.zeros(4)
        for r in range(4):
            for q in range(4):
                coef[q] += H[F, b + r] * cs[s, r, q]
        return kl.cubic_root(coef, H[F, m - 1], H[F, m])
    if end == 2:
        return kl.hermite_root(H[Z, m - 1], H[G, m - 1], H[Z, m], H[G, m], 0.0, h)
    return kl.hermite_root(
        H[D, m - 1], H[V, m - 1], H[D, m], H[V, m], kl.end_value(law, p, H[Z, m]), h
    )


@njit(**KERNEL_OPTIONS)
def node_base(kind, H, c1, at, h):
    """What the contact equation at node m needs of the earlier nodes (``at`` = (m, b, s):
    stencil s of step m - 1 from node b), as :func:`newton` takes it: z, the ODE state's
    Adams-Moulton base and weight (z_m = zb + zc g_m, on the step's cubic), delta and delta'
    at node m - 1."""
    m, b, s = at
    zb, zc = H[Z, m - 1], 0.0
    if kind[1] == 2:
        acc = 0.0
        for r in range(4):
            acc += H[G, b + r] * (h * c1[s, r])
        zc = h * c1[s, m - b]
        zb = H[Z, m - 1] + acc - zc * H[G, m]
    return H[Z, m - 1], zb, zc, H[D, m - 1], H[V, m - 1]


@njit(inline="always", **KERNEL_OPTIONS)
def solve_node(kind, p, prev, lin, guess, step):
    """The contact equation at a node (``prev`` from :func:`node_base`, ``lin`` and ``step``
    as :func:`newton` takes them): F, delta, delta', z and whether Newton converged."""
    state = kind[1]
    A, B, kd0, kv0 = lin
    Fm, zm, ok = newton(kind, p, lin, guess, prev, step)
    d, v = A - kd0 * Fm, B - kv0 * Fm
    if state == 1 and not ok:  # converged: newton's z is this one, at the same F
        zm = max(prev[0], kl.turn_max(prev[3], prev[4], d, v, step[0]))
    return Fm, d, v, zm, ok


@njit(**KERNEL_OPTIONS)
def integrals(H, at, h, cs, c1, res):
    """The impulse up to separation (``at`` = (last, fraction, nodes)), the peak force, and
    the contact work and impulse over the whole steps up to the last node, into ``res``."""
    last, frac, n = at
    imp, work, before = 0.0, 0.0, 0.0
    for k in range(last):
        s, b = (k + 1, 0) if k < 2 else (0, k - 2)
        si, sw = 0.0, 0.0
        for r in range(4):
            si += c1[s, r] * H[F, b + r]
            sw += c1[s, r] * (H[F, b + r] * H[V, b + r])
        before = imp
        imp += h * si
        work += h * sw
    k = last - 1
    s, b = (k + 1, 0) if k < 2 else (0, k - 2)
    part = 0.0
    # frac^(j + 1) as numba multiplies an integer power, written out: the same bits interpreted
    f2 = frac * frac
    powers = (frac, f2, frac * f2, f2 * f2)
    for r in range(4):
        q = 0.0
        for j in range(4):
            q += cs[s, r, j] * (powers[j] / (j + 1.0))
        part += q * H[F, b + r]
    res[5], res[7], res[8] = before + h * part, work, imp
    top = 0
    for k in range(1, last + 1):
        if H[F, k] > H[F, top]:
            top = k
    i = min(max(top, 1), n - 2)
    a = H[F, i - 1]
    mid = H[F, i] if i <= last else -np.inf
    c = H[F, i + 1] if i + 1 <= last else -np.inf
    den = a - 2.0 * mid + c
    top_f, rise = H[F, top], c - a
    res[6] = mid - 0.125 * (rise * rise) / den if np.isfinite(den) and den < 0.0 else top_f
