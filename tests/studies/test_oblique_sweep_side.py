"""``oblique_sweep``'s side axes and ``oblique_map``'s side incidence (a 3-D ball crossing the
face): each case is ``simulate``'s (1e-12), side angle and side spin 0 are today's outputs bit
for bit, bad values are refused in one line naming the parameter."""

from __future__ import annotations

import numpy as np
import pytest

import fem_racket
from fem_racket.impact.incidence import Incidence
from fem_racket.impact.simulate_oblique import simulate_oblique
from fem_racket.studies.oblique_sweep import OUTPUTS, SIDE_OUTPUTS, oblique_map, oblique_sweep
from fem_racket.validation import InputError
from tests.clirun import run_json


def _close(got: float, want: float) -> None:
    # the same normal impact and tangential march as simulate's: equal to rounding (1e-12)
    assert got == pytest.approx(want, rel=1e-12, abs=1e-12)


def test_side_outputs_are_named_as_the_sweeps_dataset():
    from fem_racket.studies.cases import LATERAL_VARIABLES

    assert SIDE_OUTPUTS == LATERAL_VARIABLES
    assert SIDE_OUTPUTS == ("side_angle_out_deg", "side_spin_out_rpm", "racket_yaw_rate_rad_s")


@pytest.mark.parametrize("clamped", [False, True])
def test_every_side_case_is_the_single_3d_impact(clamped):
    sweep = fem_racket.oblique_sweep(
        angles=(20.0,), spins=(0.0, 1500.0), side_angles=(-10.0, 15.0), side_spins=(0.0, 800.0),
        speed=25.0, clamped=clamped,
    )  # fmt: skip
    assert sweep["side_spin_out_rpm"].shape == (1, 2, 1, 2, 2)
    assert list(sweep.side_angle_deg) == [-10.0, 15.0]
    assert list(sweep.side_spin_rpm) == [0.0, 800.0]
    for j, spin in enumerate(sweep.spin_rpm):
        for m, b in enumerate(sweep.side_angle_deg):
            for n, w in enumerate(sweep.side_spin_rpm):
                inc = Incidence(angle=20.0, spin=spin, side_angle=b, side_spin=w)
                if clamped:
                    ref = simulate_oblique(incidence=inc, speed=25.0, clamped=True).summary()
                else:
                    ref = fem_racket.simulate(incidence=inc, speed=25.0).summary()
                for key in (*OUTPUTS, *SIDE_OUTPUTS):
                    _close(sweep[key][0, j, 0, m, n], ref[key])
                assert sweep["contact_regime"][0, j, 0, m, n] == ref["contact_regime"]
    # the ball crossing the face turns the free racket about its normal, not a clamped head
    yaw = sweep["racket_yaw_rate_rad_s"]
    assert (yaw == 0.0).all() if clamped else (yaw[0, :, 0, 1, :] != 0.0).all()


def test_a_side_case_is_the_commands(capsys):
    # fem-racket simulate --angle 20 --side-angle 10 --side-spin 800 --speed 25
    argv = ("--angle", "20", "--side-angle", "10", "--side-spin", "800", "--speed", "25")
    one = run_json(capsys, "simulate", *argv)
    sweep = oblique_sweep(angles=(20.0,), side_angles=(10.0,), side_spins=(800.0,), speed=25.0)
    for key in (*OUTPUTS, *SIDE_OUTPUTS):
        _close(float(sweep[key][0, 0, 0, 0, 0]), one[key])
    assert sweep["contact_regime"][0, 0, 0, 0, 0] == one["contact_regime"]


