"""The sweep's 3-D oblique axes ``side_angle``/``side_spin`` and its strung oblique cases: each
case is the single impact ``simulate`` gives (1e-12), side angle and side spin 0 are today's
sweep bit for bit, and what cannot combine is refused in one line before any work."""

from __future__ import annotations

import re

import numpy as np
import pytest

from fem_racket.contact.presets import get_law
from fem_racket.impact.incidence import Incidence
from fem_racket.impact.simulate_oblique import simulate_oblique
from fem_racket.strings.bed import StringBed
from fem_racket.studies.cases import COLUMNS, result_variables
from fem_racket.studies.sweep import sweep_result
from fem_racket.studies.sweep_physics import regime_label
from fem_racket.validation import InputError

#: Outputs of the 3-D oblique impact (simulate's side rows) and of the plane's.
SIDE = ("side_angle_out_deg", "side_spin_out_rpm", "racket_yaw_rate_rad_s")
PLANE = ("spin_out_rpm", "angle_out_deg", "ball_speed_out_m_s", "tangential_cor", "cor")


def _close(got: float, want: float) -> None:
    # the same normal impact and tangential march as simulate's: equal to rounding (1e-12)
    assert got == pytest.approx(want, rel=1e-12, abs=1e-12)


def test_side_axes_are_the_single_3d_impacts():
    r = sweep_result(angle=20.0, side_angle="-10,0,10", side_spin="0,1000", speed=25.0,
                     backend="serial")  # fmt: skip
    ds = r.to_xarray()
    assert ds.side_spin_out_rpm.dims == ("side_angle", "side_spin")
    assert ds.side_angle.attrs["units"] == "deg" and ds.side_spin.attrs["units"] == "rpm"
    assert ds.side_angle_out_deg.attrs["units"] == "deg"
    assert ds.racket_yaw_rate_rad_s.attrs["units"] == "rad/s"
    assert ds.attrs["angle_deg"] == 20.0
    for b in ds.side_angle.values:
        for w in ds.side_spin.values:
            inc = Incidence(angle=20.0, side_angle=b, side_spin=w)
            ref = simulate_oblique(incidence=inc, speed=25.0).summary()
            case = ds.sel(side_angle=b, side_spin=w)
            for key in (*SIDE, *PLANE, "contact_time_s"):
                _close(float(case[key]), ref[key])
            assert regime_label(float(case.contact_regime)) == ref["contact_regime"]
    # the side spin is picked up across the face (toward the side the ball moves to)
    assert float(ds.side_spin_out_rpm.sel(side_angle=10.0, side_spin=0.0)) > 0.0
    assert float(ds.side_spin_out_rpm.sel(side_angle=-10.0, side_spin=0.0)) < 0.0


def test_side_angle_and_spin_0_are_todays_sweep_bit_for_bit():
    grid = {"angle": "20,45", "spin": "-1000,2000", "speed": 25.0, "backend": "serial"}
    today = sweep_result(**grid)
    side = sweep_result(**grid, side_angle=0.0, side_spin=0.0)
    for name in result_variables(today.spec):
        k = COLUMNS.index(name)
        assert np.array_equal(side.values[:, k], today.values[:, k], equal_nan=True), name
    for name in SIDE:
        assert np.all(side.values[:, COLUMNS.index(name)] == 0.0), name
    assert today.spec.digest != side.spec.digest  # the side values are part of the key


def test_a_side_angle_and_a_side_spin_need_no_angle():
    # across the face alone: the path out of the plane, angle 0 within it
    ds = sweep_result(side_angle="5,15", side_spin=300.0, backend="serial").to_xarray()
    for b in ds.side_angle.values:
        ref = simulate_oblique(incidence=Incidence(side_angle=b, side_spin=300.0)).summary()
        for key in (*SIDE, "spin_out_rpm", "ball_speed_out_m_s"):
            _close(float(ds[key].sel(side_angle=b)), ref[key])


def test_strung_oblique_cases_are_simulates():
    # a string bed with an oblique ball (simulate --string-tension ... --angle ...)
    r = sweep_result(string_tension="220,270", angle="20,40", spin=500.0, speed=25.0,
                     backend="serial")  # fmt: skip
    ds = r.to_xarray()
    assert "stringbed_stiffness_n_m" in ds and "spin_out_rpm" in ds and "kcb_n_m" not in ds
    assert "side_spin_out_rpm" not in ds  # only with the side axes
    for t in ds.string_tension.values:
        for a in ds.angle.values:
            inc = Incidence(angle=a, spin=500.0)
            bed = StringBed(tension_n=float(t))
            ref = simulate_oblique(incidence=inc, speed=25.0, strings=bed).summary()
            case = ds.sel(string_tension=t, angle=a)
            for key in (*PLANE, "contact_time_s", "rebound_speed_m_s", "stringbed_stiffness_n_m"):
                _close(float(case[key]), ref[key])
            assert regime_label(float(case.contact_regime)) == ref["contact_regime"]


