"""What every paper figure produces: named tables (columns with units), scalar values, a PNG.

A figure is a :class:`FigureSpec`: a ``compute(quick)`` function returning :class:`FigureData`
and the name of its plotting function in :mod:`fem_racket.paper.plots`. :func:`write_figure` writes
``<name>_<table>.csv`` for each table and ``<name>.png`` into an output folder, atomically.
"""

from __future__ import annotations

import csv
import logging
import os
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import numpy as np

from fem_racket.outputs import add_png_provenance, atomic_output, atomic_outputs, provenance
from fem_racket.paper.figures.data import FigureData, FigureSpec

__all__ = [
    "FigureData",
    "FigureSpec",
    "expected_files",
    "write_csv",
    "write_figure",
    "write_figure_into",
]

log = logging.getLogger(__name__)


def expected_files(spec: FigureSpec, out_dir: str | os.PathLike) -> list[Path]:
    """The files :func:`write_figure` will write for ``spec`` (CSV tables, then the PNG)."""
    out = Path(out_dir)
    return [out / f"{spec.name}_{t}.csv" for t in spec.tables] + [out / f"{spec.name}.png"]


def write_csv(
    path: str | os.PathLike, columns: Mapping[str, np.ndarray], *, overwrite: bool = False
) -> Path:
    """Write equal-length ``columns`` (name with unit -> values) as CSV with a header row."""
    with atomic_output(path, overwrite=overwrite) as tmp:
        _write_table(tmp, columns, Path(path).name)
    return Path(path)


def _write_table(path: Path, columns: Mapping[str, np.ndarray], label: str) -> None:
    names = list(columns)
    arrays = [np.asarray(columns[n]) for n in names]
    lengths = {a.shape for a in arrays}
    if len(lengths) != 1 or len(next(iter(lengths))) != 1:
        raise ValueError(f"columns of {label} must be 1-D arrays of one length, got {lengths}")
    with open(path, "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(names)
        for row in zip(*arrays, strict=True):
            w.writerow([_fmt(v) for v in row])


def _fmt(v: object) -> str:
    if isinstance(v, (float, np.floating)):
        return repr(float(v))
    return str(v)


def write_figure(
    spec: FigureSpec,
    data: FigureData,
    out_dir: str | os.PathLike,
    *,
    overwrite: bool = False,
    meta: Mapping[str, Any] | None = None,
) -> list[Path]:
    """Write the tables and the PNG of ``data`` into ``out_dir`` (all or none); returns the
    paths written.

    The PNG carries the provenance ``meta`` (:func:`fem_racket.outputs.provenance`; by default
    one naming the figure) in its text chunks."""
    paths = expected_files(spec, out_dir)
    with atomic_outputs(paths, overwrite=overwrite) as temps:
        write_figure_into(spec, data, temps, meta)
    log.info("wrote %s", ", ".join(p.name for p in paths))
    return paths


def write_figure_into(
    spec: FigureSpec,
    data: FigureData,
    paths: list[Path],
    meta: Mapping[str, Any] | None = None,
) -> None:
    """Write the tables and the PNG of ``data`` to ``paths``, in the order of
    :func:`expected_files` (temporaries of a caller's :func:`fem_racket.outputs.atomic_outputs`:
    no checks here)."""
    from fem_racket.paper import plots

    for table, path in zip(spec.tables, paths[:-1], strict=True):
        _write_table(path, data.tables[table], f"{spec.name}_{table}.csv")
    getattr(plots, spec.plot)(data, paths[-1])
    add_png_provenance(paths[-1], meta or provenance({"figure": spec.name}))
