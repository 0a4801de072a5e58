"""The contact force as a piecewise cubic on a uniform grid, and its exact modal response.

The general integrator (:mod:`fem_racket.impact.general.integrator`) represents F(t) on step k,
t = t_k + h sigma with sigma in [0, 1], by the cubic through four grid values (Lagrange)::

    F(t_k + h sigma) = sum_r L_r(sigma) F_{k + o_r}

with the *backward* stencil o = (-2, -1, 0, 1) for k >= 2 (the step's two ends and the two
nodes before it: causal, one new unknown per step, as Adams-Moulton 4) and the *forward*
stencil o = (-k, 1 - k, 2 - k, 3 - k), i.e. nodes 0-3, on steps 0 and 1 (starting values).
F is continuous and interpolated to O(h^4), so every quantity built from it (states, impulse,
contact work) is fourth order (product integration, Brunner 2004, "Collocation Methods for
Volterra Integral and Related Functional Equations", ch. 2; Linz 1985, ch. 7).

A frame mode x'' + omega^2 x = b F(t) responds to such a force exactly: with y = x' + i omega x,
y' = i omega y + b F, so over a step y(t_k + h s) = e^{i omega h s} (y_k + b h sum_q c_q
conj(M_q(theta, s))...) where theta = omega h and the polynomial-exponential moments are::

    M_q(theta, s) = int_0^s exp(i theta u) u^q du = s^{q+1} I_q(theta s)
    I_q(x) = int_0^1 exp(i x u) u^q du = (exp(i x) - q I_{q-1}(x)) / (i x)    (|x| >= 2)
           = sum_n (i x)^n / (n! (n + q + 1))                                 (|x| < 2)

(the recursion loses at most a factor q/|x| <= 1.5 per order for |x| >= 2; the series has 34
terms, 2^34/34! < 1e-27). Rigid coordinates (omega = 0) use M_q(0, s) = s^{q+1}/(q+1).
"""

from __future__ import annotations

import functools
import math

import numpy as np

__all__ = [
    "BACKWARD",
    "ORDER",
    "STENCILS",
    "forward_stencil",
    "lagrange",
    "moments",
    "step_stencil",
]

#: Polynomial degree + 1 of the force on a step (cubic: fourth order).
ORDER = 4
#: Node offsets of the backward stencil relative to the step's start k.
BACKWARD = (-2, -1, 0, 1)
_SERIES = 34
_FACT = np.array([math.factorial(n) for n in range(_SERIES)], dtype=float)


@functools.lru_cache(maxsize=16)
def lagrange(offsets: tuple[float, ...]) -> np.ndarray:
    """Coefficients c[r, q] of sigma^q in the Lagrange basis L_r of nodes ``offsets`` (cached:
    do not modify)."""
    nodes = np.asarray(offsets, dtype=float)
    coef = np.zeros((nodes.size, nodes.size))
    for r, p in enumerate(nodes):
        others = np.delete(nodes, r)
        poly = np.poly(others) / np.prod(p - others)  # highest power first
        coef[r] = poly[::-1]
    return coef


def forward_stencil(k: int) -> tuple[int, ...]:
    """Node offsets (relative to k) of the starting stencil, nodes 0-3, on step k (0 or 1)."""
    return tuple(j - k for j in range(ORDER))


def step_stencil(k: int) -> tuple[int, ...]:
    """Node offsets relative to k of the cubic on step k (forward on steps 0, 1)."""
    return forward_stencil(k) if k < 2 else BACKWARD


#: Lagrange coefficients (3, 4, 4) of the backward stencil and of the forward ones of steps 0, 1.
STENCILS = np.stack([lagrange(k) for k in (BACKWARD, forward_stencil(0), forward_stencil(1))])


def moments(theta: np.ndarray, s: np.ndarray | float = 1.0) -> np.ndarray:
    """M_q(theta, s) = int_0^s exp(i theta u) u^q du for q = 0..3, shape (4,) + broadcast.

    Parameters
    ----------
    theta : ndarray
        omega h [-] (>= 0).
    s : float or ndarray
        Upper limit in steps [-] (0-1).
    """
    theta, s = np.broadcast_arrays(np.asarray(theta, dtype=float), np.asarray(s, dtype=float))
    x = theta * s
    out = np.empty((ORDER,) + x.shape, dtype=complex)
    big = np.abs(x) >= 2.0
    xb = np.where(big, x, 2.0)
    e = np.exp(1j * xb)
    prev = (e - 1.0) / (1j * xb)
    ix_pow = (1j * np.where(big, 0.0, x))[..., None] ** np.arange(_SERIES) / _FACT
    for q in range(ORDER):
        if q > 0:
            prev = (e - q * prev) / (1j * xb)
        series = np.sum(ix_pow / (np.arange(_SERIES) + q + 1.0), axis=-1)
        out[q] = np.where(big, prev, series) * s ** (q + 1)
    return out
