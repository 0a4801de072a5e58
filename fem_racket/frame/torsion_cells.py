"""Cell data of a frame in torsion: per-cell GJ [N m^2] and rhoIp [kg m] from its torsion
segments (:class:`~fem_racket.frame.segments.TorsionSegment`), on any mesh."""

from __future__ import annotations

import numpy as np

from fem_racket.frame.segments import Frame

__all__ = ["torsion_cells"]


def torsion_cells(frame: Frame, points: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Per-cell GJ [N m^2] and rhoIp [kg m] of ``frame``'s torsion segments on nodes ``points``.

    A cell holding a torsion step gets the exact means over it: rhoIp by length (its polar
    moment is kept) and GJ harmonically (its static twist under a torque is kept); on cells
    inside one segment these are that segment's values. Put the steps on nodes for the
    elements' full convergence order.
    """
    steps = frame.torsion_steps
    steps[-1] = points[-1]
    gj = np.array([s.GJ for s in frame.torsion])
    rip = np.array([s.rhoIp for s in frame.torsion])

    def integral(values: np.ndarray) -> np.ndarray:  # int_0^x of the piecewise constant
        cum = np.concatenate([[0.0], np.cumsum(values * np.diff(steps))])
        k = np.clip(np.searchsorted(steps, points, side="right") - 1, 0, values.size - 1)
        return cum[k] + values[k] * (points - steps[k])

    h = np.diff(points)
    first = np.searchsorted(steps, points[:-1], side="right") - 1
    last = np.searchsorted(steps, points[1:], side="left") - 1
    inside = first == last  # the cell lies in one segment: its values, bit for bit
    k = np.clip(first, 0, gj.size - 1)
    cell_gj = np.where(inside, gj[k], h / np.diff(integral(1.0 / gj)))
    return cell_gj, np.where(inside, rip[k], np.diff(integral(rip)) / h)
