"""fem-racket simulate with a string bed: the bed replaces K_CB; tension changes the impact."""

import json

import pytest

from tests.clirun import run, run_json


def _value(out: str, name: str) -> float:
    line = next(ln for ln in out.splitlines() if ln.startswith(name))
    return float(line[len(name) :].split()[0])


def test_tension_changes_contact_time_and_cor(capsys):
    # issue 25, "done when": 220 N and 270 N print different contact times and e_A, with the
    # bed stiffness (k ~ T: 270/220 of it)
    got = {}
    for tension in (220, 270):
        code, out, err = run(capsys, "simulate", "--string-tension", tension)
        assert code == 0 and err == ""
        got[tension] = out
        assert "stringbed stiffness" in out and "kawazoe-1997-ball" in out
    tc = {t: _value(o, "contact time") for t, o in got.items()}
    cor = {t: _value(o, "coefficient of restitution") for t, o in got.items()}
    k = {t: _value(o, "stringbed stiffness") for t, o in got.items()}
    assert tc[270] < tc[220] and cor[270] != cor[220]
    assert k[270] / k[220] == pytest.approx(270 / 220, rel=1e-3)


def test_json_and_options(capsys, tmp_path):
    code, out, _ = run(
        capsys, "simulate", "--pattern", "18x20", "--head-area", "700", "--string-material",
        "polyester", "--json", "--position", "0.8", "--out", tmp_path / "r.json",
    )  # fmt: skip
    assert code == 0
    s = json.loads(out[: out.rindex("}") + 1])
    assert s["pattern"] == "18x20" and s["string"] == "polyester"
    assert s["head_area_cm2"] == pytest.approx(700.0, rel=1e-12)
    assert s["stringbed_stiffness_n_m"] > 0 and len(s["stringbed_frequencies_hz"]) == 3
    data = json.loads((tmp_path / "r.json").read_text())
    assert set(data["history"]) >= {"time [s]", "bed deflection [m]", "ball deflection [m]"}
    assert data["summary"]["cor"] == s["cor"]


@pytest.mark.parametrize(
    ("argv", "message"),
    [
        (["--string-tension", "250", "--kcb", "5e4"], "kcb is not allowed with a string bed"),
        (
            [
                "--pattern",
                "16x",
            ],
            "pattern = '16x' is not allowed",
        ),
        (["--pattern", "16x19", "--solver", "bdf"], "solver = 'bdf' is not allowed"),
        (["--string-tension", "250", "--position", "0.3"], "must lie on the head"),
        (["--head-area", "600", "--head-length", "0.3", "--head-width", "0.25"], "two of the"),
        (["--string-tension", "-3"], "string tension = -3.0 N is not allowed"),
        (["--string-tension", "250", "--grip", "firm"], "a hand is not allowed with a string"),
    ],
)
def test_bad_input(capsys, argv, message):
    code, out, err = run(capsys, "simulate", *argv)
    assert code == 2 and out == ""
    assert message in err and len(err.strip().splitlines()) == 1


def test_run_file_strings_table(capsys, tmp_path):
    # a [strings] table replaces K_CB as the options do; the command line wins over the file
    cfg = tmp_path / "run.toml"
    cfg.write_text('[strings]\ntension_n = 230\npattern = "18x20"\nstring = "polyester"\n')
    s = run_json(capsys, "simulate", "--config", cfg)
    assert s["pattern"] == "18x20" and s["string_tension_n"] == 230.0
    s = run_json(capsys, "simulate", "--config", cfg, "--string-tension", "260")
    assert s["string_tension_n"] == 260.0
    cfg.write_text('[strings]\npattern = "18"\n')
    code, out, err = run(capsys, "simulate", "--config", cfg)
    assert code == 2 and "strings.pattern = '18' is not allowed" in err


def test_export_vtk_draws_the_bed(capsys, tmp_path):
    code, out, err = run(
        capsys, "export-vtk", "--string-tension", "250", "--frames", "4", "--out", tmp_path / "v"
    )
    assert code == 0 and err == ""
    pvd = tmp_path / "v" / "impact.pvd"
    assert out.strip().startswith(f"wrote {pvd.parent}/") and pvd.is_file()
    text = pvd.read_text()
    assert text.count('name="strings"') == 4 and text.count('name="frame"') == 4
    code, _, err = run(capsys, "export-vtk", "--pattern", "16x19", "--field", "slope [rad]")
    assert code == 2 and "--field is not allowed with a string bed" in err


def test_bed_edge_option(capsys):
    s = run_json(capsys, "simulate", "--bed-edge", "hoop", "--position", "0.6")
    assert s["stringbed_edge"] == "hoop"
