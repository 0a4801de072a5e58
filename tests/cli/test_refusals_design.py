"""Options the design studies, refine, calibrate and config would ignore are refused (issue 21.3:
"no argument is ever silently ignored"): exit 2, one line naming the option and why, no file
written; the same option where it is used still runs."""

import pytest
from clirun import run

from fem_racket.cli import main

#: A cheap optimize / sensitivity (one EI variable, 3 impact points, one speed).
CHEAP = ("--vary", "ei", "--link-ei", "--zone-points", "3", "--speeds", "30",
         "--backend", "serial", "--quiet")  # fmt: skip
OPT = ("optimize", *CHEAP, "--maxiter", "1", "--out", "study")
SENS = ("sensitivity", *CHEAP, "--designs", "8")
REFINE = ("refine", "--elements", "5,10", "--positions", "0.7", "--count", "2", "--quiet")

#: argv -> words of the one error line (the option named, and why).
REFUSED = {
    # optimize's search budget by method
    (*OPT, "--popsize", "20"): ("popsize = 20", "'SLSQP'", "differential-evolution"),
    (*OPT, "--pop-size", "20"): ("pop_size = 20", "only nsga2"),
    (*OPT, "--generations", "5"): ("generations = 5", "only nsga2"),
    (*OPT, "--seed", "7"): ("seed = 7", "nothing random runs"),
    (*OPT, "--method", "trust-constr", "--seed", "7"): ("seed = 7", "'trust-constr'"),
    (*OPT, "--method", "differential-evolution", "--pop-size", "8"): ("pop_size = 8",),
    # the variables
    (*OPT, "--mass-bounds", "0,0.05"): ("mass_bounds = [0.0, 0.05]", "'mass' in vary"),
    (*OPT, "--mass-start", "0.01"): ("mass_start = 0.01", "without mass_positions"),
    (*OPT, "--mass-positions", "0.5", "--mass-bounds", "0,0.05"): ("mass_bounds",),
    (*OPT, "--position-bounds", "0.2,0.8"): ("position_bounds", "'position' in vary"),
    (*OPT, "--vary", "ei,mass"): ("vary = ['ei', 'mass']", "without mass_positions"),
    (*OPT, "--string-bounds", "0.6,1.5"): ("string_bounds = [0.6, 1.5]", "'string' in vary"),
    (*OPT, "--cubic-bounds", "0,1e9"): ("cubic_bounds", "'string_cubic' in vary"),
    (*OPT, "--interpolation", "linear"): ("interpolation = 'linear'", "ei_points"),
    (*OPT, "--rhoa-bounds", "0.3,1"): ("rhoa_bounds = [0.3, 1.0]", "'rhoa' in vary"),
    # the zone, the swing, the hand
    (*OPT, "--zone-sigma", "0.1"): ("zone_sigma = 0.1", "zone 'uniform'"),
    (*OPT, "--zone", "node", "--zone-range", "0.5,0.8"): ("zone_range", "zone 'node'"),
    (*OPT, "--objective", "power_region"): ("zone_points = 3", "['power_region']"),
    (*OPT, "--swing-exponent", "-0.1"): ("swing_exponent = -0.1", "without racket_speed"),
    (*OPT, "--reference", "0.6"): ("reference = 0.6", "at rest"),
    (*OPT, "--pivot", "0.2"): ("pivot = 0.2", "at rest"),
    (*OPT, "--grip", "firm"): ("grip = 'firm'", "objectives ['cor']", "handle_shock"),
    (*OPT, "--shock-window", "0.01"): ("shock_window = 0.01", "objectives ['cor']"),
    # where the designs run
    (*OPT, "--workers", "2"): ("workers = 2", "backend 'serial'"),
    (*SENS, "--scheduler", "tcp://localhost:8786"): ("scheduler = 'tcp://localhost:8786'",),
    # sensitivity: the same table, and what an analysis of one output does not use
    (*SENS, "--grip", "firm"): ("grip = 'firm'",),
    (*SENS, "--seed", "3", "--zone-sigma", "0.1"): ("zone_sigma = 0.1",),
    # (not an option of sensitivity: tests/cli/test_sensitivity_no_constraints.py)
    (*SENS, "--mass-range", "start"): ("unrecognized option --mass-range",),
    (*SENS, "--power-fraction", "0.8"): ("power_fraction = 0.8", "output 'cor'"),
    (*SENS, "--objective", "cor,ball_speed"): ("objective = ['cor', 'ball_speed']",),
    (*SENS, "--overwrite"): ("--overwrite", "without --out"),
    # refine
    (*REFINE, "--family", "uniform", "--grading", "2"): ("grading = 2.0", "family 'uniform'"),
    (*REFINE, "--no-files", "--plot", "rr.png"): ("no_files = True", "--plot"),
    (*REFINE, "--no-files", "--csv", "r.csv"): ("no_files = True", "--csv"),
    (*REFINE, "--no-files", "--format", "svg"): ("format = 'svg'", "--no-files"),
    (*REFINE, "--json", "--dpi", "300"): ("dpi = 300.0", "--json without --csv or --plot"),
    (*REFINE, "--json", "--format", "svg"): ("format = 'svg'", "no plot is drawn"),
    (*REFINE, "--no-files", "--overwrite"): ("--overwrite", "nothing is written"),
    # calibrate, config
    ("calibrate", "--overwrite"): ("--overwrite", "without --out"),
    ("config", "--example", "--overwrite"): ("--overwrite", "without --out"),
    ("config", "--check", "run.toml", "--out", "x.toml"): ("--out 'x.toml'", "--check"),
    ("config", "--check", "run.toml", "--overwrite"): ("--overwrite",),
}


