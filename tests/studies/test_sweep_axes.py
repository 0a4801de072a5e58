"""The sweep's string-bed and oblique-ball axes (issue 25 item 3, issue 26 item 4): each case
is the single impact ``simulate`` gives, the new outputs carry units, and what cannot combine
is refused in one line before any work."""

from __future__ import annotations

import numpy as np
import pytest

from fem_racket.impact.incidence import Incidence
from fem_racket.impact.problem import ImpactProblem
from fem_racket.impact.simulate_oblique import simulate_oblique
from fem_racket.impact.solvers import make_solver
from fem_racket.strings.bed import StringBed
from fem_racket.studies.sweep import sweep_result
from fem_racket.studies.sweep_physics import regime_code, regime_label


def test_oblique_axes_are_the_single_oblique_impacts():
    r = sweep_result(
        angle="20,55", spin="-2000,3000", friction="0,0.4", speed=25.0, backend="serial"
    )
    ds = r.to_xarray()
    assert ds.spin_out_rpm.dims == ("angle", "spin", "friction")
    assert ds.spin_out_rpm.attrs["units"] == "rpm" and ds.angle_out_deg.attrs["units"] == "deg"
    for a in ds.angle.values:
        for s in ds.spin.values:
            for mu in ds.friction.values:
                inc = Incidence(angle=a, spin=s, friction=mu)
                ref = simulate_oblique(incidence=inc, speed=25.0).summary()
                case = ds.sel(angle=a, spin=s, friction=mu)
                for key in ("spin_out_rpm", "angle_out_deg", "ball_speed_out_m_s", "cor"):
                    assert float(case[key]) == ref[key], key  # the shared normal: exact
                assert regime_label(float(case.contact_regime)) == ref["contact_regime"]
    # mu = 0: the spin is unchanged (issue 26's check), to the last digit
    assert np.array_equal(ds.spin_out_rpm.sel(friction=0.0), np.broadcast_to(ds.spin, (2, 2)))


def test_string_axes_are_the_single_strung_impacts():
    r = sweep_result(
        string_tension="220,270", pattern="16x19,18x20", position=0.74, speed=30.0,
        backend="serial",
    )  # fmt: skip
    ds = r.to_xarray()
    assert "kcb_n_m" not in ds and ds.stringbed_stiffness_n_m.attrs["units"] == "N/m"
    assert ds.pattern.attrs["flag_meanings"] == "16x19 18x20"
    solver = make_solver("exact")
    for t in ds.string_tension.values:
        for code in ds.pattern.values:
            bed = StringBed(tension_n=float(t), mains=int(code) // 100, crosses=int(code) % 100)
            one = solver.solve(ImpactProblem.build(None, position=0.74, speed=30.0, strings=bed))
            case = ds.sel(string_tension=t, pattern=code)
            assert float(case.cor) == pytest.approx(one.cor, rel=1e-12)
            assert float(case.contact_time_s) == pytest.approx(one.contact_time, rel=1e-12)
            assert float(case.stringbed_stiffness_n_m) == one.point.bed_stiffness
    # 50 N more tension: a stiffer bed, a shorter contact and a lower e_A (issue 25)
    assert np.all(ds.stringbed_stiffness_n_m.diff("string_tension") > 0)
    assert np.all(ds.contact_time_s.diff("string_tension") < 0)
    assert np.all(ds.cor.diff("string_tension") < 0)


@pytest.mark.parametrize(
    "label", ["slide", "grip", "slide-grip", "grip-slide", "slide-grip-slide", "grip-slide-grip"]
)
def test_regime_codes_round_trip(label):
    assert regime_label(regime_code(label)) == label


def test_head_on_without_spin_is_a_case_not_a_failure(tmp_path):
    # angle 0, spin 0: the tangential COR is 0/0 (NaN), every other output is the head-on
    # impact's (issue 26: "head-on with zero spin: identical to today")
    r = sweep_result(angle="0,30", spin="0,2000", output=tmp_path / "o.csv", backend="serial")
    assert r.failed == 0
    from fem_racket import simulate

    assert r.values[0, 0] == simulate(speed=20.0).cor  # the exact solution, as simulate's
    rows = (tmp_path / "o.csv").read_text().splitlines()
    assert rows[0].startswith("angle [deg],spin [rpm],cor [-],")
    assert "spin_out_rpm [rpm]" in rows[0] and rows[1].endswith(",grip")
    assert (tmp_path / "o.csv.json").is_file()


def test_the_balls_inertia_radius_and_compliance_are_axes_too():
    # a hollower ball (larger I/(m R^2)) takes less spin from the same grip (beta_t = 1 + mR^2/I)
    r = sweep_result(angle=30.0, ball_inertia="0.4,0.66", compliance_ratio=1.2, ball_radius=0.034,
                     speed=25.0, backend="serial")  # fmt: skip
    ds = r.to_xarray()
    assert ds.spin_out_rpm.dims == ("ball_inertia",)
    assert ds.attrs["compliance_ratio_eta2"] == 1.2 and ds.attrs["ball_radius_m"] == 0.034
    for k, inertia in enumerate(ds.ball_inertia.values):
        inc = Incidence(angle=30.0, ball_inertia=inertia, compliance_ratio=1.2, radius=0.034)
        ref = simulate_oblique(incidence=inc, speed=25.0).summary()
        assert float(ds.spin_out_rpm[k]) == ref["spin_out_rpm"]
