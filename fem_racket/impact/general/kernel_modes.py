"""Modal bookkeeping of the compiled march (numba): step weights and state updates.

A kept mode (or the pseudo-mode) x'' + omega^2 x = a^2 F carries y = x' + i omega x; over a
step with the cubic force through 4 nodal values F_r it becomes exactly
y e^{i theta} + a^2 h e^{i theta} sum_r F_r G_r, G_r = sum_q c_rq conj(M_q(theta, 1)),
theta = omega h (:mod:`fem_racket.impact.general.cubic_force`); the rigid modes and the ball
(compliance mu0) integrate the cubic twice. Used by :mod:`fem_racket.impact.general.kernel`.

The starting steps use :func:`advance` (complex states, any stencil). After them every step has
the backward stencil, and the march (:func:`fem_racket.impact.general.kernel._case`, where this
loop is written out) carries the states as real and imaginary rows with the
weights B_r = e^{i theta} a^2 h G_r folded per mode (rows of one array,
:func:`backward_weights`); a node's own weight B_3 (which multiplies the force still unknown
while its node is solved) is carried into the next step as B_2 + e^{i theta} B_3, so a node
costs one pass over the modes.
"""

from __future__ import annotations

import numpy as np

from fem_racket.impact.general.jit import njit
from fem_racket.impact.kernel_cache import KERNEL_OPTIONS

__all__ = [
    "advance",
    "backward_weights",
    "moments",
    "start_weights",
    "step_weights",
    "weights",
]

_SERIES = 34
#: A series term below this no longer changes M_3 (|M_3| > 0.1 for |x| < 2, and a term bounds
#: the rest of the series to a factor 2 there).
_TERM = 1e-19
#: 1 / k for k = 1 .. _SERIES + 4 (products are cheaper than divisions).
_RECIPROCAL = 1.0 / np.arange(1.0, _SERIES + 5.0)


@njit(inline="always", **KERNEL_OPTIONS)
def _over_ix(z, x):
    """z / (i x), written out as numba divides it (CPython's algorithm, for a divisor whose
    real part is zero): the same bits when the kernels run interpreted."""
    return complex(z.imag / x, -z.real / x)


@njit(**KERNEL_OPTIONS)
def moments(x, e, out):
    """M_q(x, 1) = int_0^1 exp(i x u) u^q du, q = 0..3 (as cubic_force.moments), into ``out``
    (``e`` = e^{i x}).

    |x| >= 2: the upward recursion M_q = (e^{ix} - q M_{q-1}) / (i x); below, M_3 by its series
    sum_n (i x)^n / (n! (n + 4)) and the downward recursion M_{q-1} = (e^{ix} - i x M_q) / q,
    which is stable there (it multiplies an error by |x| / q < 1).
    """
    ix = 1j * x
    if abs(x) >= 2.0:
        prev = _over_ix(e - 1.0, x)
        out[0] = prev
        for q in range(1, 4):
            prev = _over_ix(e - q * prev, x)
            out[q] = prev
        return
    tr, ti = 1.0, 0.0
    ar, ai = 0.25, 0.0
    for n in range(1, _SERIES):
        xn = x * _RECIPROCAL[n - 1]
        tr, ti = -ti * xn, tr * xn
        ar += tr * _RECIPROCAL[n + 3]
        ai += ti * _RECIPROCAL[n + 3]
        if abs(tr) + abs(ti) < _TERM:
            break
    out[3] = ar + 1j * ai
    for q in range(3, 0, -1):
        out[q - 1] = (e - ix * out[q]) * _RECIPROCAL[q - 1]


@njit(**KERNEL_OPTIONS)
def weights(w, h, cs):
    """Per mode and stencil (backward, forward 0, forward 1) G_r = sum_q c_rq conj(M_q), and
    the rigid weights c1_r = sum_q c_rq / (q + 1), c2_r = sum_q c_rq / ((q + 1)(q + 2))."""
    return step_weights(np.exp(1j * w * h), w, h, cs)