@pytest.mark.parametrize("argv", list(REFUSED), ids=[" ".join(a) for a in REFUSED])
def test_an_ignored_option_is_refused(capsys, tmp_path, monkeypatch, argv):
    if argv[0] == "sensitivity":
        pytest.importorskip("SALib")
    monkeypatch.chdir(tmp_path)
    (tmp_path / "run.toml").write_text("[frame]\nelements = 20\n")
    before = sorted(tmp_path.rglob("*"))
    code, out, err = run(capsys, *argv)
    assert code == 2, (out, err)
    assert err.count("\n") == 1 and "Traceback" not in err, err
    for words in REFUSED[argv]:
        assert words in err, err
    assert sorted(tmp_path.rglob("*")) == before, "a file was written"


def test_the_same_options_run_where_they_are_used(capsys, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    assert main([*OPT[:-2], "--method", "differential-evolution", "--popsize", "4",
                 "--seed", "3", "--maxiter", "1", "--out", "de"]) == 0  # fmt: skip
    assert main([*OPT[:-2], "--racket-speed", "10", "--reference", "0.7", "--pivot", "0.12",
                 "--swing-exponent", "-0.1", "--out", "swing"]) == 0  # fmt: skip
    assert main([*REFINE, "--family", "both", "--grading", "2", "--no-files"]) == 0
    assert main([*REFINE, "--family", "graded", "--grading", "2", "--json", "--csv", "r.csv",
                 "--format", "svg", "--dpi", "100"]) == 0  # fmt: skip
    assert (tmp_path / "output" / "refine.svg").exists()
    assert main(["config", "--example", "--out", "run.toml", "--overwrite"]) == 0
    capsys.readouterr()


def test_a_shared_output_table_overwrite_is_refused_where_nothing_is_written(
    capsys, tmp_path, monkeypatch
):
    # [output] overwrite where the command writes nothing is refused as --overwrite is (it
    # was skipped: silently ignored), naming the key; so is the command's own table's
    monkeypatch.chdir(tmp_path)
    path = tmp_path / "run.toml"
    path.write_text("[output]\noverwrite = true\n")
    code, _, err = run(capsys, "config", "--check", path)
    assert code == 2 and "simulate would refuse it: output.overwrite = True" in err, err
    code, _, err = run(capsys, *REFINE, "--no-files", "--config", path)
    assert code == 2 and f"output.overwrite = True ({path}) is not allowed without" in err, err
    assert "nothing is written" in err
    assert main([*REFINE, "--config", str(path)]) == 0  # refine writes its files: it is used
    assert (tmp_path / "output" / "refine.csv").exists()
    capsys.readouterr()
    path.write_text("[refine]\noverwrite = true\nno_files = true\n")
    code, _, err = run(capsys, *REFINE, "--config", path)
    assert code == 2 and "refine.overwrite = True" in err and "nothing is written" in err, err
