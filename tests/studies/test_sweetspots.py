"""Sweet spots: centre of percussion, nodes, rigid-racket e_A, maxima of e_A and v_out."""

from __future__ import annotations

import math

import numpy as np
import pytest

from fem_racket.contact.linear import DEFAULT_BALL_MASS, LinearContact
from fem_racket.frame.model import FrameModel
from fem_racket.frame.segments import standard_frame
from fem_racket.studies.racket_map import apparent_cor_along, racket_map
from fem_racket.studies.sweetspots import centre_of_percussion, power_region
from fem_racket.validation import InputError


def test_centre_of_percussion_from_the_papers_mass_distribution(standard_model):
    # x_COP = x_CG + I_CG / (M (x_CG - p)) with M, x_CG, I_CG summed by hand from section 2.2
    # (0.204 m at 0.696 kg/m, 0.476 m at 0.458 kg/m), pivot at the hand 0.10 m from the butt.
    m1, m2 = 0.696 * 0.204, 0.458 * 0.476
    M = m1 + m2
    cg = (m1 * 0.102 + m2 * (0.204 + 0.238)) / M
    i_cg = m1 * 0.204**2 / 12 + m1 * (0.102 - cg) ** 2 + m2 * 0.476**2 / 12 + m2 * (0.442 - cg) ** 2
    p = 0.10
    want = cg + i_cg / (M * (cg - p))
    assert centre_of_percussion(standard_model.props, p) == pytest.approx(want, rel=1e-12)
    m = racket_map(standard_model, pivot=p, positions=np.linspace(0.5, 1.0, 5))
    assert m.spots.cop == pytest.approx(want / 0.68, rel=1e-12)
    with pytest.raises(InputError, match="centre of gravity"):
        centre_of_percussion(standard_model.props, standard_model.props.cg)


def test_nodes_match_the_paper(standard_model):
    # The paper: mode-1 nodes 0.200 L and 0.769 L, mode-2 0.125, 0.484, 0.864 L (3 digits).
    m = racket_map(standard_model, positions=np.linspace(0.5, 1.0, 5))
    assert m.spots.mode1_nodes == pytest.approx([0.200, 0.769], abs=2e-3)
    assert m.spots.mode2_nodes == pytest.approx([0.125, 0.484, 0.864], abs=2e-3)
    assert m.spots.node == m.spots.mode1_nodes[-1]


def test_rigid_racket_apparent_cor_closed_form():
    # Issue 14 / DESIGN section 8: e_A = (e_r - m_B/M_eff) / (1 + m_B/M_eff),
    # 1/M_eff = 1/M + b^2/I_CG, e_r = exp(-pi z_r / sqrt(1 - z_r^2)), z_r = C_CB/(2 sqrt(mu K_CB)),
    # mu = m_B M_eff/(m_B + M_eff). To 1e-6 at EI1 = 1e7 (measured: <= 9.9e-7 over 0.3-0.95 L;
    # the residual frame flexibility, ~1/EI1).
    model = FrameModel.build(standard_frame(1e7), 20)
    p, mb, speed = model.props, DEFAULT_BALL_MASS, 20.0
    law = LinearContact.for_speed(speed)
    x = np.linspace(0.3, 0.95, 14)
    got = apparent_cor_along(model, x, speed, tolerance=None)  # every mode: no reduction error
    b = x * p.length - p.cg
    meff = 1.0 / (1.0 / p.mass + b**2 / p.inertia)
    mu = mb * meff / (mb + meff)
    zr = law.damping(mb) / (2.0 * np.sqrt(mu * law.stiffness))
    er = np.exp(-math.pi * zr / np.sqrt(1.0 - zr**2))
    want = (er - mb / meff) / (1.0 + mb / meff)
    np.testing.assert_allclose(got, want, rtol=0, atol=1e-6)


def test_max_ball_speed_moves_toward_the_tip_as_angular_speed_rises(standard_model):
    # DESIGN section 8 (Brody, Cross & Lindsey 2002): the v_out maximum moves tipward with the
    # racket's angular speed (hand pivot 0.10 m, ball 20 m/s).
    x = np.linspace(0.5, 1.0, 51)
    spots = [
        racket_map(standard_model, speed=20.0, racket_speed=v, pivot=0.10, positions=x).spots
        for v in (5.0, 15.0, 30.0)
    ]
    where = [s.max_ball_speed for s in spots]
    assert where[0] < where[1] < where[2]
    # On a stationary racket the largest e_A lies toward the throat of the max-v_out point.
    assert spots[0].max_apparent_cor < where[2]


def test_power_region_on_a_parabola():
    x = np.linspace(0.0, 1.0, 101)
    v = 1.0 - (x - 0.4) ** 2
    lo, hi = power_region(x, v, 0.96)
    assert (lo, hi) == pytest.approx((0.2, 0.6), abs=1e-4)
    assert power_region(x, v, 0.5) == (0.0, 1.0)
