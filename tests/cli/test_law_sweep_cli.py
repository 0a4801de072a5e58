"""Law parameters swept by ``fem-racket sweep`` (options and run files) and ``map --law``."""

from __future__ import annotations

import json

import numpy as np
from clirun import run, run_json

from fem_racket.contact.presets import get_law
from fem_racket.studies.racket_map import racket_map
from fem_racket.studies.sweep import sweep


def test_sweep_law_parameter_options_are_the_library_call(capsys, cwd):
    import xarray as xr

    argv = ["sweep", "--law", "hysteretic", "--k2", "6e16:1.2e17:3", "--position", "0.6,0.8"]
    summary = run_json(capsys, *argv, "--speed", "30", "--serial", "--quiet")
    assert summary["dims"] == {"position": 2, "k2": 3}
    assert summary["contact_law"] == "hysteretic" and summary["solver"] == "general"
    # a process pool: the same batches as --serial (fixed chunks under a law)
    ref = sweep(law="hysteretic", k2="6e16:1.2e17:3", position=[0.6, 0.8], speed=30.0, workers=2)
    with xr.open_dataset(cwd / "output" / "sweep.nc") as ds:
        np.testing.assert_array_equal(ds.cor.values, ref.cor.values)
        assert ds.k2.attrs["units"] == "N/m^n" and ds.attrs["contact_law"] == "hysteretic"
        assert json.loads(ds.attrs["run_parameters"])["k2"] == "6e16:1.2e17:3"


def test_run_file_sweeps_a_law_parameter(capsys, cwd):
    import xarray as xr

    (cwd / "run.toml").write_text(
        '[contact]\nlaw = "hunt-crossley"\nhc_stiffness_n_m_n = 1e7\n'
        "[impact]\nspeed_m_s = 20.0\n"
        '[sweep]\nhc_exponent = [1.5, 2.0]\nhc_alpha = "0:0.05:2"\nout = "s.nc"\n'
    )
    code, _, err = run(capsys, "sweep", "--config", "run.toml", "--serial", "--quiet")
    assert code == 0, err
    ref = sweep(
        law="hunt-crossley",
        hc_stiffness=1e7,
        hc_exponent=[1.5, 2.0],
        hc_alpha=[0.0, 0.05],
        backend="serial",
    )
    with xr.open_dataset(cwd / "s.nc") as ds:
        assert ds.cor.dims == ("hc_exponent", "hc_alpha")
        np.testing.assert_array_equal(ds.cor.values, ref.cor.values)
        assert ds.attrs["contact_hc_stiffness_n_m_n"] == 1e7
    code, out, err = run(capsys, "config", "--check", "run.toml")
    assert code == 0, err
    assert "hc_exponent = [1.5, 2.0]" in out


def test_map_with_a_law_records_it(capsys, cwd):
    import xarray as xr

    argv = ["map", "--positions", "0.5:1.0:6", "--racket-speed", "20", "--pivot", "0.1"]
    law = ["--law", "hunt-crossley", "--hc-stiffness", "1e7", "--hc-exponent", "1.5"]
    data = run_json(capsys, *argv, *law, "--out", "m.nc", "m.csv")
    ref = racket_map(
        racket_speed=20.0,
        pivot=0.1,
        positions=np.linspace(0.5, 1.0, 6),
        law=get_law("hunt-crossley", hc_stiffness=1e7, hc_exponent=1.5),
    )
    assert data["curves"]["apparent_cor"] == ref.apparent_cor.tolist()
    assert data["contact"]["law"] == "hunt-crossley"
    assert data["contact"]["hc_stiffness_n_m_n"] == 1e7
    with xr.open_dataset(cwd / "m.nc") as ds:
        assert ds.attrs["contact_law"] == "hunt-crossley"
        assert ds.attrs["contact_hc_exponent"] == 1.5
        np.testing.assert_array_equal(ds.apparent_cor.values[0], data["curves"]["apparent_cor"])
    side = json.loads((cwd / "m.csv.json").read_text())
    assert side["sweet_spots"]["standard"]["contact"]["law"] == "hunt-crossley"


def test_map_under_the_linear_law_is_today_s_map(capsys, cwd):
    argv = ["map", "--positions", "0.5:1.0:6", "--racket-speed", "20", "--out", "m.nc"]
    today = run_json(capsys, *argv)
    linear = run_json(capsys, *argv, "--law", "linear", "--overwrite")
    assert linear["curves"] == today["curves"] and linear["contact"] == {"law": "linear"}


def test_map_takes_the_law_from_a_run_file(capsys, cwd):
    (cwd / "run.toml").write_text(
        # a Hertz-like ball (1e7 N/m^n with the default n = 14.87 would deflect 0.54 m under
        # 1 kN: refused as no ball)
        '[contact]\nlaw = "hunt-crossley"\nhc_stiffness_n_m_n = 1e7\nhc_exponent = 1.5\n'
        '[map]\npositions = "0.5:1:5"\nout = ["r.nc"]\n'
    )
    data = run_json(capsys, "map", "--config", "run.toml")
    law = get_law("hunt-crossley", hc_stiffness=1e7, hc_exponent=1.5)
    assert data["contact"] == law.describe()
