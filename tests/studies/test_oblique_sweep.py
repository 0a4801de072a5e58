"""Oblique sweeps over angle, spin and friction (fem_racket.studies.oblique_sweep) and the README
figure's script (scripts/oblique_spin.py)."""

import pytest
from script_loader import load_script

from fem_racket.impact.incidence import Incidence
from fem_racket.impact.simulate_oblique import simulate_oblique
from fem_racket.studies.oblique_sweep import oblique_sweep
from fem_racket.validation import InputError


@pytest.mark.parametrize("clamped", [True, False])
def test_every_case_is_the_single_impact(clamped):
    # the shared normal impact changes nothing: each case equals simulate_oblique exactly
    sweep = oblique_sweep(
        angles=(20.0, 55.0), spins=(-2000.0, 0.0, 3000.0), frictions=(0.0, 0.4), speed=25.0,
        clamped=clamped,
    )  # fmt: skip
    assert sweep["spin_out_rpm"].shape == (2, 3, 2)
    for i, angle in enumerate(sweep.angle_deg):
        for j, spin in enumerate(sweep.spin_rpm):
            for k, mu in enumerate(sweep.friction):
                inc = Incidence(angle=angle, spin=spin, friction=mu)
                ref = simulate_oblique(incidence=inc, speed=25.0, clamped=clamped).summary()
                for key in ("spin_out_rpm", "angle_out_deg", "ball_speed_out_m_s", "cor"):
                    assert sweep[key][i, j, k] == ref[key]
                assert sweep["contact_regime"][i, j, k] == ref["contact_regime"]
    # no friction: the spin stays; friction turns a ball without spin into topspin
    assert (sweep["spin_out_rpm"][:, :, 0] == sweep.spin_rpm[None, :]).all()
    assert (sweep["spin_out_rpm"][:, 1, 1] > 0).all()


def test_bad_axes_are_refused():
    with pytest.raises(InputError, match=r"^angle = 95.0 deg is not allowed"):
        oblique_sweep(angles=(10.0, 95.0), clamped=True)
    with pytest.raises(InputError, match=r"^spins = \(\) is not allowed"):
        oblique_sweep(angles=(10.0,), spins=(), clamped=True)


def test_the_readme_figure_script_quick(tmp_path):
    path = load_script("oblique_spin").main(["--quick", "--out", str(tmp_path / "spin.png")])
    assert path.is_file() and path.stat().st_size > 10_000


def test_the_spin_map_over_the_face():
    # each point is the single impact there; the free racket recoils along its axis with its
    # whole mass wherever it is struck, so the spin varies only through the normal impact
    from fem_racket.studies.oblique_sweep import oblique_map

    inc = Incidence(angle=40.0, spin=-3820.0)
    m = oblique_map(positions=(0.6, 0.75, 0.9), incidence=inc, speed=25.0)
    assert m["spin_out_rpm"].shape == (3,)
    for i, x in enumerate(m["position_x_over_l"]):
        ref = simulate_oblique(incidence=inc, speed=25.0, position=x).summary()
        assert m["spin_out_rpm"][i] == ref["spin_out_rpm"]
        assert m["cor"][i] == ref["cor"]
