"""Face-map outputs: netCDF (dims racket, offset, position), CSV (+ JSON sidecar) and a PNG of
filled contours inside the head outline.

The maps of :func:`fem_racket.studies.face_map.face_map`; several rackets must share one grid.
Every file is written atomically with its provenance (:mod:`fem_racket.outputs`), as the 1-D
power maps (:mod:`fem_racket.io.map_files`).
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
from fem_racket.io.map_files import check_map_outputs
from fem_racket.outputs import (
    atomic_output,
    provenance,
)
from fem_racket.outputs.labels import LABELS
from fem_racket.studies.face_map import FaceMap

__all__ = ["face_dataset", "face_figure", "write_face"]

#: Attributes of a FaceMap summary stored per racket in the netCDF attributes.
PER_RACKET = (
    "power_area_cm2",
    "max_apparent_cor",
    "max_apparent_cor_x_over_l",
    "max_apparent_cor_offset_m",
    "node_x_over_l",
    "cop_x_over_l",
    "length_m",
)


def face_dataset(maps: Sequence[FaceMap], parameters: Mapping[str, Any] | None = None) -> Any:
    """The face maps as an :class:`xarray.Dataset` (dims racket, offset, position)."""
    import xarray as xr

    x, y = shared_grid(maps)
    dims = ("racket", "offset", "position")
    data = {
        "apparent_cor": (
            dims,
            np.stack([m.apparent_cor for m in maps]),
            {**LABELS["apparent_cor"].attrs(), "comment": "NaN off the face"},
        ),
        "ball_speed_out_m_s": (
            dims,
            np.stack([m.ball_speed_out for m in maps]),
            {**LABELS["ball_speed_out_m_s"].attrs(), "comment": "NaN off the face"},
        ),
    }
    coords = {
        "racket": ("racket", [m.name for m in maps]),
        "offset": ("offset", y, LABELS["offset"].attrs()),
        "position": ("position", x, LABELS["position"].attrs()),
    }
    sums = [m.summary() for m in maps]
    attrs: dict[str, Any] = {k: np.array([s[k] for s in sums], dtype=float) for k in PER_RACKET}
    h = maps[0].head
    attrs.update(
        power_fraction=maps[0].power_fraction,
        head_length_m=h.length_m,
        head_width_m=h.width_m,
        head_centre_x_over_l=h.centre,
        ball_speed_m_s=maps[0].speed,
        racket_butt_speed_m_s=maps[0].swing.velocity,
        racket_angular_speed_rad_s=maps[0].swing.omega,
        formula="1/M_eff = 1/M + b^2/I_cg + y^2/I_p (rigid limit); v_out = e_A v_in + "
        "(1 + e_A) v_r (Brody, Cross & Lindsey 2002)",
    )
    prov = provenance(parameters)
    attrs.update({k: v for k, v in prov.items() if k != "parameters"})
    attrs["run_parameters"] = json.dumps(prov.get("parameters", {}), sort_keys=True, default=str)
    return xr.Dataset(data, coords=coords, attrs=attrs)


def face_figure(maps: Sequence[FaceMap]) -> Any:
    """The PNG's figure: e_A (and v_out with a swing) as filled contours on the face of each
    racket, side by side on one colour scale, with the head outline, the mode-1 node line, the
    COP, the maximum and the power area's boundary."""
    from matplotlib.figure import Figure

    swinging = any(m.swing.velocity or m.swing.omega for m in maps)
    fields = [("apparent_cor", "apparent COR e_A [-]")]
    if swinging:
        fields.append(("ball_speed_out", "ball speed out v_out [m/s]"))
    n = len(maps)
    fig = Figure(figsize=(2.4 * n + 1.4, 3.9 * len(fields) + 0.4), layout="constrained")
    axes = np.atleast_2d(fig.subplots(len(fields), n, squeeze=False))
    t = np.linspace(0.0, 2.0 * np.pi, 200)
    for row, (attr, label) in enumerate(fields):
        values = np.stack([getattr(m, attr) for m in maps])
        levels = np.linspace(np.nanmin(values), np.nanmax(values), 15)
        for col, m in enumerate(maps):
            ax = axes[row, col]
            h, L = m.head, m.length
            X, Y = m.offsets * 100, m.positions * L * 100  # cm: y across, x up the page
            cs = ax.contourf(X, Y, getattr(m, attr).T, levels=levels, cmap="viridis")
            ax.plot(50 * h.width_m * np.cos(t), 100 * h.centre_m + 50 * h.length_m * np.sin(t), "k")
            e = m.apparent_cor
            if attr == "apparent_cor" and np.any(np.isfinite(e)):
                top = m.power_fraction * np.nanmax(e)
                ax.contour(X, Y, e.T, levels=[top], colors="w", linewidths=1.2)
            for xv, style, name in ((m.node, ":", "node"), (m.cop, "--", "COP")):
                if np.isfinite(xv):
                    hw = float(h.half_width(xv * L))
                    hw = hw if np.isfinite(hw) else h.width_m / 2
                    ax.plot([-100 * hw, 100 * hw], [100 * xv * L] * 2, "w" + style, lw=1)
                    ax.annotate(
                        name, (0, 100 * xv * L), xytext=(0, 2), textcoords="offset points",
                        color="w", fontsize=7, ha="center",
                    )  # fmt: skip
            values_m = getattr(m, attr)
            if np.any(np.isfinite(values_m)):  # the field's maximum
                j, i = np.unravel_index(int(np.nanargmax(values_m)), values_m.shape)
                ax.plot([X[j]], [Y[i]], "w*", ms=9)
            ax.set_aspect("equal")
            ax.set_xlabel("offset y [cm]")
            ax.set_title(
                f"{m.name}\npower area {m.power_area_cm2:.0f} cm^2" if row == 0 else m.name,
                fontsize=9,
            )
        axes[row, 0].set_ylabel("x from the butt [cm]")
        fig.colorbar(cs, ax=list(axes[row]), label=label, shrink=0.9)
    pct = round(100 * maps[0].power_fraction)
    fig.suptitle(
        f"ball at {maps[0].speed:g} m/s; white line: e_A = {pct} % of its max (power area)\n"
        "star: maximum; dotted: mode-1 node; dashed: COP",
        fontsize=9,
    )
    return fig


