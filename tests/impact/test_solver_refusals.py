"""What the library refuses in one InputError line instead of ignoring or failing on (issue 21,
D3; audit items 2 and 13): ``modes`` with the physical basis, an unknown option of
``ImpactProblem.build``, a solver asked to solve what is not a problem, and a separation
under another law than the paper's, said alike by a problem and a batch."""

from __future__ import annotations

import pytest

import fem_racket as fr
from fem_racket.contact.presets import get_law
from fem_racket.impact.problem import ImpactProblem
from fem_racket.impact.problem_batch import ProblemBatch
from fem_racket.impact.solvers import make_solver
from fem_racket.validation import InputError


@pytest.mark.parametrize("name", ["bdf", "cvode"])
def test_modes_with_the_physical_basis_is_refused(name):
    why = f"modes = 10 is not allowed with solver '{name}' with basis 'physical': it integrates"
    with pytest.raises(InputError, match=why):
        make_solver(name, basis="physical", modes=10)
    with pytest.raises(InputError, match=why):
        fr.simulate(solver=name, basis="physical", modes=10)
    assert make_solver(name, basis="physical").options.given() == {"basis": "physical"}


def test_an_unknown_option_of_build_is_refused_naming_the_allowed():
    with pytest.raises(
        InputError,
        match="foo is not an option of ImpactProblem.build: must be "
        "one of elements, position, speed, ball_mass, law, hand, shock_window, kcb",
    ):
        ImpactProblem.build(None, foo=1)


@pytest.mark.parametrize("method", ["solve", "solve_many"])
def test_a_solver_refuses_what_is_not_a_problem(method):
    with pytest.raises(InputError, match="is not allowed: must be"):
        getattr(make_solver("exact"), method)(5)
    with pytest.raises(InputError, match="= 5 is not allowed: must be an ImpactProblem"):
        getattr(make_solver("exact"), method)([5] if method == "solve_many" else 5)


def test_a_batch_refuses_a_separation_under_a_law_as_a_problem_does():
    law = get_law("hunt-crossley")
    with pytest.raises(InputError) as one:
        ImpactProblem.build(None, law=law, separation="force")
    problem = ImpactProblem.build(None, law=law)
    with pytest.raises(InputError) as many:
        ProblemBatch((problem.model,), position=[0.6, 0.7], speed=20.0, law=law, separation="force")
    assert str(many.value) == str(one.value)
    assert "separation = 'force' is not allowed with contact law 'hunt-crossley'" in str(one.value)
