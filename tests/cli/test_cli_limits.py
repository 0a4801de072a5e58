"""Limits through the CLI and run files (issue 12): refused at once in one line, exit 2; the
CLI runs BLAS on one thread."""

import time

import pytest

from fem_racket.cli import main
from fem_racket.frame.mesh import MAX_ELEMENTS
from tests.clirun import refused_before_any_file


@pytest.mark.parametrize(
    ("argv", "message"),
    [
        (
            ["modes", "--elements", "9223372036854775807"],
            f"must be an integer from 2 to {MAX_ELEMENTS}",
        ),
        (["simulate", "--solver", "cvode", "--rtol", "1"], "rtol = 1.0 is not allowed"),
        (["simulate", "--ei1", "1e300"], "ei1 = 1e+300 N m^2 is not allowed"),
        (["sweep", "--ei1", "1e-6,1e300"], "ei1 = 1e+300 N m^2 is not allowed"),
        (["sweep", "--position", "0:1:10000", "--speed", "10:40:10000"], "100000000 cases"),
        # histories (--out) at 1e-5 s steps: at most 1e6 of them
        (["simulate", "--t-max", "11", "--out", "h.json"], "t_max = 11.0 s is not allowed"),
        (["simulate", "--kcb", "1e-6", "--out", "h.json"], "kcb = 1e-06 N/m is not allowed"),
    ],
)
def test_limits_refused_at_once(capsys, cwd, argv, message):
    t0 = time.process_time()  # CPU seconds: other processes on the machine do not count
    assert message in refused_before_any_file(capsys, *argv)
    assert time.process_time() - t0 < 2.0


@pytest.mark.parametrize(
    ("option", "step", "message"),
    [
        (["--t-max", "11"], [], "t_max = 11.0 s is not allowed"),
        # the softest kcb allowed (audit F15) at a fine step
        (["--kcb", "100"], ["--output-step", "1e-7"], "kcb = 100.0 N/m is not allowed"),
    ],
)
def test_output_times_limit_names_the_option_given(cwd, capsys, option, step, message):
    # Issue 12: refused with an error about output_step, which the user never gave. With --out
    # (histories written) the limit names what makes the output times so many; without it no
    # history is kept, so nothing limits the run.
    out = ["--out", "r.json"]
    assert message in refused_before_any_file(capsys, "simulate", *option, *step, *out)
    assert main(["simulate", *option]) == 0


def test_run_file_elements_limit(tmp_path, capsys):
    # Issue 12: elements = 100000000 in a run file grew to 24 GB and was killed.
    run = tmp_path / "run.toml"
    run.write_text("[frame]\nelements = 100000000\n")
    assert main(["simulate", "--config", str(run)]) == 2
    assert "elements = 100000000 is not allowed" in capsys.readouterr().err


def test_cli_pins_blas_to_one_thread(capsys):
    from threadpoolctl import threadpool_info, threadpool_limits

    with threadpool_limits(limits=2, user_api="blas"):
        assert main(["modes", "--json"]) == 0
        blas = [lib["num_threads"] for lib in threadpool_info() if lib["user_api"] == "blas"]
    assert blas and all(n == 1 for n in blas)


# -- round 3 (issue 22.3): every count refused before anything is allocated ----------------------
_NSGA = ["--method", "nsga2", "--objective", "cor,ball_speed"]


@pytest.mark.parametrize(
    ("argv", "message"),
    [
        # before: 10-11.5 GB and SIGTERM at 30 s not honoured
        (["optimize", *_NSGA, "--pop-size", "100000000"], "pop_size = 100000000 is not allowed"),
        (["optimize", "--zone-points", "100000000"], "zone_points = 100000000 is not allowed"),
        (["sensitivity", "--zone-points", "100000000"], "zone_points = 100000000 is not allowed"),
        # before: a 1 TiB allocation and a traceback
        (["sensitivity", "--designs", "100000000000"], "designs = 100000000000 is not allowed"),
        (["optimize", *_NSGA, "--generations", "100000000"], "generations = 100000000"),
        (["optimize", "--maxiter", "100000000"], "maxiter = 100000000 is not allowed"),
        (
            ["optimize", "--method", "differential-evolution", "--popsize", "10000000"],
            "popsize = 10000000 is not allowed",
        ),
        # NSGA-II takes 2 or 3 objectives; the other methods one (before: cor alone, silently)
        (
            [
                "optimize",
                "--method",
                "nsga2",
                "--objective",
                "cor,ball_speed,power_region,handle_shock",
            ],
            "is not allowed with nsga2: give 2 or 3",
        ),
        (
            ["optimize", "--objective", "cor,ball_speed"],
            "objectives = ['cor', 'ball_speed'] is not allowed with SLSQP: it maximises one",
        ),
        (
            ["optimize", "--method", "trust-constr", "--objective", "cor,ball_speed"],
            "is not allowed with trust-constr",
        ),
        # before: refused after 10 s and 734 MB (each of 1e7 values checked first)
        (["sweep", "--speed", "20:40:10000000", "--ei1", "100,200"], "20000000 cases"),
        (["refine", "--count", "100000000"], "count = 100000000 is not allowed"),
        # output times: a hand's shock window, a law's contact (before: 34 GiB, 108 GiB)
        (
            ["simulate", "--grip", "firm", "--output-step", "1e-11", "--out", "h.json"],
            "output_step = 1e-11 s is not allowed: at most 1e+06 output times over the shock",
        ),
        (
            ["simulate", "--grip", "firm", "--solver", "cvode", "--output-step", "1e-11"]
            + ["--out", "h.json"],
            "output_step = 1e-11 s is not allowed",
        ),
        (
            ["simulate", "--law", "series", "--output-step", "1e-11", "--out", "h.json"],
            "output_step = 1e-11 s is not allowed: at most 1e+06 output times over twice the law",
        ),
        (
            ["simulate", "--output-step", "1e-11", "--out", "h.json"],
            "output_step = 1e-11 s is not allowed: at most 1e+06 output times",
        ),
        (["export-vtk", "--output-step", "1e-11"], "output_step = 1e-11 s is not allowed"),
    ],
    ids=lambda v: v if isinstance(v, str) and len(v) < 30 else None,
)
def test_counts_refused_before_allocating(capsys, cwd, argv, message):
    import resource

    t0 = time.process_time()
    line = refused_before_any_file(capsys, *argv)
    assert message in line, line
    assert time.process_time() - t0 < 3.0
    # the test process's peak stays far below the sizes asked (GB)
    assert resource.getrusage(resource.RUSAGE_SELF).ru_maxrss < 2_000_000  # kB


def test_a_closing_speed_of_zero_or_less_is_refused_under_a_law(capsys):
    # Before: a traceback (ZeroDivisionError) at 0 and COR -0.79 below it; the linear law
    # refused both at once.
    for racket in ("-20", "-30"):
        argv = ["simulate", "--law", "series", "--speed", "20", "--racket-speed", racket]
        assert main(argv) == 2
        err = capsys.readouterr().err
        assert err.count("\n") == 1 and "the two must close (v_in + v_r > 0)" in err, err
