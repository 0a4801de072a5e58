"""The meshed bed's edge from the head outline alone: its straight edges as half-planes.

The membrane (:func:`fem_racket.strings.membrane.bed_mesh`) is meshed on scikit-fem's unit disk
``MeshTri.init_circle(refine)`` mapped to the head ellipse x = (L_h/2) X, y = (W/2) Y, so the bed
is the convex polygon of the disk's boundary nodes so mapped. ``init_circle`` starts from the four
nodes (1, 0), (0, 1), (-1, 0), (0, -1) and ``refine`` times splits every edge (u, v) at
m = (u + v) / 2 and divides every boundary node by its norm: on the boundary, the edge (u, v)
becomes (u, m) and (v, m), m numbered after every older node. :func:`bed_edge` does exactly that
to the boundary alone, so its nodes and edges are the mesh's to the bit
(``tests/strings/test_edge.py``) without scikit-fem's import or the membrane's assembly (~0.3 s):
what a check of the impact point needs (:mod:`fem_racket.strings.reach`). Each edge is written
``n . p >= h`` (inward unit normal n, level h [m]) from its lower-numbered node, as the mesh's
facets list it.
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np

__all__ = ["bed_edge", "clearance", "edge_lines"]

#: ``init_circle``'s boundary nodes before refinement, and its boundary edges (node pairs, the
#: lower-numbered node first).
_SQUARE = np.array([[1.0, 0.0], [0.0, 1.0], [-1.0, 0.0], [0.0, -1.0]])
_SIDES = np.array([[0, 1], [1, 2], [2, 3], [0, 3]])


def _unit_edge(refine: int) -> tuple[np.ndarray, np.ndarray]:
    """The boundary edges of ``init_circle(refine)``: their lower- and higher-numbered nodes
    (X, Y) on the unit circle, shape (4 2^refine, 2) each."""
    p, sides = _SQUARE, _SIDES
    for _ in range(refine):
        mid = np.arange(len(p), len(p) + len(sides))
        p = np.vstack([p, (p[sides[:, 0]] + p[sides[:, 1]]) / 2.0])
        p = (p.T / np.linalg.norm(p.T, axis=0)).T  # as init_circle: every boundary node
        sides = np.vstack([np.column_stack([side, mid]) for side in sides.T])
    return p[sides[:, 0]], p[sides[:, 1]]


def edge_lines(a: np.ndarray, b: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Inward unit normals n, shape (k, 2), and levels h, shape (k,) [m], of the straight edges
    from ``a`` to ``b`` (x, y) [m], shape (k, 2) each, of a convex polygon about the origin."""
    t = b - a
    n = np.column_stack([-t[:, 1], t[:, 0]]) / np.hypot(t[:, 0], t[:, 1])[:, None]
    h = np.einsum("ij,ij->i", n, a)
    n[h > 0.0] *= -1.0  # inward: the centre (0, 0) has n . 0 = 0 >= h
    return n, -np.abs(h)


@lru_cache(maxsize=16)
def bed_edge(length_m: float, width_m: float, refine: int) -> tuple[np.ndarray, np.ndarray]:
    """The edge of the bed meshed on the ellipse ``length_m`` x ``width_m`` [m] with ``refine``
    refinements: inward unit normals n, shape (k, 2), and levels h, shape (k,) [m], of its
    edges ``n . p >= h`` (p from the head's centre [m]; read-only arrays, cached)."""
    axes = np.array([0.5 * length_m, 0.5 * width_m])
    lines = edge_lines(*(nodes * axes for nodes in _unit_edge(refine)))
    for array in lines:
        array.flags.writeable = False
    return lines


def clearance(lines: tuple[np.ndarray, np.ndarray], points: np.ndarray) -> np.ndarray:
    """Distance [m] of each point (x, y) [m], shape (p, 2), inside the polygon of edge
    ``lines`` (n, h) (negative outside it)."""
    n, h = lines
    return np.min(np.atleast_2d(points) @ n.T - h, axis=1)
