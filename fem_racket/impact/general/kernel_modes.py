"""Modal bookkeeping of the compiled march (numba): step weights and state updates.

A kept mode (or the pseudo-mode) x'' + omega^2 x = a^2 F carries y = x' + i omega x; over a
step with the cubic force through 4 nodal values F_r it becomes exactly
y e^{i theta} + a^2 h e^{i theta} sum_r F_r G_r, G_r = sum_q c_rq conj(M_q(theta, 1)),
theta = omega h (:mod:`fem_racket.impact.general.cubic_force`); the rigid modes and the ball
(compliance mu0) integrate the cubic twice. Used by :mod:`fem_racket.impact.general.kernel`.
"""

from __future__ import annotations

import numpy as np
from numba import njit

__all__ = ["advance", "moments", "response", "weights"]

_JIT = {"cache": True, "nogil": True, "error_model": "numpy"}
_SERIES = 34


@njit(**_JIT)
def moments(x):
    """M_q(x, 1) = int_0^1 exp(i x u) u^q du, q = 0..3 (as cubic_force.moments)."""
    out = np.empty(4, dtype=np.complex128)
    if abs(x) >= 2.0:
        ix = 1j * x
        e = np.exp(ix)
        prev = (e - 1.0) / ix
        out[0] = prev
        for q in range(1, 4):
            prev = (e - q * prev) / ix
            out[q] = prev
        return out
    for q in range(4):
        term = 1.0 + 0.0j
        acc = term / (q + 1.0)
        for n in range(1, _SERIES):
            term = term * (1j * x) / n
            acc += term / (n + q + 1.0)
        out[q] = acc
    return out


@njit(**_JIT)
def weights(w, h, cs):
    """Per mode and stencil (backward, forward 0, forward 1) G_r = sum_q c_rq conj(M_q), and
    the rigid weights c1_r = sum_q c_rq / (q + 1), c2_r = sum_q c_rq / ((q + 1)(q + 2))."""
    nm = w.size
    Gw = np.empty((3, 4, nm), dtype=np.complex128)
    for j in range(nm):
        M = np.conj(moments(w[j] * h))
        for s in range(3):
            for r in range(4):
                Gw[s, r, j] = cs[s, r, 0] * M[0] + cs[s, r, 1] * M[1] + cs[s, r, 2] * M[2]
                Gw[s, r, j] += cs[s, r, 3] * M[3]
    c1, c2 = np.zeros((3, 4)), np.zeros((3, 4))
    for s in range(3):
        for r in range(4):
            for q in range(4):
                c1[s, r] += cs[s, r, q] / (q + 1.0)
                c2[s, r] += cs[s, r, q] / ((q + 1.0) * (q + 2.0))
    return Gw, c1, c2


@njit(**_JIT)
def advance(y, R, Rv, f, s, e, a2, mu0, h, Gw, c1, c2):
    """Modal states over one step with stencil s and its 4 nodal forces f; returns R, R'."""
    fd, fv = 0.0, 0.0
    for r in range(4):
        fd += f[r] * c2[s, r]
        fv += f[r] * c1[s, r]
    for j in range(y.size):
        acc = Gw[s, 0, j] * f[0] + Gw[s, 1, j] * f[1] + Gw[s, 2, j] * f[2] + Gw[s, 3, j] * f[3]
        y[j] = e[j] * (y[j] + a2[j] * h * acc)
    return R + h * Rv + mu0 * h * h * fd, Rv + mu0 * h * fv


@njit(**_JIT)
def response(y, R, Rv, w):
    """The forced part of delta and delta' at a node (rigid + ball, then every mode)."""
    d, v = R, Rv
    for j in range(y.size):
        d += y[j].imag / w[j]
        v += y[j].real
    return d, v
