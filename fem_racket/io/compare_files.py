"""Files of ``compare``: a one-page figure (PNG, SVG or PDF) and netCDF of the maps.

The figure: a table of every racket's numbers (and B - A), e_A and v_out along the frame with
the power regions shaded and the best points marked, and the difference curves of each racket
minus the first. The netCDF: the maps of :func:`fem_racket.io.map_files.map_dataset` (dims
racket, position) plus ``apparent_cor_difference`` and ``ball_speed_out_difference_m_s`` (dims
difference, position: each racket after the first minus the first), every scalar of the report
as a variable over racket (NaN where undefined) and, with face maps, ``apparent_cor_face`` and
``ball_speed_out_face_m_s`` (racket, offset, position) with their ``_difference`` (difference,
offset, position). With face maps the figure's bottom row shows the face maps' differences.
"""

from __future__ import annotations

import os
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

import numpy as np

from fem_racket.io.figure_files import FIGURE_FORMATS, fill_figure
from fem_racket.io.map_files import map_dataset
from fem_racket.outputs import Target, atomic_outputs, check_targets, provenance
from fem_racket.studies.compare import Report
from fem_racket.validation import InputError

__all__ = [
    "COMPARE_OUTPUT",
    "COMPARE_SUFFIXES",
    "ROWS",
    "check_compare_outputs",
    "compare_figure",
    "write_compare",
]

#: Where ``fem-racket compare`` writes its figure unless told (``--out``), replacing the figure an
#: earlier compare wrote there.
COMPARE_OUTPUT = Path("output") / "compare.png"

#: Suffixes compare writes: a figure or netCDF.
COMPARE_SUFFIXES = tuple(f".{f}" for f in FIGURE_FORMATS) + (".nc",)
#: Rows of the table: value key -> (label, factor, digits).
ROWS = {
    "mass_kg": ("mass [g]", 1e3, 1),
    "balance_m": ("balance [cm]", 1e2, 2),
    "swing_weight_kg_cm2": ("swing weight [kg cm^2]", 1.0, 1),
    "twist_weight_kg_cm2": ("twistweight [kg cm^2]", 1.0, 2),
    "f1_hz": ("f1 [Hz]", 1.0, 1),
    "torsion_f1_hz": ("torsion f1 [Hz]", 1.0, 1),
    "ball_mass_kg": ("ball [g]", 1e3, 1),
    "node_x_over_l": ("mode-1 node [x/L]", 1.0, 3),
    "max_apparent_cor_x_over_l": ("max e_A at [x/L]", 1.0, 3),
    "max_apparent_cor": ("max e_A [-]", 1.0, 3),
    "max_ball_speed_out_m_s": ("max v_out [m/s]", 1.0, 2),
    "power_region_length_m": ("power region [cm]", 1e2, 1),
    "power_area_cm2": ("power area [cm^2]", 1.0, 0),
    "contact_time_s": ("contact time [ms]", 1e3, 3),
    "handle_shock_rms_n": ("handle shock RMS [N]", 1.0, 1),
    "peak_grip_force_n": ("peak grip force [N]", 1.0, 1),
}


def _targets(paths: Sequence[str | os.PathLike]) -> list[Target]:
    """The files of ``paths``, suffixes checked."""
    for path in map(Path, paths):
        if path.suffix.lower() not in COMPARE_SUFFIXES:
            raise InputError(
                f"output = '{path}' is not allowed: must end in {', '.join(COMPARE_SUFFIXES)}"
            )
    return [Target(Path(p)) for p in paths]


def check_compare_outputs(
    paths: Sequence[str | os.PathLike], *, overwrite: bool = False
) -> list[Path]:
    """``paths`` if compare can write them: suffixes, destinations and no path given twice,
    checked before the work."""
    return [t.path for t in check_targets(_targets(paths), overwrite=overwrite)]


def _cell(value: float | None, factor: float, digits: int, signed: bool = False) -> str:
    if value is None:
        return "-"
    return f"{value * factor:{'+' if signed else ''}.{digits}f}"


def table_rows(reports: Sequence[Report], diffs: Mapping[str, Mapping[str, Any]]) -> list[list]:
    """The table: a row per :data:`ROWS` key, a column per racket and per difference."""
    values = [r.values() for r in reports]
    rows = []
    for key, (label, factor, digits) in ROWS.items():
        row = [label] + [_cell(v[key], factor, digits) for v in values]
        row += [_cell(d[key], factor, digits, signed=True) for d in diffs.values()]
        rows.append(row)
    return rows


