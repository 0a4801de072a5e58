"""The frame's 1-D mesh: nodes along the racket with per-cell EI [N m^2] and rhoA [kg/m].

A :class:`FrameMesh` is what the finite-element assembly consumes. Build one from a
:class:`~fem_racket.params.Frame` with :func:`frame_mesh` (a node at every section step), or read
a user's line mesh with :func:`read_mesh` (any file meshio reads, with cell data ``EI`` and
``rhoA``).
"""

from __future__ import annotations

import contextlib
import io
import os
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from .params import Frame
from .validation import InputError, check_integer

__all__ = [
    "FrameMesh",
    "frame_from_mesh",
    "frame_mesh",
    "graded_mesh",
    "insert_nodes",
    "read_mesh",
    "write_mesh",
]


@dataclass(frozen=True, eq=False)
class FrameMesh:
    """Nodes along the frame and the section properties of each cell.

    Parameters
    ----------
    points : ndarray, shape (n+1,)
        Node coordinates [m], strictly increasing, starting at the grip end (0).
    EI : ndarray, shape (n,)
        Bending rigidity of each cell [N m^2].
    rhoA : ndarray, shape (n,)
        Mass per unit length of each cell [kg/m].
    """

    points: np.ndarray
    EI: np.ndarray
    rhoA: np.ndarray

    def __post_init__(self) -> None:
        p = np.asarray(self.points, dtype=float).ravel()
        ei = np.asarray(self.EI, dtype=float).ravel()
        ra = np.asarray(self.rhoA, dtype=float).ravel()
        if p.size < 2:
            raise InputError(f"mesh points: {p.size} given, a mesh needs at least 2 nodes")
        if not np.all(np.isfinite(p)):
            raise InputError("mesh points: contain NaN or inf; must be finite coordinates in m")
        h = np.diff(p)
        if np.any(h <= 0.0):
            i = int(np.argmax(h <= 0.0))
            kind = "zero-length cell" if h[i] == 0.0 else "unsorted nodes"
            raise InputError(
                f"mesh points: {kind} between x = {p[i]:g} m and x = {p[i + 1]:g} m; "
                "nodes must be strictly increasing"
            )
        for name, arr, unit in (("EI", ei, "N m^2"), ("rhoA", ra, "kg/m")):
            if arr.size != h.size:
                raise InputError(
                    f"mesh cell data {name}: {arr.size} values for {h.size} cells; "
                    "need one per cell"
                )
            bad = ~np.isfinite(arr) | (arr <= 0.0)
            if np.any(bad):
                i = int(np.argmax(bad))
                raise InputError(
                    f"mesh cell data {name} = {float(arr[i])!r} {unit} in cell {i} "
                    f"(x = {p[i]:g}..{p[i + 1]:g} m) is not allowed: must be a finite number > 0"
                )
        p = p - p[0]
        for name, arr in (("points", p), ("EI", ei), ("rhoA", ra)):
            arr.setflags(write=False)
            object.__setattr__(self, name, arr)

    @property
    def length(self) -> float:
        """Frame length L [m]."""
        return float(self.points[-1])

    @property
    def n_elements(self) -> int:
        """Number of cells."""
        return int(self.points.size - 1)

    def scaled(self, ei_factor: float = 1.0) -> FrameMesh:
        """The same mesh with every cell's EI multiplied by ``ei_factor``."""
        return FrameMesh(self.points, self.EI * ei_factor, self.rhoA)


def _check_elements(frame: Frame, elements: int) -> None:
    check_integer("elements", elements, minimum=len(frame.segments))


def _mesh_segments(frame: Frame, elements: int, spacing) -> FrameMesh:
    """Cells shared among segments by length; ``spacing(n)`` gives n+1 points on [0, 1]."""
    _check_elements(frame, elements)
    lengths = np.array([s.length for s in frame.segments])
    counts = _share(elements, lengths)
    pts = [np.zeros(1)]
    ei, ra = [], []
    steps = frame.steps
    for k, (seg, n) in enumerate(zip(frame.segments, counts, strict=True)):
        inner = steps[k] + seg.length * spacing(int(n))[1:]
        inner[-1] = steps[k + 1]  # the step itself, bit for bit
        pts.append(inner)
        ei.append(np.full(n, seg.EI))
        ra.append(np.full(n, seg.rhoA))
    points = np.concatenate(pts)
    points[-1] = frame.length
    return FrameMesh(points, np.concatenate(ei), np.concatenate(ra))


