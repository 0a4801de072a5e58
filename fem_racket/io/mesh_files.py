"""Mesh files: read and write a frame's 1-D line mesh through meshio.

A mesh file holds 2-node ``line`` cells along x with cell data ``EI`` [N m^2] and ``rhoA``
[kg/m], and optionally ``GJ`` [N m^2] and ``rhoIp`` [kg m] (torsion, both or neither); any
format meshio reads works (``meshes/`` uses .vtu: one self-contained file that ParaView opens).
:func:`read_mesh` validates what it reads and names what is wrong and where; :func:`write_mesh`
writes the formats of :data:`MESH_SUFFIXES` only, those :func:`read_mesh` reads the frame back
from.
"""

from __future__ import annotations

import contextlib
import io
import os
from pathlib import Path

import numpy as np

from fem_racket.frame.mesh import FrameMesh
from fem_racket.frame.plausible import check_implement
from fem_racket.validation import InputError, check_file, show_path

__all__ = ["MESH_SUFFIXES", "check_mesh_suffix", "read_mesh", "save_mesh", "write_mesh"]


#: Relative tolerance (of the mesh length) within which cell ends must meet.
JOIN_TOL = 1e-9

#: The suffixes a mesh is written with: the meshio formats that keep 2-node line cells and
#: their cell data (EI, rhoA, GJ, rhoIp), so :func:`read_mesh` reads the frame back (each
#: round-trip tested: exact but .avs, 15 digits). Left out: formats of surface or volume cells
#: (.stl, .obj, .off, .ply, .wkt, dolfin .xml), those that drop cell data (.inp, .bdf, .nas,
#: .fem, .mesh, .meshb, .vol, .mdpa, .dato, .post, exodus .e/.exo/.ex2), those meshio cannot
#: write lines to or read back (.f3grid, .h5m, .cgns, .su2, .ugrid, tetgen .node/.ele) and .hmf
#: (meshio calls it experimental and prints so at every write).
MESH_SUFFIXES = (".vtu", ".vtk", ".xdmf", ".xmf", ".msh", ".med", ".dat", ".tec", ".avs")


def check_mesh_suffix(path: str | os.PathLike, name: str = "out") -> Path:
    """``path`` as a Path, refused (naming ``name`` and the path as given) unless it ends in a
    suffix of :data:`MESH_SUFFIXES` (any case): checked before a mesh is computed."""
    given, path = path, Path(path)
    if path.suffix.lower() not in MESH_SUFFIXES:
        raise InputError(
            f"{name} = {show_path(path)} is not allowed: a mesh file must end in one of "
            f"{', '.join(MESH_SUFFIXES)} (formats that keep line cells and their cell data)",
            parameter=name,
            value=given,
        )
    return path


