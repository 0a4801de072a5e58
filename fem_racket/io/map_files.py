"""Power-map outputs: netCDF (xarray), CSV (+ JSON sidecar) and a PNG plot with sweet spots.

Each file's format from its suffix (:data:`MAP_SUFFIXES`); the files of one call are written
as one set (all or none, :func:`write_maps`) and each carries the provenance
(:mod:`fem_racket.outputs`): netCDF global attributes, the CSV's sidecar ``<file>.json``, PNG
text chunks. Several rackets share the position grid when they were mapped on the same one; the
dataset's dimensions are (racket, position) and each sweet spot is an attribute holding one
value per racket (NaN where undefined). The contact law (shared by the rackets of one call) is
recorded as ``contact_law`` and ``contact_<parameter>`` attributes, in the CSV's sidecar and in
the plot's title.
"""

from __future__ import annotations

import csv
import json
import os
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

import numpy as np

from fem_racket.io.figure_files import save_map_png
from fem_racket.outputs import (
    Target,
    atomic_outputs,
    check_targets,
    provenance,
    sidecar_path,
)
from fem_racket.outputs.labels import LABELS
from fem_racket.studies.racket_map import RacketMap
from fem_racket.validation import InputError

__all__ = [
    "MAP_SUFFIXES",
    "check_map_outputs",
    "fill_maps",
    "map_dataset",
    "map_figure",
    "map_targets",
    "write_maps",
]

#: Suffixes a map can be written to.
MAP_SUFFIXES = (".nc", ".csv", ".png")
#: Curves: attribute of RacketMap -> variable name (labels: fem_racket.outputs.labels.LABELS).
CURVES = {
    "apparent_cor": "apparent_cor",
    "ball_speed_out": "ball_speed_out_m_s",
    "racket_speed": "racket_speed_at_impact_m_s",
}
#: Sweet spots: SweetSpots attribute -> attribute name (x/L).
SPOTS = {
    "cop": "cop_x_over_l",
    "node": "node_x_over_l",
    "max_apparent_cor": "max_apparent_cor_x_over_l",
    "max_ball_speed": "max_ball_speed_x_over_l",
}


def _same_grid(maps: Sequence[RacketMap]) -> np.ndarray:
    x = maps[0].positions
    for m in maps[1:]:
        if m.positions.shape != x.shape or not np.array_equal(m.positions, x):
            raise InputError("maps = several position grids is not allowed: must share one grid")
    return x


def map_dataset(maps: Sequence[RacketMap], parameters: Mapping[str, Any] | None = None) -> Any:
    """The maps as an :class:`xarray.Dataset` (dims racket, position), sweet spots as attributes."""
    import xarray as xr

    x = _same_grid(maps)
    data = {
        var: (
            ("racket", "position"),
            np.stack([getattr(m, attr) for m in maps]),
            LABELS[var].attrs(),
        )
        for attr, var in CURVES.items()
    }
    coords = {
        "racket": ("racket", [m.name for m in maps]),
        "position": ("position", x, LABELS["position"].attrs()),
    }
    attrs: dict[str, Any] = {
        name: np.array([getattr(m.spots, attr) for m in maps], dtype=float)
        for attr, name in SPOTS.items()
    }
    attrs["power_region_start_x_over_l"] = np.array([m.spots.power_region[0] for m in maps])
    attrs["power_region_end_x_over_l"] = np.array([m.spots.power_region[1] for m in maps])
    attrs["power_fraction"] = maps[0].spots.power_fraction
    attrs["mode1_nodes_x_over_l"] = json.dumps([list(m.spots.mode1_nodes) for m in maps])
    attrs["mode2_nodes_x_over_l"] = json.dumps([list(m.spots.mode2_nodes) for m in maps])
    attrs["ball_speed_m_s"] = maps[0].speed
    attrs["length_m"] = np.array([m.length for m in maps])
    attrs["racket_butt_speed_m_s"] = np.array([m.swing.velocity for m in maps])
    attrs["racket_angular_speed_rad_s"] = np.array([m.swing.omega for m in maps])
    attrs["formula"] = "v_out = e_A v_in + (1 + e_A) v_r (Brody, Cross & Lindsey 2002, ch. 11)"
    attrs.update({f"contact_{k}": v for k, v in maps[0].law_summary().items()})
    prov = provenance(parameters)
    attrs.update({k: v for k, v in prov.items() if k != "parameters"})
    attrs["run_parameters"] = json.dumps(prov.get("parameters", {}), sort_keys=True, default=str)
    return xr.Dataset(data, coords=coords, attrs=attrs)


