"""Default outputs that can be rerun, the one success line, and JSON numbers without float noise.

A command writing to its default location replaces its own earlier output (recognised by its
provenance) and refuses anything else there; ``--json`` alone writes nothing; every file written
(sidecars included) is reported as ``wrote PATH``.
"""

import json

from tests.clirun import run, run_json

MAP = ["map", "--positions", "0.5:1:12"]


def test_map_replaces_its_own_default_output_and_nothing_else(capsys, cwd):
    code, out, _ = run(capsys, *MAP)
    assert code == 0 and out.splitlines()[-1] == "wrote output/map.png"
    first = (cwd / "output/map.png").read_bytes()
    code, out, _ = run(capsys, *MAP, "--speed", "30")  # the README's examples, in order
    assert code == 0 and out.splitlines()[-1] == "wrote output/map.png"
    assert (cwd / "output/map.png").read_bytes() != first
    (cwd / "output/map.png").write_bytes(b"someone else's picture")
    code, out, err = run(capsys, *MAP)
    assert code == 2 and out == "" and "already exists" in err and "--overwrite" in err
    assert (cwd / "output/map.png").read_bytes() == b"someone else's picture"


def test_a_named_destination_is_never_replaced_without_overwrite(capsys, cwd):
    assert run(capsys, *MAP, "--out", "m.png")[0] == 0
    code, _, err = run(capsys, *MAP, "--out", "m.png")
    assert code == 2 and "already exists" in err


def test_json_alone_and_no_files_write_nothing(capsys, cwd):
    assert run_json(capsys, *MAP)["racket"] == "standard"
    code, out, _ = run(capsys, *MAP, "--no-files")
    assert code == 0 and "wrote" not in out
    assert not (cwd / "output").exists()
    code, _, err = run(capsys, *MAP, "--no-files", "--out", "m.png")
    assert code == 2 and "no_files" in err
    assert run_json(capsys, "refine", "--elements", "5,10", "--quiet")["files"] == []
    assert not (cwd / "output").exists()


def test_every_file_written_is_reported_sidecars_included(capsys, cwd):
    code, out, _ = run(capsys, "simulate", "--out", "s.csv")
    assert code == 0 and out.splitlines()[-2:] == ["wrote s.csv", "wrote s.csv.json"]
    fit = ["fit", "--length", "0.685", "--mass", "0.318", "--balance", "0.32"]
    code, out, _ = run(capsys, *fit, "--swing-weight", "316")
    assert out.splitlines()[-2:] == ["wrote output/racket.vtu", "wrote output/racket.vtu.json"]
    code, out, _ = run(capsys, *fit, "--swing-weight", "320")  # its own: replaced
    assert code == 0 and out.splitlines()[-1] == "wrote output/racket.vtu.json"
    code, out, _ = run(capsys, "refine", "--elements", "5,10", "--quiet")
    assert out.splitlines()[-3:] == [
        "wrote output/refine.csv",
        "wrote output/refine.csv.json",
        "wrote output/refine.png",
    ]
    code, out, _ = run(capsys, "config", "--example", "--out", "run.toml")
    assert (code, out) == (0, "wrote run.toml\n")


def test_json_numbers_carry_no_float_noise(capsys, cwd):
    # K_CB at 20 m/s is the paper's 2.74e4 N/m; the power law through its points gave
    # 27399.999999999993 before JSON rounded floats to 15 significant digits.
    code, out, _ = run(capsys, "simulate", "--json")
    assert code == 0 and '"kcb_n_m": 27400.0,' in out
    run(capsys, "simulate", "--out", "s.json")
    assert json.loads((cwd / "s.json").read_text())["summary"]["kcb_n_m"] == 27400.0
