"""The frame as the string bed's edge sees it: modes and their values at the impact point.

On the racket's axis (lateral offset y = 0) the frame's free-free bending modes (two rigid:
translation, rotation). Off the axis the frame also twists (:mod:`fem_racket.impact.offaxis`):
the bending and torsion modes side by side, three rigid (translation, rotation, roll), and a
point (x, y) of the head ring moves by ``w(x) + y theta(x)``. The bed's edge follows the ring as
:attr:`fem_racket.strings.bed.StringBed.edge` says:

- ``"point"``: uniformly with the ring at the impact point, ``a_k = w_k(x_i) + y_i theta_k(x_i)``
  (the rigid roll's value y_i / sqrt(I_p));
- ``"hoop"``: each edge point (x_e, y_e) with the ring there, ``w_k(x_e) + y_e theta_k(x_e)``,
  averaged by the bed's static edge transmission T to the impact point,
  ``a_k = sum_e T_e (w_k(x_e) + y_e theta_k(x_e))``. On the axis T is mirror symmetric in y_e,
  so the twist cancels and the bending modes alone are used, as before.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from fem_racket.frame.model import FrameModel
from fem_racket.impact.offaxis import combined_modes, combined_point_vector
from fem_racket.strings.bed import StringBed
from fem_racket.strings.point import edge_transmission

__all__ = ["FrameAtPoint", "frame_at_point"]


@dataclass(frozen=True, eq=False)
class FrameAtPoint:
    """The frame's modes seen at one impact point through the bed's edge.

    Attributes
    ----------
    omega : ndarray
        Flexible angular frequencies, ascending [rad/s].
    a : ndarray
        Values at the point, rigid modes first [1/sqrt(kg)].
    shapes : ndarray, shape (ndof, rigid + flexible)
        Mass-normalised shapes: bending Hermite DOFs in the first ``ndof_bending`` rows, torsion
        DOFs below (off the axis).
    ndof_bending : int
    rigid : int
        Rigid modes: 2 on the axis, 3 off it.
    """

    omega: np.ndarray
    a: np.ndarray
    shapes: np.ndarray
    ndof_bending: int
    rigid: int


def frame_at_point(
    model: FrameModel, bed: StringBed, position: float, point: np.ndarray, refine: int
) -> FrameAtPoint:
    """The frame at the impact point ``position`` (x/L), which is ``point`` on the bed [m, from
    the head's centre: along, across]; every mode of ``model``."""
    L = model.mesh.length
    x_i, lateral_m = position * L, float(point[1])
    if lateral_m == 0.0:
        fm = model.modes(None)
        omega, shapes, nb, rigid = fm.omega, fm.all_shapes, model.fe.ndof, 2
    else:
        cm = combined_modes(model, None)
        omega, shapes, nb, rigid = cm.omega, cm.all_shapes, cm.ndof_bending, 3
    if bed.edge == "point":
        g = (
            model.fe.point_vector(x_i)
            if lateral_m == 0.0
            else combined_point_vector(model, x_i, lateral_m)
        )
        a = shapes.T @ g
    else:
        xy, T = edge_transmission(bed, np.asarray(point)[None], refine)
        x_e = bed.head_centre * L + xy[:, 0]
        R = model.fe.field_matrix(x_e, 0)  # bending deflection at the edge points
        ring = R @ shapes[:nb]
        if lateral_m != 0.0:  # the ring's twist: y_e theta(x_e)
            ring = ring + xy[:, 1:2] * (model.torsion.point_matrix(x_e) @ shapes[nb:])
        a = np.asarray(T[0] @ np.asarray(ring)).ravel()
    return FrameAtPoint(np.asarray(omega), np.asarray(a), np.asarray(shapes), nb, rigid)
