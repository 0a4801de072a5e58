"""Shared plotting helpers: matplotlib on the Agg backend, saving, position markers.

matplotlib is imported inside :func:`pyplot`, so ``import fem_racket`` stays light.
"""

from __future__ import annotations

import os

__all__ = ["DPI", "mark_position", "pyplot", "save_figure"]

#: Resolution of the saved PNGs [dots per inch].
DPI = 110


def pyplot():
    """matplotlib.pyplot on the non-interactive Agg backend."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def save_figure(fig, path: str | os.PathLike) -> None:
    """Save ``fig`` as a PNG at ``path`` and close it."""
    fig.savefig(path, dpi=DPI, format="png")
    pyplot().close(fig)


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
