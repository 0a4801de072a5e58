"""The exact solver honours a COR ``tolerance`` when it computes histories (issue 21, D3: "no
argument is ever silently ignored"; audit item 1). Without histories the batched engine keeps
the modes below beta omega_c and a residual pseudo-mode for the rest; with histories and a
tolerance the same roots are summed at every output time
(:func:`fem_racket.impact.exact.single.engine_impact`), so the state at separation, and the
COR, are those without histories bit for bit. Without a tolerance, histories keep every mode
(the eigen-solution), as before.
"""

from __future__ import annotations

import numpy as np
import pytest

import fem_racket as fr
from fem_racket.impact.incidence import Incidence
from fem_racket.impact.problem import ImpactProblem
from fem_racket.impact.solvers import make_solver
from fem_racket.impact.swing import Swing

#: simulate()'s COR on main before this change (histories, every mode): it must not move.
DEFAULT_COR = 0.3765697539451113
#: simulate(output_step=None, tolerance=0.1): the engine keeping the modes the tolerance needs.
LOOSE_COR = 0.3765647691247458


def test_the_default_histories_are_unchanged():
    r = fr.simulate()
    assert r.cor == DEFAULT_COR
    every = fr.simulate(tolerance=0)  # 0: every mode, which is what histories keep by default
    assert every.cor == r.cor
    np.testing.assert_array_equal(every.frame_displacement, r.frame_displacement)
    assert r.tolerance is None and every.tolerance is None


@pytest.mark.parametrize(
    "problem",
    [{}, {"swing": Swing(30.0)}, {"offset": 0.02}, {"separation": "force"}],
    ids=["rest", "swing", "offset", "force"],
)
def test_a_loose_tolerance_changes_histories_as_it_changes_the_engine(problem):
    loose = fr.simulate(tolerance=0.1, **problem)
    alone = fr.simulate(tolerance=0.1, output_step=None, **problem)
    assert loose.cor == alone.cor  # the same sums at t_c
    assert loose.contact_time == alone.contact_time
    assert loose.peak_force == alone.peak_force
    assert loose.cor != fr.simulate(**problem).cor
    assert loose.tolerance == 0.1 and loose.t.size > 100
    if not problem:
        assert loose.cor == LOOSE_COR


def test_histories_by_the_engines_roots_match_the_eigen_solution():
    """Two independent paths: every mode kept, the engine's roots summed at each output time
    against the eigenvectors of the closed form (the residues lose a few digits near the modes'
    poles: 4e-9 of the largest frame velocity here, as the engine's own state at t_c)."""
    engine = fr.simulate(tolerance=1e-12)  # keeps every one of the 40 modes here
    exact = fr.simulate()
    assert engine.n_modes == exact.n_modes == 40
    np.testing.assert_allclose(engine.t, exact.t, rtol=1e-12)  # t_c by another root finder
    scale = np.abs(exact.frame_displacement).max()
    np.testing.assert_allclose(
        engine.frame_displacement, exact.frame_displacement, atol=1e-10 * scale
    )
    scale = np.abs(exact.frame_velocity).max()
    np.testing.assert_allclose(engine.frame_velocity, exact.frame_velocity, atol=1e-8 * scale)
    np.testing.assert_allclose(engine.ball_velocity, exact.ball_velocity, rtol=0, atol=1e-10)
    assert engine.cor == pytest.approx(exact.cor, abs=1e-12)


def test_the_solver_and_an_oblique_ball_use_it_too():
    p = ImpactProblem.build(None)
    assert make_solver("exact", tolerance=0.1).solve(p).cor == LOOSE_COR
    incidence = Incidence(angle=30.0)
    cor = {t: fr.simulate(incidence=incidence, tolerance=t).summary()["cor"] for t in (0.1, 0)}
    default = fr.simulate(incidence=incidence).summary()["cor"]
    assert cor[0.1] != default and cor[0] == default
