"""A random seed is an integer numpy's generators take, 0 to 2**32 - 1, checked before any
design runs: differential evolution seeded with 1e22 (or -1) once ran one design, left its
history and then failed with numpy's traceback; a rerun "to resume" failed the same way."""

import numpy as np
import pytest
from clirun import file_refused_alike, refused_alike, refused_before_any_file

from fem_racket.studies.design.evaluate import Evaluator
from fem_racket.studies.design.options import MAX_SEED, SearchOptions
from fem_racket.studies.design.paper_problem import paper_problem
from fem_racket.studies.design.pareto import pareto_front
from fem_racket.studies.design.sensitivity import sobol_indices
from fem_racket.studies.design.solvers import optimize
from fem_racket.validation import InputError

#: A cheap study: one EI variable, 3 impact points, one speed.
CHEAP = ("--vary", "ei", "--link-ei", "--zone-points", "3", "--speeds", "30",
         "--backend", "serial", "--quiet")  # fmt: skip
DE = ("optimize", *CHEAP, "--method", "differential-evolution", "--maxiter", "1",
      "--popsize", "4", "--out", "o6")  # fmt: skip
SENS = ("sensitivity", *CHEAP, "--designs", "8")
BOUND = "must be an integer from 0 to 4294967295"
BAD = ("99999999999999999999999", "-1", str(MAX_SEED + 1))


def _linear(problem, designs):
    """cor = u_1 (unit coordinate): a design function without impacts."""
    out = np.zeros((len(designs), len(Evaluator(problem).names)))
    out[:, -1] = problem.to_unit(designs)[:, 0]
    return out


def _problem():
    from fem_racket.studies.design.options import VariableOptions

    return paper_problem(None, VariableOptions(boundaries=(0.3,), vary=("ei",), link_ei=True))


@pytest.mark.parametrize("seed", BAD)
def test_optimize_refuses_a_seed_numpy_cannot_take(capsys, cwd, seed):
    line = refused_before_any_file(capsys, *DE, "--seed", seed)  # no o6.history left
    assert f"seed = {seed} is not allowed: {BOUND}" in line, line
    p = _problem()
    with pytest.raises(InputError, match=f"seed = {seed} is not allowed: {BOUND}"):
        optimize(p, method="differential-evolution", seed=int(seed), progress=False)
    refused_alike(
        capsys,
        [*DE, "--seed", seed],
        lambda: SearchOptions(method="differential-evolution", seed=int(seed)),
        f"seed = {seed} is not allowed: {BOUND}",
        start=True,
    )


@pytest.mark.parametrize(
    ("table", "command"),
    [
        ("[design]\nmethod = 'differential-evolution'\n", "optimize"),
        ("[sensitivity]\n", "sensitivity"),
    ],
)
def test_a_run_files_seed_is_refused_alike(capsys, cwd, table, command):
    if command == "sensitivity":
        pytest.importorskip("SALib")
    file_refused_alike(
        capsys,
        f"{table}seed = -1\n",
        [command, "--config", "run.toml"],
        lambda config: getattr(config, command)(),
        f"seed = -1 is not allowed: {BOUND}",
    )


@pytest.mark.parametrize("seed", BAD)
def test_sensitivity_and_nsga2_refuse_it_too(capsys, cwd, seed):
    pytest.importorskip("SALib")
    line = refused_before_any_file(capsys, *SENS, "--seed", seed)
    assert f"seed = {seed} is not allowed: {BOUND}" in line, line
    p = _problem()
    ev = Evaluator(p, function=_linear)
    with pytest.raises(InputError, match=f"seed = {seed} is not allowed"):
        sobol_indices(p, designs=8, seed=int(seed), evaluator=ev, progress=False)
    pytest.importorskip("pymoo")
    with pytest.raises(InputError, match=f"seed = {seed} is not allowed"):
        pareto_front(paper_problem(None, objectives=("cor", "ball_speed")), seed=int(seed))


def test_the_bounds_themselves_run():
    p = _problem()
    for seed in (0, MAX_SEED):  # scipy's generator takes both ends
        r = optimize(
            p,
            method="differential-evolution",
            seed=seed,
            maxiter=1,
            popsize=4,
            polish=False,
            evaluator=Evaluator(p, function=_linear),
            progress=False,
        )
        assert 0.0 <= p.to_unit(r.x)[0] <= 1.0


def test_seed_0_gives_the_same_confidence_intervals_twice():
    """SALib leaves its bootstrap unseeded for seed 0 (``if seed:``): the intervals came out
    different at each run; seeded by a generator they repeat."""
    pytest.importorskip("SALib")
    p = _problem()
    runs = [
        sobol_indices(p, designs=64, seed=0, evaluator=Evaluator(p, function=_linear))
        for _ in range(2)
    ]
    assert np.array_equal(runs[0].s1_conf, runs[1].s1_conf)
    assert np.array_equal(runs[0].st_conf, runs[1].st_conf)