def test_strung_oblique_under_the_general_solver():
    law = get_law("kawazoe-1997-ball")
    r = sweep_result(string_tension=250.0, angle=30.0, friction=0.3, solver="general",
                     law=law, backend="serial")  # fmt: skip
    ds = r.to_xarray()
    inc = Incidence(angle=30.0, friction=0.3)
    ref = simulate_oblique(incidence=inc, strings=StringBed(tension_n=250.0), solver="general",
                           law=law).summary()  # fmt: skip
    for key in PLANE:
        _close(float(ds[key]), ref[key])


@pytest.mark.parametrize(
    ("given", "words"),
    [
        ({"side_angle": "-10,90"}, "side_angle = 90.0 deg is not allowed: must lie in (-90, 90)"),
        ({"side_angle": -90}, "side_angle = -90 deg is not allowed"),
        ({"side_spin": "nan"}, "side_spin = nan rpm is not allowed"),
        ({"side_angle": "1,1"}, "side_angle = [1.0, 1.0] is not allowed: values must be distinct"),
        (
            {"string_tension": 250, "side_angle": "0,10"},
            "side_angle = [0.0, 10.0] is not allowed with string_tension (a string bed): the "
            "oblique impact on the bed is modelled in the plane of the long axis only",
        ),
        (
            {"pattern": "16x19", "angle": 20, "side_spin": 500},
            "side_spin = 500.0 is not allowed with pattern (a string bed)",
        ),
    ],
)
def test_refused_in_one_line(given, words):
    with pytest.raises(InputError) as err:
        sweep_result(backend="serial", **given)
    assert words in str(err.value) and "\n" not in str(err.value)


def test_a_strung_sweep_takes_side_angle_and_spin_0():
    # nothing crosses the face: the strung oblique impact in the plane, as simulate takes it
    r = sweep_result(string_tension=250.0, angle=20.0, side_angle=0.0, side_spin=0.0,
                     backend="serial")  # fmt: skip
    ref = simulate_oblique(
        incidence=Incidence(angle=20.0), strings=StringBed(tension_n=250.0)
    ).summary()
    _close(float(r.to_xarray().spin_out_rpm), ref["spin_out_rpm"])


def test_a_frame_without_torsion_data_is_refused_before_any_work(tmp_path):
    from fem_racket.frame.segments import Frame, standard_frame

    bare = Frame(standard_frame().segments)  # no GJ, rhoIp: no yaw inertia
    words = r"^side_spin = \[0\.0, 500\.0\] rpm is not allowed on this frame: it has no torsion"
    with pytest.raises(InputError, match=words):
        sweep_result(bare, angle=20.0, side_spin="0,500", output=tmp_path / "s.nc")
    assert not any(tmp_path.iterdir())  # no checkpoint folder: refused before any work
    ds = sweep_result(bare, angle=20.0, side_angle=0.0, backend="serial").to_xarray()
    assert float(ds.side_spin_out_rpm) == 0.0  # nothing crosses the face: no yaw needed


def test_kcb_is_the_normal_impacts():
    # K_CB follows the normal speed V cos(side) cos(angle) (simulate's kcb_n_m), not V: the
    # stiffness the case's normal impact was solved with
    ds = sweep_result(angle=60.0, side_angle="0,40", speed=25.0, backend="serial").to_xarray()
    for b in ds.side_angle.values:
        ref = simulate_oblique(incidence=Incidence(angle=60.0, side_angle=b), speed=25.0)
        _close(float(ds.kcb_n_m.sel(side_angle=b)), ref.summary()["kcb_n_m"])


@pytest.mark.parametrize(
    ("axes", "words"),
    [
        ({"offset": "0,0.02"}, "offset = [0.0, 0.02] m is not allowed on this frame"),
        ({"offset": 0.02}, "offset = 0.02 m is not allowed on this frame"),
        ({"angle": 20.0, "side_angle": "0,10"}, "side_angle = [0.0, 10.0] deg is not allowed"),
    ],
)
def test_the_refusal_without_torsion_data_names_the_values(tmp_path, axes, words):
    from fem_racket.frame.segments import Frame, standard_frame

    bare = Frame(standard_frame().segments)
    with pytest.raises(InputError, match="^" + re.escape(words)) as err:
        sweep_result(bare, output=tmp_path / "s.nc", **axes)
    assert "sweep it at 0; off the axis, give a frame with cell data GJ" in str(err.value)
    assert not any(tmp_path.iterdir())
