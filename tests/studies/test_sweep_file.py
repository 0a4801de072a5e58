"""The sweep's netCDF file written without xarray (``fem_racket.outputs.netcdf``) is the file
xarray's writer gives: read back with ``xarray.open_dataset`` the two are identical (values,
dimensions, coordinates, every attribute), and at the netCDF level they hold the same
dimensions, variables (type, fill value, storage) and attributes. The ``modes_kept`` attribute
records the modes the solver kept, the same number ``simulate`` reports as used."""

from __future__ import annotations

import netCDF4
import numpy as np
import pytest
import xarray as xr

from fem_racket import FrameModel, impacts, simulate, standard_frame
from fem_racket.cli import main
from fem_racket.studies.sweep import sweep_result
from fem_racket.validation import InputError

#: Sweeps whose files are compared: the exact engine over three dimensions (with the command
#: line's run parameters), a law's parameter as a dimension with the peak force, one case (no
#: dimension) with a swing.
CASES = {
    "exact": dict(
        position=[0.6, 0.769, 0.9],
        speed=[20.0, 40.0],
        ei1=[60.0, 146.0, 2000.0],
        parameters={"command": "sweep", "out": "s.nc", "speed": "20,40"},
    ),
    "law axis": dict(  # k fixed where every swept n is a ball (1-4 mm under 1 kN)
        law="hunt-crossley",
        hc_stiffness=1e7,
        hc_exponent="1.3:1.7:3",
        position=[0.6, 0.8],
        peak_force=True,
    ),
    "one case": dict(racket_speed=10.0, pivot=0.1),
}


def _structure(path) -> tuple:
    """Everything netCDF stores about a file but the data (NaN attributes by their repr)."""

    def attributes(obj):
        return [(k, type(obj.getncattr(k)).__name__, repr(obj.getncattr(k))) for k in obj.ncattrs()]

    with netCDF4.Dataset(path) as nc:
        dims = [(d.name, d.size, d.isunlimited()) for d in nc.dimensions.values()]
        variables = [
            (v.name, v.dtype, v.dimensions, v.chunking(), v.filters(), v.endian(), attributes(v))
            for v in nc.variables.values()
        ]
        return nc.data_model, dims, variables, sorted(attributes(nc))


@pytest.mark.parametrize("name", list(CASES))
def test_the_file_is_the_one_xarray_writes(tmp_path, name):
    new, old = tmp_path / "new.nc", tmp_path / "xarray.nc"
    result = sweep_result(**CASES[name], output=new, backend="serial", progress=False)
    ds = result.to_xarray()
    ds.to_netcdf(old)
    assert _structure(new) == _structure(old)
    with xr.open_dataset(new) as a, xr.open_dataset(old) as b:
        xr.testing.assert_identical(a.load(), b.load())
        xr.testing.assert_identical(a, ds)  # and sweep()'s dataset (created_utc shared)
        assert a.cor.dims == result.spec.dims and a.cor.shape == result.spec.shape


def test_failed_cases_are_nan_in_the_file(tmp_path):
    """NaN (a failed case) is written as NaN, not masked to another value."""
    result = sweep_result(position=[0.6, 0.8], backend="serial", progress=False)
    result.values[1, :] = np.nan
    result.write(tmp_path / "s.nc")
    with xr.open_dataset(tmp_path / "s.nc") as back:
        assert np.isnan(back.cor.values[1]) and back.cor.values[0] == result.values[0, 0]


def test_the_command_line_writes_the_library_s_dataset(tmp_path, capsys):
    out = tmp_path / "s.nc"
    assert main(["sweep", "--position", "0.6,0.8", "--speed", "20,40", "--out", str(out)]) == 0
    capsys.readouterr()
    with xr.open_dataset(out) as cli:
        lib = sweep_result(position=[0.6, 0.8], speed=[20.0, 40.0], progress=False).to_xarray()
        skip = ("created_utc", "run_parameters")
        xr.testing.assert_identical(cli.drop_attrs(), lib.drop_attrs())
        assert {k: v for k, v in cli.attrs.items() if k not in skip} == {
            k: v for k, v in lib.attrs.items() if k not in skip
        }


def test_modes_kept_by_the_engine_are_recorded_not_those_asked():
    """The engine's COR tolerance keeps a few modes per case; every mode without it."""
    pos, speed = np.meshgrid([0.6, 0.8], [20.0, 40.0], indexing="ij")
    batch = impacts(FrameModel.build(standard_frame(), 20), position=pos, speed=speed)
    low, high = int(batch.modes.min()), int(batch.modes.max())
    assert low < high < 40  # so the test tells a range from a number
    r = sweep_result(position=[0.6, 0.8], speed=[20.0, 40.0], backend="serial", progress=False)
    assert r.attrs["modes_kept"] == f"{low} to {high} (per case)"
    assert r.attrs["modes"] == 80  # the request, beside what was kept
    every = sweep_result(position=[0.6, 0.8], tolerance=None, progress=False)
    assert every.attrs["modes_kept"] == simulate(position=0.6).settings()["modes"] == 40


def test_modes_kept_are_those_simulate_reports_as_used():
    options = dict(solver="cvode", modes=10)
    r = sweep_result(position=[0.6, 0.8], backend="serial", progress=False, **options)
    assert r.attrs["modes_kept"] == simulate(position=0.6, **options).settings()["modes"] == 10
    # the law's integrator keeps the modes it needs: modes under a law is refused by both
    # (it used to be taken and ignored, every mode kept)
    law = dict(law="hunt-crossley", modes=10)
    with pytest.raises(InputError, match="modes = 10 is not allowed with solver 'general'"):
        sweep_result(position=[0.6, 0.8], backend="serial", progress=False, **law)
    with pytest.raises(InputError, match="modes = 10 is not allowed with solver 'general'"):
        simulate(position=0.6, **law)


def test_no_modes_under_the_physical_basis():
    r = sweep_result(position=0.6, basis="physical", solver="cvode", progress=False)
    assert r.attrs["modes_kept"] == "none (physical basis)"


@pytest.mark.parametrize("value", [None, True, {"a": 1}])
def test_attributes_netcdf_cannot_hold_are_refused_as_by_xarray(tmp_path, value):
    from fem_racket.outputs.netcdf import write_netcdf

    with pytest.raises(TypeError, match="netCDF attribute a"):
        write_netcdf(tmp_path / "x.nc", {}, {"a": value})
    with pytest.raises(TypeError):
        xr.Dataset(attrs={"a": value}).to_netcdf(tmp_path / "y.nc")
