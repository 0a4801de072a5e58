"""Off-axis impacts through every solver path of ``simulate`` (issue 24): the paths agree off
axis as on it, offset 0 is the axis, and momentum and energy balance."""

import numpy as np
import pytest

from fem_racket import simulate
from fem_racket.impact.exact.engine import impacts
from fem_racket.impact.result_twist import roll_momentum
from fem_racket.impact.swing import Swing
from fem_racket.validation import InputError

X, Y, V = 0.74, 0.05, 30.0


@pytest.fixture(scope="module")
def exact_run(standard_model):
    return simulate(standard_model, position=X, speed=V, output_step=1e-5, offset=Y)


def test_offset_zero_is_the_axis(standard_model):
    for kw in ({}, {"output_step": None}, {"solver": "general"}):
        a = simulate(standard_model, position=X, speed=V, **kw)
        b = simulate(standard_model, position=X, speed=V, offset=0.0, **kw)
        assert a.cor == b.cor and b.twist is None and "offset_m" not in b.summary()


def test_paths_agree_off_axis(standard_model, exact_run):
    # the closed form with histories is exact; the engine keeps the modes its COR tolerance
    # 1e-6 needs, the general integrator steps for the same tolerance, CVODE rtol 1e-10
    ref = exact_run.cor
    engine = simulate(standard_model, position=X, speed=V, output_step=None, offset=Y)
    batch = impacts(standard_model, position=X, speed=V, offset=Y)
    general = simulate(standard_model, position=X, speed=V, solver="general", offset=Y)
    cvode = simulate(standard_model, position=X, speed=V, solver="cvode", offset=Y)
    assert abs(engine.cor - ref) < 1e-6 and abs(float(batch.cor) - engine.cor) < 1e-12
    assert abs(general.cor - ref) < 1e-6
    assert abs(cvode.cor - ref) < 1e-9
    assert abs(cvode.contact_time - exact_run.contact_time) < 1e-8
    s, c = exact_run.summary(), cvode.summary()
    assert s["roll_rate_rad_s"] == pytest.approx(c["roll_rate_rad_s"], rel=1e-8)
    assert s["torsion_energy_share"] == pytest.approx(c["torsion_energy_share"], rel=1e-7)


def test_momenta_and_energy_balance(standard_model, exact_run):
    r = exact_run
    p, a = r.momentum()  # linear and about the grip end: torsion carries neither
    for h in (p, a):
        np.testing.assert_allclose(h, h[0], rtol=1e-12)
    L = roll_momentum(r)  # about the long axis: the contact force has no net torque
    np.testing.assert_allclose(L, Y * r.ball.mass * V, rtol=1e-12)
    e = r.energies()  # cumulative Simpson on the 1e-5 s grid, as on the axis
    assert np.ptp(e["total"]) / e["total"][0] < 2e-5
    assert e["torsion_kinetic"][-1] > 0.0


def test_roll_rate_is_the_rigid_roll_of_the_impulse(exact_run):
    # I_p Omega = y J (angular impulse about the long axis), J = m_B (V + v_out)
    r = exact_run
    J = r.ball.mass * (V - r.ball_velocity[-1])
    ip = r.model.torsion.polar_moment
    assert r.summary()["roll_rate_rad_s"] == pytest.approx(Y * J / ip, rel=1e-12)


def test_swing_off_axis_superposes(standard_model):
    swing = Swing(velocity=2.0, omega=20.0)  # v_r = 12 m/s toward the ball
    kw = dict(position=X, speed=V, offset=Y, swing=swing)
    exact = simulate(standard_model, output_step=None, **kw)
    cvode = simulate(standard_model, solver="cvode", **kw)
    assert abs(exact.apparent_cor - cvode.apparent_cor) < 1e-6
    assert exact.ball_speed_out == pytest.approx(cvode.ball_speed_out, rel=1e-6)


def test_refusals(standard_model):
    with pytest.raises(InputError, match="basis = 'physical' is not allowed with offset"):
        simulate(standard_model, position=X, offset=Y, solver="bdf", basis="physical")
    with pytest.raises(InputError, match=r"^offset = 0.3 m is not allowed"):
        simulate(standard_model, position=X, offset=0.3)
    with pytest.raises(InputError, match="frame_velocity of shape"):
        simulate(standard_model, position=X, offset=Y, frame_velocity=np.zeros(42))


def test_impact_problem_offset_field(standard_model):
    from fem_racket.frame.hand import Hand
    from fem_racket.impact.problem import ImpactProblem

    p = ImpactProblem.build(standard_model, position=X, offset=Y)
    assert p.offset == Y and "y = 0.05 m" in repr(p)
    assert ImpactProblem.build(standard_model, position=X).offset == 0.0
    with pytest.raises(InputError, match=r"^offset = 0.05 m is not allowed with a hand"):
        ImpactProblem.build(standard_model, position=X, offset=Y, hand=Hand())
    with pytest.raises(InputError, match=r"^offset = 0.13 m is not allowed: the point must lie"):
        ImpactProblem.build(standard_model, position=X, offset=0.13)
    with pytest.raises(InputError, match=r"^offset = nan m is not allowed"):
        ImpactProblem.build(standard_model, position=X, offset=float("nan"))
