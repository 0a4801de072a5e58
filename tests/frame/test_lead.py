"""Lead tape at clock places: exact changes of mass, balance, swing weight and twistweight."""

import math

import numpy as np
import pytest

from fem_racket import frame_mesh, standard_frame
from fem_racket.frame.catalogue import catalogue
from fem_racket.frame.clock import PLACES, place_at
from fem_racket.frame.head import DEFAULT_HEAD, HeadOutline
from fem_racket.frame.lead import Lead, add_lead, lead_moments, parse_lead
from fem_racket.frame.masses import DEFAULT_WIDTH
from fem_racket.frame.mesh import FrameMesh
from fem_racket.frame.specs import SWING_AXIS
from fem_racket.validation import InputError

W = DEFAULT_WIDTH


@pytest.fixture(scope="module")
def mesh():
    return frame_mesh(standard_frame(), 20)


@pytest.fixture(scope="module")
def head(mesh):
    return DEFAULT_HEAD.on_frame(mesh.length)


def specs(mesh):
    c = catalogue(mesh, f1=False)
    return np.array([c.mass, c.mass * c.balance, c.swing_weight, c.twist_weight])


def test_default_head_is_a_100_square_inch_head(head):
    # 100 in^2 = 645.16 cm^2 (the string bed of a "midplus" racket); the centre line's ellipse
    assert head.area_m2 == pytest.approx(645.16e-4, rel=0.01)
    # DESIGN.md section 10: r at 3/9 about 0.11-0.13 m
    assert 0.11 <= place_at("3/9", head).r <= 0.13


def test_clock_places_on_the_ellipse(head):
    a, b, xc = head.length_m / 2, head.width_m / 2, head.centre_m
    for name in ("2/10", "3/9", "4/8"):
        p = place_at(name, head)
        # on the ellipse ((x - xc)/a)^2 + (r/b)^2 = 1
        assert ((p.x - xc) / a) ** 2 + (p.r / b) ** 2 == pytest.approx(1.0, abs=1e-14)
    assert place_at("12", head).x == head.frame_length_m
    assert place_at("throat", head).x == pytest.approx(xc - a, abs=1e-15)
    assert place_at("0.32", head).x == 0.32


def test_lead_at_the_balance_point_keeps_the_balance(mesh, head):
    before = catalogue(mesh, f1=False)
    out = catalogue(add_lead(mesh, [Lead(repr(before.balance), 0.015)], head), f1=False)
    assert out.mass == pytest.approx(before.mass + 0.015, rel=1e-14)
    assert out.balance == pytest.approx(before.balance, rel=1e-13)


def test_lead_at_12_adds_m_x_squared_to_the_swing_weight(mesh, head):
    m = 0.010
    out = add_lead(mesh, [Lead("12", m)], head)
    d = specs(out) - specs(mesh)
    x = mesh.length - W / 2  # the strip [L - w, L]
    # parallel axes: m (x - 0.10 m)^2 plus the strip's own inertia m w^2 / 12
    assert d[2] == pytest.approx(m * ((x - SWING_AXIS) ** 2 + W**2 / 12), rel=1e-12)
    # the point-mass limit: a narrow strip gives m (L - 0.10)^2 to O(w)
    thin = add_lead(mesh, [Lead("12", m)], head, width=1e-5)
    dt = specs(thin)[2] - specs(mesh)[2]
    assert dt == pytest.approx(m * (mesh.length - SWING_AXIS) ** 2, rel=1e-4)
    assert lead_moments("12", head)[3] == 0.0  # on the axis: no twistweight
    assert d[3] == pytest.approx(0.0, abs=1e-15 * specs(mesh)[3])


def test_lead_at_3_9_adds_m_r_squared_to_twistweight_and_less_swing_weight(mesh, head):
    m = 0.010
    k39 = lead_moments("3/9", head)
    assert m * k39[3] == pytest.approx(m * (head.width_m / 2) ** 2, rel=1e-15)
    # on the mesh: two halves m/2 at r = width / 2 on either side add m r^2 to the polar moment
    tw = specs(add_lead(mesh, [Lead("3/9", m)], head))[3] - specs(mesh)[3]
    assert tw == pytest.approx(m * (head.width_m / 2) ** 2, rel=1e-12)
    sw39 = specs(add_lead(mesh, [Lead("3/9", m)], head))[2]
    sw12 = specs(add_lead(mesh, [Lead("12", m)], head))[2]
    assert sw39 < sw12
    assert sw39 - specs(mesh)[2] == pytest.approx(m * k39[2], rel=1e-12)


@pytest.mark.parametrize("place", [*PLACES, "0.32"])
def test_linear_coefficients_match_the_mesh(mesh, head, place):
    m = 0.007
    d = specs(add_lead(mesh, [Lead(place, m)], head)) - specs(mesh)
    assert d == pytest.approx(m * lead_moments(place, head), rel=1e-11, abs=1e-16)


def test_leads_add_up(mesh, head):
    leads = [Lead("3/9", 0.010), Lead("0.32", 0.005), Lead("12", 0.004)]
    d = specs(add_lead(mesh, leads, head)) - specs(mesh)
    want = sum(lead.mass * lead_moments(lead.place, head) for lead in leads)
    assert d == pytest.approx(want, rel=1e-11)


def test_parse_lead():
    assert parse_lead("3/9:10") == Lead("3/9", 0.010)
    assert parse_lead("0.32:5").mass == pytest.approx(0.005, rel=1e-15)
    for bad in ("3/9", ":5", "3/9:-1", "3/9:x", "12:nan"):
        with pytest.raises(InputError, match="LOCATION:GRAMS"):
            parse_lead(bad)


@pytest.mark.parametrize("bad", ["13", "0.9", "-0.1", "nan", "tip"])
def test_unknown_place(head, bad):
    with pytest.raises(InputError, match="place"):
        place_at(bad, head)


def test_head_must_fit(mesh):
    with pytest.raises(InputError, match="head length"):
        HeadOutline(frame_length_m=0.3)
    with pytest.raises(InputError, match="frame length"):
        add_lead(mesh, [Lead("12", 0.01)], DEFAULT_HEAD.on_frame(0.7))
    assert math.isclose(DEFAULT_HEAD.on_frame(0.7).centre_m, 0.74 * 0.7)


def test_twistweight_is_the_torsion_model_polar_moment(mesh, head):
    # independent path: the torsion FE model's mass matrix (fem_racket.frame.torsion)
    from fem_racket import FrameModel

    custom = add_lead(mesh, [Lead("3/9", 0.010), Lead("2/10", 0.004)], head)
    for m in (mesh, custom):
        tw = catalogue(m, f1=False).twist_weight
        assert tw == pytest.approx(FrameModel.build(m).torsion.polar_moment, rel=1e-12)


def test_no_torsion_data_no_twistweight(mesh, head):
    bare = FrameMesh(mesh.points, mesh.EI, mesh.rhoA)
    out = catalogue(add_lead(bare, [Lead("3/9", 0.010)], head), f1=False)
    assert out.twist_weight is None


def test_more_lead_than_three_rackets_is_refused():
    from fem_racket.frame.lead import MAX_LEAD_G

    with pytest.raises(InputError, match=r"add-mass = '12:1e9' is not allowed: .* at most 1000 g"):
        parse_lead("12:1e9")
    assert parse_lead(f"12:{MAX_LEAD_G:g}").mass == pytest.approx(1.0, rel=1e-15)
