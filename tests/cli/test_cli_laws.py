"""--law on the commands, the [contact] law keys of run files, and fem-racket calibrate."""

import json

import pytest
from clirun import run, run_json

from fem_racket import simulate
from fem_racket.contact.presets import PRESETS, get_law


def test_simulate_law_preset_json_records_the_law(capsys):
    data = run_json(capsys, "simulate", "--law", "kawazoe-1997-nonlinear", "--speed", "30")
    ref = simulate(speed=30.0, law=PRESETS["kawazoe-1997-nonlinear"])  # the call it wraps
    assert data["cor"] == ref.cor and data["solver"] == "general"
    assert data["law"] == "hysteretic" and data["k1_n_m_n"] == PRESETS["kawazoe-1997-nonlinear"].k1


def test_simulate_law_family_options(capsys):
    data = run_json(
        capsys,
        "simulate",
        "--law",
        "hunt-crossley",
        "--hc-exponent",
        "9",
        "--hc-alpha",
        "0.01",
        "--hc-stiffness",
        "8e16",
        "--speed",
        "30",
    )
    ref = simulate(
        speed=30.0, law=get_law("hunt-crossley", hc_stiffness=8e16, hc_exponent=9.0, hc_alpha=0.01)
    )
    assert data["cor"] == ref.cor and data["hc_exponent"] == 9.0


def test_law_options_errors_are_one_line(capsys):
    code, _, err = run(capsys, "simulate", "--law", "series", "--k1", "3")
    assert code == 2 and "k1" in err and len(err.strip().splitlines()) == 1
    code, _, err = run(capsys, "simulate", "--law", "hysteretic", "--solver", "bdf")
    assert code == 2 and "solver" in err


def test_run_file_contact_law(capsys, tmp_path):
    cfg = tmp_path / "run.toml"
    cfg.write_text(
        '[contact]\nlaw = "hunt-crossley"\nhc_alpha_s_m = 0.02\n[impact]\nspeed_m_s = 30.0\n'
    )
    data = run_json(capsys, "simulate", "--config", cfg)
    assert data["law"] == "hunt-crossley" and data["hc_alpha_s_m"] == 0.02
    cfg.write_text('[contact]\nlaw = "hunt-crossley"\nhc_alpha = 0.02\n')
    code, _, err = run(capsys, "simulate", "--config", cfg)
    assert code == 2 and "hc_alpha_s_m" in err


@pytest.mark.slow
def test_calibrate_writes_table_run_file_and_plot(capsys, tmp_path):
    code, out, err = run(capsys, "calibrate", "--out", tmp_path)
    assert code == 0, err
    assert "meets every target: True" in out
    toml = tmp_path / "hysteretic-kawazoe-1997.toml"
    assert run_json(capsys, "simulate", "--config", toml, "--speed", "30")["law"] == "hysteretic"
    assert (tmp_path / "hysteretic-kawazoe-1997.png").read_bytes()[:4] == b"\x89PNG"
    fit = json.loads((tmp_path / "hysteretic-kawazoe-1997.json").read_text())
    assert fit["meets_targets"] and fit["provenance"]["parameters"]["family"] == "hysteretic"


def test_sweep_with_a_law_records_it(capsys, tmp_path):
    import xarray as xr

    out = tmp_path / "s.nc"
    code, _, err = run(
        capsys,
        "sweep",
        "--law",
        "kawazoe-1997-nonlinear",
        "--position",
        "0.6,0.8",
        "--speed",
        "30",
        "--serial",
        "--quiet",
        "--out",
        out,
    )
    assert code == 0, err
    with xr.open_dataset(out) as ds:
        assert ds.attrs["contact_law"] == "hysteretic" and ds.attrs["solver"] == "general"
        ref = simulate(position=0.8, speed=30.0, law="kawazoe-1997-nonlinear", output_step=None)
        # a batch shares the step of its shortest contact: both within the 1e-5 target
        assert float(ds.cor.sel(position=0.8)) == pytest.approx(ref.cor, abs=1e-5)
