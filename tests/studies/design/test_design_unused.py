"""Design settings a study would ignore are refused when they are made (issue 21.3), in the
library as on the command line (:mod:`fem_racket.studies.design.unused`): one line naming the
option, and a default value or a used one passes."""

import pytest

from fem_racket.contact.presets import get_law
from fem_racket.io.design_study import OptimizationRun, OutputOptions, run_optimization
from fem_racket.studies.design.build import design_problem
from fem_racket.studies.design.options import DesignOptions, SearchOptions, VariableOptions
from fem_racket.studies.design.paper_problem import paper_problem
from fem_racket.studies.design.solvers import optimize
from fem_racket.studies.design.unused import RULES, SEARCH_RULES
from fem_racket.studies.map_options import check_at_rest
from fem_racket.validation import InputError

#: Keywords of design_problem -> the option named in the refusal.
REFUSED = {
    "ei_bounds=(100, 2000), vary=('rhoa',)": "ei_bounds",
    "link_ei=True, vary=('rhoa',)": "link_ei",
    "rhoa_bounds=(0.3, 1.0), vary=('ei',)": "rhoa_bounds",
    "link_rhoa=True, vary=('ei',)": "link_rhoa",
    "mass_start=0.01": "mass_start",
    "mass_width=0.03": "mass_width",
    "mass_positions=(0.5,), mass_bounds=(0.0, 0.05)": "mass_bounds",
    "mass_positions=(0.5,), position_bounds=(0.2, 0.8)": "position_bounds",
    "interpolation='linear'": "interpolation",
    "string_bounds=(0.6, 1.5)": "string_bounds",
    "cubic_bounds=(0.0, 1e9)": "cubic_bounds",
    "objectives=('power_region',), zone='node'": "zone",
    "objectives=('power_region',), zone_points=5": "zone_points",
    "objectives=('power_region',), zone_range=(0.5, 0.8)": "zone_range",
    "objectives=('power_region',), zone_sigma=0.1": "zone_sigma",
    "zone='node', zone_range=(0.5, 0.8)": "zone_range",
    "zone_sigma=0.1": "zone_sigma",
    "reference=0.6": "reference",
    "pivot=0.2": "pivot",
    "swing_exponent=-0.1": "swing_exponent",
    "zeta=0.05, law=get_law('hunt-crossley')": "zeta",
    "grip='firm'": "grip",
    "shock_window=0.01": "shock_window",
    "vary=('ei', 'mass')": "vary",
    "vary=('ei', 'position')": "vary",
}


def _kw(text):
    return eval(f"dict({text})", {"get_law": get_law})


@pytest.mark.parametrize("text", list(REFUSED))
def test_design_problem_refuses_what_it_would_ignore(text):
    name = REFUSED[text]
    with pytest.raises(InputError, match=rf"^{name} = .* is not allowed ") as err:
        design_problem(**_kw(text))
    assert "\n" not in str(err.value)


def test_every_rule_is_exercised_and_names_a_field():
    named = set(REFUSED.values())
    assert {name for _, name, _, _ in RULES} <= named
    for group, name, _, _ in RULES:
        assert hasattr(getattr(DesignOptions(), group), name)
    for name, _, _ in SEARCH_RULES:
        assert hasattr(SearchOptions(), name)


@pytest.mark.parametrize(
    "text",
    [
        "vary=('ei',), link_ei=True, ei_bounds=(100, 2000), zone_points=3",  # used
        "mass_positions=(0.5,), mass_start=0.01, vary=('ei', 'mass'), mass_bounds=(0, 0.05)",
        "mass_positions=(0.5,), vary=('ei', 'position'), position_bounds=(0.2, 0.8)",
        "ei_points=(0.0, 0.5, 1.0), interpolation='linear'",
        "zone='node', zone_sigma=0.1, zone_points=5",
        "racket_speed=10.0, reference=0.7, pivot=0.12, swing_exponent=-0.1",
        "objectives=('handle_shock',), grip='firm', shock_window=0.01",
        "vary=('ei', 'string'), string_bounds=(0.6, 1.5)",
        "power_fraction=0.8",  # the report's power region at every objective
    ],
)
def test_used_or_default_options_pass(text):
    assert design_problem(**_kw(text)).n_var >= 1


