"""The frame's deformation during an impact as VTK grids: what :mod:`.vtk` writes as a time series.

The frame is a polyline in 3-D: x along the racket from the grip end, y = 0, z = the deflection
w(x, t) (times ``scale``), refined between the FE nodes with the element's own cubic Hermite
interpolation w(x) = g(x) q (Kawazoe & Kanda 1997, section 2.3: beam elements), so the drawn shape
is the finite-element solution, not straight lines between nodes. The ball is a sphere of radius
R_B whose centre moves with the ball displacement u_B (positive towards the frame, +z).

Fields, with their units in the names:

- frame points: ``deflection [m]`` w, ``slope [rad]`` dw/dx, ``frame velocity [m/s]`` dw/dt;
- frame cells (the polyline segments): ``curvature [1/m]`` d^2w/dx^2 and ``bending moment [N m]``
  M = EI d^2w/dx^2, evaluated at each segment's midpoint (cubic Hermite elements are C1, so the
  curvature jumps at the nodes and is a cell quantity), and ``EI [N m^2]``;
- ball points: ``deflection [m]`` its own displacement u_B along z (so that one colour map shows
  both blocks), ``ball velocity [m/s]`` v_B and ``contact force [N]`` F = K_CB delta + C_CB
  delta' (eq 1's spring-dashpot).

Format, chosen by measurement (``scripts/bench_vtk.py --compare-hdf``, 200 steps of the standard
impact): one ``.vtu`` per step and dataset plus a ``.pvd`` collection carrying the physical times
(0.9 s, 4.7 MB with the ball). A single transient ``.vtkhdf`` from VTK's ``vtkHDFWriter`` is
faster (0.3 s, 3.5 MB, frame only) but stores the step times as float32 (errors up to 2e-10 s),
renames fields containing '/' (``velocity [m/s]`` becomes ``velocity [m_s]``), and neither meshio
nor pyvista reads it as a time series (pyvista's HDF reader has no time support), whereas the
``.vtu`` files read back exactly with meshio and pyvista (``PVDReader.time_values``) and the
``.pvd`` opens in ParaView. meshio, pyvista and VTK have no ``.pvd`` writer (pyvista only reads
it), so that small XML collection is written here with ``xml.etree``; the ``.vtu`` files are
made by VTK's XML writer (as pyvista's ``save`` does), because meshio's VTU writer drops field
data (the ``TimeValue`` that ParaView reads from a single file). meshio cannot read VTK string
arrays, hence the provenance is a sidecar JSON, ``provenance.json``.
"""

from __future__ import annotations

import functools
import logging
from dataclasses import dataclass
from typing import TYPE_CHECKING

import numpy as np

from fem_racket.display import number, short_repr
from fem_racket.io.vtk_steps import check_int, sample_steps
from fem_racket.validation import InputError, check_positive, check_range, show

if TYPE_CHECKING:
    import pyvista as pv

    from fem_racket.impact.simulate import ImpactResult

__all__ = [
    "BALL_FIELDS",
    "BALL_RADIUS",
    "FRAME_FIELDS",
    "MAX_SCALE",
    "ImpactSeries",
    "check_scale",
    "field_name",
    "impact_series",
]

#: Largest deflection exaggeration [-]: millimetres drawn as kilometres; far beyond any use, and
#: far below where the drawn coordinates would overflow to infinity.
MAX_SCALE = 1e6

log = logging.getLogger(__name__)

#: Ball radius R_B [m]: mid-range of the ITF rules' diameter, 6.54-6.86 cm.
BALL_RADIUS = 0.0335

#: Point fields of the frame, then its cell fields (all per step).
FRAME_FIELDS = (
    "deflection [m]",
    "slope [rad]",
    "frame velocity [m/s]",
    "curvature [1/m]",
    "bending moment [N m]",
)
#: Point fields of the ball (uniform over the sphere, per step).
BALL_FIELDS = ("deflection [m]", "ball velocity [m/s]", "contact force [N]")

#: Short names accepted for the frame fields (``--field moment``).
FIELD_ALIASES = {name.split(" [")[0].split()[-1]: name for name in FRAME_FIELDS}


