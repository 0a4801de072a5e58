"""The design commands and scripts: fem-racket optimize / sensitivity in-process, run files with
a [design] table, scripts/design_study.py and scripts/bench_design.py in their quick variants."""

import json
from pathlib import Path

import pytest
from clirun import run_json
from script_loader import load_script

from fem_racket.cli import main
from fem_racket.io.mesh_files import read_mesh

SMALL = ["--boundaries", "0.3", "--speeds", "30", "--zone-points", "3", "--backend", "serial"]


def test_design_study_quick_writes_the_mean_cor_study(tmp_path, capsys):
    rows = load_script("design_study").main(["--quick", "--out", str(tmp_path / "d")])
    assert [r["study"] for r in rows] == [
        "cor",
        "same_specs",
        "ball_speed",
        "pareto",
        "shock",
        "smooth",
    ]
    out = tmp_path / "d"
    data = json.loads((out / "result.json").read_text())
    assert data["objective_name"] == "cor"
    assert data["objective"] > data["start_objective"]
    (mass,) = data["constraints"]
    assert mass["name"] == "mass_kg" and mass["holds"]
    assert mass["low"] == mass["high"] == pytest.approx(0.359992, rel=1e-12)
    assert mass["value"] == pytest.approx(0.359992, abs=1e-6)
    # the optimum loads as a --mesh: same mass as result.json reports
    assert main(["modes", "--mesh", str(out / "optimum.vtu"), "--json"]) == 0
    modes = json.loads(capsys.readouterr().out.split("wrote")[-1].split("\n", 1)[1])
    assert modes["mass_kg"] == pytest.approx(data["outputs"]["mass_kg"], rel=1e-12)
    assert read_mesh(out / "optimum.vtu").length == pytest.approx(0.68)
    assert (out / "pareto" / "pareto.png").is_file()
    shock = json.loads((out / "shock" / "result.json").read_text())
    assert shock["outputs"]["handle_shock"] > 0.0 and (out / "shock" / "pareto.png").is_file()
    assert (out / "ball_speed" / "map.png").is_file()
    # study 6: EI(x) through 5 control points (a variable each), rhoA per segment, mass kept
    smooth = json.loads((out / "smooth" / "result.json").read_text())
    names = [v["name"] for v in smooth["variables"]]
    assert names == [f"ei_{k}" for k in range(1, 6)] + [f"rhoa_{k}" for k in range(1, 5)]
    assert smooth["problem"]["ei_stations_x_over_l"] == [0.0, 0.25, 0.5, 0.75, 1.0]
    assert smooth["constraints"][0]["holds"] and smooth["objective"] > smooth["start_objective"]
    assert (out / "smooth" / "profiles.png").is_file()  # studies 1 and 6 side by side


def test_optimize_json_and_files(tmp_path, capsys):
    out = tmp_path / "o"
    argv = [
        "optimize",
        *SMALL,
        "--mass-range",
        "start",
        "--maxiter",
        "3",
        "--out",
        str(out),
    ]
    data = run_json(capsys, *argv)
    assert data["objective"] >= data["start_objective"]
    assert set(data["variables"]) == {"ei_1", "ei_2", "rhoa_1", "rhoa_2"}
    names = {p.name for p in out.iterdir()}
    assert {
        "optimum.vtu",
        "start.vtu",
        "result.json",
        "history.nc",
        "progress.png",
        "map.png",
    } <= names
    assert not Path(str(out) + ".history").exists()  # removed once the results are written
    import xarray as xr

    with xr.open_dataset(out / "history.nc") as ds:
        assert ds.sizes["evaluation"] > 1 and "cor" in ds and ds.attrs["version"]
    # an existing folder is refused without --overwrite, exit 2
    assert main(argv) == 2
    assert "already exists" in capsys.readouterr().err


def test_run_file_design_table(tmp_path, capsys):
    run = tmp_path / "run.toml"
    run.write_text(
        "[ball]\nmass_kg = 0.058\n[design]\nboundaries = [0.3]\nspeeds = [30]\n"
        "zone_points = 3\nobjective = ['cor']\nmass_range = 'start'\nmaxiter = 2\n"
        "backend = 'serial'\n"
        f"out = '{tmp_path / 'r'}'\n"
    )
    assert main(["optimize", "--config", str(run), "--json"]) == 0
    data = json.loads((tmp_path / "r" / "result.json").read_text())
    assert data["problem"]["ball_mass_kg"] == 0.058
    assert data["problem"]["speeds_m_s"] == [30.0]


def test_sensitivity_json(tmp_path, capsys):
    png = tmp_path / "s.png"
    argv = ["sensitivity", *SMALL, "--vary", "ei", "--designs", "16", "--out", str(png)]
    data = run_json(capsys, *argv)
    assert set(data["indices"]) == {"ei_1", "ei_2"}
    assert png.is_file() and json.loads(Path(str(png) + ".json").read_text())["provenance"]


def test_bench_design_quick(capsys):
    rows = load_script("bench_design").main(["--quick"])
    assert [r["task"] for r in rows] == ["SLSQP 8 variables", "NSGA-II", "Sobol"]
    assert all(r["designs"] > 0 and r["wall_s"] > 0 for r in rows)
    assert "us/impact" in capsys.readouterr().out
