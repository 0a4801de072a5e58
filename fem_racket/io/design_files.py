"""The files of a design study, written into one folder atomically, each with its provenance.

``write_study(result, "out/")`` writes:

- ``optimum.vtu``, ``start.vtu``: the best and the starting racket as mesh files (``--mesh``);
- ``result.json``: objective and start_objective, every output of both, the variables with
  bounds, each constraint with value, bounds and whether it holds, the optimum's mass
  properties, modes and sweet spots, the solver's report, provenance;
- ``history.nc``: every evaluated design (variables and outputs, batch index) as netCDF;
- ``progress.png`` and ``map.png`` (e_A and v_out of optimum vs start), and for a Pareto front
  ``pareto.png``; PNGs carry the provenance in text chunks.
"""

from __future__ import annotations

import json
import os
from pathlib import Path
from typing import Any

import numpy as np

from fem_racket.io.design_plots import plot_map, plot_pareto, plot_progress
from fem_racket.io.mesh_files import write_mesh
from fem_racket.outputs import add_png_provenance, atomic_folder, check_output_folder, provenance
from fem_racket.studies.design.report import design_maps, racket_report
from fem_racket.studies.design.variables import OBJECTIVES, QUANTITIES

__all__ = ["MARKER", "check_study_folder", "history_dataset", "study_summary", "write_study"]

#: File that marks a folder as a design study's (``--overwrite`` replaces only such folders).
MARKER = "result.json"


def check_study_folder(path: str | os.PathLike, *, overwrite: bool = False) -> Path:
    """Check the output folder before the study runs (see :func:`fem_racket.outputs`)."""
    return check_output_folder(path, overwrite=overwrite, marker=MARKER)


def _finite(v: float) -> float | None:
    return float(v) if np.isfinite(v) else None


def study_summary(result, maps: dict | None = None) -> dict[str, Any]:
    """The content of ``result.json`` (without provenance); ``maps``: the optimum's and the
    start's :func:`~fem_racket.studies.design.report.design_maps` if already computed."""
    p = result.problem
    maps = maps or {}
    data: dict[str, Any] = {
        "objective_name": p.objectives[0],
        "objective": result.objective,
        "start_objective": result.start_objective,
        "gain": result.objective - result.start_objective,
        "method": result.method,
        "success": result.success,
        "message": result.message,
        "iterations": result.iterations,
        **result.evaluator.describe(),
        "variables": [
            {
                "name": v.name,
                "value": float(x),
                "start": float(s),
                "low": v.low,
                "high": v.high,
                "unit": v.unit,
            }
            for v, x, s in zip(p.variables, result.x, result.x_start, strict=True)
        ],
        "constraints": [
            {**c, "low": _finite(c["low"]), "high": _finite(c["high"])}
            for c in result.constraints()
        ],
        "outputs": result.outputs,
        "start_outputs": result.start_outputs,
        "units": {**{k: v[0] for k, v in QUANTITIES.items()}, **OBJECTIVES},
        "optimum": racket_report(p, result.x, maps.get("optimum")),
        "start": racket_report(p, result.x_start, maps.get("start")),
        "problem": p.describe(),
    }
    if result.pareto_f is not None:
        data["pareto"] = {
            "objectives": list(p.objectives),
            "designs": [
                {
                    "variables": dict(zip(p.names, map(float, x), strict=True)),
                    "objectives": list(map(float, f)),
                }
                for x, f in zip(result.pareto_x, result.pareto_f, strict=True)
            ],
        }
    return data


def history_dataset(result, attrs: dict[str, Any]) -> Any:
    """Every evaluated design as an :class:`xarray.Dataset` (dimension ``evaluation``)."""
    import xarray as xr

    p = result.problem
    x, y, batch = result.evaluator.arrays()
    data = {"batch": ("evaluation", batch, {"long_name": "batch (iteration or generation)"})}
    for k, v in enumerate(p.variables):
        data[v.name] = ("evaluation", x[:, k], {"units": v.unit, "long_name": "design variable"})
    for k, name in enumerate(result.evaluator.names):
        label = QUANTITIES[name][0] if name in QUANTITIES else OBJECTIVES[name]
        data[name] = ("evaluation", y[:, k], {"long_name": label})
    flat = {
        k: (json.dumps(v, default=str) if isinstance(v, (dict, list)) else v)
        for k, v in attrs.items()
    }
    return xr.Dataset(data, coords={"evaluation": np.arange(len(x))}, attrs=flat)


def write_study(
    result,
    folder: str | os.PathLike,
    *,
    overwrite: bool = False,
    parameters: dict[str, Any] | None = None,
) -> Path:
    """Write the study's files (module docstring) into ``folder``; returns the folder."""
    p = result.problem
    meta = provenance(parameters)
    maps = {"start": design_maps(p, result.x_start), "optimum": design_maps(p, result.x)}
    summary = study_summary(result, maps)
    with atomic_folder(folder, overwrite=overwrite, marker=MARKER) as tmp:
        write_mesh(p.mesh(result.x), tmp / "optimum.vtu")
        write_mesh(p.mesh(result.x_start), tmp / "start.vtu")
        attrs = {k: v for k, v in meta.items() if k != "parameters"}
        attrs["parameters"] = meta.get("parameters", {})
        attrs["problem"] = p.describe()
        history_dataset(result, attrs).to_netcdf(tmp / "history.nc")
        plot_progress(result, tmp / "progress.png")
        plot_map(p, maps, tmp / "map.png")
        pngs = ["progress.png", "map.png"]
        if result.pareto_f is not None:
            plot_pareto(result, tmp / "pareto.png")
            pngs.append("pareto.png")
        for name in pngs:
            add_png_provenance(tmp / name, meta)
        text = json.dumps({**summary, "provenance": meta}, indent=2, default=str)
        (tmp / MARKER).write_text(text + "\n", encoding="utf-8")
    return Path(folder)
