"""One node of the compiled march (numba): the contact equation, the end of contact.

At node m the force solves ``F_m = law(delta_m, delta'_m, z_m)`` with delta_m, delta'_m affine in
F_m (:func:`newton`, as :func:`fem_racket.impact.general.step.solve_step` does for one case);
:func:`solve_node` sets the node's histories; :func:`ended` and :func:`fraction` find the end of
contact in a step on the law's own end condition. A case's histories are the rows of one array
(:data:`F` ... :data:`G`), passed whole: no reference counts per node. Used by
:mod:`fem_racket.impact.general.kernel`.
"""

from __future__ import annotations

import numpy as np

from fem_racket.impact.general import kernel_laws as kl
from fem_racket.impact.general.jit import njit

__all__ = ["D", "F", "G", "NEWTON_ITER", "V", "Z", "ended", "fraction", "newton", "solve_node"]

_JIT = {"cache": True, "nogil": True, "error_model": "numpy"}
#: Newton iterations at most.
NEWTON_ITER = 40
#: Rows of a case's histories: F, delta, delta', z, z'.
F, D, V, Z, G = range(5)


@njit(**_JIT)
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
    for _ in range(NEWTON_ITER):
        d, v = A - kd0 * F, B - kv0 * F
        if state == 1:
            z = max(zp, kl.turn_max(d0, v0, d, v, h))
        f, fd, fv, fz = kl.force_partials(law, p, d, v, z)
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


@njit(inline="always", **_JIT)
def ended(kind, p, H, m):
    """True where the contact ends in step m - 1 (nodes m - 1, m)."""
    law, end = kind[0], kind[2]
    if end == 1:
        return H[F, m - 1] > 0 and H[F, m] <= 0
    if end == 2:
        return H[Z, m - 1] > 0 and H[Z, m] <= 0
    e0, e1 = kl.end_value(law, p, H[Z, m - 1]), kl.end_value(law, p, H[Z, m])
    return H[D, m - 1] - e0 > 0 and H[D, m] - e1 <= 0


@njit(**_JIT)
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


@njit(inline="always", **_JIT)
def solve_node(kind, p, H, at, lin, guess, step, c1):
    """The contact equation at node m (``at`` = (m, b, s): stencil s of step m - 1 from node
    b; ``lin``, ``step`` as :func:`_newton`); False if Newton fails."""
    law, state = kind[0], kind[1]
    m, b, s = at
    A, B, kd0, kv0 = lin
    h = step[0]
    zb, zc = H[Z, m - 1], 0.0
    if state == 2:  # Adams-Moulton on the step's cubic: z_m = zb + zc g_m
        acc = 0.0
        for r in range(4):
            acc += H[G, b + r] * (h * c1[s, r])
        zc = h * c1[s, m - b]
        zb = H[Z, m - 1] + acc - zc * H[G, m]
    Fm, zm, ok = newton(kind, p, lin, guess, (H[Z, m - 1], zb, zc, H[D, m - 1], H[V, m - 1]), step)
    d, v = A - kd0 * Fm, B - kv0 * Fm
    if state == 1:
        zm = max(H[Z, m - 1], kl.turn_max(H[D, m - 1], H[V, m - 1], d, v, h))
    H[F, m], H[D, m], H[V, m], H[Z, m] = Fm, d, v, zm
    if state == 2:
        H[G, m] = kl.rate(law, p, d, v, zm)
    return ok