@pytest.mark.parametrize("clamped", [False, True])
def test_side_0_is_todays_sweep_bit_for_bit(clamped):
    grid = {"angles": (20.0, 45.0), "spins": (-1000.0, 2000.0), "frictions": (0.0, 0.4)}
    today = oblique_sweep(**grid, speed=25.0, clamped=clamped)
    side = oblique_sweep(**grid, speed=25.0, clamped=clamped, side_angles=0.0, side_spins=0.0)
    assert today.side_angle_deg is None and today.side_spin_rpm is None
    assert list(today.outputs) == [*OUTPUTS, "contact_regime"]  # no side outputs unless given
    for key in (*OUTPUTS, "contact_regime"):
        assert today[key].shape == (2, 2, 2)
        assert np.array_equal(side[key][..., 0, 0], today[key]), key
    for key in SIDE_OUTPUTS:
        assert (side[key] == 0.0).all(), key


def test_one_side_axis_takes_the_others_from_base():
    base = Incidence(side_spin=500.0)
    sweep = oblique_sweep(angles=(30.0,), side_angles=(5.0,), base=base, clamped=True)
    assert list(sweep.side_spin_rpm) == [500.0] and sweep["spin_out_rpm"].shape == (1,) * 5
    ref = simulate_oblique(
        incidence=Incidence(angle=30.0, side_angle=5.0, side_spin=500.0), clamped=True
    ).summary()
    _close(float(sweep["side_spin_out_rpm"][0, 0, 0, 0, 0]), ref["side_spin_out_rpm"])
    # a base crossing the face without side axes: today's shape, with the side outputs
    plain = oblique_sweep(angles=(30.0,), base=Incidence(side_angle=5.0), clamped=True)
    assert plain["side_angle_out_deg"].shape == (1, 1, 1) and plain.side_angle_deg is None
    ref = simulate_oblique(incidence=Incidence(angle=30.0, side_angle=5.0), clamped=True)
    _close(float(plain["side_angle_out_deg"][0, 0, 0]), ref.summary()["side_angle_out_deg"])


def test_the_map_carries_the_side_outputs():
    inc = Incidence(angle=30.0, spin=-2000.0, side_angle=12.0, side_spin=-600.0)
    m = fem_racket.oblique_map(positions=(0.6, 0.8), incidence=inc, speed=25.0)
    assert m["side_spin_out_rpm"].shape == (2,)
    for i, x in enumerate(m["position_x_over_l"]):
        ref = fem_racket.simulate(incidence=inc, speed=25.0, position=x).summary()
        for key in (*OUTPUTS, *SIDE_OUTPUTS):
            _close(m[key][i], ref[key])
        assert m["contact_regime"][i] == ref["contact_regime"]
    plane = oblique_map(positions=(0.6,), incidence=Incidence(angle=30.0), speed=25.0)
    assert list(plane) == ["position_x_over_l", *OUTPUTS, "contact_regime"]  # as before


@pytest.mark.parametrize(
    ("given", "words"),
    [
        (
            {"side_angles": (10.0, 90.0)},
            "side_angle = 90.0 deg is not allowed: must lie in (-90, 90)",
        ),
        ({"side_angles": (-90.0,)}, "side_angle = -90.0 deg is not allowed"),
        ({"side_spins": (0.0, np.nan)}, "side_spin = nan rpm is not allowed"),
        ({"side_spins": (np.inf,)}, "side_spin = inf rpm is not allowed"),
        ({"side_angles": ()}, "side_angles = () is not allowed: must be one or more numbers"),
        ({"side_spins": [[1.0]]}, "side_spins = [[1.0]] is not allowed"),
    ],
)
def test_bad_side_values_are_refused_in_one_line(given, words):
    with pytest.raises(InputError) as err:
        oblique_sweep(angles=(20.0,), clamped=True, **given)
    assert words in str(err.value) and "\n" not in str(err.value)


def test_the_maps_bad_incidence_is_refused_in_one_line():
    with pytest.raises(InputError, match=r"^incidence = 12\.0 is not allowed: must be an Inc"):
        oblique_map(positions=(0.7,), incidence=12.0)
    with pytest.raises(InputError, match=r"^side_angle = 95\.0 deg is not allowed"):
        oblique_map(positions=(0.7,), incidence=Incidence(side_angle=95.0))
