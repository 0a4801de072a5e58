"""The frame's 1-D mesh: nodes along the racket with per-cell EI [N m^2] and rhoA [kg/m].

A :class:`FrameMesh` is what the finite-element assembly consumes. Build one from a
:class:`~fem_racket.params.Frame` with :func:`frame_mesh` (a node at every section step), or read
a user's line mesh with :func:`read_mesh` (any file meshio reads, with cell data ``EI`` and
``rhoA``).
"""

from __future__ import annotations

import os
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

import numpy as np

from .params import Frame
from .validation import InputError

__all__ = ["FrameMesh", "frame_mesh", "read_mesh", "write_mesh"]


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
                    f"mesh cell data {name} = {arr[i]!r} {unit} in cell {i} is not allowed: "
                    "must be a finite number > 0"
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
    n_seg = len(frame.segments)
    if isinstance(elements, bool) or not isinstance(elements, (int, np.integer)):
        raise InputError(f"elements = {elements!r} is not allowed: must be an integer >= {n_seg}")
    if elements < n_seg:
        raise InputError(
            f"elements = {elements} is not allowed: must be an integer >= {n_seg} "
            "(one per frame segment)"
        )
    lengths = np.array([s.length for s in frame.segments])
    counts = _share(elements, lengths)
    pts = [np.zeros(1)]
    ei, ra = [], []
    x0 = 0.0
    for seg, n in zip(frame.segments, counts, strict=True):
        pts.append(x0 + seg.length * np.arange(1, n + 1) / n)
        ei.append(np.full(n, seg.EI))
        ra.append(np.full(n, seg.rhoA))
        x0 += seg.length
    points = np.concatenate(pts)
    points[-1] = frame.length
    mesh = FrameMesh(points, np.concatenate(ei), np.concatenate(ra))
    return insert_nodes(mesh, extra_points)


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


def read_mesh(path: str | os.PathLike) -> FrameMesh:
    """Read a 1-D line mesh with cell data ``EI`` [N m^2] and ``rhoA`` [kg/m] through meshio.

    The cells must be 2-node lines along x; they are sorted by position and must join without
    gaps or overlaps.
    """
    import meshio

    path = Path(path)
    if not path.is_file():
        raise InputError(f"mesh = '{path}' is not allowed: no such file")
    try:
        m = meshio.read(path)
    except Exception as exc:  # meshio raises many types for malformed files
        raise InputError(f"mesh = '{path}' could not be read: {exc}".splitlines()[0]) from None
    lines = [(i, b) for i, b in enumerate(m.cells) if b.type == "line"]
    if not lines:
        raise InputError(f"mesh = '{path}' is not allowed: it has no 'line' cells")
    conn, ei, ra = [], [], []
    for i, block in lines:
        for name, store in (("EI", ei), ("rhoA", ra)):
            if name not in m.cell_data:
                raise InputError(
                    f"mesh = '{path}' is not allowed: cell data '{name}' is missing "
                    "(need EI [N m^2] and rhoA [kg/m] on every cell)"
                )
            store.append(np.asarray(m.cell_data[name][i], dtype=float).ravel())
        conn.append(block.data)
    conn = np.concatenate(conn)
    ei, ra = np.concatenate(ei), np.concatenate(ra)
    x = np.asarray(m.points, dtype=float)[:, 0]
    xa, xb = x[conn[:, 0]], x[conn[:, 1]]
    left, right = np.minimum(xa, xb), np.maximum(xa, xb)
    order = np.argsort(left)
    left, right, ei, ra = left[order], right[order], ei[order], ra[order]
    if np.any(right - left <= 0.0):
        i = int(np.argmax(right - left <= 0.0))
        raise InputError(f"mesh = '{path}' is not allowed: zero-length cell at x = {left[i]:g} m")
    gap = left[1:] - right[:-1]
    tol = 1e-9 * (right[-1] - left[0])
    if np.any(np.abs(gap) > tol):
        i = int(np.argmax(np.abs(gap) > tol))
        kind = "gap" if gap[i] > 0 else "overlap"
        raise InputError(
            f"mesh = '{path}' is not allowed: {kind} between x = {right[i]:g} m and "
            f"x = {left[i + 1]:g} m; cells must join end to end"
        )
    points = np.concatenate([left, right[-1:]])
    if points[0] != 0.0:
        points = points - points[0]
    return FrameMesh(points, ei, ra)


def write_mesh(mesh: FrameMesh, path: str | os.PathLike) -> Path:
    """Write ``mesh`` with cell data ``EI`` and ``rhoA`` in any meshio format (by suffix).

    The file is written to a temporary name in the same folder and renamed into place.
    """
    import meshio

    path = Path(path)
    pts = np.zeros((mesh.points.size, 3))
    pts[:, 0] = mesh.points
    cells = np.column_stack([np.arange(mesh.n_elements), np.arange(1, mesh.n_elements + 1)])
    out = meshio.Mesh(
        pts, [("line", cells)], cell_data={"EI": [mesh.EI.copy()], "rhoA": [mesh.rhoA.copy()]}
    )
    tmp = path.with_name(f".{path.stem}.tmp{path.suffix}")
    try:
        meshio.write(tmp, out)
        os.replace(tmp, path)
    finally:
        if tmp.exists():
            tmp.unlink()
    return path
