"""A design's impacts as ImpactProblems: the design's batch (:mod:`fem_racket.studies.design.
impacts`, one ProblemBatch by ``solve_many``) against the solvers' ``solve_many`` one problem at
a time, on the same problems."""

from itertools import chain

import numpy as np
import pytest

from fem_racket.contact.linear import kcb_from_speed
from fem_racket.contact.presets import get_law
from fem_racket.frame.hermite import assemble_closed_form
from fem_racket.frame.model import FrameModel
from fem_racket.impact.solvers import make_solver
from fem_racket.studies.design.build import design_problem
from fem_racket.studies.design.cases import closing_kcb, design_solver, free_cases, held_cases
from fem_racket.studies.design.impacts import apparent_cor, grip_shock
from fem_racket.validation import InputError

X = np.array([0.62, 0.8, 0.95])
V = np.array([21.0, 33.0, 38.5])


def models(p, n=2):
    """``n`` designs' frames (seeded)."""
    u = np.random.default_rng(7).random((n, p.n_var))
    return [FrameModel(assemble_closed_form(p.mesh(x))) for x in p.from_unit(u)]


def test_linear_cases_agree_with_the_exact_solver_one_by_one():
    # every mode on both sides (tolerance None): the engine batched over two frames with
    # equal mode counts against one eigen-solution per problem, round-off apart
    p = design_problem(vary=("ei", "string"), zone_points=3)
    factor = np.array([0.7, 1.6])
    kcb = closing_kcb(np.vstack([V, V]), factor)
    runs = [free_cases(p, m, X, V, k) for m, k in zip(models(p), kcb, strict=True)]
    got = apparent_cor(make_solver("auto", tolerance=None, modes=None, output_step=None), runs)
    cases = list(chain(*runs))  # the ImpactProblems, each made and validated as it is read
    ref = make_solver("exact", tolerance=None, modes=None, output_step=None).solve_many(cases)
    np.testing.assert_allclose(got, [r.cor for r in ref], rtol=1e-10)
    assert cases[4].kcb == 1.6 * kcb_from_speed(V[1])  # the design's factor on K_CB(v)


def test_law_cases_agree_with_the_general_solver_one_by_one():
    p = design_problem(vary=("ei",), law=get_law("hysteretic"), zone_points=3, speeds=(25.0,))
    runs = [free_cases(p, model, X, V, p.law) for model in models(p)]
    got = apparent_cor(design_solver(p), runs)
    ref = make_solver("general", output_step=None).solve_many(chain(*runs))
    # the general integrator vouched for at the COR tolerance 1e-6 on both sides
    np.testing.assert_allclose(got, [r.cor for r in ref], atol=2e-6)


def test_held_cases_agree_with_the_held_runs():
    p = design_problem(objectives=("handle_shock",), zone_points=3, speeds=(30.0,))
    cases = [held_cases(p, model, X, V) for model in models(p)]
    rms, peak = grip_shock(design_solver(p, held=True), cases)
    runs = make_solver("exact", tolerance=p.tolerance, output_step=None).solve_many(chain(*cases))
    # the same modal path, one run per problem: round-off apart (measured 1e-12)
    np.testing.assert_allclose(rms, [r.grip_vibration_rms for r in runs], rtol=1e-10)
    np.testing.assert_allclose(peak, [r.peak_grip_force for r in runs], rtol=1e-10)
    assert grip_shock(design_solver(p, held=True), cases, peak=False)[1] is None


def test_the_solver_refuses_what_it_cannot_do():
    p = design_problem(vary=("ei",), law=get_law("hysteretic"), zone_points=3)
    cases = free_cases(p, models(p, 1)[0], X, V, p.law)
    with pytest.raises(InputError, match="solver = 'exact' is not allowed with contact law"):
        apparent_cor(make_solver("exact", output_step=None), [cases])
    with pytest.raises(InputError, match="need one position, speed"):
        free_cases(p, models(p, 1)[0], X, V[:2], p.law)
    assert cases[1:3] == [] or [q.impact.position for q in cases[1:3]] == list(X[1:3])
