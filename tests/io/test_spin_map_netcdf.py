"""The spin map's netCDF labels its ``racket`` coordinate with the rackets' names, as the e_A
face map's file does, so one racket is selected by name in either."""

from __future__ import annotations

from clirun import run_ok


def test_spin_and_face_map_files_name_their_rackets(capsys, cwd):
    import xarray as xr

    grid = ["--preset", "standard", "rigid", "--positions", "0.7,0.8", "--offsets=-0.05,0.05"]
    run_ok(capsys, "map", *grid, "--angle", "30", "--out", "spin.nc")
    run_ok(capsys, "map", *grid, "--out", "face.nc")
    with xr.open_dataset("spin.nc") as spin, xr.open_dataset("face.nc") as face:
        assert spin.racket.values.tolist() == face.racket.values.tolist() == ["standard", "rigid"]
        one = spin.sel(racket="rigid")
        assert one.spin_out_rpm.shape == (2, 2)
        assert (one.spin_out_rpm == spin.spin_out_rpm[1]).all()
        assert spin.attrs["rackets"] == "standard rigid"  # kept as before