def field_name(field: str) -> str:
    """The full frame field name for ``field`` (full name or short alias, e.g. ``"moment"``)."""
    if field in FRAME_FIELDS:
        return field
    if field in FIELD_ALIASES:
        return FIELD_ALIASES[field]
    allowed = ", ".join([*FIELD_ALIASES, *(repr(f) for f in FRAME_FIELDS)])
    raise InputError(f"field = {show(field)} is not allowed: must be one of {allowed}")


@dataclass(frozen=True, eq=False)
class ImpactSeries:
    """The frame and ball of one impact, sampled for drawing; arrays are per step.

    Attributes
    ----------
    t : ndarray, shape (ns,)
        Times [s], a subset of the simulation's output times (``steps`` indexes them).
    x : ndarray, shape (np,)
        Polyline points along the frame [m]: the FE nodes, ``subdivide`` - 1 points inside each
        element, and the impact point.
    EI : ndarray, shape (np - 1,)
        Bending rigidity of the element holding each segment [N m^2].
    point_fields, cell_fields : dict of ndarray, shapes (ns, np) and (ns, np - 1)
        Frame fields keyed by :data:`FRAME_FIELDS` names, true (unscaled) values.
    ball_fields : dict of ndarray, shape (ns,)
        Ball fields keyed by :data:`BALL_FIELDS` names.
    ball_z : ndarray, shape (ns,)
        Height of the ball's centre in the drawing [m] (see :func:`impact_series`).
    scale : float
        Deflection exaggeration of the drawing (fields keep their true values).
    """

    t: np.ndarray
    steps: np.ndarray
    x: np.ndarray
    EI: np.ndarray
    point_fields: dict[str, np.ndarray]
    cell_fields: dict[str, np.ndarray]
    ball_fields: dict[str, np.ndarray]
    ball_z: np.ndarray
    x_impact: float
    scale: float
    ball_radius: float = BALL_RADIUS
    #: Lateral offset y of the impact point [m]: the ball is drawn there (off axis the frame's
    #: point field "twist [rad]" holds the twist about the long axis).
    ball_y: float = 0.0

    def __repr__(self) -> str:
        return short_repr(
            "ImpactSeries",
            [
                ("steps", str(self.n_steps)),
                ("time", f"{number(self.t[0] * 1e3)}-{number(self.t[-1] * 1e3)} ms"),
                ("points", str(self.x.size)),
                ("scale", number(self.scale)),
                ("fields", str([*self.point_fields, *self.cell_fields])),
            ],
        )

    @property
    def n_steps(self) -> int:
        """Number of steps ns."""
        return int(self.t.size)

    def frame_points(self, i: int) -> np.ndarray:
        """Polyline points of step ``i`` [m], shape (np, 3): (x, 0, scale * w)."""
        z = self.scale * self.point_fields["deflection [m]"][i]
        return np.column_stack([self.x, np.zeros_like(self.x), z])

    def frame_grid(self, i: int) -> pv.UnstructuredGrid:
        """The frame at step ``i``: line cells between consecutive points, all frame fields."""
        import pyvista as pv

        n = self.x.size
        lines = np.column_stack([np.arange(n - 1), np.arange(1, n)])
        grid = pv.UnstructuredGrid({pv.CellType.LINE: lines}, self.frame_points(i))
        for name, values in self.point_fields.items():
            grid.point_data[name] = values[i]
        for name, values in self.cell_fields.items():
            grid.cell_data[name] = values[i]
        grid.cell_data["EI [N m^2]"] = self.EI
        self._add_field_data(grid, i)
        grid.set_active_scalars("deflection [m]")
        return grid

    def ball_grid(self, i: int, resolution: int = 24) -> pv.UnstructuredGrid:
        """The ball at step ``i``: a sphere of radius R_B centred at (x_i, 0, ball_z)."""
        grid = _sphere(resolution).copy()
        grid.points = grid.points * self.ball_radius + (self.x_impact, self.ball_y, self.ball_z[i])
        for name, values in self.ball_fields.items():
            grid.point_data[name] = np.full(grid.n_points, values[i])
        self._add_field_data(grid, i)
        grid.set_active_scalars("contact force [N]")
        return grid

    def _add_field_data(self, grid: pv.DataSet, i: int) -> None:
        # "TimeValue" is the name VTK's XML readers (and ParaView) take as the step's time.
        grid.field_data["TimeValue"] = np.array([self.t[i]])
        grid.field_data["deflection scale [-]"] = np.array([self.scale])


