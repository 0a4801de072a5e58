"""TOML run files: the example runs as is, the command line overrides the file, outputs carry
provenance. Bad files are catalogued in test_bad_input.py."""

import json

import pytest
from clirun import run, run_json

from fem_racket import Frame, Segment, frame_mesh, load_config, standard_frame, write_mesh
from fem_racket.io.config import example_config, parse_config


def simulate_json(capsys, *argv):
    return run_json(capsys, "simulate", *argv)


@pytest.fixture
def example(tmp_path, capsys):
    """The printed example, written to run.toml."""
    code, out, _ = run(capsys, "config", "--example")
    assert code == 0
    path = tmp_path / "run.toml"
    path.write_text(out)
    return path


def test_example_runs_as_is_and_is_the_default_run(capsys, example):
    # The example states the paper's standard case, i.e. every built-in default: same answer.
    from_file = simulate_json(capsys, "--config", example)
    default = simulate_json(capsys)
    assert from_file == default
    modes = run_json(capsys, "modes", "--config", example)
    assert modes["frequencies_hz"][0] == pytest.approx(122.14, abs=0.01)


def test_example_lists_the_tables_of_commands_that_read_run_files(capsys):
    _, out, _ = run(capsys, "config", "--example")
    for table in ("[frame]", "[ball]", "[contact]", "[impact]", "[solver]", "[output]"):
        assert table in out
    assert "# [modes]" in out and "# count = 4" in out
    assert "speed_m_s" in out and "position_x_over_l" in out and "mass_kg" in out


def test_command_line_overrides_file_even_with_the_default_value(capsys, tmp_path):
    path = tmp_path / "run.toml"
    path.write_text("[impact]\nspeed_m_s = 30.0\nposition_x_over_l = 0.6\n")
    assert simulate_json(capsys, "--config", path)["speed_m_s"] == 30.0
    # --speed 20 is the built-in default: it must still win over the file's 30.
    data = simulate_json(capsys, "--config", path, "--speed", "20")
    assert data["speed_m_s"] == 20.0 and data["position_x_over_l"] == 0.6
    data = simulate_json(capsys, "--speed=25", "--config", path)
    assert data["speed_m_s"] == 25.0


def test_every_core_key_reaches_the_run(capsys, tmp_path):
    path = tmp_path / "run.toml"
    path.write_text(
        "[frame]\npreset = 'rigid'\nelements = 10\n"
        "[ball]\nmass_kg = 0.058\n"
        "[contact]\nkcb_n_m = 30000\nclamped_cor = 0.8\n"
        "[impact]\nposition_x_over_l = 0.7\nspeed_m_s = 25\n"
        "[solver]\nname = 'cvode'\nseparation = 'force'\nbasis = 'modal'\nmodes = 12\n"
        "rtol = 1e-9\natol = 1e-11\nt_max_s = 0.05\n"
    )
    data = simulate_json(capsys, "--config", path)
    assert data["elements"] == 10 and data["ball_mass_kg"] == 0.058
    assert data["kcb_n_m"] == 30000.0 and data["modes"] == 12
    assert data["solver"] == "cvode" and data["separation"] == "force"
    assert data["position_x_over_l"] == 0.7 and data["speed_m_s"] == 25.0
    from fem_racket import zeta_from_cor

    assert data["zeta"] == zeta_from_cor(0.8)
    cli = simulate_json(
        capsys,
        *("--ei1", "9999", "--elements", "10", "--ball-mass", "0.058", "--kcb", "30000"),
        *("--zeta", repr(zeta_from_cor(0.8)), "--position", "0.7", "--speed", "25"),
        *("--solver", "cvode", "--separation", "force", "--modes", "12"),
        *("--rtol", "1e-9", "--atol", "1e-11", "--t-max", "0.05"),
    )
    assert cli == data


def test_segments_and_mesh_files_give_the_standard_racket(capsys, tmp_path):
    default = simulate_json(capsys)
    seg = tmp_path / "seg.toml"
    seg.write_text(
        "[[frame.segments]]\nlength_m = 0.204\nei_n_m2 = 146.0\nrhoa_kg_m = 0.696\n"
        "[[frame.segments]]\nlength_m = 0.476\nei_n_m2 = 128.48\nrhoa_kg_m = 0.458\n"
    )
    # Same segments as standard_frame() (EI2 = 0.88 * 146 = 128.48): same COR to round-off.
    assert simulate_json(capsys, "--config", seg)["cor"] == pytest.approx(default["cor"], rel=1e-12)
    (tmp_path / "meshes").mkdir()
    write_mesh(frame_mesh(standard_frame(), 20), tmp_path / "meshes" / "std.vtu")
    sub = tmp_path / "cases"
    sub.mkdir()
    mesh_toml = sub / "mesh.toml"
    mesh_toml.write_text("[frame]\nmesh = '../meshes/std.vtu'\n")  # relative to the file
    assert simulate_json(capsys, "--config", mesh_toml)["cor"] == pytest.approx(
        default["cor"], rel=1e-12
    )


def test_command_table_sets_that_commands_options(capsys, tmp_path):
    path = tmp_path / "run.toml"
    path.write_text("[modes]\ncount = 2\njson = true\n[simulate]\njson = true\n")
    code, out, _ = run(capsys, "modes", "--config", path)
    assert code == 0 and len(json.loads(out)["frequencies_hz"]) == 2
    code, out, _ = run(capsys, "modes", "--config", path, "--count", "3")
    assert len(json.loads(out)["frequencies_hz"]) == 3
    code, out, _ = run(capsys, "simulate", "--config", path)
    assert code == 0 and "cor" in json.loads(out)