def read_mesh(path: str | os.PathLike) -> FrameMesh:
    """Read a 1-D line mesh with cell data ``EI`` [N m^2] and ``rhoA`` [kg/m] (optionally
    ``GJ`` [N m^2] and ``rhoIp`` [kg m]) through meshio.

    Any format meshio reads (.vtu, .vtk, .xdmf, .msh, ...). The cells must be 2-node ``line``
    cells along x (y and z constant); they may come in any order and are sorted by position, but
    must join end to end (within ``JOIN_TOL`` of the length) without gaps, overlaps or zero-length
    cells. x is the distance from the grip end: the grip end is the smallest x, which must be
    >= 0 (a file starting further along is shifted to x = 0); negative x is refused rather than
    guessed at (a frame drawn from x = -L to 0 with its grip at 0 would come out mirrored).
    Other cell types (e.g. vertices) are ignored.

    Raises
    ------
    InputError
        One line naming the file and what is wrong, and where.
    """
    import meshio

    path = check_file("mesh", path, "mesh file")
    where = f"mesh = '{path}'"
    chatter = io.StringIO()  # meshio prints its reasons (stdout) and errors (stderr)
    try:
        with contextlib.redirect_stdout(chatter), contextlib.redirect_stderr(chatter):
            m = meshio.read(path)
    except (Exception, SystemExit) as exc:  # meshio raises many types, even SystemExit
        said = " ".join(chatter.getvalue().split()).removeprefix("Error: ")
        msg = " ".join(str(exc).split()) if not isinstance(exc, SystemExit) else ""
        msg = "; ".join(t for t in (said, msg) if t) or type(exc).__name__
        raise InputError(
            f"{where} could not be read ({msg}): must be a line mesh in a format meshio reads"
        ) from None
    lines = [(i, b) for i, b in enumerate(m.cells) if b.type == "line"]
    if not lines:
        types = ", ".join(sorted({b.type for b in m.cells})) or "none"
        raise InputError(
            f"{where} is not allowed: it has no 'line' cells (cell types: {types}); "
            "need 2-node line cells along x"
        )
    pts = np.asarray(m.points, dtype=float)
    if pts.ndim != 2 or pts.shape[0] < 2 or not np.all(np.isfinite(pts)):
        raise InputError(f"{where} is not allowed: point coordinates must be finite numbers")
    conn, data = [], {"EI": [], "rhoA": []}
    given = [n for n in ("GJ", "rhoIp") if n in m.cell_data]
    if len(given) == 1:
        raise InputError(
            f"{where} is not allowed: cell data '{given[0]}' without "
            f"'{({'GJ', 'rhoIp'} - set(given)).pop()}'; torsion needs both GJ [N m^2] and "
            "rhoIp [kg m] (or neither)"
        )
    data.update({n: [] for n in given})
    for name, store in data.items():
        if name not in m.cell_data:
            have = ", ".join(sorted(m.cell_data)) or "none"
            raise InputError(
                f"{where} is not allowed: cell data '{name}' is missing (have: {have}); "
                "need EI [N m^2] and rhoA [kg/m] on every cell"
            )
        for i, block in lines:
            values = np.asarray(m.cell_data[name][i])
            if values.ndim > 1 and values.size != len(block.data):
                raise InputError(
                    f"{where} is not allowed: cell data '{name}' has shape {values.shape}; "
                    "need one number per cell"
                )
            try:
                store.append(values.astype(float).ravel())
            except (TypeError, ValueError):
                raise InputError(
                    f"{where} is not allowed: cell data '{name}' is not numeric"
                ) from None
    for _, block in lines:
        conn.append(np.asarray(block.data))
    conn = np.concatenate(conn)
    ei, ra = np.concatenate(data["EI"]), np.concatenate(data["rhoA"])
    torsion = [np.concatenate(data[n]) for n in given]
    if conn.min() < 0 or conn.max() >= len(pts):
        raise InputError(f"{where} is not allowed: a line cell refers to a point that is not there")
    span = np.ptp(pts[:, 0])
    if pts.shape[1] > 1 and np.any(np.ptp(pts[:, 1:], axis=0) > JOIN_TOL * max(span, 1e-300)):
        raise InputError(
            f"{where} is not allowed: points are not on one line along x (y or z varies); "
            "the frame axis must be x"
        )
    x = pts[:, 0]
    xa, xb = x[conn[:, 0]], x[conn[:, 1]]
    left, right = np.minimum(xa, xb), np.maximum(xa, xb)
    order = np.argsort(left, kind="stable")
    left, right, ei, ra = left[order], right[order], ei[order], ra[order]
    torsion = [t[order] for t in torsion]
    length = right.max() - left.min()
    if length <= 0.0:
        raise InputError(f"{where} is not allowed: the mesh has zero length")
    tol = JOIN_TOL * length
    if left[0] < -tol:
        raise InputError(
            f"{where} is not allowed: x runs from {left[0]:g} to {right.max():g} m; x is the "
            "distance from the grip end, so it must be >= 0 (mirror the file, x -> -x, if its "
            "grip end is at x = 0)"
        )
    short = right - left <= tol
    if np.any(short):
        i = int(np.argmax(short))
        raise InputError(
            f"{where} is not allowed: zero-length cell at x = {left[i]:g} m "
            f"(cell {int(order[i])} of the file)"
        )
    gap = left[1:] - right[:-1]
    bad = np.abs(gap) > tol
    if np.any(bad):
        i = int(np.argmax(bad))
        kind = "gap" if gap[i] > 0 else "overlap"
        raise InputError(
            f"{where} is not allowed: {kind} between x = {right[i]:g} m and "
            f"x = {left[i + 1]:g} m (cells {int(order[i])} and {int(order[i + 1])} of the file); "
            "cells must join end to end"
        )
    points = np.concatenate([left, right[-1:]]) - left[0]
    try:
        mesh = FrameMesh(points, ei, ra, *(torsion or (None, None)))
    except InputError as exc:
        raise InputError(f"{where}: {exc}") from None
    return check_implement(mesh, where)  # a mesh in millimetres is refused, not computed


