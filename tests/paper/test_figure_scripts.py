"""Every script in scripts/ runs (figure scripts at reduced resolution with --quick)."""

import csv
import json
import re
from pathlib import Path

import pytest
from script_loader import SCRIPTS, load_script

FIGURE_SCRIPTS = sorted(SCRIPTS.glob("fig*.py"))
UNIT = re.compile(r".+ \[[^\]]*\]$")  # "name [unit]"


def test_there_is_a_script_per_paper_figure():
    from fem_racket.paper.figures import FIGURES

    assert {p.stem for p in FIGURE_SCRIPTS} == {s.name for s in FIGURES.values()}


@pytest.mark.parametrize("path", FIGURE_SCRIPTS, ids=lambda p: p.stem)
def test_figure_script_writes_data_and_png(path, tmp_path, capsys):
    files = load_script(path.stem).main(["--out", str(tmp_path), "--quick"])
    out = capsys.readouterr().out
    assert all(str(p) in out for p in files)
    assert {p.name for p in files} == {p.name for p in tmp_path.iterdir()}
    assert any(p.suffix == ".png" for p in files) and any(p.suffix == ".csv" for p in files)
    for p in files:
        assert p.stat().st_size > 0
        if p.suffix == ".png":
            assert p.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
            from PIL import Image

            with Image.open(p) as im:  # provenance in the PNG's text chunks
                im.load()
                meta = json.loads(im.text["provenance"])
            assert meta["parameters"] == {
                "figure": p.stem,
                "quick": True,
                "format": "png",
                "dpi": 150.0,
            }
            assert meta["version"] and meta["used"]["modes"] == 40
        else:
            with open(p, newline="") as fh:
                rows = list(csv.reader(fh))
            header = rows[0]
            assert all(UNIT.match(h) for h in header), header  # units in every column name
            assert len(rows) > 1 and all(len(r) == len(header) for r in rows)
            assert all(float(x) == float(x) for r in rows[1:] for x in r)  # numbers, no NaN


def test_bench_script_runs(capsys):
    rows = load_script("bench_impact").main(["--quick", "--repeat", "1"])
    assert rows and all(r["wall_s"] > 0 for r in rows)
    assert "COR" in capsys.readouterr().out


def test_bench_map_script_runs(capsys):
    rows = load_script("bench_map").main(["--quick"])
    assert rows and all(r["wall_s"] > 0 for r in rows)
    assert "racket_map" in capsys.readouterr().out


def test_bench_cli_script_runs(capsys):
    # start-up of the command line (issue 13): wall times are printed, not asserted (a loaded
    # machine); tests/cli/test_startup.py checks what each command imports
    rows = load_script("bench_cli").main(["--quick"])
    assert [r["command"] for r in rows] == ["--help", "simulate"]
    assert all(r["wall_s"] >= r["fastest_s"] > 0 and r["imports_s"] for r in rows)
    assert "numpy" in rows[1]["imports_s"] and "skfem" not in rows[1]["imports_s"]
    assert "target" in capsys.readouterr().out


def test_bench_cli_help_commands_runs(capsys):
    # --help of each command (here the quick set): what it imports and its time, as a ratio to
    # the top-level --help; tests/cli/test_startup.py checks the imports themselves
    rows = load_script("bench_cli").main(["--help-commands", "--quick"])
    assert [r["command"] for r in rows] == ["--help", "simulate --help"]
    assert rows[0]["wall_ratio"] == rows[0]["cpu_ratio"] == 1.0 and not rows[0]["heavy"]
    assert rows[1]["modules"] > rows[0]["modules"] > 0 and "scipy" not in rows[1]["heavy"]
    assert "x help" in capsys.readouterr().out


def test_figure_script_refuses_to_overwrite(tmp_path, capsys):
    main = load_script("fig04_frame_modes").main
    first = main(["--out", str(tmp_path)])
    before = {p: p.stat().st_mtime_ns for p in first}
    with pytest.raises(SystemExit) as exc:
        main(["--out", str(tmp_path)])
    assert exc.value.code == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "already exists" in err and "--overwrite" in err
    assert {p: p.stat().st_mtime_ns for p in first} == before
    assert main(["--out", str(tmp_path), "--overwrite"]) == first


