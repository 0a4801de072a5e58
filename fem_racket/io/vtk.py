"""Write an impact as a VTK time series that ParaView opens: one ``.vtu`` per step and dataset
plus an ``impact.pvd`` collection with the physical times, and a ``provenance.json``.

The grids and their fields are described in :mod:`.vtk_series` (with the measurements that chose
the format).

VTK never writes a file itself here: each ``.vtu`` is made in memory by VTK's XML writer (the
settings of pyvista's ``save``: base64 binary, zlib; byte for byte the same file) and written by
Python. VTK's own file output does not report a full disk reliably (it truncated files silently
and, on a nearly full file system, corrupted the heap and aborted the process); Python's write
raises an ``OSError``, which :func:`fem_racket.outputs.atomic_folder` turns into one line naming
the folder, leaving no partial folder behind.
"""

from __future__ import annotations

import json
import logging
import os
import xml.etree.ElementTree as ET
from contextlib import nullcontext
from pathlib import Path
from typing import TYPE_CHECKING, Any

from fem_racket.extras import require
from fem_racket.io.impact_provenance import impact_provenance
from fem_racket.io.vtk_series import BALL_FIELDS, FRAME_FIELDS, field_name, impact_series
from fem_racket.outputs import atomic_folder, deferred_interrupts
from fem_racket.progress import progress_bar

if TYPE_CHECKING:
    from fem_racket.impact.simulate import ImpactResult

__all__ = ["PROVENANCE_NAME", "PVD_NAME", "write_pvd", "write_vtk_series", "write_vtu"]

log = logging.getLogger(__name__)

PVD_NAME = "impact.pvd"
PROVENANCE_NAME = "provenance.json"


def write_vtu(grid: Any, path: Path) -> None:
    """Write ``grid`` (a pyvista UnstructuredGrid) as ``.vtu`` through Python (see above)."""
    from vtkmodules.vtkIOXML import vtkXMLUnstructuredGridWriter

    writer = vtkXMLUnstructuredGridWriter()
    writer.SetInputData(grid)
    writer.SetDataModeToBinary()
    writer.SetCompressorTypeToZLib()
    writer.WriteToOutputStringOn()
    if writer.Write() != 1:
        raise OSError(f"the VTK writer could not make {path.name}")
    path.write_bytes(writer.GetOutputString().encode("ascii"))


def write_pvd(path: Path, entries: list[tuple[float, int, str, str]]) -> None:
    """The ParaView collection: one ``DataSet`` per (time [s], part, name, file)."""
    root = ET.Element("VTKFile", type="Collection", version="1.0", byte_order="LittleEndian")
    coll = ET.SubElement(root, "Collection")
    for time, part, name, file in entries:
        # repr() round-trips the float64 time exactly.
        ET.SubElement(
            coll, "DataSet", timestep=repr(float(time)), group="", part=str(part), name=name,
            file=file,
        )  # fmt: skip
    ET.indent(root)
    ET.ElementTree(root).write(path, encoding="utf-8", xml_declaration=True)


def write_vtk_series(
    result: ImpactResult,
    folder: str | os.PathLike,
    *,
    subdivide: int = 8,
    frames: int | None = None,
    scale: float = 1.0,
    field: str = "deflection [m]",
    overwrite: bool = False,
    parameters: dict[str, Any] | None = None,
    progress: bool | None = None,
) -> Path:
    """Write an impact as a VTK time series into ``folder``; return the ``.pvd`` path.

    The folder holds ``impact.pvd`` (open it in ParaView: part 0 is the frame, part 1 the ball,
    each step at its physical time in s; off axis part 2 the string face as a surface bent and
    twisted, :mod:`fem_racket.io.vtk_face`), ``frame_NNNN.vtu`` and ``ball_NNNN.vtu`` (and
    ``face_NNNN.vtu``) per step, and
    ``provenance.json`` (software, version, date, the impact's settings and results). It is
    written into a temporary folder and renamed into place when complete; an existing folder is
    replaced only with ``overwrite`` and only if it holds a ``provenance.json``.

    Parameters
    ----------
    result : ImpactResult
    folder : path
        Output folder.
    subdivide, frames, scale
        See :func:`impact_series`.
    field : str
        Frame field made active (the colouring ParaView shows first).
    overwrite : bool
        Replace an existing export.
    parameters : dict, optional
        Extra entries for the provenance (e.g. the command line).
    progress : bool or None
        A progress bar over the steps on stderr (None: when stderr is a terminal).
    """
    with deferred_interrupts():  # an interrupted import of VTK crashes its module loader
        require("pyvista", "write_vtk_series (export-vtk)")
    field = field_name(field)
    series = impact_series(result, subdivide=subdivide, frames=frames, scale=scale)
    settings = {
        "subdivide": subdivide,
        "steps": series.n_steps,
        "deflection_scale": series.scale,
        "ball_radius_m": series.ball_radius,
        "frame_fields": [*FRAME_FIELDS, "EI [N m^2]"],
        "ball_fields": list(BALL_FIELDS),
        "time_s": series.t.tolist(),
    }
    face = None
    if result.twist is not None:  # off axis: the face as a surface that bends and twists
        from fem_racket.io.vtk_face import face_series

        face = face_series(result, series.steps, series.scale)
        settings["face_fields"] = ["displacement [m]", "twist [rad]"]
    meta = impact_provenance(result, {**settings, **(parameters or {})})
    with atomic_folder(folder, overwrite=overwrite, marker=PROVENANCE_NAME) as tmp:
        entries = []
        steps = progress_bar(
            range(series.n_steps), desc="export-vtk", unit="step", enabled=progress
        )
        for n, i in enumerate(steps):
            # the first step makes pyvista import VTK's modules; one interrupted by a signal
            # crashes VTK's module loader, so a signal waits for that step's end
            with deferred_interrupts() if n == 0 else nullcontext():
                frame = series.frame_grid(i)
                if field in series.cell_fields:  # readers colour by the active point scalars first
                    frame.point_data.active_scalars_name = None
                frame.set_active_scalars(field)
                write_vtu(frame, tmp / f"frame_{i:04d}.vtu")
                write_vtu(series.ball_grid(i), tmp / f"ball_{i:04d}.vtu")
                entries += [
                    (series.t[i], 0, "frame", f"frame_{i:04d}.vtu"),
                    (series.t[i], 1, "ball", f"ball_{i:04d}.vtu"),
                ]
                if face is not None:
                    write_vtu(face.grid(i), tmp / f"face_{i:04d}.vtu")
                    entries.append((series.t[i], 2, "face", f"face_{i:04d}.vtu"))
        write_pvd(tmp / PVD_NAME, entries)
        (tmp / PROVENANCE_NAME).write_text(json.dumps(meta, indent=2) + "\n")
    log.info("wrote %d steps to %s", series.n_steps, folder)
    return Path(folder) / PVD_NAME
