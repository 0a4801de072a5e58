"""Run files drive every command: sweep, export-vtk, animate, refine and reproduce read their own
table (``[sweep]``, ``[vtk]`` ...) and the core tables, the command line wins, and what they
write records the run (provenance). simulate and modes: tests/io/test_config.py."""

import json
import re
from pathlib import Path

import numpy as np
import pytest

from fem_racket.cli import main


def run(capsys, *argv):
    code = main([str(a) for a in argv])
    out, err = capsys.readouterr()
    assert code == 0, err
    return out


def test_sweep_table_gives_the_dataset_of_the_command_line(capsys, cwd):
    import xarray as xr

    (cwd / "run.toml").write_text(
        "[ball]\nmass_kg = 0.058\n"
        "[sweep]\nposition = [0.6, 0.75]\nspeed = '20,30'\nei1 = '100:200:2:log'\n"
        "serial = true\nquiet = true\nout = 'file.nc'\n"
    )
    run(capsys, "sweep", "--config", "run.toml")
    cli = ["--position", "0.6,0.75", "--speed", "20,30", "--ei1", "100:200:2:log"]
    run(capsys, "sweep", *cli, "--ball-mass", "0.058", "--serial", "--quiet", "--out", "cli.nc")
    with xr.open_dataset("file.nc") as a, xr.open_dataset("cli.nc") as b:
        assert a.sizes == {"position": 2, "speed": 2, "ei1": 2}
        xr.testing.assert_identical(a.drop_attrs(), b.drop_attrs())
        skip = {"created_utc", "run_parameters"}
        assert {k: v for k, v in a.attrs.items() if k not in skip} == {
            k: v for k, v in b.attrs.items() if k not in skip
        }
        assert a.attrs["ball_mass_kg"] == 0.058 and a.attrs["solver"] == "exact"
        assert a.attrs["rtol"] == 1e-10 and a.attrs["atol"] == 1e-12
        assert a.attrs["version"] and a.attrs["created_utc"]
        assert json.loads(a.attrs["run_parameters"])["config"] == "run.toml"
    # The command line wins over the table: a fixed speed, one dimension fewer.
    run(capsys, "sweep", "--config", "run.toml", "--speed", "40", "--out", "over.nc")
    with xr.open_dataset("over.nc") as c:
        assert c.sizes == {"position": 2, "ei1": 2} and c.attrs["speed_m_s"] == 40.0


def test_core_tables_reach_sweep_but_output_out_does_not(capsys, cwd):
    import xarray as xr

    # [output] out is simulate's JSON; sweep keeps its own default (or [sweep] out).
    (cwd / "run.toml").write_text(
        "[impact]\nspeed_m_s = 30\nposition_x_over_l = 0.7\n[solver]\nmodes = 40\n"
        "[output]\nout = 'impact.json'\n"
    )
    run(capsys, "sweep", "--config", "run.toml", "--quiet", "--position", "0.6,0.7")
    assert not (cwd / "impact.json").exists()
    with xr.open_dataset(cwd / "output" / "sweep.nc") as ds:
        assert ds.attrs["speed_m_s"] == 30.0 and ds.attrs["modes"] == 40
        assert ds.position.values.tolist() == [0.6, 0.7]
        # Same COR as simulate with the same file at 0.7 L: simulate --out computes histories
        # with every mode, the sweep's engine its default COR tolerance, 1e-6
        # (tests/impact/exact/test_engine.py).
        sim = json.loads(
            run(capsys, "simulate", "--config", "run.toml", "--json", "--out", "s.json")
        )
        assert float(ds.cor.sel(position=0.7)) == pytest.approx(sim["cor"], abs=1e-6)