def compare_figure(reports: Sequence[Report], diffs: Mapping[str, Mapping[str, Any]]) -> Any:
    """The one-page figure (module docstring): a matplotlib ``Figure``, laid out."""
    from matplotlib.figure import Figure

    fig = Figure(figsize=(8.27, 11.69))
    grid = fig.add_gridspec(4, 2, height_ratios=[1.6, 1.0, 1.0, 1.0])
    ax_t = fig.add_subplot(grid[0, :])
    ax_t.axis("off")
    names = [r.map.name for r in reports]
    cols = ["", *names, *(f"{n}\n- {names[0]}" for n in diffs)]
    n = len(cols) - 1
    tab = ax_t.table(
        cellText=table_rows(reports, diffs),
        colLabels=cols,
        colWidths=[0.26] + [0.74 / n] * n,
        loc="center",
    )
    tab.auto_set_font_size(False)
    tab.set_fontsize(7)
    for (row, _), cell in tab.get_celld().items():
        cell.set_height(0.085 if row == 0 else 0.058)
    ax_e, ax_v = fig.add_subplot(grid[1, :]), fig.add_subplot(grid[2, :], sharex=None)
    ax_de, ax_dv = fig.add_subplot(grid[3, 0]), fig.add_subplot(grid[3, 1])
    for k, r in enumerate(reports):
        c, m = f"C{k}", r.map
        ax_e.plot(m.positions, m.apparent_cor, color=c, label=m.name)
        ax_v.plot(m.positions, m.ball_speed_out, color=c, label=m.name)
        ax_v.axvspan(*m.spots.power_region, color=c, alpha=0.12)
        best = m.spots.max_apparent_cor
        ax_e.plot([best], [np.interp(best, m.positions, m.apparent_cor)], "o", color=c)
        if np.isfinite(m.spots.node):
            for ax in (ax_e, ax_v):
                ax.axvline(m.spots.node, color=c, ls=":", lw=1)
    x = reports[0].map.positions
    faces = reports[0].face is not None
    for k, (name, d) in enumerate([] if faces else diffs.items(), start=1):
        label = f"{name} - {names[0]}"
        ax_de.plot(x, d["apparent_cor_curve"], color=f"C{k}", label=label)
        ax_dv.plot(x, d["ball_speed_out_curve_m_s"], color=f"C{k}", label=label)
    for ax in (ax_de, ax_dv):
        ax.axhline(0.0, color="k", lw=0.6)
        ax.set_xlabel("impact point x/L [-]")
    ax_e.set_ylabel("apparent COR e_A [-]")
    ax_v.set_ylabel("ball speed out v_out [m/s]")
    ax_v.set_xlabel("impact point x/L from the butt [-] (dotted: mode-1 nodes; dots: max e_A)")
    ax_de.set_ylabel("difference in e_A [-]")
    ax_dv.set_ylabel("difference in v_out [m/s]")
    if faces:  # the face maps' differences instead of the axis's
        _face_differences(fig, ax_de, ax_dv, reports, diffs)
    m0 = reports[0].map
    ax_e.set_title(
        f"ball at {m0.speed:g} m/s; shaded: power region (v_out >= "
        f"{round(100 * m0.spots.power_fraction)} % of its max)",
        fontsize=9,
    )
    for ax in (ax_e, ax_v, ax_de, ax_dv):
        ax.grid(alpha=0.3)
        if ax.get_legend_handles_labels()[0]:
            ax.legend(fontsize=7, loc="best")
    fig.tight_layout()
    return fig


def _face_differences(fig: Any, ax_e: Any, ax_v: Any, reports: Sequence[Report], diffs) -> None:
    """Filled contours of the first difference's e_A and v_out over the face (y [m] against
    x/L), the head outline drawn."""
    face = reports[0].face
    name, d = next(iter(diffs.items()))
    for ax, key, text in (
        (ax_e, "apparent_cor_face", "e_A"),
        (ax_v, "ball_speed_out_face_m_s", "v_out [m/s]"),
    ):
        z = d[key]
        top = float(np.nanmax(np.abs(z))) if np.any(np.isfinite(z)) else 0.0
        top = top or 1.0
        levels = np.linspace(-top, top, 17)
        cs = ax.contourf(face.positions, face.offsets, z, levels=levels, cmap="RdBu_r")
        fig.colorbar(cs, ax=ax, shrink=0.9)
        ax.set_ylabel("offset y [m] (line: the long axis)")
        ax.set_title(f"difference in {text}: {name} - {reports[0].map.name}", fontsize=8)


def _dataset(
    reports: Sequence[Report],
    diffs: Mapping[str, Mapping[str, Any]],
    parameters: Mapping[str, Any] | None,
) -> Any:
    ds = map_dataset([r.map for r in reports], parameters)
    ds = ds.assign_coords(
        difference=("difference", [f"{n} - {reports[0].map.name}" for n in diffs])
    )
    for var, key, unit in (
        ("apparent_cor_difference", "apparent_cor_curve", "1"),
        ("ball_speed_out_difference_m_s", "ball_speed_out_curve_m_s", "m/s"),
    ):
        data = np.array([d[key] for d in diffs.values()], dtype=float)
        ds[var] = (("difference", "position"), data, {"units": unit})
    if reports[0].face is not None:
        faces = [r.face for r in reports]
        ds = ds.assign_coords(offset=("offset", faces[0].offsets, {"units": "m"}))
        dims = ("racket", "offset", "position")
        for key, attr, unit in (
            ("apparent_cor_face", "apparent_cor", "1"),
            ("ball_speed_out_face_m_s", "ball_speed_out", "m/s"),
        ):
            ds[key] = (dims, np.stack([getattr(f, attr) for f in faces]), {"units": unit})
            data = np.array([d[key] for d in diffs.values()], dtype=float)
            ds[f"{key}_difference"] = (("difference", "offset", "position"), data)
    values = [r.values() for r in reports]
    for key in values[0]:
        column = [np.nan if v[key] is None else v[key] for v in values]
        ds[key] = ("racket", np.array(column, dtype=float))
    return ds


def write_compare(
    reports: Sequence[Report],
    diffs: Mapping[str, Mapping[str, Any]],
    paths: Sequence[str | os.PathLike],
    *,
    overwrite: bool = False,
    parameters: Mapping[str, Any] | None = None,
) -> list[Path]:
    """Write the figure (.png, .svg, .pdf) and/or the netCDF (.nc) to every one of ``paths``
    as one set: all of them or, on any fault, none (:func:`fem_racket.outputs.atomic_outputs`)."""
    targets = _targets(paths)
    with atomic_outputs(targets, overwrite=overwrite) as temps:
        for t, tmp in zip(targets, temps, strict=True):
            suffix = t.path.suffix.lower()
            if suffix == ".nc":
                _dataset(reports, diffs, parameters).to_netcdf(tmp)
            else:
                fig = compare_figure(reports, diffs)
                fill_figure(fig, tmp, suffix[1:], provenance(parameters))
    return [t.path for t in targets]
