"""The meshed bed's edge from the head outline alone (:mod:`fem_racket.strings.edge`): the
membrane's own boundary to the bit, and a strung problem's point checked without scikit-fem."""

import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from fem_racket.strings.edge import bed_edge, edge_lines

ROOT = Path(__file__).resolve().parents[2]
#: Heads [m]: the default 0.326 x 0.252, a circle, a narrow and a long one.
HEADS = [(0.326, 0.252), (0.28, 0.28), (0.3, 0.2), (0.9, 0.07)]


def _rows(lines: tuple[np.ndarray, np.ndarray]) -> np.ndarray:
    """The lines (n, h) as rows (n_x, n_y, h), sorted: the polygon whatever the edges' order."""
    rows = np.column_stack(lines)
    return rows[np.lexsort(rows.T[::-1])]


@pytest.mark.parametrize("refine", range(6))
@pytest.mark.parametrize("head", HEADS, ids=["default", "circle", "narrow", "long"])
def test_edge_is_the_meshed_bed_s_boundary_to_the_bit(head, refine):
    # The membrane's mesh as bed_mesh makes it: scikit-fem's unit disk mapped to the ellipse;
    # its boundary facets (lower-numbered node first) give the same lines, every bit.
    from skfem import MeshTri

    disk = MeshTri.init_circle(refine)
    ax, ay = 0.5 * head[0], 0.5 * head[1]
    p = np.array([ax * disk.p[0], ay * disk.p[1]])
    a, b = (p[:, i].T for i in disk.facets[:, disk.boundary_facets()])
    lines = bed_edge(*head, refine)
    assert lines[0].shape == (2 ** (refine + 2), 2)
    assert np.array_equal(_rows(lines), _rows(edge_lines(a, b)))
    assert not lines[0].flags.writeable and not lines[1].flags.writeable  # the cache's own


def test_edge_lines_are_a_polygon_s_inward_half_planes():
    # The unit square's edges, listed either way round: inward normals, levels -1/2.
    a = np.array([[0.5, -0.5], [0.5, 0.5], [-0.5, 0.5], [-0.5, -0.5]])
    for b, start in ((np.roll(a, -1, axis=0), a), (a, np.roll(a, -1, axis=0))):
        n, h = edge_lines(start, b)
        assert np.array_equal(h, np.full(4, -0.5))
        mid = 0.5 * (start + b)
        assert np.all(np.einsum("ij,ij->i", n, mid) < 0.0)  # each normal towards the centre
        assert np.array_equal(np.abs(n).sum(axis=1), np.ones(4))  # axis-aligned unit normals


PROBE = """
import sys
from fem_racket.impact.problem import ImpactProblem
from fem_racket.strings.bed import StringBed
from fem_racket.validation import InputError
ImpactProblem.build(elements=8, position=0.76, offset=0.03, strings=StringBed())
try:
    ImpactProblem.build(elements=8, position=0.3, strings=StringBed())
except InputError as exc:
    print(exc)
print(sorted(m for m in sys.modules if m == "skfem" or m.startswith("skfem.")))
"""


def test_a_strung_problem_is_checked_without_the_membrane(tmp_path):
    # config --check of a strung run file builds its problems: the point's reach is checked from
    # the head outline, without importing scikit-fem or assembling the membrane (~0.3 s).
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    done = subprocess.run(
        [sys.executable, "-c", PROBE], cwd=tmp_path, env=env, capture_output=True, text=True
    )
    assert done.returncode == 0, done.stderr
    refusal, modules = done.stdout.splitlines()
    assert refusal.startswith("position = 0.3 x/L is not allowed with the string bed")
    assert modules == "[]"
