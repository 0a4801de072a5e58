"""Many problems as one ProblemBatch: each solver's ``solve_many`` answers it case by case
what ``solve`` answers for the batch's problems (the batched engine, the general integrator's
one call, the ODE solvers' loop), and refuses in one line what it cannot do."""

from __future__ import annotations

import numpy as np
import pytest

from fem_racket.contact.presets import get_law
from fem_racket.frame.model import FrameModel
from fem_racket.frame.segments import standard_frame
from fem_racket.impact.problem_batch import ProblemBatch
from fem_racket.impact.solvers import make_solver
from fem_racket.validation import InputError


@pytest.fixture(scope="module")
def models():
    return (FrameModel.build(standard_frame(146.0), 20), FrameModel.build(None, 12))


def _batch(models, **fields):
    return ProblemBatch(
        models,
        position=[0.6, 0.75, 0.9, 0.8],
        speed=[20.0, 30.0, 25.0, 40.0],
        frame=[0, 0, 1, 1],
        ei_factor=[1.0, 2.0, 1.0, 0.5],
        swing=[[0.0, 0.0], [0.0, 0.0], [1.0, 20.0], [0.0, 0.0]],
        **fields,
    )


def test_exact_batch_is_each_problem_solved_exactly(models):
    # every mode (tolerance None): the engine and the closed form of each problem agree to
    # their root-finding precision (1e-9 relative, the engine's sum rules)
    batch = _batch(models, kcb=[3e4, 5e4, 6e4, 8e4], peak_force=True)
    out = make_solver("exact", tolerance=None).solve_many(batch)
    solver = make_solver("exact", tolerance=None, output_step=None)
    for i in range(len(batch)):
        r = solver.solve(batch.problem(i))
        assert out.cor[i] == pytest.approx(r.cor, rel=1e-9)
        assert out.contact_time[i] == pytest.approx(r.contact_time, rel=1e-9)
        assert out.ball_speed_out[i] == pytest.approx(r.ball_speed_out, rel=1e-9)
    assert np.array_equal(out.kcb, batch.kcb)
    assert out.racket_speed[2] == pytest.approx(1.0 + 20.0 * 0.9 * models[1].mesh.length)
    assert np.all(np.isfinite(out.peak_force))


def test_general_batch_is_each_problem_by_the_general_integrator(models):
    law = get_law("kawazoe-1997-nonlinear")
    batch = _batch(models, law=law)
    out = make_solver("general").solve_many(batch)
    solver = make_solver("general", output_step=None)
    for i in range(len(batch)):
        r = solver.solve(batch.problem(i))
        # one integrator per case, each vouched for to the COR tolerance 1e-6
        assert out.cor[i] == pytest.approx(r.cor, abs=2e-6)
        assert out.ball_speed_out[i] == pytest.approx(r.ball_speed_out, abs=2e-6 * 40)
    assert np.all(np.isnan(out.kcb))


def test_auto_picks_per_batch_and_cvode_loops(models):
    batch = ProblemBatch(models[1:], position=[0.75], speed=[20.0])
    auto = make_solver("auto").solve_many(batch)
    exact = make_solver("exact").solve_many(batch)
    assert auto.cor[0] == exact.cor[0]
    ode = make_solver("cvode", output_step=None).solve_many(batch)
    assert ode.cor[0] == pytest.approx(exact.cor[0], abs=1e-6)


@pytest.mark.parametrize(
    ("solver", "fields", "words"),
    [
        ("exact", {"law": "hunt-crossley"}, "solver = 'exact' is not allowed with contact law"),
        ("general", {}, "solver = 'general' is not allowed with a ProblemBatch under the paper"),
    ],
)
def test_a_solver_refuses_a_batch_it_cannot_do(models, solver, fields, words):
    if "law" in fields:
        fields = {"law": get_law(fields["law"])}
    with pytest.raises(InputError, match=words):
        make_solver(solver).solve_many(ProblemBatch(models, position=0.75, speed=20.0, **fields))


def test_options_a_batch_does_not_use_are_refused(models):
    with pytest.raises(InputError, match="output_step = 1e-05 is not allowed with solver 'exact'"):
        make_solver("exact", output_step=1e-5).solve_many(
            ProblemBatch(models, position=0.75, speed=20.0)
        )


@pytest.mark.parametrize(
    ("fields", "words"),
    [
        ({"frame": [0, 2]}, "frame is not allowed: must index the 2 models"),
        ({"kcb": 3e4, "law": "hunt-crossley"}, "kcb = 30000.0 is not allowed with contact law"),
        (
            {"speed": [20.0, 30.0, 40.0]},
            "position of 2 values is not allowed",
        ),
    ],
)
def test_a_malformed_batch_is_refused(models, fields, words):
    if "law" in fields:
        fields["law"] = get_law(fields["law"])
    fields.setdefault("speed", 20.0)
    with pytest.raises(InputError, match=words):
        ProblemBatch(models, position=[0.7, 0.8], **fields)


@pytest.mark.parametrize("modes, tolerance", [(80, 1e-6), (7, 1e-6), (None, None), (12, None)])
def test_frames_in_one_engine_call_give_each_case_its_own_bits(
    models, monkeypatch, modes, tolerance
):
    # frames whose modes go whole to the engine share modal_impacts calls (engine_calls.grouped):
    # every case as one engine call per frame gives it, to the bit, EI factors and swings too
    import fem_racket.impact.batch_solve as batch_solve
    from fem_racket.impact.engine_calls import whole_modes

    rng = np.random.default_rng(2)
    n = 30
    frames = (*models, FrameModel.build(None, 20))  # two frames of 40 modes, one of 24
    batch = ProblemBatch(
        frames,
        position=rng.uniform(0.5, 0.95, n),
        speed=rng.uniform(15.0, 40.0, n),
        frame=rng.integers(0, 3, n),
        ei_factor=rng.choice([1.0, 0.7, 1.9], n),
        swing=np.column_stack([rng.uniform(0.0, 3.0, n), rng.uniform(0.0, 20.0, n)]),
        zeta=rng.uniform(0.0, 0.2, n),
        peak_force=True,
    )
    solver = make_solver("exact", modes=modes, tolerance=tolerance)
    assert whole_modes(batch, solver.options.settings())
    together = solver.solve_many(batch)
    monkeypatch.setattr(batch_solve, "whole_modes", lambda *args: False)
    apart = solver.solve_many(batch)
    assert np.array_equal(together.columns(), apart.columns())
    # with static totals (a tolerance, every mode) or off the axis: one call per frame
    assert not whole_modes(batch, make_solver("exact", modes=None).options.settings())
