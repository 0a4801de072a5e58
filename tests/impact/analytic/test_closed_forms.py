"""The FE impact against the paper's closed forms: eqs 1-4 (clamped), 5-12 (rigid), 16."""

import numpy as np
import pytest

from fem_racket import (
    Frame,
    FrameModel,
    Segment,
    clamped_impact,
    kcb_from_speed,
    rigid_impact,
    rigid_impact_at,
    simulate,
    zeta_from_cor,
)

M_B = 0.057


def test_clamped_closed_form_gives_paper_cor():
    # Eqs 2 and 4: with zeta from e = 0.83 the clamped rebound is -0.83 V_B0 at any speed.
    for v in (20.0, 30.0, 40.0):
        c = clamped_impact(M_B, kcb_from_speed(v), zeta_from_cor(0.83), v)
        assert c.cor == pytest.approx(0.83, rel=1e-13)
        assert c.contact_time == pytest.approx(np.pi / c.omega_d, rel=1e-15)


@pytest.mark.parametrize("speed", [20.0, 40.0])
def test_heavy_stiff_frame_behaves_as_clamped(speed):
    # A frame 1e7 times heavier and stiffer than the standard one is clamped for the ball:
    # corrections are of order m_B / m_R ~ 2e-8 (measured: COR 6.7e-8, t_c 1.4e-8 relative).
    heavy = Frame((Segment(0.204, 146e7, 0.696e7), Segment(0.476, 128.48e7, 0.458e7)))
    r = simulate(heavy, position=0.75, speed=speed)
    c = clamped_impact(M_B, kcb_from_speed(speed), zeta_from_cor(0.83), speed)
    assert r.cor == pytest.approx(0.83, abs=3e-7)
    assert r.contact_time == pytest.approx(c.contact_time, rel=1e-7)


@pytest.mark.parametrize("position", [0.55, 0.6, 0.75, 0.9, 0.95])
def test_very_rigid_frame_matches_eqs_11_12(standard_model, position):
    # Eqs 11-12 (rigid frame, zeta = 0). EI x 1e6 puts mode 1 at ~1.2e5 Hz, so the elastic
    # correction of t_c is ~(f_ball / f_1)^2 ~ 1e-6 (measured <= 2e-7); the COR's is far
    # smaller (measured <= 5e-11).
    stiff = standard_model.scaled(1e6)
    props = stiff.props
    r = simulate(stiff, position=position, speed=20.0, zeta=0.0)
    rf = rigid_impact_at(props, position, 20.0)
    assert r.cor == pytest.approx(rf.cor, abs=1e-9)
    assert r.contact_time == pytest.approx(rf.contact_time, rel=1e-6)


def test_rigid_closed_form_components_sum():
    # Eq 7 at t = 0 gives V_B0 = V_T + V_R + V_I (eq 14 with eq 15).
    rf = rigid_impact(M_B, 0.36, 0.0145, 0.2, 2.74e4, 20.0)
    assert rf.v_translation + rf.v_rotation + rf.v_vibration == pytest.approx(20.0, rel=1e-14)


@pytest.mark.parametrize("position", np.linspace(0.55, 0.95, 9))
def test_elastic_never_beats_rigid_eq16(standard_model, position):
    # Eq 16: with zeta = 0 the elastic frame's rebound cannot exceed the rigid frame's.
    props = standard_model.props
    rf = rigid_impact_at(props, position, 20.0)
    r = simulate(standard_model, position=position, speed=20.0, zeta=0.0, output_step=None)
    assert r.cor <= rf.cor + 1e-12


def test_no_damping_saturated_cor_is_speed_independent():
    # Section 5: without damping the COR of a (near) rigid frame is the same at every speed,
    # since eq 12 holds no K_CB.
    model = FrameModel.build(None, 20).scaled(1e5)
    cors = [simulate(model, speed=v, zeta=0.0, output_step=None).cor for v in (20, 30, 40)]
    assert np.ptp(cors) < 1e-9  # measured 2.5e-11
