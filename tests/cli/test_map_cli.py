"""``fem-racket map``: JSON contract, files with sweet spots, several rackets, bad input."""

from __future__ import annotations

import json

import numpy as np
import pytest
from clirun import run, run_json

from fem_racket.frame.mesh import frame_mesh
from fem_racket.frame.segments import standard_frame
from fem_racket.io.mesh_files import write_mesh
from fem_racket.studies.racket_map import racket_map

GRID = ("--positions", "0.5:1.0:21")


def test_map_json_is_the_library_call_and_files_hold_the_spots(capsys, cwd):
    swing = ("--speed", "20", "--racket-speed", "25", "--pivot", "0.1")
    files = ("--out", "m.nc", "m.csv", "m.png")
    data = run_json(capsys, "map", *swing, *GRID, *files)
    ref = racket_map(speed=20.0, racket_speed=25.0, pivot=0.1, positions=np.linspace(0.5, 1.0, 21))
    for key in ("cop_x_over_l", "node_x_over_l", "max_apparent_cor_x_over_l"):
        assert data[key] == ref.spots.summary()[key]
    assert data["max_ball_speed_x_over_l"] == ref.spots.max_ball_speed
    assert data["curves"]["ball_speed_out_m_s"] == ref.ball_speed_out.tolist()
    import xarray as xr

    with xr.open_dataset(cwd / "m.nc") as ds:
        assert ds.apparent_cor.dims == ("racket", "position")
        assert float(ds.attrs["cop_x_over_l"]) == pytest.approx(data["cop_x_over_l"])
        assert "version" in ds.attrs
    side = json.loads((cwd / "m.csv.json").read_text())
    assert side["sweet_spots"]["standard"]["node_x_over_l"] == data["node_x_over_l"]
    from PIL import Image

    with Image.open(cwd / "m.png") as im:
        im.load()
        assert "provenance" in im.text


def test_several_rackets_are_overlaid(capsys, cwd):
    write_mesh(frame_mesh(standard_frame(300.0), 20), cwd / "stiff.vtu")
    argv = ("map", "--preset", "standard", "--mesh", "stiff.vtu", "--preset", "rigid", *GRID)
    rackets = run_json(capsys, *argv, "--out", "o.png")["rackets"]
    assert [r["racket"] for r in rackets] == ["standard", "rigid", "stiff"]
    # Without a pivot there is no centre of percussion, without a swing no max-v_out point.
    assert rackets[0]["cop_x_over_l"] is None
    assert rackets[0]["max_ball_speed_x_over_l"] is None


def test_existing_output_is_refused_before_the_work(capsys, cwd):
    (cwd / "m.png").write_bytes(b"keep")
    code, _, err = run(capsys, "map", *GRID, "--out", "m.png")
    assert code == 2 and "m.png" in err
    assert (cwd / "m.png").read_bytes() == b"keep"
    code, _, err = run(capsys, "map", *GRID, "--out", "m.txt")
    assert code == 2 and "must end in .nc, .csv, .png" in err
    assert not (cwd / "output").exists()
