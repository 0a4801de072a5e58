"""The strung racket's impact as a VTK time series: the frame, the ball and the string bed.

Three parts in ``impact.pvd`` (ParaView opens it; each step at its physical time [s]):

- ``frame`` (part 0): the beam as a polyline through its nodes, x along the racket, y = 0,
  z = its deflection w(x, t) x ``scale``; point field ``deflection [m]`` (and ``twist [rad]``
  when the ball strikes off the axis);
- ``ball`` (part 1): a sphere of radius R_B = 0.033 m touching the bed at the impact point at
  t = 0, its centre moving with u_B; point field ``displacement [m]``;
- ``strings`` (part 2): the bed as a deforming surface (the membrane mesh's triangles on the
  head's ellipse, centred on the frame at the head's centre), z = its deflection: its edge's
  motion (edge ``"point"``: the frame's motion at the impact point everywhere; ``"hoop"``:
  the frame's deflection and twist y theta at each edge point, extended statically inside, as
  the coupling assumes, :mod:`fem_racket.impact.strung.point`) plus the bed's modes (and its
  pseudo-mode's static shape); point field ``deflection [m]``.

Written as :mod:`fem_racket.io.vtk` writes the frame's series (one ``.vtu`` per step and part,
XML by VTK, files by Python, the folder all-or-nothing), with a ``provenance.json``.
"""

from __future__ import annotations

import json
import os
from contextlib import nullcontext
from pathlib import Path
from typing import Any

import numpy as np

from fem_racket.frame.model import FrameModel
from fem_racket.impact.strung.impact import StrungImpact
from fem_racket.io.vtk import PROVENANCE_NAME, PVD_NAME, write_pvd, write_vtu
from fem_racket.io.vtk_series import BALL_RADIUS, check_scale
from fem_racket.io.vtk_steps import sample_steps
from fem_racket.outputs import atomic_folder, deferred_interrupts, provenance
from fem_racket.strings.membrane import bed_mesh

__all__ = ["frame_twist", "strung_fields", "write_strung_vtk"]


def _frame_dofs(result: StrungImpact) -> np.ndarray:
    """The frame's DOFs at every output time (nt, ndof): bending Hermite DOFs, then (off the
    axis) torsion DOFs."""
    p = result.point
    return result.coordinates[:, 1:][:, ~p.bed] @ p.frame_shapes.T


def frame_twist(result: StrungImpact, model: FrameModel) -> np.ndarray | None:
    """The frame's twist [rad] at its nodes at every output time (nt, nodes); None on the
    axis, where it is not excited."""
    q = _frame_dofs(result)
    nb = result.point.ndof_bending
    if q.shape[1] == nb:
        return None
    x_nodes = np.asarray(model.mesh.points, dtype=float).ravel()
    return q[:, nb:] @ model.torsion.point_matrix(x_nodes).T


def strung_fields(result: StrungImpact, model: FrameModel) -> tuple[np.ndarray, np.ndarray]:
    """Deflections [m] at every output time: the frame's at its nodes (nt, nodes) and the bed's
    at its mesh's vertices (nt, vertices)."""
    p = result.point
    eta = result.coordinates[:, 1:]
    frame = ~p.bed
    q = _frame_dofs(result)
    nb = p.ndof_bending
    nodes = q[:, model.fe.deflection_dofs]
    L = model.mesh.length
    mesh = bed_mesh(float(p.strings.head_length_m), float(p.strings.head_width_m), p.refine)
    if p.strings.edge == "point":  # the head ring moves with the impact point (and its twist)
        edge = eta[:, frame] @ p.a[frame]
        full = np.repeat(edge[:, None], mesh.basis.N, axis=1)
    else:  # each edge point with the frame at its x (and y theta), extended statically inside
        from scipy.sparse.linalg import splu

        x_e = p.strings.head_centre * L + mesh.edge_points[:, 0]
        w_e = np.asarray(model.fe.field_matrix(x_e, 0) @ q[:, :nb].T)  # (n_edge, nt)
        if q.shape[1] > nb:
            w_e = w_e + mesh.edge_points[:, 1:2] * (model.torsion.point_matrix(x_e) @ q[:, nb:].T)
        r = float(p.strings.n_x / p.strings.n_y)
        K_ii = (r * mesh.Kxx + mesh.Kyy).tocsc()
        full = np.zeros((q.shape[0], mesh.basis.N))
        full[:, mesh.edge] = w_e.T
        full[:, mesh.interior] = -splu(K_ii).solve((r * mesh.Kxx_ib + mesh.Kyy_ib) @ w_e).T
    full[:, mesh.interior] += eta[:, p.bed] @ p.bed_shapes.T
    return nodes, full[:, mesh.basis.nodal_dofs[0]]


