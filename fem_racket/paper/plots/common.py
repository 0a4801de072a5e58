"""Shared plotting helpers: matplotlib on the Agg backend, position markers.

matplotlib is imported inside :func:`pyplot`, so ``import fem_racket`` stays light. The plot
functions return their figure; :func:`fem_racket.paper.figures.base.write_figure` saves it
(PNG, SVG or PDF at any resolution, with the provenance:
:func:`fem_racket.io.figure_files.save_figure`).
"""

from __future__ import annotations

__all__ = ["loss_labels", "mark_position", "plot_title", "pyplot"]


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


def loss_labels(data) -> tuple[str, str]:
    """Legend labels of the curves with and without the ball/string losses: the paper's zeta
    and zeta = 0, or a contact law's name and its elastic counterpart (``data.law``)."""
    if not data.law:
        return "ζ = 0.059", "ζ = 0"
    return data.law, "elastic counterpart"


def plot_title(data) -> str:
    """``data.title`` with a contact law's name (its ending ``", NAME law"``) on its own line."""
    tail = f", {data.law} law"
    if data.law and data.title.endswith(tail):
        return data.title[: -len(tail)] + f"\n{data.law} law"
    return data.title
