"""The string face as a surface for VTK: the head outline's plane, deformed by bending and twist.

Off axis the frame twists, and a line along the long axis cannot show it. The face (the head
outline, :class:`~fem_racket.frame.head.HeadOutline`) is drawn as a quad grid over the ellipse:
``n_along`` stations x_j from the throat end to the tip, at each ``n_across`` points
y = r half_width(x_j), r in [-1, 1]. Each point moves normal to the face by

    z(x, y, t) = w(x, t) + y theta(x, t)

(bending deflection plus the twist about the long axis, exactly as the ball's contact point;
:mod:`fem_racket.impact.offaxis`), drawn times the deflection scale. Point fields:
``displacement [m]`` (z) and ``twist [rad]`` (theta at the point's x).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from fem_racket.frame.head import DEFAULT_HEAD

__all__ = ["FaceSeries", "face_series"]


@dataclass(frozen=True, eq=False)
class FaceSeries:
    """The face's points and motion at the sampled steps.

    Attributes
    ----------
    x, y : ndarray, shape (n_along, n_across)
        Point positions on the undeformed face [m].
    w, theta : ndarray, shape (ns, n_along)
        Bending deflection [m] and twist [rad] at each station and step.
    scale : float
        Deflection exaggeration of the drawn geometry.
    """

    x: np.ndarray
    y: np.ndarray
    w: np.ndarray
    theta: np.ndarray
    scale: float

    def displacement(self, i: int) -> np.ndarray:
        """z = w + y theta at step ``i`` [m], shape (n_along, n_across)."""
        return self.w[i][:, None] + self.y * self.theta[i][:, None]

    def grid(self, i: int) -> Any:
        """The face at step ``i`` as a pyvista UnstructuredGrid of quads."""
        import pyvista as pv

        z = self.displacement(i)
        shape = (*self.x.shape, 1)
        surface = pv.StructuredGrid(
            self.x.reshape(shape), self.y.reshape(shape), (self.scale * z).reshape(shape)
        )
        surface.point_data["displacement [m]"] = z.ravel(order="F")
        theta = np.broadcast_to(self.theta[i][:, None], self.x.shape)
        surface.point_data["twist [rad]"] = theta.ravel(order="F")
        grid = surface.cast_to_unstructured_grid()
        grid.set_active_scalars("displacement [m]")
        return grid


def face_series(
    result: Any, steps: np.ndarray, scale: float, n_along: int = 41, n_across: int = 15
) -> FaceSeries:
    """The face of an off-axis ``result`` (with twist histories) at output steps ``steps``."""
    length = result.model.mesh.length
    head = DEFAULT_HEAD.on_frame(length)
    lo, hi = head.x_range
    s = np.linspace(-1.0, 1.0, n_along)
    xs = head.centre_m + 0.5 * (hi - lo) * np.sin(0.5 * np.pi * s)  # finer near both ends
    half = np.nan_to_num(head.half_width(xs))
    r = np.linspace(-1.0, 1.0, n_across)
    x = np.broadcast_to(xs[:, None], (n_along, n_across)).copy()
    y = half[:, None] * r[None, :]
    w = result.frame_field(xs, 0)[steps]
    T = result.model.torsion.point_matrix(xs)
    theta = (result.twist @ T.T)[steps]
    return FaceSeries(x, y, w, theta, scale)