def test_simulate_out_writes_provenance_and_histories(capsys, tmp_path):
    out = tmp_path / "res" / "impact.json"
    code, _, err = run(capsys, "simulate", "--out", out, "--solver", "cvode", "--rtol", "1e-9")
    assert code == 0, err
    data = json.loads(out.read_text())
    prov = data["provenance"]
    assert prov["software"] == "fem_racket" and prov["version"] and prov["created_utc"]
    params = prov["parameters"]
    assert params["solver"] == "cvode" and params["rtol"] == 1e-9 and params["atol"] == 1e-12
    assert params["speed"] == 20.0 and params["ei1"] == 146.0
    hist = data["history"]
    assert len(hist["time [s]"]) == len(hist["contact force [N]"]) > 100
    assert hist["time [s]"][-1] == pytest.approx(data["summary"]["contact_time_s"])
    # A second run must not replace the file silently; --overwrite does.
    before = out.read_text()
    code, _, err = run(capsys, "simulate", "--out", out)
    assert code == 2 and "--overwrite" in err and out.read_text() == before
    assert run(capsys, "simulate", "--out", out, "--overwrite")[0] == 0
    assert json.loads(out.read_text())["provenance"]["parameters"]["solver"] == "exact"
    assert sorted(p.name for p in out.parent.iterdir()) == ["impact.json"]


def test_output_table_and_config_path_reach_provenance(capsys, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    path = tmp_path / "run.toml"
    path.write_text("[output]\nout = 'o/r.json'\n[impact]\nspeed_m_s = 30\n")
    assert run(capsys, "simulate", "--config", path)[0] == 0
    params = json.loads((tmp_path / "o" / "r.json").read_text())["provenance"]["parameters"]
    assert params["config"] == str(path) and params["speed"] == 30.0


def test_config_example_out_and_check(capsys, tmp_path):
    path = tmp_path / "run.toml"
    assert run(capsys, "config", "--example", "--out", path)[0] == 0
    assert path.read_text() == example_config() + path.read_text()[len(example_config()) :]
    last = path.read_text().splitlines()[-1]  # the written file records its provenance
    assert last.startswith("# provenance: ") and json.loads(last[14:])["version"]
    assert run(capsys, "config", "--example", "--out", path)[0] == 2
    code, out, _ = run(capsys, "config", "--check", path)
    assert code == 0 and out.startswith(f"{path}: ok") and "speed = 20.0" in out


def test_library_api(tmp_path):
    cfg = parse_config(example_config())
    assert cfg.get("impact.speed_m_s") == 20.0
    assert cfg.simulate_kwargs()["position"] == 0.75
    assert cfg.frame() == standard_frame()
    path = tmp_path / "run.toml"
    path.write_text("[frame]\nsegments = [{length_m = 0.5, ei_n_m2 = 100, rhoa_kg_m = 0.6}]\n")
    assert load_config(path).frame() == Frame((Segment(0.5, 100.0, 0.6),))


def test_a_new_command_plugs_in_with_one_call(tmp_path):
    """How sweep/refine/export-vtk/animate adopt run files: add_config_option(p), nothing else.

    A stand-in sub-command with the kinds of options those commands have (a list, a flag, a
    choice, a positional) reads its own table, converted and checked like the command line."""
    import argparse

    from fem_racket import InputError
    from fem_racket.cli.common import (
        OneLineErrorParser,
        add_config_option,
        add_impact_options,
        add_output_options,
        apply_config,
    )

    parser = OneLineErrorParser(prog="fem-racket")
    sub = parser.add_subparsers(dest="command")
    p = sub.add_parser("sweep")
    p.add_argument("name")
    add_impact_options(p)
    p.add_argument("--ei1-values", type=float, nargs="+", default=[146.0])
    p.add_argument("--backend", choices=["serial", "dask"], default="serial")
    p.add_argument("--progress", action="store_true")
    add_output_options(p, "output/sweep.nc")
    add_config_option(p)

    def apply(text, *argv):
        path = tmp_path / "run.toml"
        path.write_text(text)
        argv = ["sweep", "case", *argv, "--config", str(path)]
        return apply_config(parser, argv, parser.parse_args(argv))

    text = (
        "[impact]\nspeed_m_s = 30\n[output]\noverwrite = true\n"
        "[sweep]\nei1_values = [50, 100.5]\nbackend = 'dask'\nprogress = true\n"
        "out = 'output/s.nc'\n"
    )
    args = apply(text)
    assert isinstance(args, argparse.Namespace) and args.name == "case"
    assert args.ei1_values == [50.0, 100.5] and args.backend == "dask" and args.progress
    assert args.speed == 30.0 and args.overwrite is True and args.out == "output/s.nc"
    args = apply(text, "--backend", "serial", "--ei1-values", "7")
    assert args.backend == "serial" and args.ei1_values == [7.0] and args.progress
    for bad, words in (
        ("[sweep]\nbackend = 'mpi'\n", "sweep.backend = 'mpi' is not allowed: must be one of"),
        ("[sweep]\nei1_values = 3\n", "sweep.ei1_values = 3 is not allowed: must be an array"),
        ("[sweep]\nei1_values = ['a']\n", "sweep.ei1_values = 'a' is not allowed"),
        ("[sweep]\nprogres = true\n", "did you mean 'progress'"),
        ("[sweep]\nprogress = 1\n", "must be true or false"),
    ):
        with pytest.raises(InputError, match=words):
            apply(bad)