def test_vtk_and_animate_tables(capsys, cwd):
    (cwd / "run.toml").write_text(
        "[impact]\nposition_x_over_l = 0.6\n"
        "[vtk]\nframes = 3\nout = 'series'\nfield = 'moment'\n"
        "[animate]\nframes = 4\nout = 'a.gif'\nsize = '160x160'\nfps = 10.0\n"
    )
    printed = run(capsys, "export-vtk", "--config", "run.toml").strip()
    assert printed == "wrote series/ (8 files; open impact.pvd in ParaView)"
    assert len(list((cwd / "series").glob("frame_*.vtu"))) == 3
    prov = json.loads((cwd / "series" / "provenance.json").read_text())
    params = prov["parameters"]
    assert prov["used"]["position_x_over_l"] == 0.6 and params["steps"] == 3
    assert params["config"] == "run.toml" and params["rtol"] == 1e-10 and prov["version"]
    # The command line wins over [animate].
    assert (
        run(capsys, "animate", "--config", "run.toml", "--frames", "2").strip()
        == "wrote a.gif\nwrote a.gif.json"
    )
    meta = json.loads((cwd / "a.gif.json").read_text())
    assert meta["parameters"]["frames"] == 2 and meta["parameters"]["fps"] == 10.0
    assert meta["parameters"]["size_px"] == [160, 160]
    assert meta["parameters"]["config"] == "run.toml" and meta["parameters"]["solver"] == "exact"
    import imageio.v3 as iio

    assert iio.imread(cwd / "a.gif", index=None).shape[:3] == (2, 160, 160)


def test_refine_table_with_small_element_counts(capsys, cwd):
    # [frame] elements (the impact mesh of simulate) does not reach refine's list of counts.
    (cwd / "run.toml").write_text(
        "[frame]\nelements = 50\n[impact]\nspeed_m_s = 30\n"
        "[refine]\nelements = [4, 8]\nfamily = 'uniform'\npositions = [0.75]\ncount = 2\n"
        "csv = 'r.csv'\nplot = 'r.png'\njson = true\n"
    )
    from_file = json.loads(run(capsys, "refine", "--config", "run.toml"))
    argv = ["--elements", "4", "8", "--family", "uniform", "--positions", "0.75", "--count", "2"]
    cli = json.loads(run(capsys, "refine", *argv, "--json", "--no-files", "--speed", "30"))
    assert from_file["elements"] == [4, 8]
    for key in ("frequencies_hz", "exact_frequencies_hz", "cor", "contact_time_s"):
        assert from_file[key] == cli[key], key
    # Provenance: the CSV's sidecar and the PNG's text chunks.
    side = json.loads((cwd / "r.csv.json").read_text())
    assert side["parameters"]["elements"] == [4, 8] and side["parameters"]["speed"] == 30.0
    assert side["parameters"]["config"] == "run.toml" and side["version"]
    from PIL import Image

    with Image.open(cwd / "r.png") as im:
        im.load()
        png = json.loads(im.text["provenance"])
    assert png["parameters"] == side["parameters"] and im.text["Software"].startswith("fem_racket")


def test_reproduce_table_is_read_and_checked(capsys, cwd):
    (cwd / "run.toml").write_text("[reproduce]\nquick = true\nout = 'figs'\nreport = 'R.md'\n")
    out = run(capsys, "config", "--check", "run.toml")
    line = next(ln for ln in out.splitlines() if ln.startswith("[reproduce]"))
    for setting in ('out = "figs"', 'report = "R.md"', "quick = true"):
        assert setting in line


def _uncommented_example(text: str) -> str:
    """The example with every command table and every key that has a default uncommented."""
    head, sep, tail = text.partition("# Each command's own options")
    lines = []
    for line in tail.splitlines():
        table = re.match(r"^# (\[[\w-]+\])", line)
        key = re.match(r"^# (\w+ = [^<#]*?)\s+# ", line)
        lines.append(table.group(1) if table else key.group(1) if key else line)
    return head + sep + "\n".join(lines) + "\n"