def frame_mesh(frame: Frame, elements: int = 20, extra_points: Sequence[float] = ()) -> FrameMesh:
    """Mesh a stepped frame with a node at every section step.

    Parameters
    ----------
    frame : Frame
        The segments, grip end first.
    elements : int
        Total number of cells (at least one per segment). Cells are shared among the segments in
        proportion to their lengths and are uniform inside each segment.
    extra_points : sequence of float
        Positions x/L that must also be nodes (e.g. the impact point); each splits the cell that
        contains it, so the mesh gets one more cell per point not already a node.

    Returns
    -------
    FrameMesh
    """
    mesh = _mesh_segments(frame, elements, lambda n: np.arange(n + 1) / n)
    return insert_nodes(mesh, extra_points)


def graded_mesh(
    frame: Frame,
    elements: int = 20,
    grading: float = 4.0,
    extra_points: Sequence[float] = (),
) -> FrameMesh:
    """Mesh a stepped frame with cells graded towards every section step and both free ends.

    Inside each segment the nodes are the image of a uniform grid s_j = j/n under the smooth map
    ``x(s) = s - c sin(2 pi s) / (2 pi)``, ``c = (grading - 1) / (grading + 1)``: the cells at
    the segment ends are ``grading`` times shorter than those in its middle, and neighbouring
    cells differ by a factor that tends to 1 as n grows, so a sequence of graded meshes keeps the
    convergence order of uniform ones. Every step stays a node.

    Parameters
    ----------
    frame : Frame
    elements : int
        Total number of cells (at least one per segment), shared among segments by length.
    grading : float
        Ratio of the largest to the smallest cell in a segment (>= 1; 1 is uniform).
    extra_points : sequence of float
        Positions x/L that must also be nodes (see :func:`frame_mesh`).
    """
    from .validation import check_finite

    g = check_finite("grading", grading)
    if g < 1.0:
        raise InputError(f"grading = {grading!r} is not allowed: must be a finite number >= 1")
    c = (g - 1.0) / (g + 1.0)

    def spacing(n: int) -> np.ndarray:
        s = np.arange(n + 1) / n
        return s - c * np.sin(2.0 * np.pi * s) / (2.0 * np.pi)

    return insert_nodes(_mesh_segments(frame, elements, spacing), extra_points)


def insert_nodes(mesh: FrameMesh, positions: Sequence[float]) -> FrameMesh:
    """Add nodes at ``positions`` (x/L) by splitting cells; existing nodes are kept as they are."""
    points, ei, ra = mesh.points.copy(), mesh.EI.copy(), mesh.rhoA.copy()
    length = mesh.length
    for s in positions:
        if not 0.0 <= float(s) <= 1.0:
            raise InputError(f"extra point = {s!r} x/L is not allowed: must lie in [0, 1]")
        x = float(s) * length
        if np.min(np.abs(points - x)) <= 1e-12 * length:
            continue
        i = int(np.searchsorted(points, x)) - 1
        points = np.insert(points, i + 1, x)
        ei = np.insert(ei, i, ei[i])
        ra = np.insert(ra, i, ra[i])
    return FrameMesh(points, ei, ra)


def frame_from_mesh(mesh: FrameMesh) -> Frame:
    """The piecewise-uniform frame a mesh describes.

    Consecutive cells with equal EI and rhoA merge into one
    :class:`~fem_racket.params.Segment`, so re-meshing the result with :func:`frame_mesh` keeps
    every section step of ``mesh`` on a node.
    """
    from .params import Segment

    p, ei, ra = mesh.points, mesh.EI, mesh.rhoA
    change = np.flatnonzero((ei[1:] != ei[:-1]) | (ra[1:] != ra[:-1])) + 1
    starts = np.concatenate([[0], change])
    ends = np.concatenate([change, [ei.size]])
    return Frame(
        tuple(
            Segment(float(p[e] - p[s]), float(ei[s]), float(ra[s]))
            for s, e in zip(starts, ends, strict=True)
        )
    )


