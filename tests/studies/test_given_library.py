"""The library's studies keep which options were given (issue 21.3): one given at its default
value is refused where any other value is, with simulate's line where simulate refuses the same
combination; left out, the study runs with the numbers it gave before."""

import numpy as np
import pytest

import fem_racket as fr
from fem_racket.strings.options import bed_from_options
from fem_racket.studies.compare import Play
from fem_racket.studies.design.build import design_problem
from fem_racket.studies.design.options import DesignOptions, VariableOptions, ZoneOptions
from fem_racket.studies.design.solvers import optimize
from fem_racket.studies.map_options import MapPlay
from fem_racket.studies.refine import refinement_study
from fem_racket.studies.sweep import sweep_result
from tests.clirun import library_error

#: Options at their defaults that simulate refuses in these combinations.
AS_SIMULATE = {
    "law-separation": {"law": "hunt-crossley", "separation": "displacement"},
    "cvode-law-basis": {"law": "hunt-crossley", "solver": "cvode", "basis": "modal"},
    "cvode-law-modes": {"law": "hunt-crossley", "solver": "cvode", "modes": 80},
    "cvode-physical-modes": {"solver": "cvode", "basis": "physical", "modes": 80},
    "bed-tolerance": {"string_tension": 246.0, "tolerance": 1e-6},
}


@pytest.mark.parametrize("name", list(AS_SIMULATE))
def test_sweep_refuses_a_default_given_as_simulate_does(name):
    kw = AS_SIMULATE[name]
    said = library_error(lambda: sweep_result(speed=[20.0], position=[0.7], **kw))
    one = {k: v for k, v in kw.items() if k != "string_tension"}  # simulate takes the bed
    if "string_tension" in kw:
        one["strings"] = bed_from_options({"string_tension": kw["string_tension"]})
    assert said == library_error(lambda: fr.simulate(speed=20.0, position=0.7, **one))
    assert said.startswith(f"{[k for k in kw if k not in ('law', 'solver')][-1]} = ")


def test_a_swing_point_or_a_kcb_factor_given_at_its_default_is_refused():
    words = "reference = 0.75 x/L is not allowed without a swing"
    for call in (
        lambda: sweep_result(speed=[20.0], position=[0.7], reference=0.75),
        lambda: fr.racket_map(reference=0.75),
        lambda: MapPlay(reference=0.75),
        lambda: Play(reference=0.75),
    ):
        assert library_error(call).startswith(words)
    said = library_error(lambda: fr.racket_map(law="hunt-crossley", kcb_factor=1.0))
    assert said.startswith("kcb_factor = 1.0 is not allowed with contact law 'hunt-crossley'")
    # left out, it is the swing's default point
    assert MapPlay(racket_speed=5.0).reference == 0.75 and MapPlay().reference is None


def test_refine_and_design_refuse_a_default_given():
    assert library_error(lambda: refinement_study(family="uniform", grading=4.0)).startswith(
        "grading = 4.0 is not allowed with family 'uniform'"
    )
    for kw, words in [
        (
            {"vary": ("rhoa",), "ei_bounds": (50.0, 3000.0)},
            "ei_bounds = (50.0, 3000.0) is not allowed",
        ),
        ({"zone_sigma": 0.05}, "zone_sigma = 0.05 is not allowed with zone 'uniform'"),
        ({"reference": 0.75}, "reference = 0.75 is not allowed without racket_speed"),
    ]:
        assert library_error(lambda kw=kw: design_problem(**kw)).startswith(words)
    # the same defaults not given pass (the options' own defaults ask for nothing)
    options = DesignOptions(VariableOptions(vary=("rhoa",)), ZoneOptions())
    assert options.given == frozenset()
    problem = design_problem(vary=("ei",), link_ei=True, zone_points=3, speeds=(30.0,))
    for kw, name in [({"popsize": 10}, "popsize"), ({"seed": 1}, "seed")]:
        said = library_error(lambda kw=kw: optimize(problem, maxiter=1, **kw))
        assert said.startswith(f"{name} = {kw[name]} is not allowed with method 'SLSQP'")
    assert library_error(lambda: optimize(problem, maxiter=1, polish=True)).startswith(
        "polish = True is not allowed with method 'SLSQP'"
    )


def test_left_out_the_sweep_runs_as_before():
    # under the paper's law an option the exact solver takes, given at its default, changes
    # nothing, bit for bit, and the checkpoint's digest is the same (the pinned digests:
    # test_sweep_digest.py)
    grid = {"speed": [20.0, 30.0], "position": [0.6, 0.8]}
    left = sweep_result(**grid, progress=False)
    given = sweep_result(
        **grid, separation="displacement", modes=80, tolerance=1e-6, progress=False
    )
    assert left.spec.digest == given.spec.digest
    assert np.array_equal(left.values, given.values, equal_nan=True)
    assert left.attrs == given.attrs
    # basis, which the exact solver does not take, given at its default: refused as simulate
    # refuses it (it was accepted as "neutral" before; issue 21.3: one rule, given = refused)
    said = library_error(lambda: sweep_result(**grid, basis="modal", progress=False))
    assert said == library_error(lambda: fr.simulate(solver="exact", basis="modal"))
    assert said.startswith("basis = 'modal' is not allowed with solver 'exact'")
    # under a law, the separation left out: the law's own, as simulate's
    law = sweep_result(speed=[20.0], position=[0.7], law="hunt-crossley", progress=False)
    one = fr.simulate(speed=20.0, position=0.7, law="hunt-crossley", output_step=None)
    assert law.values[0, 0] == pytest.approx(one.cor, rel=1e-12)


def test_a_tolerance_given_at_its_default_is_used_as_simulate_uses_it():
    # an oblique case's normal impact keeps every mode unless a tolerance is given (simulate's
    # rule): the sweep now passes the tolerance given at 1e-6, as simulate takes it
    from fem_racket.impact.incidence import Incidence

    grid = {"speed": [20.0], "position": [0.7], "angle": 30.0, "progress": False}
    for kw in ({}, {"tolerance": 1e-6}):
        one = fr.simulate(speed=20.0, position=0.7, incidence=Incidence(30.0), **kw)
        assert sweep_result(**grid, **kw).values[0, 0] == one.summary()["cor"]
