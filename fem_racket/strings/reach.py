"""Where the ball may strike the string bed: its contact disk lies on the meshed bed.

The ball loads the bed over a disk of radius a (``StringBed.load_radius_m``) and the bed's
deflection "at the impact point" is the mean over that disk (:func:`~fem_racket.strings.membrane.
disk_load`), so the whole disk must lie on the bed the membrane is solved on: the convex polygon
of the head ellipse's boundary nodes (:func:`~fem_racket.strings.membrane.bed_mesh`; at the
default refinement 64 nodes, its edges at most 0.15 mm inside the ellipse of the default head),
taken from the head outline alone (:func:`~fem_racket.strings.edge.bed_edge`: no membrane is
assembled to check a point).
A disk lies in a convex polygon iff its centre c is at least a inside every edge line,
``n_k . c - h_k >= a`` (n_k inward unit normals), so along a line c = p + t d the allowed t
form one interval, found in closed form: the reachable offsets at a position and the reachable
positions on the axis.
"""

from __future__ import annotations

import numpy as np

from fem_racket.strings.bed import StringBed
from fem_racket.strings.edge import bed_edge, clearance
from fem_racket.strings.point import DEFAULT_REFINE

__all__ = ["on_bed", "strike_interval"]


def _edge(bed: StringBed, refine: int) -> tuple[np.ndarray, np.ndarray]:
    return bed_edge(float(bed.head_length_m), float(bed.head_width_m), refine)


def on_bed(bed: StringBed, point: np.ndarray, refine: int = DEFAULT_REFINE) -> bool:
    """True if the ball's disk centred at ``point`` (x, y) [m from the head's centre] lies on
    the bed meshed with ``refine`` refinements."""
    return bool(clearance(_edge(bed, refine), np.asarray(point, float))[0] >= bed.load_radius_m)


def strike_interval(
    bed: StringBed, point: np.ndarray, direction: np.ndarray, refine: int = DEFAULT_REFINE
) -> tuple[float, float]:
    """The interval [t_lo, t_hi] of t for which the ball's disk centred at ``point`` + t
    ``direction`` [m from the head's centre] lies on the bed (t_lo > t_hi: nowhere)."""
    n, h = _edge(bed, refine)
    p, d = np.asarray(point, float), np.asarray(direction, float)
    need = h + bed.load_radius_m - n @ p  # t (n . d) >= need on each edge line
    nd = n @ d
    if np.any((nd == 0.0) & (need > 0.0)):
        return 1.0, 0.0
    lo = need[nd > 0.0] / nd[nd > 0.0]
    hi = need[nd < 0.0] / nd[nd < 0.0]
    return (float(lo.max()) if lo.size else -np.inf), (float(hi.min()) if hi.size else np.inf)
