"""Spin-map outputs: netCDF (dims racket, offset, position), CSV (+ JSON sidecar) and a PNG of
filled contours of the outgoing spin and angle inside the head outline.

The maps of :func:`fem_racket.studies.spin_map.spin_map` (``fem-racket map --angle``); several
rackets must share one grid. Every file is written atomically with its provenance
(:mod:`fem_racket.outputs`), as the e_A face maps (:mod:`fem_racket.io.face_files`).
"""

from __future__ import annotations

import json
import os
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

import numpy as np

from fem_racket.io.face_grid import shared_grid, write_cells_csv
from fem_racket.io.figure_files import save_map_png
from fem_racket.outputs import (
    atomic_output,
    provenance,
)
from fem_racket.studies.spin_map import SpinMap, map_fields

__all__ = ["write_spin_map"]

#: The fields drawn in the PNG, in rows (and the side spin when the ball crosses the face).
DRAWN = ("spin_out_rpm", "angle_out_deg")
#: The CSV's columns of :func:`fem_racket.studies.spin_map.map_fields`, in its order.
CSV_COLUMNS = {
    "spin_out_rpm": "spin out [rpm]",
    "angle_out_deg": "angle out [deg]",
    "ball_speed_out_m_s": "ball speed out [m/s]",
    "side_spin_out_rpm": "side spin out [rpm]",
    "side_angle_out_deg": "side angle out [deg]",
    "racket_yaw_rate_rad_s": "racket yaw rate [rad/s]",
}


def _netcdf(maps: Sequence[SpinMap], path: Path, parameters: Mapping[str, Any] | None) -> None:
    from fem_racket.outputs.netcdf import write_netcdf

    x, y = shared_grid(maps)
    dims = ("racket", "offset", "position")
    variables: dict[str, Any] = {
        key: (dims, np.stack([m.fields[key] for m in maps]), {"units": u, "long_name": text})
        for key, (u, text) in map_fields(maps[0].incidence).items()
    }
    variables["racket"] = (("racket",), [m.name for m in maps], {"long_name": "racket"})
    variables["offset"] = (("offset",), y, {"units": "m", "long_name": "lateral offset"})
    variables["position"] = (("position",), x, {"units": "x/L", "long_name": "impact point"})
    inc = maps[0].incidence.summary()
    attrs: dict[str, Any] = {"rackets": " ".join(m.name for m in maps)}
    attrs.update({k: float(v) for k, v in inc.items()}, speed_m_s=maps[0].speed)
    prov = provenance(parameters)
    attrs.update({k: v for k, v in prov.items() if k != "parameters"})
    attrs["run_parameters"] = json.dumps(prov.get("parameters", {}), sort_keys=True, default=str)
    with atomic_output(path, overwrite=True) as tmp:
        write_netcdf(tmp, variables, attrs)


def _png(maps: Sequence[SpinMap], path: Path, parameters: Mapping[str, Any] | None) -> None:
    from matplotlib.figure import Figure

    n = len(maps)
    inc = maps[0].incidence
    drawn = (*DRAWN, "side_spin_out_rpm") if inc.lateral else DRAWN
    fig = Figure(figsize=(max(2.4 * n + 1.4, 5.2), 3.9 * len(drawn) + 0.4), layout="constrained")
    axes = np.atleast_2d(fig.subplots(len(drawn), n, squeeze=False))
    t = np.linspace(0.0, 2.0 * np.pi, 200)
    for row, key in enumerate(drawn):
        values = np.stack([m.fields[key] for m in maps])
        lo, hi = np.nanmin(values), np.nanmax(values)
        levels = np.linspace(lo, hi if hi > lo else lo + 1.0, 15)
        for col, m in enumerate(maps):
            ax = axes[row, col]
            h, L = m.head, m.length
            X, Y = m.offsets * 100, m.positions * L * 100  # cm: y across, x up the page
            cs = ax.contourf(X, Y, m.fields[key].T, levels=levels, cmap="coolwarm")
            ax.plot(50 * h.width_m * np.cos(t), 100 * h.centre_m + 50 * h.length_m * np.sin(t), "k")
            ax.set_aspect("equal")
            ax.set_xlabel("offset y [cm]")
            ax.set_title(m.name, fontsize=9)
        axes[row, 0].set_ylabel("x from the butt [cm]")
        fig.colorbar(cs, ax=list(axes[row]), label=map_fields(inc)[key][1], shrink=0.9)
    side = f"\nside angle {inc.side_angle:g} deg, side spin {inc.side_spin:g} rpm"
    fig.suptitle(
        f"ball at {maps[0].speed:g} m/s, {inc.angle:g} deg from the normal, spin "
        f"{inc.spin:g} rpm, friction {inc.friction:g}{side if inc.lateral else ''}",
        fontsize=9,
    )
    with atomic_output(path, overwrite=True) as tmp:
        save_map_png(fig, tmp, parameters)


def _cell_row(m: SpinMap, j: int, i: int) -> list[Any] | None:
    vals = [m.fields[k][j, i] for k in m.fields]
    if not np.isfinite(vals[0]):
        return None
    x, y = m.positions[i], m.offsets[j]
    return [m.name, *(repr(float(a)) for a in (x, y, *vals)), m.regimes[j, i]]


def _csv(maps: Sequence[SpinMap], path: Path, parameters: Mapping[str, Any] | None) -> None:
    cols = ["racket", "position [x/L]", "offset [m]"]
    cols += [CSV_COLUMNS[k] for k in maps[0].fields] + ["contact regime [-]"]
    write_cells_csv(
        maps, path, cols, _cell_row, summary_key="spin_map", parameters=parameters, overwrite=True
    )


def write_spin_map(
    maps: Sequence[SpinMap],
    path: str | os.PathLike,
    *,
    parameters: Mapping[str, Any] | None = None,
) -> Path:
    """Write the spin maps to ``path``: .nc (netCDF), .csv (+ ``<file>.json``) or .png (the
    caller has checked the paths; an existing file is replaced)."""
    path = Path(path)
    writer = {".png": _png, ".csv": _csv}.get(path.suffix.lower(), _netcdf)
    writer(maps, path, parameters)
    return path