def _share(total: int, lengths: np.ndarray) -> np.ndarray:
    """Split ``total`` cells among segments in proportion to length, at least one each."""
    ideal = total * lengths / lengths.sum()
    counts = np.maximum(1, np.floor(ideal).astype(int))
    while counts.sum() < total:
        counts[np.argmax(ideal - counts)] += 1
    while counts.sum() > total:
        j = np.argmax(np.where(counts > 1, counts - ideal, -np.inf))
        counts[j] -= 1
    return counts


#: Relative tolerance (of the mesh length) within which cell ends must meet.
JOIN_TOL = 1e-9


def read_mesh(path: str | os.PathLike) -> FrameMesh:
    """Read a 1-D line mesh with cell data ``EI`` [N m^2] and ``rhoA`` [kg/m] through meshio.

    Any format meshio reads (.vtu, .vtk, .xdmf, .msh, ...). The cells must be 2-node ``line``
    cells along x (y and z constant); they may come in any order and are sorted by position, but
    must join end to end (within ``JOIN_TOL`` of the length) without gaps, overlaps or zero-length
    cells. Coordinates are shifted so the grip end is at x = 0. Other cell types (e.g. vertices)
    are ignored.

    Raises
    ------
    InputError
        One line naming the file and what is wrong, and where.
    """
    import meshio

    path = Path(path)
    where = f"mesh = '{path}'"
    if not path.is_file():
        raise InputError(f"{where} is not allowed: no such file")
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
    length = right.max() - left.min()
    if length <= 0.0:
        raise InputError(f"{where} is not allowed: the mesh has zero length")
    tol = JOIN_TOL * length
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
        return FrameMesh(points, ei, ra)
    except InputError as exc:
        raise InputError(f"{where}: {exc}") from None


def write_mesh(
    mesh: FrameMesh,
    path: str | os.PathLike,
    *,
    overwrite: bool = False,
    binary: bool = True,
) -> Path:
    """Write ``mesh`` with cell data ``EI`` [N m^2] and ``rhoA`` [kg/m] in any meshio format.

    The format follows the suffix (.vtu recommended: one self-contained file that ParaView
    opens). The file is written under a temporary name in the same folder and renamed into place
    (:func:`fem_racket.outputs.atomic_output`).

    Parameters
    ----------
    mesh : FrameMesh
    path : path-like
    overwrite : bool
        Replace an existing file; by default an existing file raises :class:`InputError`.
    binary : bool
        For .vtu / .vtk: base64/binary data (exact round trip, the default) or ASCII text (easy
        to read and diff, 12 significant digits). .xdmf is written with its data inline (XML).
    """
    import meshio

    from .outputs import atomic_output

    path = Path(path)
    pts = np.zeros((mesh.points.size, 3))
    pts[:, 0] = mesh.points
    cells = np.column_stack([np.arange(mesh.n_elements), np.arange(1, mesh.n_elements + 1)])
    out = meshio.Mesh(
        pts, [("line", cells)], cell_data={"EI": [mesh.EI.copy()], "rhoA": [mesh.rhoA.copy()]}
    )
    suffix = path.suffix.lower()
    kwargs: dict = {}
    if suffix in (".vtu", ".vtk"):
        kwargs["binary"] = binary
    elif suffix == ".xdmf":
        kwargs["data_format"] = "XML"  # no .h5 beside it (meshio would put it in the cwd)
    elif suffix == ".msh":
        kwargs["file_format"] = "gmsh"  # meshio would otherwise pick ANSYS for .msh
    with atomic_output(path, overwrite=overwrite) as tmp:
        try:
            meshio.write(tmp, out, **kwargs)
        except Exception as exc:  # unknown suffix, unsupported cell data, ...
            msg = " ".join(str(exc).split()) or type(exc).__name__
            raise InputError(f"mesh output = '{path}' cannot be written: {msg}") from None
    return path
