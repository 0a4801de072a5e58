"""The strung impact sampled for drawing: the frame and ball as an impact series, and the bed.

The frame and the ball of a :class:`~fem_racket.impact.strung.impact.StrungImpact` become an
:class:`~fem_racket.io.vtk_series.ImpactSeries` (the same fields and drawing conventions as an
impact on the paper's racket: the frame's fields from its Hermite DOFs on a refined polyline, the
ball drawn at ``scale w_ring + (u_B - w_ring) - R_B``, w_ring the head ring's motion at the
impact point, so it follows the exaggerated frame and keeps its true travel into the bed and
its own compression). The bed (:class:`BedSeries`) is its membrane mesh's triangles with the
deflection of every vertex at every step (:func:`fem_racket.io.strung_vtk.strung_fields`: the
ring's motion plus the bed's own).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from fem_racket.frame.model import FrameModel
from fem_racket.impact.strung.impact import StrungImpact
from fem_racket.io.strung_vtk import strung_fields
from fem_racket.io.vtk_series import BALL_RADIUS, ImpactSeries, check_scale
from fem_racket.io.vtk_steps import sample_steps
from fem_racket.strings.membrane import bed_mesh

__all__ = ["BedSeries", "strung_series"]


@dataclass(frozen=True, eq=False)
class BedSeries:
    """The string bed at the drawn steps.

    Attributes
    ----------
    xy : ndarray, shape (nv, 2)
        The mesh's vertices on the racket's face [m] (x along the frame from the grip end).
    triangles : ndarray, shape (nc, 3)
        Vertex indices of its triangles.
    deflection : ndarray, shape (ns, nv)
        Deflection of every vertex [m] at each step.
    contact : ndarray, shape (ns,)
        Displacement of the ball's contact with the bed, u_B - delta [m] (delta: the ball's
        compression), at each step.
    """

    xy: np.ndarray
    triangles: np.ndarray
    deflection: np.ndarray
    contact: np.ndarray


def _polyline(model: FrameModel, x_impact: float, subdivide: int) -> np.ndarray:
    p = np.asarray(model.mesh.points, dtype=float).ravel()
    s = np.arange(subdivide) / subdivide
    x = np.concatenate([(p[:-1, None] + np.diff(p)[:, None] * s).ravel(), p[-1:]])
    return np.unique(np.append(x, x_impact))


def strung_series(
    result: StrungImpact,
    model: FrameModel,
    *,
    subdivide: int = 8,
    frames: int | None = None,
    scale: float = 1.0,
) -> tuple[ImpactSeries, BedSeries]:
    """The frame and ball (an :class:`ImpactSeries`) and the bed (:class:`BedSeries`) of
    ``result`` on the frame ``model`` at ``frames`` steps (every output time when None), the
    frame's deflection exaggerated ``scale`` times (the fields keep their true values)."""
    scale = check_scale(scale)
    steps = sample_steps(result.t.size, frames)
    p = result.point
    L = model.mesh.length
    x_i = p.position * L
    x = _polyline(model, x_i, int(subdivide))
    mid = 0.5 * (x[1:] + x[:-1])
    pts = np.asarray(model.mesh.points, dtype=float).ravel()
    cell = np.clip(np.searchsorted(pts, mid, side="right") - 1, 0, pts.size - 2)
    EI = np.asarray(model.mesh.EI)[cell]
    frame = ~p.bed
    nb = p.ndof_bending
    q = (result.coordinates[:, 1:][:, frame] @ p.frame_shapes.T)[steps]
    qd = (result.rates[:, 1:][:, frame] @ p.frame_shapes.T)[steps]

    def field(points: np.ndarray, order: int, dofs: np.ndarray) -> np.ndarray:
        return np.asarray(model.fe.field_matrix(points, order) @ dofs[:, :nb].T).T

    curvature = field(mid, 2, q)
    point_fields = {
        "deflection [m]": field(x, 0, q),
        "slope [rad]": field(x, 1, q),
        "frame velocity [m/s]": field(x, 0, qd),
    }
    if q.shape[1] > nb:  # off the axis: the twist about the long axis on the same points
        point_fields["twist [rad]"] = q[:, nb:] @ model.torsion.point_matrix(x).T
    u_B = result.coordinates[steps, 0]
    ring = result.coordinates[steps][:, 1:][:, frame] @ p.a[frame]
    series = ImpactSeries(
        t=result.t[steps],
        steps=steps,
        x=x,
        EI=EI,
        point_fields=point_fields,
        cell_fields={"curvature [1/m]": curvature, "bending moment [N m]": curvature * EI},
        ball_fields={
            "deflection [m]": u_B,
            "ball velocity [m/s]": result.rates[steps, 0],
            "contact force [N]": result.force[steps],
        },
        ball_z=scale * ring + (u_B - ring) - BALL_RADIUS,
        x_impact=x_i,
        scale=scale,
        ball_y=p.lateral_m,
    )
    mesh = bed_mesh(float(p.strings.head_length_m), float(p.strings.head_width_m), p.refine)
    xy = mesh.basis.mesh.p.T + np.array([p.strings.head_centre * L, 0.0])
    contact = u_B - result.ball_deflection[steps]
    bed = BedSeries(xy, mesh.basis.mesh.t.T.copy(), strung_fields(result, model)[1][steps], contact)
    return series, bed
