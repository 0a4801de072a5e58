"""Rackets held in a hand as one ProblemBatch: the exact solver's held batch
(:mod:`fem_racket.impact.held.batch`) answers each case as a single held run does, with the
grip-shock measures as extra columns; the ODE solvers case by case; refusals in one line."""

from __future__ import annotations

import numpy as np
import pytest

from fem_racket.contact.presets import get_law
from fem_racket.frame.hand import FIRM_GRIP, LOOSE_GRIP
from fem_racket.frame.model import FrameModel
from fem_racket.impact.problem import HeldRacket, ImpactProblem
from fem_racket.impact.problem_batch import ProblemBatch
from fem_racket.impact.solvers import make_solver
from fem_racket.validation import InputError


@pytest.fixture(scope="module")
def models():
    return (FrameModel.build(None, 20), FrameModel.build(None, 12))


def _batch(models, **fields):
    fields.setdefault("hand", FIRM_GRIP)
    return ProblemBatch(
        models,
        position=[0.6, 0.75, 0.9, 0.8, 0.7],
        speed=[20.0, 30.0, 25.0, 40.0, 30.0],
        frame=[0, 0, 1, 1, 0],
        ei_factor=[1.0, 1.0, 1.0, 0.5, 1.0],
        **fields,
    )


def test_held_batch_is_each_held_run(models):
    # the same modal path (held.modal) per case; a frame's cases in one call differ from a
    # single run only by the round-off of the mode values' product (measured 1e-12)
    batch = _batch(models, zeta=0.08, swing=[[0.0, 0.0]] * 4 + [[2.0, 10.0]], peak_force=True)
    out = make_solver("exact", tolerance=1e-6).solve_many(batch)
    solver = make_solver("exact", tolerance=1e-6, output_step=None)
    for i in range(len(batch)):
        problem = batch.problem(i)
        r = solver.solve(problem)
        assert out.cor[i] == pytest.approx(r.apparent_cor, rel=1e-10)
        assert out.contact_time[i] == pytest.approx(r.contact_time, rel=1e-10)
        assert out.ball_speed_out[i] == pytest.approx(r.ball_speed_out, rel=1e-10)
        assert out.peak_force[i] == pytest.approx(r.peak_force, rel=1e-10)
        assert out.extra["grip_vibration_rms_n"][i] == pytest.approx(r.grip_vibration_rms, rel=1e-9)
        assert out.extra["peak_grip_force_n"][i] == pytest.approx(r.peak_grip_force, rel=1e-9)
        assert out.kcb[i] == problem.contact().stiffness
        assert out.modes[i] == r.used["modes"]
        assert out.racket_speed[i] == problem.racket_speed
    assert out.racket_speed[4] > 0.0
    # without peaks: NaN where they would be, the RMS unchanged
    lean = make_solver("exact", tolerance=1e-6).solve_many(_batch(models, zeta=0.08))
    assert np.all(np.isnan(lean.peak_force)) and np.all(np.isnan(lean.extra["peak_grip_force_n"]))


def test_of_a_held_problem_and_the_hand_matters(models):
    p = ImpactProblem.build(models[1], hand=LOOSE_GRIP, shock_window=0.03, position=0.8)
    loose = make_solver("exact").solve_many(ProblemBatch.of(p, speed=[20.0, 35.0]))
    firm_p = p.replace(structure=HeldRacket(models[1], FIRM_GRIP, 0.03))
    firm = make_solver("exact").solve_many(ProblemBatch.of(firm_p, speed=[20.0, 35.0]))
    single = make_solver("exact").solve(p)  # every mode, as the batch without a tolerance
    assert loose.extra["grip_vibration_rms_n"][0] == pytest.approx(
        single.grip_vibration_rms, rel=1e-9
    )
    assert not np.allclose(loose.extra["grip_vibration_rms_n"], firm.extra["grip_vibration_rms_n"])
    assert "held in a hand" in repr(ProblemBatch.of(p, speed=[20.0, 35.0]))


def test_cvode_answers_a_held_batch_case_by_case():
    model = FrameModel.build(None, 6)
    batch = ProblemBatch((model,), position=[0.7, 0.85], speed=[25.0, 30.0], hand=FIRM_GRIP)
    exact = make_solver("exact").solve_many(batch)
    ode = make_solver("cvode").solve_many(batch)
    # the integrator on every DOF of frame + hand against the eigen-solution (rtol 1e-10)
    np.testing.assert_allclose(ode.cor, exact.cor, rtol=1e-6)
    np.testing.assert_allclose(
        ode.extra["grip_vibration_rms_n"], exact.extra["grip_vibration_rms_n"], rtol=1e-3
    )
    assert np.all(np.isnan(ode.modes))


def test_what_a_held_batch_refuses(models):
    with pytest.raises(InputError, match="law is not allowed in a ProblemBatch with a hand"):
        _batch(models, law=get_law("hysteretic"))
    with pytest.raises(InputError, match="shock_window = 0.03 s is not allowed without a hand"):
        _batch(models, hand=None, shock_window=0.03)
    with pytest.raises(InputError, match="offset is not allowed in a ProblemBatch with a hand"):
        _batch(models, offset=0.01)
    with pytest.raises(InputError, match="hand = 3 is not allowed: must be a Hand"):
        _batch(models, hand=3)
    batch = _batch(models)
    with pytest.raises(InputError, match="modes = 10 is not allowed with solver 'exact' with a h"):
        make_solver("exact", modes=10).solve_many(batch)
    with pytest.raises(InputError, match="solver = 'general' is not allowed with a ProblemBatch"):
        make_solver("general").solve_many(batch)
    with pytest.raises(InputError, match="output_step = 1e-05 is not allowed with solver 'exact'"):
        make_solver("exact", output_step=1e-5).solve_many(batch)
    with pytest.raises(
        InputError, match=r"shock_window = 2.0 s is not allowed: must lie in \(0, 1\]"
    ):
        make_solver("exact").solve_many(_batch(models, shock_window=2.0))
    # a swing that does not close on the ball: refused when the batch is made
    with pytest.raises(InputError, match="the two must close"):
        _batch(models, swing=[[-50.0, 0.0]] * 5)
