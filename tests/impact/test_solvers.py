"""The solvers: one protocol, one registry; no option silently dropped (issue: one way to state
and solve an impact). Numbers are compared with the paths they stand for, bit for bit."""

from __future__ import annotations

import pytest

import fem_racket as fr
from fem_racket.impact.held.run import held_impact
from fem_racket.impact.problem import ImpactProblem
from fem_racket.impact.solvers import SOLVER_NAMES, SOLVERS, make_solver
from fem_racket.validation import InputError

MODEL = fr.FrameModel.build(None, 20)
PRESET = "kawazoe-1997-nonlinear"


def test_one_registry_with_every_method_once():
    assert set(fr.SOLVERS) == {"exact", "general", "cvode", "bdf"}
    assert fr.SOLVERS is SOLVERS
    assert len(SOLVER_NAMES) == len(set(SOLVER_NAMES)) and SOLVER_NAMES[0] == "auto"
    # the names the command line shows (impact/constants.py, no solver imported) are the
    # registry's, in its order
    assert SOLVER_NAMES == ("auto", *SOLVERS)


def test_options_are_bound_when_the_solver_is_made():
    s = make_solver("cvode", rtol=1e-9)
    assert repr(s) == "CvodeSolver(rtol=1e-09)"
    with pytest.raises(InputError, match="solver option 'rtl' is not known"):
        make_solver("cvode", rtl=1e-9)
    with pytest.raises(InputError, match="rtol = 1e-09 is not allowed with solver 'exact'"):
        make_solver("exact", rtol=1e-9)
    with pytest.raises(InputError, match="solver = 'newmark'"):
        make_solver("newmark")


def test_auto_picks_exact_for_the_paper_law_and_general_otherwise():
    auto = make_solver()
    assert auto.pick(ImpactProblem.build(MODEL)).name == "exact"
    assert auto.pick(ImpactProblem.build(MODEL, law=PRESET)).name == "general"
    moving = ImpactProblem.build(MODEL, frame_velocity=(1.0, 0.0))
    assert auto.pick(moving).name == "general"
    assert auto.pick(ImpactProblem.build(MODEL, hand=fr.Hand())).name == "exact"


def test_a_law_with_the_exact_solver_is_refused_not_switched():
    # simulate(law=..., solver="exact") used to run "general" and say nothing
    with pytest.raises(InputError, match="solver = 'exact' is not allowed with contact law"):
        fr.simulate(MODEL, law=PRESET, solver="exact")
    with pytest.raises(InputError, match="solver = 'bdf' is not allowed with contact law"):
        fr.simulate(MODEL, law=PRESET, solver="bdf")


@pytest.mark.parametrize(
    ("options", "needle"),
    [
        ({"modes": 10}, "modes = 10 is not allowed with solver 'general'"),
        ({"basis": "physical"}, "basis = 'physical' is not allowed with solver 'general'"),
        ({"rtol": 1e-8}, "rtol = 1e-08 is not allowed with solver 'general'"),
    ],
)
def test_options_a_law_does_not_use_are_refused(options, needle):
    # under a nonlinear law simulate() used to ignore basis and modes: three calls with
    # different values gave the identical COR 0.16599199789738123
    with pytest.raises(InputError, match=needle):
        fr.simulate(MODEL, law=PRESET, output_step=None, **options)
    with pytest.raises(InputError, match="is not allowed with solver 'cvode'"):
        fr.simulate(MODEL, law=PRESET, solver="cvode", modes=10)


def test_the_tolerance_acts_under_a_law():
    cors = [
        fr.simulate(MODEL, law=PRESET, speed=30.0, output_step=None, tolerance=tol).cor
        for tol in (1e-3, 1e-6, 1e-8)
    ]
    assert len(set(cors)) == 3
    # each within its tolerance of the tightest (the integrator's COR error bound, DESIGN.md)
    assert abs(cors[0] - cors[2]) <= 1e-3 and abs(cors[1] - cors[2]) <= 2e-6


def test_solve_many_equals_solve_one_by_one():
    solver = make_solver("exact", output_step=None)
    problems = [ImpactProblem.build(MODEL, position=x, speed=25.0) for x in (0.6, 0.75, 0.9)]
    many = solver.solve_many(problems)
    for p, r in zip(problems, many, strict=True):
        assert r.cor == solver.solve(p).cor


def test_solve_many_checks_every_problem_before_solving_any():
    problems = [ImpactProblem.build(MODEL), ImpactProblem.build(MODEL, law=PRESET)]
    with pytest.raises(InputError, match="solver = 'exact'"):
        make_solver("exact").solve_many(problems)


def test_the_shim_equals_the_solver():
    p = ImpactProblem.build(MODEL, position=0.6, speed=30.0)
    direct = make_solver("cvode", output_step=None).solve(p)
    shim = fr.simulate(MODEL, position=0.6, speed=30.0, solver="cvode", output_step=None)
    assert shim.cor == direct.cor and shim.contact_time == direct.contact_time


def test_held_racket_through_the_solver_equals_the_held_path():
    hand = fr.Hand()
    run = fr.simulate(MODEL, hand=hand, position=0.7, speed=25.0, output_step=None)
    ref = held_impact(ImpactProblem.build(MODEL, hand=hand, position=0.7, speed=25.0))
    assert run.apparent_cor == ref.apparent_cor and run.contact_time == ref.contact_time
    assert run.peak_grip_force == ref.peak_grip_force
    with pytest.raises(InputError, match="modes = 10 is not allowed with solver 'exact' with a"):
        fr.simulate(MODEL, hand=hand, modes=10)
    with pytest.raises(InputError, match="solver = 'general' is not allowed with a hand"):
        fr.simulate(MODEL, hand=hand, solver="general")
    with pytest.raises(InputError, match="tolerance = 1e-08 is not allowed with solver 'cvode'"):
        fr.simulate(MODEL, hand=hand, solver="cvode", tolerance=1e-8)


@pytest.mark.parametrize("law", [None, "kawazoe-1997-ball", "hunt-crossley"])
def test_auto_picks_for_a_strung_batch_what_it_picks_for_each_case(law):
    # One rule for auto (impact.solvers.auto_pick): a batch on string beds under the ball's
    # linear preset used to take 'general' where each of its problems takes 'exact'
    import numpy as np

    from fem_racket.impact.problem_batch import ProblemBatch
    from fem_racket.strings.bed import StringBed

    kw = {} if law is None else {"law": law}
    problem = ImpactProblem.build(elements=6, strings=StringBed(tension_n=250.0), **kw)
    batch = ProblemBatch.of(problem, speed=np.array([20.0, 30.0]))
    auto = make_solver("auto")
    assert auto.pick(batch).name == auto.pick(problem).name
    one = auto.solve(ImpactProblem.build(elements=6, strings=StringBed(tension_n=250.0), **kw))
    assert auto.solve_many(batch).cor[0] == pytest.approx(one.cor, rel=1e-12)  # same method