@njit(**KERNEL_OPTIONS)
def step_weights(e, w, h, cs):
    """:func:`weights` from e^{i omega h} per mode (the march has it already: one complex
    exponential per mode, not two)."""
    nm = w.size
    Gw = np.empty((3, 4, nm), dtype=np.complex128)
    M = np.empty(4, dtype=np.complex128)
    for j in range(nm):
        moments(w[j] * h, e[j], M)
        for s in range(3):
            for r in range(4):  # sum_q c_rq conj(M_q), real times complex written out
                gr, gi = 0.0, 0.0
                for q in range(4):
                    gr += cs[s, r, q] * M[q].real
                    gi -= cs[s, r, q] * M[q].imag
                Gw[s, r, j] = complex(gr, gi)
    c1, c2 = np.zeros((3, 4)), np.zeros((3, 4))
    for s in range(3):
        for r in range(4):
            for q in range(4):
                c1[s, r] += cs[s, r, q] / (q + 1.0)
                c2[s, r] += cs[s, r, q] / ((q + 1.0) * (q + 2.0))
    return Gw, c1, c2


@njit(**KERNEL_OPTIONS)
def advance(y, rig, f, s, modal, rigid):
    """Modal states y over one step with stencil s and its 4 nodal forces f; ``rig`` = (R, R')
    of the rigid modes and the ball, ``modal`` = (e^{i theta}, a^2, G), ``rigid`` = (mu0, h,
    c1, c2); returns the new (R, R')."""
    R, Rv = rig
    e, a2, Gw = modal
    mu0, h, c1, c2 = rigid
    fd, fv = 0.0, 0.0
    for r in range(4):
        fd += f[r] * c2[s, r]
        fv += f[r] * c1[s, r]
    for j in range(y.size):
        acc = Gw[s, 0, j] * f[0] + Gw[s, 1, j] * f[1] + Gw[s, 2, j] * f[2] + Gw[s, 3, j] * f[3]
        y[j] = e[j] * (y[j] + a2[j] * h * acc)
    return R + h * Rv + mu0 * h * h * fd, Rv + mu0 * h * fv


@njit(**KERNEL_OPTIONS)
def start_weights(modal, w, rigid):
    """delta and delta' (4 x 4: nodes 0-3 by the unit force at nodes 0-3; row 0 zero) of a unit
    force at each starting node through steps 0, 1, 2 (stencils forward 0, forward 1,
    backward), as :func:`advance` gives the states: the rigid part and the ball, then y' and
    Im(y) / omega of every mode."""
    e, a2, Gw = modal
    mu0, h, c1, c2 = rigid
    Wd, Wv = np.zeros((4, 4)), np.zeros((4, 4))
    for node in range(4):
        R, Rv = 0.0, 0.0
        for k in range(3):
            s = 1 + k if k < 2 else 0
            R, Rv = R + h * Rv + mu0 * h * h * c2[s, node], Rv + mu0 * h * c1[s, node]
            Wd[k + 1, node], Wv[k + 1, node] = R, Rv
    for j in range(w.size):
        g = a2[j] * h
        iw = 1.0 / w[j]
        for node in range(4):
            y = 0.0 + 0.0j
            for k in range(3):
                y = e[j] * (y + g * Gw[1 + k if k < 2 else 0, node, j])
                Wd[k + 1, node] += y.imag * iw
                Wv[k + 1, node] += y.real
    return Wd, Wv


@njit(**KERNEL_OPTIONS)
def backward_weights(e, a2, h, Gw, w):
    """Rows (15, modes) for the march's step over the modes: e^{i theta}, B_0, B_1, B_2,
    B_2 + e^{i theta} B_3, B_3 (real and imaginary rows each), 1 / omega (B_r = e^{i theta}
    a^2 h G_r, backward stencil), and two rows left for the march's states (real, imaginary):
    in the same array as the weights, at fixed rows, the compiler sees that the pass over the
    modes reads and writes rows that do not overlap and needs no run-time checks."""
    nm = w.size
    out = np.empty((15, nm))
    for j in range(nm):
        g = e[j] * a2[j] * h
        b2, b3 = g * Gw[0, 2, j], g * Gw[0, 3, j]
        rows = (e[j], g * Gw[0, 0, j], g * Gw[0, 1, j], b2, b2 + e[j] * b3, b3)
        for k in range(6):
            out[2 * k, j], out[2 * k + 1, j] = rows[k].real, rows[k].imag
        out[12, j] = 1.0 / w[j]
    return out
