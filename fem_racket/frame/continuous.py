"""Exact natural frequencies of a free-free piecewise-uniform Euler-Bernoulli beam.

Each uniform segment (length l, EI, rhoA) obeys ``EI w'''' = rhoA omega^2 w``, so with
``beta^4 = rhoA omega^2 / EI`` and ``z = beta x`` its state in the scaled variables
``s = [w, w'/beta, w''/beta^2, w'''/beta^3]`` is carried across the segment by the transfer
matrix of Krylov functions::

    T(z) = [[S, T, U, V], [V, S, T, U], [U, V, S, T], [T, U, V, S]]
    S = (cosh z + cos z)/2, T = (sinh z + sin z)/2, U = (cosh z - cos z)/2, V = (sinh z - sin z)/2

At a section step w, w', M = EI w'' and V = EI w''' are continuous (a diagonal change of scale
between the two segments' variables). Free ends (M = V = 0 at x = 0 and x = L) leave a 2-D space
of starting states, spanned by (w, w') = (1, 0) and (0, 1); a natural frequency is an omega at
which that space reaches x = L with a singular (M, V) block. That 2x2 determinant is a single
component of the second exterior power (compound matrix) of the product of transfer matrices,
which is what we propagate: its entries are the 2x2 minors of T, computed by splitting T into its
``e^z, e^-z, cos z, sin z`` parts so that the ``e^z e^z`` product, which cancels exactly, is never
formed. This keeps the determinant accurate to round-off where the plain product of 4x4 transfer
matrices loses a factor cosh(z) of precision (6 digits at z = 14); every segment's factor is
divided by e^z and the state re-normalised, so nothing overflows. The scaled determinant keeps its
sign and has simple roots; for a uniform beam it is (1 - cos(beta L) cosh(beta L)) / 2 e^-beta L,
whose roots are the textbook beta L = 4.7300, 7.8532, 10.9956, 14.1372.

Roots are bracketed by sign changes on a grid of 16 points per pi of the total phase
sum(beta_k l_k) (free-free roots are about pi apart), every grid interval whose samples show a
local minimum of |det| without a sign change is searched (bounded minimisation of the signed
determinant, which falls linearly into the narrow notch between two close roots) to split pairs of
close roots, and each bracket is refined with Brent's method to round-off (xtol 1e-15 relative).
"""

from __future__ import annotations

from collections.abc import Sequence
from itertools import combinations

import numpy as np

from fem_racket.frame.mesh import FrameMesh, frame_from_mesh
from fem_racket.frame.segments import Frame, Segment
from fem_racket.validation import InputError, check_integer

__all__ = ["free_free_determinant", "free_free_frequencies", "uniform_roots"]

#: Index pairs (rows/columns of the 2x2 minors) of the scaled state [w, w', M, V].
_PAIRS = tuple(combinations(range(4), 2))
_START = _PAIRS.index((0, 1))  # free end at x = 0: (w, w') free, M = V = 0
_END = _PAIRS.index((2, 3))  # free end at x = L: det of the (M, V) rows must vanish
#: Grid points per pi of total phase when bracketing roots.
_GRID_PER_PI = 16


def _krylov_parts() -> np.ndarray:
    """Constant matrices A_i with T(z) = sum_i f_i(z) A_i, f = (e^z, e^-z, cos z, sin z)."""
    # Krylov functions as coefficients of (e^z, e^-z, cos, sin).
    S = np.array([0.25, 0.25, 0.5, 0.0])
    T = np.array([0.25, -0.25, 0.0, 0.5])
    U = np.array([0.25, 0.25, -0.5, 0.0])
    V = np.array([0.25, -0.25, 0.0, -0.5])
    layout = [[S, T, U, V], [V, S, T, U], [U, V, S, T], [T, U, V, S]]
    return np.array([[[cell[i] for cell in row] for row in layout] for i in range(4)])


def _compound_parts() -> np.ndarray:
    """B[i, j] with minors of T = sum_ij f_i f_j B[i, j] (6x6 each); B[0, 0] is exactly 0."""
    A = _krylov_parts()
    B = np.zeros((4, 4, 6, 6))
    for p, (r0, r1) in enumerate(_PAIRS):
        for q, (c0, c1) in enumerate(_PAIRS):
            B[:, :, p, q] = np.outer(A[:, r0, c0], A[:, r1, c1]) - np.outer(
                A[:, r0, c1], A[:, r1, c0]
            )
    assert not np.any(B[0, 0]), "the e^z e^z part of the minors must cancel exactly"
    return B


_B = _compound_parts()


def _segment_compound(z: float) -> np.ndarray:
    """Second compound of T(z) divided by e^z (6x6), without forming the e^z e^z products."""
    em = np.exp(-z)
    f = np.array([0.0, em, np.cos(z), np.sin(z)])  # e^-z, cos, sin; e^z handled apart
    # f_i f_j / e^z: products with one e^z factor leave the other factor; the rest carry e^-z;
    # e^z e^z multiplies B[0, 0], which is exactly zero.
    w = np.outer(f, f) * em
    w[0, :] = f
    w[:, 0] = f
    return np.tensordot(w, _B, axes=([0, 1], [0, 1]))


def _check_segments(segments: Sequence[Segment]) -> tuple[Segment, ...]:
    segs = tuple(segments)
    if not segs or not all(isinstance(s, Segment) for s in segs):
        raise InputError("segments is not allowed: must be a non-empty sequence of Segment")
    return segs


