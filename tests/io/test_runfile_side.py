"""Run files with a 3-D oblique ball: ``[sweep] side_angle``/``side_spin`` (axes or fixed
values, also from ``[oblique] side_angle_deg``/``side_spin_rpm``) and the spin map's
``[oblique]`` side keys give what the commands give."""

from __future__ import annotations

import json

import numpy as np
from clirun import run_json

from fem_racket import load_config
from fem_racket.cli import main


def test_sweep_side_axes_from_a_run_file_equal_the_command(cwd, capsys):
    import xarray as xr

    (cwd / "run.toml").write_text(
        '[oblique]\nangle_deg = 20\nside_spin_rpm = 300\n[sweep]\nside_angle = "-10,10"\n'
        'spin = [0, 1000]\nout = "s.nc"\n'
    )
    ds = load_config(cwd / "run.toml").sweep(backend="serial")
    assert ds.side_spin_out_rpm.dims == ("spin", "side_angle")
    assert ds.attrs["side_spin_rpm"] == 300.0 and ds.attrs["angle_deg"] == 20.0
    assert main(["sweep", "--config", "run.toml", "--serial", "--quiet"]) == 0
    capsys.readouterr()
    with xr.open_dataset(cwd / "s.nc") as back:
        for name in ("side_spin_out_rpm", "side_angle_out_deg", "racket_yaw_rate_rad_s", "cor"):
            np.testing.assert_array_equal(back[name].values, ds[name].values)


def test_a_bad_side_angle_in_a_run_file_is_refused_in_one_line(cwd, capsys):
    (cwd / "run.toml").write_text('[sweep]\nside_angle = "0,90"\n')
    assert main(["sweep", "--config", "run.toml"]) == 2
    err = capsys.readouterr().err.strip()
    assert "sweep.side_angle = 90.0 deg is not allowed: must lie in (-90, 90)" in err, err
    assert len(err.splitlines()) == 1


def test_spin_map_side_keys_from_a_run_file_equal_the_command(cwd, capsys):
    (cwd / "run.toml").write_text(
        "[oblique]\nangle_deg = 20\nside_angle_deg = 10\nside_spin_rpm = 500\n[map]\n"
        'positions = "0.6,0.9"\noffsets = "-0.05,0.05"\nno_files = true\n'
    )
    (m,) = load_config(cwd / "run.toml").map()
    assert m.incidence.side_angle == 10.0 and m.incidence.side_spin == 500.0
    cli = run_json(capsys, "map", "--config", "run.toml")
    py = json.loads(json.dumps(m.summary()))
    for key in ("side_spin_out_rpm_max", "side_angle_out_deg_min", "racket_yaw_rate_rad_s_max"):
        assert py[key] == cli[key], key
