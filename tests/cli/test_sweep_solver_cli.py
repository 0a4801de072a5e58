"""``fem-racket sweep --solver`` takes what ``simulate --solver`` takes (audit A4, A6): the
general integrator under the paper's law (also on a string bed), refusals in the solver's own
line, and ``auto`` picking as simulate's."""

from __future__ import annotations

from clirun import one_error, run_json


def test_sweep_runs_general_under_the_papers_law_as_simulate(capsys, cwd):
    import xarray as xr

    alone = run_json(capsys, "simulate", "--solver", "general")
    summary = run_json(
        capsys, "sweep", "--solver", "general", "--serial", "--quiet", "--out", "x.nc"
    )
    assert summary["solver"] == "general"
    with xr.open_dataset(cwd / "x.nc") as ds:  # the same impact, the same path: bit for bit
        assert ds.cor.values.ravel().tolist() == [alone["cor"]]
        assert ds.attrs["solver"] == "general"


def test_a_strung_sweep_takes_general_and_refuses_bdf_in_the_solvers_line(capsys, cwd):
    strung = ("sweep", "--string-tension", "250", "--elements", "10", "--serial", "--quiet")
    assert run_json(capsys, *strung, "--solver", "general", "--out", "g.nc")["solver"] == "general"
    line = one_error(capsys, *strung, "--solver", "bdf", "--out", "b.nc")
    assert line.endswith(
        "solver = 'bdf' is not allowed with a string bed: must be one of exact, general, cvode"
    )
    alone = one_error(capsys, "simulate", "--string-tension", "250", "--solver", "bdf")
    assert line.split(": error: ")[1] == alone.split(": error: ")[1]


def test_auto_on_a_string_bed_under_the_balls_law_picks_exact(capsys, cwd):
    argv = ["sweep", "--string-tension", "250", "--law", "kawazoe-1997-ball", "--speed", "20,30"]
    summary = run_json(capsys, *argv, "--serial", "--quiet", "--out", "k.nc")
    alone = run_json(capsys, "simulate", *argv[1:5], "--speed", "20")
    assert summary["solver"] == alone["solver"] == "exact"