def _motion(maps: Sequence[RacketMap]) -> str:
    """The swing in words, once for every racket (their angular speeds as a range when the
    rackets' lengths make them differ)."""
    omegas = sorted({round(m.swing.omega, 12) for m in maps})
    sw = maps[0].swing
    if sw.omega != 0.0:
        rate = f"{omegas[0]:.1f}" if len(omegas) == 1 else f"{omegas[0]:.1f}-{omegas[-1]:.1f}"
        who = "racket" if len(maps) == 1 else "rackets"
        return f"{who} turning at {rate} rad/s about {sw.pivot:.3g} m from the butt"
    return f"racket moving at {sw.velocity:.3g} m/s" if sw.velocity else "racket at rest"


def _spots_text(m: RacketMap) -> str:
    """``name: COP 0.739, mode-1 node 0.770, max v_out at 0.799`` (x/L; the spots defined)."""
    s = m.spots
    spots = [("COP", s.cop), ("mode-1 node", s.node), ("max v_out at", s.max_ball_speed)]
    return f"{m.name}: " + ", ".join(f"{k} {v:.3f}" for k, v in spots if np.isfinite(v))


def map_figure(maps: Sequence[RacketMap], *, pyplot: bool = False) -> Any:
    """The maps' figure: e_A (top) and v_out (bottom) along the frame, sweet spots as markers
    and lines named with their positions in the legends (no text on the curves: several
    rackets' labels would overlap).

    Parameters
    ----------
    maps : sequence of RacketMap
        One curve each (:func:`fem_racket.racket_map`).
    pyplot : bool
        Make the figure with pyplot (a notebook then shows it inline); by default a plain
        matplotlib Figure (no global state), as the ``.png`` of :func:`write_maps`.

    Returns
    -------
    matplotlib.figure.Figure
    """
    size = (7.5, 7.4 + 0.25 * len(maps))
    if pyplot:
        import matplotlib.pyplot as plt

        fig = plt.figure(figsize=size, layout="constrained")
    else:
        from matplotlib.figure import Figure  # no pyplot: ~0.2 s less to import

        fig = Figure(figsize=size, layout="constrained")
    from matplotlib.lines import Line2D

    ax1, ax2 = fig.subplots(2, 1, sharex=True)
    for k, m in enumerate(maps):
        c, s = f"C{k}", m.spots
        ax1.plot(
            m.positions,
            m.apparent_cor,
            color=c,
            label=f"{m.name}: max e_A at {s.max_apparent_cor:.3f}",
        )
        ax1.plot(
            [s.max_apparent_cor],
            [np.interp(s.max_apparent_cor, m.positions, m.apparent_cor)],
            "o",
            color=c,
        )
        ax2.plot(m.positions, m.ball_speed_out, color=c, label=_spots_text(m))
        ax2.axvspan(*s.power_region, color=c, alpha=0.12)
        if np.isfinite(s.max_ball_speed):
            y = np.interp(s.max_ball_speed, m.positions, m.ball_speed_out)
            ax2.plot([s.max_ball_speed], [y], "s", color=c)
        for xv, style in ((s.node, ":"), (s.cop, "--")):
            if np.isfinite(xv):
                for ax in (ax1, ax2):
                    ax.axvline(xv, color=c, ls=style, lw=1)
    pct = round(100 * maps[0].spots.power_fraction)
    ax1.set_ylabel("apparent COR e_A [-]")
    ax2.set_ylabel("ball speed out v_out [m/s]")
    ax2.set_xlabel("impact point x/L from the butt [-]")
    law = maps[0].law_summary()["law"]
    name = f" ({maps[0].name})" if len(maps) == 1 else ""
    ax1.set_title(
        f"ball at {maps[0].speed:g} m/s, {_motion(maps)}{name}, {law} contact law\n"
        f"shaded: power region (v_out >= {pct} % of its max)",
        fontsize=9,
    )
    ax1.legend(fontsize=8, loc="lower left")
    keys = [
        Line2D([], [], color="0.3", ls="--", lw=1, label="centre of percussion (COP)"),
        Line2D([], [], color="0.3", ls=":", lw=1, label="mode-1 node"),
        Line2D([], [], color="0.3", marker="s", ls="", label="max v_out"),
    ]
    handles, _ = ax2.get_legend_handles_labels()
    ax2.legend(
        handles=handles + keys,
        fontsize=8,
        loc="upper center",
        bbox_to_anchor=(0.5, -0.14),
        ncol=1,
        frameon=False,
    )
    for ax in (ax1, ax2):
        ax.grid(alpha=0.3)
    return fig


