"""netCDF-4 files from plain arrays, as ``xarray.Dataset.to_netcdf`` writes them, without xarray.

Building an ``xarray.Dataset`` and writing it costs a command far more than its data: xarray
imports dask and dask.array (and through them scipy) the first time it makes a variable, and
``to_netcdf`` imports dask.distributed, neither avoidable while dask is installed (about 1 s of
the 1.4 s the Fig 13 sweep took on the command line). :func:`write_netcdf` writes the same file
through netCDF4 (the library xarray's default engine uses, a dependency already), so
``xarray.open_dataset`` reads back exactly what the xarray writer gave: the same dimensions,
variables (float64, ``_FillValue`` NaN, no compression, contiguous), their attributes and the
global attributes, set in the same order and by the same calls (a list of strings as
``NC_STRING``, anything else by ``setncattr``).

Call it inside :func:`fem_racket.outputs.atomic_output` for an all-or-nothing file.
"""

from __future__ import annotations

import os
from collections.abc import Mapping
from typing import Any

import numpy as np

__all__ = ["write_netcdf"]

#: One variable: (dimension names, values, attributes).
Variable = tuple[tuple[str, ...], np.ndarray, Mapping[str, Any]]


def _set_attribute(obj: Any, key: str, value: Any) -> None:
    """As xarray's netCDF4 backend: a list of strings as NC_STRING, anything else as given."""
    if isinstance(value, (list, tuple)) and value and all(isinstance(v, str) for v in value):
        obj.setncattr_string(key, value)
    else:
        obj.setncattr(key, value)


def write_netcdf(
    path: str | os.PathLike, variables: Mapping[str, Variable], attrs: Mapping[str, Any]
) -> None:
    """Write ``variables`` and the global ``attrs`` to a new netCDF-4 file ``path``.

    Parameters
    ----------
    path : path
        The file (replaced if it exists; pass a temporary of ``atomic_output``).
    variables : mapping
        Name -> (dimension names, float array of their sizes, attributes), in the order they are
        written; a dimension's coordinate is the variable of its name (an array of strings, such
        as racket names, is written as strings). Dimensions are made in the order first met.
    attrs : mapping
        Global attributes: strings, numbers or lists of them (netCDF cannot hold None, bool or
        a dict; they are refused, as by xarray).

    Raises
    ------
    TypeError
        An attribute value netCDF cannot hold.
    """
    import netCDF4

    for key, value in attrs.items():
        if value is None or isinstance(value, (bool, dict)):
            raise TypeError(f"netCDF attribute {key} = {value!r}: not a string, number or list")
    with netCDF4.Dataset(os.fspath(path), "w", format="NETCDF4") as nc:
        for key, value in attrs.items():  # first, as xarray does
            _set_attribute(nc, key, value)
        for name, (dims, values, var_attrs) in variables.items():
            text = np.asarray(values).dtype.kind in "UO"  # names: strings, as xarray writes them
            values = np.asarray(values, dtype=object if text else float)
            for dim, size in zip(dims, values.shape, strict=True):
                if dim not in nc.dimensions:
                    nc.createDimension(dim, size)
            if text:
                var = nc.createVariable(name, str, dims)
            else:
                var = nc.createVariable(name, "f8", dims, fill_value=np.nan)
                var.set_auto_maskandscale(False)  # NaN is written as NaN, as xarray does
            for key, value in var_attrs.items():
                _set_attribute(var, key, value)
            var[...] = values
