"""Smooth EI(x) and rhoA(x) from a few control points, as piecewise-constant cells of a mesh.

A design may give EI or rhoA by its values q_j at fixed stations s_j (x/L, the first 0 and the
last 1) instead of one value per segment. Between the stations the profile is the monotone
piecewise-cubic Hermite interpolant (PCHIP: Fritsch & Carlson 1980, SIAM J. Numer. Anal. 17,
with the derivative choice of Fritsch & Butland 1984, as :class:`scipy.interpolate.
PchipInterpolator`) or the piecewise-linear one. Neither overshoots its data, so a profile
through positive values stays positive and within the values' range.

The frame model is piecewise uniform, so each mesh cell [x_a, x_b] takes the profile's exact mean
over it::

    q_cell = (Q(x_b) - Q(x_a)) / (x_b - x_a),     Q the antiderivative of the interpolant

which keeps the total mass of a rhoA profile exact on any mesh; the model converges to the smooth
profile's as the cells shrink (the objective's change from 20 to 40 cells is measured by the
tests).
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np

from fem_racket.validation import InputError, check_choice

__all__ = ["INTERPOLATIONS", "cell_means", "check_stations", "tributary_edges"]

#: Interpolants between control points.
INTERPOLATIONS = ("pchip", "linear")


def check_stations(name: str, stations: Sequence[float]) -> tuple[float, ...]:
    """Control-point stations x/L: at least two, increasing, the first 0 and the last 1."""
    s = np.asarray(stations, dtype=float)
    if (
        s.ndim != 1
        or s.size < 2
        or not np.all(np.isfinite(s))
        or np.any(np.diff(s) <= 0.0)
        or s[0] != 0.0
        or s[-1] != 1.0
    ):
        raise InputError(
            f"{name} = {list(stations)} x/L is not allowed: give at least two increasing "
            "stations, the first 0 and the last 1"
        )
    return tuple(float(v) for v in s)


def tributary_edges(stations: Sequence[float]) -> np.ndarray:
    """Interval of the frame each station stands for (x/L): between the midpoints to its
    neighbours (a starting racket's values at the stations are its means over these)."""
    s = np.asarray(stations, dtype=float)
    return np.concatenate([[0.0], 0.5 * (s[1:] + s[:-1]), [1.0]])


def cell_means(
    stations: Sequence[float], values: np.ndarray, points: np.ndarray, kind: str = "pchip"
) -> np.ndarray:
    """Mean of the profile through (``stations`` x/L, ``values``) over each mesh cell.

    Parameters
    ----------
    stations : sequence of float
        Control points x/L (see :func:`check_stations`).
    values : ndarray, shape (n,)
        The profile's values there (SI).
    points : ndarray
        Mesh nodes [m], from 0 to L.
    kind : {"pchip", "linear"}

    Returns
    -------
    ndarray, shape (len(points) - 1,)
    """
    from scipy.interpolate import PchipInterpolator, make_interp_spline

    check_choice("interpolation", kind, INTERPOLATIONS)
    x = np.asarray(stations, dtype=float) * points[-1]
    y = np.asarray(values, dtype=float)
    if kind == "pchip":
        q = PchipInterpolator(x, y).antiderivative()
    else:
        q = make_interp_spline(x, y, k=1).antiderivative()
    return np.diff(q(points)) / np.diff(points)
