"""The figures of Kawazoe & Kanda (1997), each as data (tables with units, scalars) + a figure.

``FIGURES`` maps a short key (``"fig08"``) to its :class:`FigureSpec`; :func:`make_figure`
computes one and writes its CSV tables and its PNG (or SVG, PDF) into an output folder.
"""

from __future__ import annotations

import os
from pathlib import Path

from fem_racket.io.figure_files import DEFAULT_DPI, check_dpi
from fem_racket.paper.figures.base import (
    FigureData,
    FigureSpec,
    expected_files,
    used_settings,
    write_csv,
    write_figure,
    write_figure_into,
)
from fem_racket.paper.figures.histories import FIG_05, FIG_06, FIG_07
from fem_racket.paper.figures.inputs import FIG_02_03, FIG_04
from fem_racket.paper.figures.modal_split import FIG_11, FIG_12
from fem_racket.paper.figures.positions import FIG_08, FIG_09
from fem_racket.paper.figures.rigidity import FIG_13

__all__ = [
    "FIGURES",
    "FigureData",
    "FigureSpec",
    "expected_files",
    "make_figure",
    "used_settings",
    "write_csv",
    "write_figure",
    "write_figure_into",
]

#: Every figure, in the paper's order.
FIGURES: dict[str, FigureSpec] = {
    "fig02_03": FIG_02_03,
    "fig04": FIG_04,
    "fig05": FIG_05,
    "fig06": FIG_06,
    "fig07": FIG_07,
    "fig08": FIG_08,
    "fig09": FIG_09,
    "fig11": FIG_11,
    "fig12": FIG_12,
    "fig13": FIG_13,
}


def make_figure(
    key: str,
    out_dir: str | os.PathLike,
    *,
    quick: bool = False,
    overwrite: bool = False,
    fmt: str = "png",
    dpi: float = DEFAULT_DPI,
) -> tuple[FigureData, list[Path]]:
    """Compute figure ``key`` (a key of :data:`FIGURES`) and write its data and figure.

    Parameters
    ----------
    key : str
        e.g. ``"fig08"``.
    out_dir : path
        Output folder (created if needed).
    quick : bool
        Reduced resolution (coarser grids), for tests.
    overwrite : bool
        Replace existing files; otherwise an existing file is an error, raised before computing.
    fmt : {"png", "svg", "pdf"}
        Format of the figure.
    dpi : float
        Resolution [dots per inch] of a PNG (and of raster parts of an SVG or PDF).

    Returns
    -------
    (FigureData, list of Path)
    """
    from fem_racket.outputs import check_targets
    from fem_racket.validation import check_choice

    spec = FIGURES[check_choice("figure", key, FIGURES)]
    check_dpi(dpi)
    check_targets(expected_files(spec, out_dir, fmt), overwrite=overwrite)
    from fem_racket.outputs import provenance

    data = spec.compute(quick)
    meta = provenance({"figure": spec.name, "quick": quick, "format": fmt, "dpi": dpi})
    meta["used"] = used_settings()
    files = write_figure(spec, data, out_dir, overwrite=overwrite, meta=meta, fmt=fmt, dpi=dpi)
    return data, files