#: The CSV's columns: one row per face point with a result.
_CSV_COLUMNS = (
    "racket",
    "position [x/L]",
    "offset [m]",
    "apparent COR [-]",
    "ball speed out [m/s]",
)


def _cell_row(m: FaceMap, j: int, i: int) -> list[Any] | None:
    x, y = m.positions[i], m.offsets[j]
    e, v = m.apparent_cor[j, i], m.ball_speed_out[j, i]
    if not np.isfinite(e):
        return None
    return [m.name, *(repr(float(a)) for a in (x, y, e, v))]


def write_face(
    maps: Sequence[FaceMap],
    path: str | os.PathLike,
    *,
    overwrite: bool = False,
    parameters: Mapping[str, Any] | None = None,
) -> Path:
    """Write the face maps to ``path``: .nc (netCDF), .csv (+ ``<file>.json``) or .png."""
    check_map_outputs([path], overwrite=overwrite)
    path = Path(path)
    suffix = path.suffix.lower()
    if suffix == ".png":
        fig = face_figure(maps)
        with atomic_output(path, overwrite=overwrite) as tmp:
            save_map_png(fig, tmp, parameters)
        return path
    if suffix == ".csv":
        write_cells_csv(
            maps,
            path,
            _CSV_COLUMNS,
            _cell_row,
            summary_key="face",
            parameters=parameters,
            overwrite=overwrite,
        )
        return path
    ds = face_dataset(maps, parameters)
    with atomic_output(path, overwrite=overwrite) as tmp:
        ds.to_netcdf(tmp)
    return path