def _write_csv(
    maps: Sequence[RacketMap], tmp: Path, side: Path, parameters: Mapping[str, Any] | None
) -> None:
    cols = [
        "racket",
        "position [x/L]",
        "apparent COR [-]",
        "ball speed out [m/s]",
        "racket speed at impact [m/s]",
    ]
    meta = provenance(parameters)
    meta["sweet_spots"] = {m.name: m.summary(curves=False) for m in maps}
    with open(tmp, "w", newline="", encoding="utf-8") as f:
        w = csv.writer(f)
        w.writerow(cols)
        for m in maps:
            for row in zip(
                m.positions, m.apparent_cor, m.ball_speed_out, m.racket_speed, strict=True
            ):
                w.writerow([m.name, *(repr(float(v)) for v in row)])
    side.write_text(json.dumps(meta, indent=2, default=str) + "\n", encoding="utf-8")


def map_targets(paths: Sequence[str | os.PathLike], name: str = "out") -> list[Target]:
    """Every file writing ``paths`` makes (a CSV's sidecar too), suffixes checked; ``name`` the
    option that named them, for the refusals of :func:`~fem_racket.outputs.check_targets`."""
    targets = []
    for path in map(Path, paths):
        if path.suffix.lower() not in MAP_SUFFIXES:
            raise InputError(
                f"{'output' if name == 'out' else name} = '{path}' is not allowed: must end in "
                f"{', '.join(MAP_SUFFIXES)}"
            )
        targets.append(Target(path, name=name))
        if path.suffix.lower() == ".csv":
            targets.append(Target(sidecar_path(path), name=name))
    return targets


def check_map_outputs(paths: Sequence[str | os.PathLike], *, overwrite: bool = False) -> None:
    """Check every output before the work: suffixes, destinations, no path given twice."""
    check_targets(map_targets(paths), overwrite=overwrite)


def write_maps(
    maps: Sequence[RacketMap],
    paths: Sequence[str | os.PathLike],
    *,
    overwrite: bool = False,
    parameters: Mapping[str, Any] | None = None,
) -> list[Path]:
    """Write the maps to every one of ``paths`` (.nc, .csv + ``<file>.json``, .png) as one set:
    all of them or, on any fault, none (:func:`fem_racket.outputs.atomic_outputs`)."""
    targets = map_targets(paths)
    with atomic_outputs(targets, overwrite=overwrite) as temps:
        fill_maps(maps, targets, temps, parameters)
    return [Path(p) for p in paths]


def fill_maps(
    maps: Sequence[RacketMap],
    targets: Sequence[Target],
    temps: Sequence[Path],
    parameters: Mapping[str, Any] | None = None,
) -> None:
    """Write the maps into the temporaries ``temps`` of ``targets`` (:func:`map_targets`: a
    CSV followed by its sidecar), inside an :func:`~fem_racket.outputs.atomic_outputs` block
    that may hold other outputs of the same set."""
    pending = iter(zip(targets, temps, strict=True))
    for t, tmp in pending:
        suffix = t.path.suffix.lower()
        if suffix == ".png":
            save_map_png(map_figure(maps), tmp, parameters)
        elif suffix == ".csv":
            _write_csv(maps, tmp, next(pending)[1], parameters)
        else:
            map_dataset(maps, parameters).to_netcdf(tmp)
