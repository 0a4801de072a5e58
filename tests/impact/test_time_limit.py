"""A t_max is refused before anything its size is allocated, on every path (audit F14): the
summary-only general and ODE paths once allocated their grid up to t_max (1 TiB at 1e6 s)."""

import time

import numpy as np
import pytest

from fem_racket import simulate
from fem_racket.impact.clamped import CENTRE, ClampedHead
from fem_racket.impact.problem import Impact, ImpactProblem
from fem_racket.impact.settings import Settings, check_time_limit
from fem_racket.impact.solvers import make_solver
from fem_racket.impact.system import MAX_OUTPUT_TIMES
from fem_racket.validation import InputError
from tests.clirun import library_error, refused_before_any_file

SUMMARY = [
    (["--law", "hysteretic"], "general", {"law": "hysteretic"}),
    (["--solver", "cvode"], "cvode", {"solver": "cvode"}),
    (
        ["--law", "hysteretic", "--solver", "cvode"],
        "cvode",
        {"law": "hysteretic", "solver": "cvode"},
    ),
    (["--solver", "bdf"], "bdf", {"solver": "bdf"}),
]


@pytest.mark.parametrize(("argv", "solver", "options"), SUMMARY)
def test_summary_only_t_max_refused_before_allocating(capsys, cwd, argv, solver, options):
    # Was a 57-line traceback "Unable to allocate 1.03 TiB" (general), 378 GiB (cvode, bdf).
    t0 = time.process_time()
    line = refused_before_any_file(capsys, "simulate", *argv, "--t-max", "1e6")
    words = "t_max = 1000000.0 s is not allowed: at most 1e+06 time steps of"
    assert words in line and f"(solver {solver!r} takes" in line, line
    assert words in library_error(lambda: simulate(t_max=1e6, output_step=None, **options))
    assert time.process_time() - t0 < 2.0  # CPU seconds: nothing was integrated


def test_clamped_general_t_max_refused():
    # The general integrator on a clamped head (summary only) takes t_max too.
    problem = ImpactProblem(ClampedHead(), Impact(CENTRE, 20.0))
    text = library_error(lambda: make_solver("general", t_max=1e6).solve(problem))
    assert text.startswith("t_max = 1000000.0 s is not allowed: at most 1e+06 time steps of")


def test_output_times_keep_their_wording_on_every_solver():
    # With histories the output times bind, in the words of issue 12 (tests/cli/test_cli_limits).
    for options in ({}, {"solver": "cvode"}, {"law": "hysteretic"}):
        with pytest.raises(InputError, match=r"^t_max = 11\.0 s is not allowed: at most 1e\+06 "):
            simulate(t_max=11.0, **options)


def test_the_limit_is_the_finer_grid_at_its_edge():
    # MAX_OUTPUT_TIMES steps of the finer of output_step and the solver's grid t_est / steps.
    t_est, steps = 4.5e-3, 200
    grid = t_est / steps
    check_time_limit(Settings(t_max=MAX_OUTPUT_TIMES * grid, output_step=None), t_est, steps, "x")
    with pytest.raises(InputError, match=r"time steps of 2\.25e-05 s .* t_max <= 22\.5 s$"):
        check_time_limit(Settings(t_max=22.6, output_step=None), t_est, steps, "x")
    with pytest.raises(InputError, match=r"output times of output_step = 1e-05 s, so t_max <= 10"):
        check_time_limit(Settings(t_max=10.1, output_step=1e-5), t_est, steps, "x")
    # no grid (the exact solver without histories): its work does not grow with t_max
    check_time_limit(Settings(t_max=1e9, output_step=None), t_est, None, "exact")


def test_a_batch_checks_t_max_on_its_case_with_the_finest_grid_before_any_work():
    # CVODE lays 200 steps per eq 11 contact time up to t_max (no output times): 9.07 s for a
    # 60 m/s ball (t_c 1.81 ms), 37.9 s at 10 m/s. Only the first case was checked before the
    # batch ran: check_batch passed, and solve_many solved case 0 before refusing case 1.
    from fem_racket.impact.problem_batch import ProblemBatch

    batch = ProblemBatch.of(ImpactProblem.build(None, elements=10), speed=[10.0, 60.0])
    solver = make_solver("cvode", output_step=None, t_max=20.0)
    words = (
        "t_max = 20.0 s is not allowed: at most 1e+06 time steps of 9.07e-06 s (solver 'cvode' "
        "takes 200 per contact time, 0.00181 s by eq 11), so t_max <= 9.07 s (case 1 of the batch)"
    )
    t0 = time.process_time()
    for call in (solver.check_batch, solver.solve_many):
        with pytest.raises(InputError) as err:
            call(batch)
        assert str(err.value) == words
        assert (err.value.parameter, err.value.value) == ("t_max", 20.0)
    assert time.process_time() - t0 < 0.5  # CPU seconds: no case was integrated (0.6 s each)
    # the single case refuses it in the same line, without the case
    one = make_solver("cvode", output_step=None, t_max=20.0)
    with pytest.raises(InputError) as err:
        one.solve(batch.problem(1))
    assert f"{err.value} (case 1 of the batch)" == words
    # within every case's limit the batch runs
    within = make_solver("cvode", output_step=None, t_max=9.0)
    cor = [within.solve(batch.problem(i)).cor for i in range(2)]
    assert within.solve_many(batch).cor.tolist() == cor


def test_t_max_is_bounded_as_the_output_times_are_counted():
    # At t_max = 1e6 output_step rounded up, t_max <= 1e6 * output_step held but t_max /
    # output_step > 1e6: the time check let it pass and the linear path's own count refused
    # it as "output_step = ... over twice the contact's 0.00395 s", a span it did not use. The
    # check counts t_max / step now, so that branch could not be reached and is gone
    # (simulate_linear).
    step = 0.0013535185307303247
    t_max = MAX_OUTPUT_TIMES * step
    assert t_max / step > MAX_OUTPUT_TIMES  # the rounding this case is about
    for solver in ("cvode", "exact"):
        text = library_error(lambda s=solver: simulate(solver=s, output_step=step, t_max=t_max))
        assert text.startswith(f"t_max = {t_max!r} s is not allowed: at most 1e+06 output times")
    with pytest.raises(InputError, match=r"^t_max = 1353\.5185307303248 s is not allowed"):
        check_time_limit(Settings(t_max=t_max, output_step=step), 4.5e-3, None, "cvode")
    rng = np.random.default_rng(12)
    for step in rng.uniform(1e-7, 1e-2, 2000):  # what it lets pass, the count allows
        for t_max in (MAX_OUTPUT_TIMES * step, np.nextafter(MAX_OUTPUT_TIMES * step, 0.0)):
            try:
                check_time_limit(Settings(t_max=t_max, output_step=step), 4.5e-3, None, "x")
            except InputError:
                continue
            assert t_max / step <= MAX_OUTPUT_TIMES
