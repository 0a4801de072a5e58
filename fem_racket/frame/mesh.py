"""The frame's 1-D mesh: nodes along the racket with per-cell EI [N m^2] and rhoA [kg/m].

A :class:`FrameMesh` is what the finite-element assembly consumes. Build one from a
:class:`~fem_racket.frame.segments.Frame` with :func:`frame_mesh` (a node at every section step) or
:func:`graded_mesh`, or read a user's line mesh with :func:`fem_racket.io.mesh_files.read_mesh`.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from fem_racket.display import number, short_repr, span
from fem_racket.frame.segments import EI_RANGE, Frame, check_ei_factor
from fem_racket.validation import InputError, check_integer, show

__all__ = [
    "MAX_ELEMENTS",
    "FrameMesh",
    "frame_from_mesh",
    "frame_mesh",
    "graded_mesh",
    "insert_nodes",
]


#: Most cells of a frame mesh. Up to here free-free frequencies stay within ~1e-13 of the exact
#: continuous ones once converged, and COR and t_c within 1e-11 of their converged values
#: (tests/frame/test_fine_mesh.py); the 80 lowest modes take ~10 s and ~0.5 GB. Beyond ~70 000
#: cells scikit-fem's global Hermite basis (the DOF numbering) is singular.
MAX_ELEMENTS = 50_000


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
        if p.size - 1 > MAX_ELEMENTS:
            raise InputError(
                f"mesh: {p.size - 1} cells is not allowed: at most {MAX_ELEMENTS} "
                "(the size up to which results are checked to the stated accuracy)"
            )
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
        ratio = ei / ra
        bad = (ratio < EI_RANGE[0]) | (ratio > EI_RANGE[1])
        if np.any(bad):
            i = int(np.argmax(bad))
            raise InputError(
                f"mesh cell data EI / rhoA = {float(ratio[i]):.3g} m^4/s^2 in cell {i} "
                f"(x = {p[i]:g}..{p[i + 1]:g} m) is not allowed: must lie in "
                f"[{EI_RANGE[0]:g}, {EI_RANGE[1]:g}] m^4/s^2"
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

    def __repr__(self) -> str:
        return short_repr(
            "FrameMesh",
            [
                ("cells", str(self.n_elements)),
                ("length", f"{number(self.length)} m"),
                ("EI", span(self.EI, "N m^2")),
                ("rhoA", span(self.rhoA, "kg/m")),
            ],
        )

    def scaled(self, ei_factor: float = 1.0) -> FrameMesh:
        """The same mesh with every cell's EI multiplied by ``ei_factor``."""
        check_ei_factor(ei_factor, self.EI / self.rhoA)
        return FrameMesh(self.points, self.EI * ei_factor, self.rhoA)


def _check_elements(frame: Frame, elements: int) -> None:
    check_integer("elements", elements, minimum=len(frame.segments), maximum=MAX_ELEMENTS)


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
    from fem_racket.validation import check_finite

    g = check_finite("grading", grading)
    if g < 1.0:
        raise InputError(f"grading = {show(grading)} is not allowed: must be a finite number >= 1")
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
            raise InputError(f"extra point = {show(s)} x/L is not allowed: must lie in [0, 1]")
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
    :class:`~fem_racket.frame.segments.Segment`, so re-meshing the result with :func:`frame_mesh`
    keeps every section step of ``mesh`` on a node.
    """
    from fem_racket.frame.segments import Segment

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