def test_every_script_is_run_by_a_test():
    # DESIGN.md section 6: every script in scripts/ is run by the tests. Figure scripts run
    # above (by glob); every other script must be named by some test module.
    tests = "\n".join(p.read_text() for p in Path(__file__).resolve().parents[1].rglob("test_*.py"))
    others = [p.stem for p in SCRIPTS.glob("*.py") if not p.stem.startswith("fig")]
    assert others, "no non-figure scripts found"
    missing = [s for s in others if not re.search(rf"\b{s}\b", tests)]
    assert not missing, f"scripts not run by any test: {missing}"


def test_bench_docs_script_runs(capsys):
    # The README's stated run times are measured by scripts/bench_docs.py (here its quick set).
    rows = load_script("bench_docs").main(["--quick"])
    assert [r["command"] for r in rows] == ["fem-racket --help", "fem-racket simulate",
                                            "fem-racket config --example"]  # fmt: skip
    assert all(0 < s < 120 for r in rows for s in r["seconds"])
    assert "README" in capsys.readouterr().out


def test_bench_kernels_script_runs(capsys):
    # issue 27's benchmark, its accuracy part (one random law per family against CVODE): the
    # general integrator within its default COR tolerance 1e-6
    rows = load_script("bench_kernels").main(["--only-accuracy", "--accuracy", "1"])
    assert [r[0] for r in rows] == ["hunt-crossley", "hysteretic", "series"]
    assert all(r[1] <= 1e-6 for r in rows)
    assert "worst |dCOR| vs CVODE" in capsys.readouterr().out


def test_bench_laws_script_runs(capsys):
    # the general integrator's benchmark (issue 15) in its quick variant: every law within the
    # 1e-5 COR target against CVODE (DESIGN section 9)
    rows = load_script("bench_laws").main(["--quick"])
    assert {r["law"] for r in rows} >= {"kawazoe-1997-nonlinear", "series"}
    assert all(r["dcor"] <= 1e-5 for r in rows)
    assert "CVODE" in capsys.readouterr().out


def test_bench_laws_against_itself_counts_the_same_nodes(capsys):
    # issue 27's comparison, this tree against itself on 4 impacts: the same CORs bit for bit,
    # the same vouched nodes per impact (at least the final run's ~250 per impact), and every
    # law within the default COR tolerance 1e-6 of CVODE
    root = SCRIPTS.parent
    rows = load_script("bench_laws").main(["--against", str(root), "--batch", "4", "--repeat", "1"])
    assert len(rows) == 5
    for r in rows:
        assert r["dcor"] == 0.0 and r["cvode"] <= 1e-6
        assert r["before_nodes"] == r["after_nodes"] > 200.0
    assert "nodes a" in capsys.readouterr().out


def test_tour_runs_as_a_script(tmp_path, capsys, monkeypatch):
    """scripts/tour.py (jupytext percent cells) runs top to bottom as a plain script."""
    import runpy

    path = SCRIPTS / "tour.py"
    assert path.read_text().count("# %%") >= 10  # cells a notebook opens
    monkeypatch.setattr("sys.argv", [str(path), "--quick", "--out", str(tmp_path)])
    runpy.run_path(str(path), run_name="__main__")
    out = capsys.readouterr().out
    assert out.startswith("ImpactResult(cor=0.37657") and "RefinementStudy(" in out
    names = {p.name for p in tmp_path.iterdir()}
    assert {"force.png", "sweep.png", "refine.png", "impact_vtk"} <= names
    assert (tmp_path / "impact_vtk" / "impact.pvd").is_file()


def test_bench_held_script_runs(capsys):
    # the held racket's exact path against CVODE: every mode agrees to round-off (measured
    # ~1e-11 in COR), the default cut-off to its COR tolerance 1e-6 (x1.5, reduction.py)
    rows = load_script("bench_held").main(["--quick"])
    every, cut = rows[1], rows[2]
    assert every["cor_diff"] < 1e-9 and every["peak_grip_rel_diff"] < 1e-6
    assert cut["cor_diff"] < 1.5e-6 and cut["speedup"] > 1.0
    assert "CVODE" in capsys.readouterr().out