def write_strung_vtk(
    result: StrungImpact,
    model: FrameModel,
    folder: str | os.PathLike,
    *,
    frames: int | None = 60,
    scale: float = 1.0,
    overwrite: bool = False,
    parameters: dict[str, Any] | None = None,
) -> Path:
    """Write the strung impact ``result`` on ``model`` into ``folder``; return the ``.pvd``.

    Parameters
    ----------
    result : StrungImpact
        From :func:`fem_racket.impact.strung.impact.strung_impact` (on a free frame).
    model : FrameModel
        The frame it was computed on.
    folder : path
        Output folder (replaced only with ``overwrite`` and only if it holds a provenance).
    frames : int or None
        Steps written, evenly chosen over the output times (None: every one).
    scale : float
        Factor on the deflections drawn (the fields keep their true values).
    overwrite : bool
    parameters : dict, optional
        Extra provenance entries.
    """
    import pyvista as pv

    scale = check_scale(scale)
    steps = sample_steps(result.t.size, frames)
    nodes, bed = strung_fields(result, model)
    twist = frame_twist(result, model)
    p = result.point
    L = model.mesh.length
    mesh = bed_mesh(float(p.strings.head_length_m), float(p.strings.head_width_m), p.refine)
    tri = mesh.basis.mesh.t.T
    bed_cells = np.column_stack([np.full(len(tri), 3), tri]).ravel()
    bed_xy = mesh.basis.mesh.p.T + np.array([p.strings.head_centre * L, 0.0])
    x_nodes = np.asarray(model.mesh.points, dtype=float).ravel()
    line = np.concatenate([[nodes.shape[1]], np.arange(nodes.shape[1])])
    x_i, y_i = p.position * L, p.lateral_m
    with deferred_interrupts():  # pyvista imports VTK's modules: one interrupted crashes VTK
        sphere = pv.Sphere(radius=BALL_RADIUS, center=(0.0, 0.0, 0.0)).cast_to_unstructured_grid()
    meta = provenance({**result.summary(), "steps": int(steps.size), "scale": scale,
                       **(parameters or {})})  # fmt: skip
    entries = []
    with atomic_folder(folder, overwrite=overwrite, marker=PROVENANCE_NAME) as tmp:
        for n, i in enumerate(steps):
            with deferred_interrupts() if n == 0 else nullcontext():  # (the same, writing)
                t = float(result.t[i])
                frame = pv.UnstructuredGrid(
                    line, np.array([pv.CellType.POLY_LINE]),
                    np.column_stack([x_nodes, np.zeros_like(x_nodes), scale * nodes[i]]),
                )  # fmt: skip
                frame.point_data["deflection [m]"] = nodes[i]
                if twist is not None:
                    frame.point_data["twist [rad]"] = twist[i]
                surf = pv.UnstructuredGrid(
                    bed_cells, np.full(len(tri), pv.CellType.TRIANGLE),
                    np.column_stack([bed_xy, scale * bed[i]]),
                )  # fmt: skip
                surf.point_data["deflection [m]"] = bed[i]
                u_b = float(result.coordinates[i, 0])
                ball = sphere.translate((x_i, y_i, scale * u_b - BALL_RADIUS), inplace=False)
                ball.point_data["displacement [m]"] = np.full(ball.n_points, u_b)
                for part, (name, grid) in enumerate((("frame", frame), ("ball", ball),
                                                     ("strings", surf))):  # fmt: skip
                    grid.field_data["TimeValue"] = np.array([t])
                    write_vtu(grid, tmp / f"{name}_{i:04d}.vtu")
                    entries.append((t, part, name, f"{name}_{i:04d}.vtu"))
        write_pvd(tmp / PVD_NAME, entries)
        (tmp / PROVENANCE_NAME).write_text(json.dumps(meta, indent=2, default=str) + "\n")
    return Path(folder) / PVD_NAME