@functools.cache
def _sphere(resolution: int) -> pv.UnstructuredGrid:
    """Unit sphere at the origin, no data arrays."""
    import pyvista as pv

    sphere = pv.Sphere(
        radius=1.0, theta_resolution=resolution, phi_resolution=max(resolution // 2, 3)
    )
    grid = sphere.points_to_double().cast_to_unstructured_grid()
    grid.point_data.clear()
    grid.cell_data.clear()
    return grid


def check_scale(scale: object) -> float:
    """``scale`` as a float if it is a deflection exaggeration in (0, :data:`MAX_SCALE`]."""
    return check_range("scale", scale, 0.0, MAX_SCALE, include_low=False)


def impact_series(
    result: ImpactResult,
    *,
    subdivide: int = 8,
    frames: int | None = None,
    scale: float = 1.0,
    ball_radius: float = BALL_RADIUS,
) -> ImpactSeries:
    """Sample an impact's histories on a refined polyline for drawing or export.

    Parameters
    ----------
    result : ImpactResult
        A simulation with histories (``output_step`` not None).
    subdivide : int
        Straight segments per finite element (>= 1); the points inside an element follow its
        cubic Hermite shape functions.
    frames : int, optional
        Number of output times kept, evenly spread, first and last included; all when None.
    scale : float
        Deflection exaggeration of the geometry (> 0). The ball's centre is drawn at
        ``scale * w(x_i) + delta - R_B`` (delta = u_B - w(x_i), the ball/string compression):
        it follows the exaggerated frame but keeps its true compression, so it never passes
        through the frame; with ``scale = 1`` this is u_B - R_B, the ball's own displacement.
    ball_radius : float
        R_B [m].
    """
    subdivide = check_int("subdivide", subdivide, 1, 1000)
    scale = check_scale(scale)
    ball_radius = check_positive("ball_radius", ball_radius, "m")
    if result.t.size < 2:
        raise InputError("result has no time histories: simulate with output_step set (not None)")
    steps = sample_steps(result.t.size, frames)

    mesh = result.model.mesh
    p = mesh.points
    s = np.arange(subdivide) / subdivide
    x = np.concatenate([(p[:-1, None] + np.diff(p)[:, None] * s).ravel(), p[-1:]])
    x = np.unique(np.append(x, result.x_impact))  # the impact point is a point of the line
    mid = 0.5 * (x[1:] + x[:-1])
    cell = np.clip(np.searchsorted(p, mid, side="right") - 1, 0, p.size - 2)
    EI = np.asarray(mesh.EI)[cell]

    def field(points: np.ndarray, order: int, velocity: bool = False) -> np.ndarray:
        return result.frame_field(points, order, velocity)[steps]

    curvature = field(mid, 2)
    point_fields = {
        "deflection [m]": field(x, 0),
        "slope [rad]": field(x, 1),
        "frame velocity [m/s]": field(x, 0, velocity=True),
    }
    if result.twist is not None:  # off axis: the twist about the long axis on the same points
        T = result.model.torsion.point_matrix(x)
        point_fields["twist [rad]"] = (result.twist @ T.T)[steps]
    cell_fields = {"curvature [1/m]": curvature, "bending moment [N m]": curvature * EI}
    u_B = result.ball_displacement[steps]
    w_i = result.impact_point_displacement[steps]
    ball_fields = {
        "deflection [m]": u_B,
        "ball velocity [m/s]": result.ball_velocity[steps],
        "contact force [N]": result.force[steps],
    }
    return ImpactSeries(
        t=result.t[steps],
        steps=steps,
        x=x,
        EI=EI,
        point_fields=point_fields,
        cell_fields=cell_fields,
        ball_fields=ball_fields,
        ball_z=scale * w_i + (u_B - w_i) - ball_radius,
        x_impact=result.x_impact,
        scale=scale,
        ball_radius=ball_radius,
        ball_y=result.offset,
    )