def test_paper_problem_refuses_unused_variables():
    with pytest.raises(InputError, match="mass_start = 0.02 is not allowed without"):
        paper_problem(variables=VariableOptions(mass_start=0.02))


def test_search_refuses_a_budget_its_method_does_not_use():
    for kw, name in [
        ({"popsize": 20}, "popsize"),
        ({"pop_size": 20}, "pop_size"),
        ({"generations": 5}, "generations"),
        ({"seed": 7}, "seed"),
        ({"method": "trust-constr", "seed": 7}, "seed"),
        ({"method": "nsga2", "maxiter": 5}, "maxiter"),
        ({"method": "differential-evolution", "generations": 5}, "generations"),
    ]:
        with pytest.raises(InputError, match=rf"^{name} = "):
            SearchOptions(**kw)
    SearchOptions(method="differential-evolution", popsize=20, seed=7, maxiter=5)
    SearchOptions(method="nsga2", pop_size=20, generations=5, seed=7)
    with pytest.raises(InputError, match="method = 'nelder'"):
        SearchOptions(method="nelder", seed=3)  # the name first, then its budget


def test_optimize_and_runs_refuse_unused_arguments():
    problem = design_problem(vary=("ei",), link_ei=True, zone_points=3, speeds=(30.0,))
    with pytest.raises(InputError, match="popsize = 20 is not allowed with method 'SLSQP'"):
        optimize(problem, popsize=20, maxiter=1)
    with pytest.raises(InputError, match="seed = 3 is not allowed with method 'SLSQP'"):
        optimize(problem, seed=3, maxiter=1)
    with pytest.raises(InputError, match="polish = False is not allowed with method 'SLSQP'"):
        optimize(problem, polish=False, maxiter=1)
    with pytest.raises(InputError, match="overwrite = True is not allowed without out"):
        OutputOptions(None, overwrite=True)
    with pytest.raises(InputError, match="restart = True is not allowed without out"):
        run_optimization(OptimizationRun(problem, SearchOptions(maxiter=1), restart=True))


def test_sensitivity_refuses_what_one_output_does_not_use():
    pytest.importorskip("SALib")
    from fem_racket.studies.design.sensitivity import sobol_indices

    cheap = {"vary": ("ei",), "link_ei": True, "zone_points": 3, "speeds": (30.0,)}
    for extra, words in [
        ({"constraints": {"mass_kg": ("start",)}}, "constraints ['mass_kg'] are not allowed"),
        ({"objectives": ("cor", "ball_speed")}, "objective = ['cor', 'ball_speed']"),
        ({"power_fraction": 0.8}, "power_fraction = 0.8 is not allowed with output 'cor'"),
    ]:
        with pytest.raises(InputError, match=words.replace("[", r"\[").replace("(", r"\(")):
            sobol_indices(design_problem(**cheap, **extra), designs=8)
    problem = design_problem(vary=("ei",), link_ei=True, objectives=("power_region",))
    with pytest.raises(InputError, match="objective = \\['power_region'\\]"):
        sobol_indices(problem, output="mass_kg", designs=8)


def test_a_reference_at_rest_is_refused_in_every_command_s_words():
    # given at the default too (no longer a 0.75 default of its own), with simulate's line;
    # a swing without one takes 0.75, as before (the same problem, digest included)
    with pytest.raises(InputError) as ours:
        design_problem(reference=0.75)
    with pytest.raises(InputError) as theirs:
        check_at_rest(0.0, 0.75)  # simulate's, sweep's and map's
    line = "reference = 0.75 x/L is not allowed without a swing: give racket_speed (--racket-speed)"
    assert str(ours.value) == str(theirs.value) == line
    swung = design_problem(racket_speed=10.0)
    assert swung.swing.reference == 0.75
    assert swung.digest == design_problem(racket_speed=10.0, reference=0.75).digest