def test_example_has_every_command_table_and_they_parse(capsys, cwd):
    text = run(capsys, "config", "--example")
    for table in ("simulate", "modes", "sweep", "vtk", "animate", "refine", "reproduce"):
        assert f"# [{table}]" in text, table
    # fit needs its targets (no defaults): the check fails where `fit` would, until given.
    (cwd / "all.toml").write_text(_uncommented_example(text))
    code = main(["config", "--check", "all.toml"])
    err = capsys.readouterr().err
    assert code == 2 and "fem-racket fit would refuse it: length is required" in err
    targets = "[fit]\nlength = 0.685\nmass = 0.318\nbalance = 0.32\nswing_weight = 316.0\n"
    (cwd / "all.toml").write_text(_uncommented_example(text).replace("[fit]\n", targets))
    out = run(capsys, "config", "--check", "all.toml")
    # each line names the table the file uses, and the command when it differs
    for name in ("[sweep]", "[vtk] (fem-racket export-vtk)", "[animate]", "[refine]"):
        assert f"\n{name} " in out
    assert "\n[reproduce] " in out and "\n[design] (fem-racket optimize) " in out
    # Every uncommented default is the built-in one: the sweep is the default single impact
    # (its fast path agrees with simulate to 1e-9, tests/test_sweep.py).
    run(capsys, "sweep", "--config", "all.toml", "--serial", "--quiet", "--json")
    default = json.loads(run(capsys, "simulate", "--json"))
    import xarray as xr

    with xr.open_dataset(cwd / "output" / "sweep.nc") as ds:
        assert float(ds.cor) == pytest.approx(default["cor"], abs=1e-9)


def test_example_runs_as_is_with_every_command(capsys, cwd):
    (cwd / "run.toml").write_text(run(capsys, "config", "--example"))
    cfg = ("--config", "run.toml")
    run(capsys, "sweep", *cfg, "--serial", "--quiet")
    run(capsys, "export-vtk", *cfg, "--frames", "2")
    run(capsys, "animate", *cfg, "--frames", "2", "--size", "160x160")
    run(capsys, "refine", *cfg, "--elements", "5", "10", "--family", "uniform", "--count", "1")
    names = {p.relative_to(cwd).as_posix() for p in (cwd / "output").rglob("*") if p.is_file()}
    assert {"output/sweep.nc", "output/impact_vtk/impact.pvd", "output/impact.gif"} <= names
    assert {"output/refine.csv", "output/refine.csv.json", "output/refine.png"} <= names
    assert np.all([not n.startswith("output/.") for n in names])  # no temporary file left


def test_mesh_on_the_command_line_replaces_the_files_frame(capsys, cwd):
    import xarray as xr

    from fem_racket.cli import main as cli_main

    mesh = Path(__file__).resolve().parents[2] / "meshes" / "tapered_racket.vtu"
    # The example sets preset, ei1_n_m2 and elements = 20: --mesh replaces all three.
    (cwd / "run.toml").write_text(run(capsys, "config", "--example"))
    cfg = ("--config", "run.toml", "--mesh", mesh)
    run(capsys, "sweep", *cfg, "--serial", "--quiet", "--position", "0.6,0.8", "--out", "m.nc")
    sim = json.loads(run(capsys, "simulate", *cfg, "--position", "0.8", "--json"))
    plain = json.loads(run(capsys, "simulate", "--mesh", mesh, "--position", "0.8", "--json"))
    assert sim == plain and sim["elements"] != 20
    with xr.open_dataset("m.nc") as ds:  # fast path vs simulate: 1e-9 (tests/test_sweep.py)
        assert float(ds.cor.sel(position=0.8)) == pytest.approx(sim["cor"], abs=1e-9)
    # A mesh in the file with an explicit --ei1 is refused (the mesh gives EI).
    (cwd / "mesh.toml").write_text(f"[frame]\nmesh = '{mesh}'\n")
    assert cli_main(["sweep", "--config", "mesh.toml", "--ei1", "100"]) == 2
    assert "--ei1 cannot be combined with frame.mesh" in capsys.readouterr().err
