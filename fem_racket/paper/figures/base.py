"""What every paper figure produces: named tables (columns with units), scalar values, a figure.

A figure is a :class:`FigureSpec`: a ``compute(quick)`` function returning :class:`FigureData`
and the name of its plotting function in :mod:`fem_racket.paper.plots`. :func:`write_figure` writes
``<name>_<table>.csv`` for each table and ``<name>.png`` (or ``.svg``, ``.pdf``) into an output
folder, atomically, the figure with its provenance (:mod:`fem_racket.io.figure_files`).
"""

from __future__ import annotations

import csv
import logging
import os
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import numpy as np

from fem_racket.io.figure_files import DEFAULT_DPI, check_figure_format, same_image, save_figure
from fem_racket.outputs import atomic_output, atomic_outputs, provenance
from fem_racket.paper.figures.data import FigureData, FigureSpec

__all__ = [
    "FigureData",
    "FigureSpec",
    "expected_files",
    "used_settings",
    "write_csv",
    "write_figure",
    "write_figure_into",
]

log = logging.getLogger(__name__)


def used_settings(law: Any = None) -> dict[str, Any]:
    """What the paper's figures use, unless their tables say otherwise (the zeta = 0 curves, the
    rigid frame's EI1): the settings of the standard impact as run (solver, modes kept, m_B,
    zeta, ...; :meth:`fem_racket.ImpactResult.settings`) and K_CB at the paper's three speeds;
    under a contact ``law`` (a :class:`~fem_racket.contact.law.ContactLaw`) its name and
    parameters instead of K_CB and zeta. Every figure's provenance records it under ``"used"``."""
    from fem_racket.contact.linear import kcb_from_speed
    from fem_racket.impact.simulate import simulate

    used = simulate(position=0.75, speed=20.0, output_step=None, law=law).settings()
    del used["position_x_over_l"], used["speed_m_s"]
    if law is not None:
        return used
    del used["kcb_n_m"], used["ccb_n_s_m"]
    used["kcb_n_m_at_20_30_40_m_s"] = [kcb_from_speed(v) for v in (20.0, 30.0, 40.0)]
    return used


def expected_files(spec: FigureSpec, out_dir: str | os.PathLike, fmt: str = "png") -> list[Path]:
    """The files :func:`write_figure` will write for ``spec`` (CSV tables, then the figure in
    format ``fmt``: png, svg or pdf)."""
    out = Path(out_dir)
    figure = out / f"{spec.name}.{check_figure_format(fmt)}"
    return [out / f"{spec.name}_{t}.csv" for t in spec.tables] + [figure]


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
    fmt: str = "png",
    dpi: float = DEFAULT_DPI,
    keep_unchanged: bool = False,
) -> list[Path]:
    """Write the tables and the figure of ``data`` into ``out_dir``, all or none; returns the
    paths.

    The figure (``fmt``: png, svg or pdf; ``dpi`` [dots per inch]) carries the provenance
    ``meta`` (:func:`fem_racket.outputs.provenance`; by default one naming the figure). With
    ``keep_unchanged`` an existing PNG whose image would not change is left as it is."""
    paths = expected_files(spec, out_dir, fmt)
    with atomic_outputs(paths, overwrite=overwrite) as temps:
        write_figure_into(spec, data, temps, paths, meta, dpi=dpi, keep_unchanged=keep_unchanged)
    log.info("wrote %s", ", ".join(p.name for p in paths))
    return paths


def write_figure_into(
    spec: FigureSpec,
    data: FigureData,
    temps: list[Path],
    targets: list[Path],
    meta: Mapping[str, Any] | None = None,
    *,
    dpi: float = DEFAULT_DPI,
    keep_unchanged: bool = False,
) -> None:
    """Write the tables and the figure of ``data`` to ``temps``, the temporaries of a caller's
    :func:`fem_racket.outputs.atomic_outputs` for ``targets`` (in the order of
    :func:`expected_files`; no checks here). With ``keep_unchanged`` the figure's temporary is
    removed when the existing target PNG holds the same image, so that it is left as it is."""
    from fem_racket.paper import plots
    from fem_racket.paper.plots.common import pyplot

    for table, path in zip(spec.tables, temps[:-1], strict=True):
        _write_table(path, data.tables[table], f"{spec.name}_{table}.csv")
    fig = getattr(plots, spec.plot)(data)
    try:
        save_figure(
            fig, temps[-1], meta or provenance({"figure": spec.name}), dpi=dpi, overwrite=True
        )
    finally:
        pyplot().close(fig)
    if (
        keep_unchanged
        and temps[-1].suffix == ".png"
        and same_image(targets[-1], temps[-1].read_bytes())
    ):
        temps[-1].unlink()
