"""A stroke's face and path angles (fem_racket.impact.oblique.stroke,
fem_racket.impact.simulate_stroke)."""

import math

import pytest

from fem_racket.impact.incidence import Incidence
from fem_racket.impact.oblique.stroke import Stroke
from fem_racket.impact.simulate_oblique import simulate_oblique
from fem_racket.impact.simulate_stroke import simulate_stroke
from fem_racket.impact.swing import Swing
from fem_racket.validation import InputError

KEYS = ("spin_out_rpm", "angle_out_deg", "ball_speed_out_m_s", "cor", "tangential_cor")


def test_a_tilted_clamped_face_is_the_oblique_impact_at_90_minus_f():
    # a horizontal ball on a face at F to the horizontal meets it at 90 - F from the normal,
    # sliding down the face: the same outcome as --angle (90 - F) to 1e-12
    for face, spin in ((80.0, 0.0), (60.0, -1500.0), (35.0, 2500.0)):
        inc = Incidence(spin=spin)
        a = simulate_stroke(incidence=inc, stroke=Stroke(face), speed=25.0, clamped=True)
        b = simulate_oblique(
            incidence=Incidence(angle=90.0 - face, spin=spin), speed=25.0, clamped=True
        )
        sa, sb = a.summary(), b.summary()
        for key in KEYS:
            assert sa[key] == pytest.approx(sb[key], rel=1e-12, abs=1e-12), key
        assert sa["angle_deg"] == pytest.approx(90.0 - face, rel=1e-12)
        # the face normal points 90 - F below the horizontal and the tangential axis down the
        # face: launch = -(90 - F) - angle out
        assert sa["launch_angle_deg"] == pytest.approx(
            -(90.0 - face) - sa["angle_out_deg"], rel=1e-12
        )


def test_a_translating_swing_is_the_racket_at_rest_at_the_relative_velocity():
    # Galilean invariance: a racket translating at S along a path P meets the ball as a racket
    # at rest meets the relative velocity (speed |w|, angle from the normal); the linear law's
    # K_CB follows the normal closing speed in both. CVODE on both paths (rtol 1e-10).
    stroke, v, s = Stroke(80.0, 19.0), 20.0, 15.0
    inc = Incidence(spin=-1000.0)
    a = simulate_stroke(incidence=inc, stroke=stroke, speed=v, swing=Swing(s, 0.0), solver="cvode")
    f, d = math.radians(80.0), math.radians(61.0)
    w_n = v * math.sin(f) + s * math.sin(d)
    w_t = v * math.cos(f) + s * math.cos(d)  # the ball slides down the face, relative
    rest = Incidence(angle=math.degrees(math.atan2(w_t, w_n)), spin=-1000.0)
    b = simulate_oblique(incidence=rest, speed=math.hypot(w_n, w_t), solver="cvode")
    sa, sb = a.summary(), b.summary()
    assert sa["angle_deg"] == pytest.approx(rest.angle, rel=1e-12)
    assert sa["spin_out_rpm"] == pytest.approx(sb["spin_out_rpm"], rel=1e-8)
    assert sa["contact_regime"] == sb["contact_regime"]
    ta, tb = a.tangential, b.tangential
    # the ball's speeds relative to the strings after impact are the same
    rel_a = ta.tangential_speed_out - ta.racket_speed_out
    assert rel_a == pytest.approx(tb.tangential_speed_out - tb.racket_speed_out, rel=1e-8)


def test_a_vertical_face_and_a_level_path_is_the_head_on_swing():
    swing = Swing.from_speed(15.0, 0.68, pivot=0.1)
    a = simulate_stroke(incidence=Incidence(), stroke=Stroke(90.0, 0.0), speed=20.0, swing=swing)
    b = simulate_oblique(incidence=Incidence(), speed=20.0, swing=swing)
    sa, sb = a.summary(), b.summary()
    assert sa["cor"] == sb["cor"] and sa["rebound_speed_m_s"] == sb["rebound_speed_m_s"]
    assert abs(sa["spin_out_rpm"]) < 1e-9 and sa["launch_angle_deg"] == pytest.approx(0, abs=1e-9)


def test_stroke_checks():
    with pytest.raises(InputError, match=r"^angle = 10.0 deg is not allowed with a stroke"):
        simulate_stroke(incidence=Incidence(angle=10.0), stroke=Stroke(80.0), clamped=True)
    with pytest.raises(InputError, match=r"^face_angle = 0.0 deg is not allowed"):
        Stroke(0.0)
    with pytest.raises(InputError, match=r"^swing is not allowed with a clamped head"):
        simulate_stroke(incidence=Incidence(), stroke=Stroke(80.0), swing=Swing(5.0), clamped=True)