def write_mesh(
    mesh: FrameMesh,
    path: str | os.PathLike,
    *,
    overwrite: bool = False,
    binary: bool = True,
) -> Path:
    """Write ``mesh`` to ``path`` (:func:`save_mesh`) under a temporary name in the same folder,
    renamed into place (:func:`fem_racket.outputs.atomic_output`).

    Parameters
    ----------
    mesh : FrameMesh
    path : path-like
        Ends in a suffix of :data:`MESH_SUFFIXES` (.vtu recommended: one self-contained file
        that ParaView opens); another is refused before anything is written.
    overwrite : bool
        Replace an existing file; by default an existing file raises :class:`InputError`.
    binary : bool
        As for :func:`save_mesh`.

    Returns
    -------
    Path
        ``path``.
    """
    from fem_racket.outputs import atomic_output

    path = check_mesh_suffix(path, "path")
    with atomic_output(path, overwrite=overwrite) as tmp:
        save_mesh(mesh, tmp, binary=binary)
    return path


def save_mesh(mesh: FrameMesh, path: str | os.PathLike, *, binary: bool = True) -> Path:
    """Write ``mesh`` with cell data ``EI`` [N m^2] and ``rhoA`` [kg/m] (and ``GJ`` [N m^2],
    ``rhoIp`` [kg m] when it has them) to ``path`` itself: for a writer that holds the
    temporary of a set of outputs already (:func:`fem_racket.outputs.atomic_outputs`; a
    temporary of the temporary would nest their names), else :func:`write_mesh`.

    Parameters
    ----------
    mesh : FrameMesh
    path : path-like
        The format follows the suffix, one of :data:`MESH_SUFFIXES`.
    binary : bool
        For .vtu / .vtk: base64/binary data (exact round trip, the default) or ASCII text (easy
        to read and diff, 12 significant digits). .xdmf and .xmf are written with their data
        inline (XML).

    Returns
    -------
    Path
        ``path``.
    """
    import meshio

    path = check_mesh_suffix(path, "path")
    pts = np.zeros((mesh.points.size, 3))
    pts[:, 0] = mesh.points
    cells = np.column_stack([np.arange(mesh.n_elements), np.arange(1, mesh.n_elements + 1)])
    cell_data = {"EI": [mesh.EI.copy()], "rhoA": [mesh.rhoA.copy()]}
    if mesh.has_torsion:
        cell_data.update(GJ=[mesh.GJ.copy()], rhoIp=[mesh.rhoIp.copy()])
    out = meshio.Mesh(pts, [("line", cells)], cell_data=cell_data)
    suffix = path.suffix.lower()
    kwargs: dict = {}
    if suffix in (".vtu", ".vtk"):
        kwargs["binary"] = binary
    elif suffix in (".xdmf", ".xmf"):
        kwargs["data_format"] = "XML"  # no .h5 beside it (named after a temporary, left behind)
    elif suffix == ".msh":
        kwargs["file_format"] = "gmsh"  # meshio would otherwise pick ANSYS for .msh
    try:
        meshio.write(path, out, **kwargs)
    except OSError:
        raise  # a fault of the disk (full, ...): the caller's atomic output names the file
    except Exception as exc:  # unsupported cell data, ... (the suffix is checked before)
        msg = " ".join(str(exc).split()) or type(exc).__name__
        raise InputError(f"mesh output = '{path}' cannot be written: {msg}") from None
    return path
