"""Where the ball may strike the bed (:mod:`fem_racket.strings.reach`): its contact disk on the
meshed bed, against the regular polygon's closed form, and the one rule the disk load obeys."""

import math

import numpy as np
import pytest

from fem_racket.strings.bed import StringBed
from fem_racket.strings.membrane import bed_mesh, disk_load
from fem_racket.strings.reach import on_bed, strike_interval
from fem_racket.validation import InputError

R = 0.14  # radius of the circular test head [m]
A = 0.02  # load radius [m]


@pytest.mark.parametrize("refine", [2, 4])
def test_circular_head_reach_is_the_polygon_inradius_less_the_disk(refine):
    # scikit-fem's unit disk has 2^(refine+2) boundary nodes equally spaced on the circle (16 at
    # refine 2, 64 at 4): the meshed bed is the regular polygon of inradius R cos(pi/n), and a
    # disk of radius a lies in it iff its centre is within R cos(pi/n) - a of the centre along
    # any line through an edge's midpoint or a vertex (here: round-off, 1e-12).
    bed = StringBed(head_length_m=2 * R, head_width_m=2 * R, load_radius_m=A)
    n = 2 ** (refine + 2)
    assert bed_mesh(2 * R, 2 * R, refine).edge_lines[0].shape == (n, 2)
    inner = R * math.cos(math.pi / n) - A
    for angle in (0.0, math.pi / n):  # through a vertex or an edge's midpoint (bisector)
        d = np.array([math.cos(angle), math.sin(angle)])
        lo, hi = strike_interval(bed, np.zeros(2), d, refine)
        # along a vertex's line the nearest edges are at angle pi/n: the reach is inner/cos
        reach = inner / math.cos(math.pi / n) if angle == 0.0 else inner
        assert (-lo, hi) == pytest.approx((reach, reach), abs=1e-12)


def test_reach_is_where_the_disk_load_works():
    # The one rule: a point is reachable (on_bed) iff the ball's disk load can be made there; a
    # point beyond it is refused by the load itself in one line, never "outside of the mesh".
    # Points near the edge of the default head, where the disk reaches past the meshed bed
    # (the reviewer's H1: offset 0.1 m at 0.6 x/L).
    bed = StringBed()
    mesh = bed_mesh(bed.head_length_m, bed.head_width_m, 4)
    rng = np.random.default_rng(7)
    theta = rng.uniform(0.0, 2.0 * math.pi, 300)
    rho = np.sqrt(rng.uniform(0.55, 1.0, 300))
    pts = np.column_stack([0.163 * rho * np.cos(theta), 0.126 * rho * np.sin(theta)])
    pts = np.vstack([pts, [(0.6 - 0.74) * 0.68, 0.1]])
    reached = 0
    for p in pts:
        if on_bed(bed, p):
            assert np.all(np.isfinite(disk_load(mesh, p[None], bed.load_radius_m)))
            reached += 1
        else:
            with pytest.raises(InputError, match="must lie on the string bed"):
                disk_load(mesh, p[None], bed.load_radius_m)
    assert 50 < reached < pts.shape[0] - 50  # both sides were tried


def test_interval_ends_are_the_reach():
    # Just inside an end of the interval the disk is on the bed, just outside it is not.
    bed = StringBed(head_width_m=0.2)
    x = (0.75 - bed.head_centre) * 0.68
    lo, hi = strike_interval(bed, np.array([x, 0.0]), np.array([0.0, 1.0]))
    assert lo < 0.0 < hi
    for t, inside in ((lo + 1e-9, True), (lo - 1e-9, False), (hi - 1e-9, True), (hi + 1e-9, False)):
        assert on_bed(bed, np.array([x, t])) is inside
    far = strike_interval(bed, np.array([0.2, 0.0]), np.array([0.0, 1.0]))
    assert far[0] > far[1]  # beyond the tip: nowhere