def free_free_determinant(frame: Frame | Sequence[Segment], omega: float) -> float:
    """Scaled frequency determinant of the free-free beam at ``omega`` [rad/s].

    Zero exactly at the natural frequencies; positive factors (e^-z per segment and a
    normalisation of the propagated minors) keep it of order one, so it never overflows.
    """
    segs = _check_segments(frame.segments if isinstance(frame, Frame) else frame)
    sq = np.sqrt(float(omega))
    y = np.zeros(6)
    y[_START] = 1.0
    prev = None
    for seg in segs:
        c = (seg.rhoA / seg.EI) ** 0.25  # beta = c sqrt(omega)
        if prev is not None:
            # Continuity of w, w', EI w'', EI w''' between scaled variables of prev and seg.
            r = np.array(
                [
                    1.0,
                    prev[0] / c,
                    prev[1] * prev[0] ** 2 / (seg.EI * c**2),
                    prev[1] * prev[0] ** 3 / (seg.EI * c**3),
                ]
            )
            y = y * np.array([r[a] * r[b] for a, b in _PAIRS])
        y = _segment_compound(c * sq * seg.length) @ y
        y /= np.max(np.abs(y))
        prev = (c, seg.EI)
    return float(y[_END])


def _phase_per_sqrt_omega(segs: Sequence[Segment]) -> float:
    """Total phase sum(beta_k l_k) per sqrt(omega) [s^0.5]."""
    return float(sum((s.rhoA / s.EI) ** 0.25 * s.length for s in segs))


def free_free_frequencies(
    frame: Frame | FrameMesh | Sequence[Segment], n_modes: int = 4
) -> np.ndarray:
    """The lowest ``n_modes`` flexible natural frequencies [Hz] of the free-free beam.

    Parameters
    ----------
    frame : Frame, FrameMesh or sequence of Segment
        The piecewise-uniform beam; a mesh is read as one segment per run of equal cells.
    n_modes : int
        Number of flexible modes (the two rigid-body modes at 0 Hz are not counted).

    Returns
    -------
    ndarray, shape (n_modes,)
        Ascending frequencies [Hz], accurate to a few units of round-off.
    """
    from scipy.optimize import brentq

    if isinstance(frame, FrameMesh):
        frame = frame_from_mesh(frame)
    segs = _check_segments(frame.segments if isinstance(frame, Frame) else frame)
    check_integer("modes", n_modes)
    k = _phase_per_sqrt_omega(segs)

    def det(q: float) -> float:  # q = sqrt(omega)
        return free_free_determinant(segs, q * q)

    dq = np.pi / (_GRID_PER_PI * k)
    # The double root at omega = 0 (rigid modes) is not a sign change; start just above it.
    qs = np.empty(0)
    ds = np.empty(0)
    while True:
        new = (qs.size + 0.5 + np.arange(4 * _GRID_PER_PI)) * dq
        qs = np.concatenate([qs, new])
        ds = np.concatenate([ds, [det(q) for q in new]])
        brackets = _brackets(det, qs, ds)
        if len(brackets) >= n_modes:
            break
        if qs[-1] * k > 4.0 * np.pi * (n_modes + 8):
            raise RuntimeError("free_free_frequencies: fewer roots than expected were found")
    roots = [
        a if a == b else brentq(det, a, b, xtol=1e-15 * b, rtol=4 * np.finfo(float).eps)
        for a, b in brackets[:n_modes]
    ]
    q = np.array(roots)
    return q**2 / (2.0 * np.pi)


def _brackets(det, qs: np.ndarray, ds: np.ndarray) -> list[tuple[float, float]]:
    """Ascending brackets of the roots sampled by (qs, ds).

    A sign change between neighbours is one bracket; an exact zero is a root (a == b). Where
    |det| has a local minimum between two samples of the same sign (how a pair of close roots
    shows on a coarse grid) the interval is searched for the pair (:func:`_split_dip`).
    """
    sign = np.sign(ds)
    out = [(q, q) for q in qs[sign == 0.0]]
    out += [(qs[i], qs[i + 1]) for i in np.flatnonzero(sign[:-1] * sign[1:] < 0.0)]
    mag = np.abs(ds)
    dips = np.flatnonzero(
        (sign[1:-1] == sign[:-2])
        & (sign[1:-1] == sign[2:])
        & (mag[1:-1] <= mag[:-2])
        & (mag[1:-1] <= mag[2:])
    )
    for i in dips + 1:
        out += _split_dip(det, qs[i - 1], qs[i + 1], sign[i])
    return sorted(out)


def _split_dip(det, a: float, b: float, sign: float) -> list[tuple[float, float]]:
    """Brackets of a pair of close roots hiding in [a, b], where |det| has a local minimum.

    Near a close pair, sign * det falls linearly to a narrow notch of the other sign between the
    two roots; a bounded minimisation of sign * det converges to that notch.
    """
    from scipy.optimize import minimize_scalar

    res = minimize_scalar(
        lambda q: sign * det(q), bounds=(a, b), method="bounded", options={"xatol": 1e-15 * b}
    )
    q = float(res.x)
    d = det(q)
    if d == 0.0:
        return [(q, q), (q, q)]  # a double root to round-off
    if np.sign(d) == sign:
        return []
    return [(a, q), (q, b)]


def uniform_roots(n_modes: int = 4) -> np.ndarray:
    """beta L of a uniform free-free beam (roots of cos x cosh x = 1), from the same solver."""
    seg = Segment(1.0, 1.0, 1.0)
    f = free_free_frequencies([seg], n_modes)
    return np.sqrt(2.0 * np.pi * f)
