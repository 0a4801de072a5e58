"""Shared plotting helpers: matplotlib on the Agg backend, position markers.

matplotlib is imported inside :func:`pyplot`, so ``import fem_racket`` stays light. The plot
functions return their figure; :func:`fem_racket.paper.figures.base.write_figure` saves it
(PNG, SVG or PDF at any resolution, with the provenance:
:func:`fem_racket.io.figure_files.save_figure`).
"""

from __future__ import annotations

__all__ = ["mark_position", "pyplot"]


def pyplot():
    """matplotlib.pyplot on the non-interactive Agg backend."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def mark_position(ax, x: float, label: str, color: str) -> None:
    """A dotted vertical line at ``x`` labelled at the top of the axes."""
    ax.axvline(x, color=color, ls=":", lw=1.2)
    ax.annotate(
        label,
        (x, 1.0),
        xycoords=("data", "axes fraction"),
        xytext=(3, -12),
        textcoords="offset points",
        color=color,
        fontsize=8,
    )
