"""The impact zone: where on the string face the ball lands, as positions with weights.

Objectives average over the zone: ``mean = sum_k w_k f(x_k)`` with ``sum_k w_k = 1``.

- :func:`uniform_zone`: equal weights on evenly spaced points over ``[low, high]`` x/L (the string
  centre region 0.6-0.9 L by default).
- :func:`gaussian_zone`: a normal distribution of impacts about a centre, e.g. the first-mode node
  near 0.77 L: Hatze (1994, J. Appl. Biomech.) found most impacts of good players fall in a region
  centred there (also Choppin et al. 2011, Wimbledon qualifying). Points span +-2.5 sigma, clipped
  to [0, 1], with weights proportional to the density.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from fem_racket.studies.design.zone_kinds import ZONES
from fem_racket.validation import (
    InputError,
    check_integer,
    check_positive,
    check_range,
    show,
)

__all__ = ["MAX_ZONE_POINTS", "ZONES", "ImpactZone", "gaussian_zone", "uniform_zone"]


@dataclass(frozen=True, eq=False)
class ImpactZone:
    """Impact positions and their weights.

    Attributes
    ----------
    positions : ndarray, shape (n,)
        Impact points x/L, increasing, in [0, 1].
    weights : ndarray, shape (n,)
        Non-negative, summing to 1.
    description : str
        How the zone was made (for outputs).
    """

    positions: np.ndarray
    weights: np.ndarray
    description: str = "custom"

    def __post_init__(self) -> None:
        x = np.asarray(self.positions, dtype=float).ravel()
        w = np.asarray(self.weights, dtype=float).ravel()
        if x.size == 0 or x.size != w.size:
            raise InputError(
                f"zone: {x.size} positions and {w.size} weights; need the same number, >= 1"
            )
        if np.any((x < 0.0) | (x > 1.0)) or np.any(np.diff(x) <= 0.0):
            raise InputError("zone positions are not allowed: must increase within [0, 1] x/L")
        if np.any(w < 0.0) or not np.isfinite(w).all() or w.sum() <= 0.0:
            raise InputError("zone weights are not allowed: must be >= 0 with a positive sum")
        object.__setattr__(self, "positions", x)
        object.__setattr__(self, "weights", w / w.sum())

    def mean(self, values: np.ndarray) -> np.ndarray:
        """Weighted mean over the last axis of ``values`` (one entry per position)."""
        return np.asarray(values) @ self.weights


#: Most impact points of a zone: each is one impact per design and speed, and a batch of designs
#: holds them all at once (a smooth mean over x/L needs tens; the paper's 20, Hatze's 20-40).
MAX_ZONE_POINTS = 1000


def uniform_zone(low: float = 0.6, high: float = 0.9, points: int = 20) -> ImpactZone:
    """Evenly spaced points over [low, high] x/L with equal weights."""
    lo = check_range("zone low", low, 0.0, 1.0, unit="x/L")
    hi = check_range("zone high", high, 0.0, 1.0, unit="x/L")
    n = check_integer("zone_points", points, minimum=1, maximum=MAX_ZONE_POINTS)
    if n > 1 and hi <= lo:
        raise InputError(
            f"zone high = {show(high)} x/L is not allowed: must exceed low = {show(low)}"
        )
    x = np.linspace(lo, hi, n) if n > 1 else np.array([0.5 * (lo + hi)])
    return ImpactZone(x, np.ones(n), f"uniform over {lo:g}-{hi:g} L, {n} points")


def gaussian_zone(centre: float, sigma: float = 0.05, points: int = 20) -> ImpactZone:
    """Points over centre +- 2.5 sigma (x/L, clipped to [0, 1]) weighted by a normal density."""
    c = check_range("zone centre", centre, 0.0, 1.0, unit="x/L")
    s = check_positive("zone sigma", sigma, "x/L")
    n = check_integer("zone_points", points, minimum=2, maximum=MAX_ZONE_POINTS)
    x = np.linspace(max(0.0, c - 2.5 * s), min(1.0, c + 2.5 * s), n)
    w = np.exp(-0.5 * ((x - c) / s) ** 2)
    return ImpactZone(x, w, f"Gaussian about {c:.4g} L, sigma {s:g} L, {n} points (Hatze 1994)")
