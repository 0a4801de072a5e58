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

from fem_racket.outputs import add_png_provenance, atomic_output, check_output_path, provenance
from fem_racket.paper.figures.data import FigureData, FigureSpec

__all__ = ["FigureData", "FigureSpec", "expected_files", "write_csv", "write_figure"]

log = logging.getLogger(__name__)


def expected_files(spec: FigureSpec, out_dir: str | os.PathLike) -> list[Path]:
    """The files :func:`write_figure` will write for ``spec`` (CSV tables, then the PNG)."""
    out = Path(out_dir)
    return [out / f"{spec.name}_{t}.csv" for t in spec.tables] + [out / f"{spec.name}.png"]


def write_csv(
    path: str | os.PathLike, columns: Mapping[str, np.ndarray], *, overwrite: bool = False
) -> Path:
    """Write equal-length ``columns`` (name with unit -> values) as CSV with a header row."""
    names = list(columns)
    arrays = [np.asarray(columns[n]) for n in names]
    lengths = {a.shape for a in arrays}
    if len(lengths) != 1 or len(next(iter(lengths))) != 1:
        raise ValueError(f"columns of {path} must be 1-D arrays of one length, got {lengths}")
    with atomic_output(path, overwrite=overwrite) as tmp, open(tmp, "w", newline="") as fh:
        w = csv.writer(fh)
        w.writerow(names)
        for row in zip(*arrays, strict=True):
            w.writerow([_fmt(v) for v in row])
    return Path(path)


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
    """Write the tables and the PNG of ``data`` into ``out_dir``; returns the paths written.

    The PNG carries the provenance ``meta`` (:func:`fem_racket.outputs.provenance`; by default
    one naming the figure) in its text chunks."""
    from fem_racket.paper import plots

    paths = expected_files(spec, out_dir)
    for p in paths:
        check_output_path(p, overwrite=overwrite)
    for table, path in zip(spec.tables, paths, strict=False):
        write_csv(path, data.tables[table], overwrite=overwrite)
    with atomic_output(paths[-1], overwrite=overwrite) as tmp:
        getattr(plots, spec.plot)(data, tmp)
        add_png_provenance(tmp, meta or provenance({"figure": spec.name}))
    log.info("wrote %s", ", ".join(p.name for p in paths))
    return paths
