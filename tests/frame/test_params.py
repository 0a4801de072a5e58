"""Parameters: the paper's presets, K_CB interpolation, zeta from the clamped COR, validation."""

import math

import pytest

from fem_racket import (
    Ball,
    Frame,
    Impact,
    InputError,
    LinearContact,
    Segment,
    cor_from_zeta,
    kcb_from_speed,
    rigid_frame,
    standard_frame,
    zeta_from_cor,
)


def test_standard_frame_matches_section_2_2():
    f = standard_frame()
    # Section 2.2: L = 680 mm, step at 204 mm, EI1 = 146, EI2 = 128.5 (= 0.88 EI1),
    # rhoA1 = 0.696, rhoA2 = 0.458 kg/m.
    assert f.length == pytest.approx(0.680, abs=1e-15)
    assert f.segments[0].length == 0.204
    assert f.segments[0].EI == 146.0
    assert f.segments[1].EI == pytest.approx(128.5, abs=0.05)  # paper rounds 128.48 to 128.5
    assert (f.segments[0].rhoA, f.segments[1].rhoA) == (0.696, 0.458)


def test_rigid_frame_is_9999():
    f = rigid_frame()
    # Section 3.1: "rigid" frame EI1 = 9999 N m^2, EI2 = 0.88 EI1.
    assert f.segments[0].EI == 9999.0
    assert f.segments[1].EI == pytest.approx(0.88 * 9999.0, rel=1e-15)


@pytest.mark.parametrize(("speed", "kcb"), [(20.0, 2.74e4), (30.0, 5.0e4), (40.0, 8.33e4)])
def test_kcb_passes_through_paper_points(speed, kcb):
    # Section 2.1.1 states these three values; the interpolation must reproduce them.
    assert kcb_from_speed(speed) == pytest.approx(kcb, rel=1e-12)


def test_kcb_is_monotone_power_law_between_points():
    # Piecewise log-log: at the geometric mean of 20 and 30 m/s K is the geometric mean.
    v = math.sqrt(20.0 * 30.0)
    assert kcb_from_speed(v) == pytest.approx(math.sqrt(2.74e4 * 5.0e4), rel=1e-12)
    speeds = [5, 10, 20, 25, 30, 35, 40, 50, 60]
    ks = [kcb_from_speed(s) for s in speeds]
    assert all(a < b for a, b in zip(ks, ks[1:], strict=False))


def test_zeta_from_clamped_cor():
    # Section 2.1.2: e = 0.83 gives zeta ~ 0.059 (eqs 2-4).
    z = zeta_from_cor(0.83)
    assert z == pytest.approx(0.059, abs=5e-4)
    assert cor_from_zeta(z) == pytest.approx(0.83, rel=1e-14)
    assert zeta_from_cor(1.0) == 0.0


def test_contact_damping_grows_as_sqrt_k():
    # Section 2.1.2: C_CB is proportional to K_CB^(1/2) at fixed zeta.
    c20 = LinearContact.for_speed(20.0).damping(0.057)
    c40 = LinearContact.for_speed(40.0).damping(0.057)
    assert c40 / c20 == pytest.approx(math.sqrt(8.33e4 / 2.74e4), rel=1e-12)


@pytest.mark.parametrize(
    ("factory", "name"),
    [
        (lambda: Segment(0.0, 1.0, 1.0), "segment length"),
        (lambda: Segment(0.1, -1.0, 1.0), "EI"),
        (lambda: Segment(0.1, 1.0, float("nan")), "rhoA"),
        (lambda: Segment(float("inf"), 1.0, 1.0), "segment length"),
        (lambda: Frame(()), "segments"),
        (lambda: Ball(0.0), "ball mass"),
        (lambda: Ball(-0.05), "ball mass"),
        (lambda: Impact(1.2, 20.0), "position"),
        (lambda: Impact(-0.1, 20.0), "position"),
        (lambda: Impact(0.5, 0.0), "speed"),
        (lambda: Impact(0.5, float("inf")), "speed"),
        (lambda: LinearContact(1e4, 1.0), "zeta"),
        (lambda: LinearContact(1e4, -0.1), "zeta"),
        (lambda: LinearContact(0.0, 0.05), "kcb"),
        (lambda: standard_frame(ei1=float("nan")), "ei1"),
        (lambda: kcb_from_speed(-20.0), "speed"),
    ],
)
def test_bad_parameters_name_themselves(factory, name):
    with pytest.raises(InputError) as err:
        factory()
    msg = str(err.value)
    assert msg.startswith(name)
    assert "\n" not in msg
    assert "must" in msg
