"""Plots of COR and contact time along the frame (Figs 8-9)."""

from __future__ import annotations

from typing import TYPE_CHECKING

from fem_racket.paper.plots.common import loss_labels, mark_position, plot_title, pyplot

if TYPE_CHECKING:
    from matplotlib.figure import Figure

    from fem_racket.paper.figures.data import FigureData

__all__ = ["contact_time_position", "cor_position"]


def cor_position(data: FigureData) -> Figure:
    """Fig 8: COR against impact position."""
    plt = pyplot()
    c, v = data.tables["cor"], data.values
    x = c["position [x/L]"]
    lossy, lossless = loss_labels(data)
    if not data.law:
        lossless = "no damping (ζ = 0)"
    fig, ax = plt.subplots(figsize=(9, 6), layout="constrained")
    ax.plot(x, c["COR standard [-]"], "C0-", lw=2, label="standard, EI1 = 146 N m²")
    ax.plot(x, c["COR rigid [-]"], "C3-", lw=2, label="rigid, EI1 = 9999 N m²")
    if "COR standard undamped [-]" in c:  # a law without an elastic counterpart has none
        ax.plot(x, c["COR standard undamped [-]"], "C0--", label=f"standard, {lossless}")
        ax.plot(x, c["COR rigid undamped [-]"], "C3--", label=f"rigid, {lossless}")
        ax.plot(
            x[::2],
            c["COR eq 12 rigid undamped [-]"][::2],
            "kx",
            label="rigid closed form, eq 12 (no " + ("loss)" if data.law else "damping)"),
        )
    ax.plot(
        x,
        c["COR standard rigid modes + mode 1 [-]"],
        "C2:",
        lw=2,
        label="standard, rigid modes + mode 1 only",
    )
    mark_position(ax, v["node_x_over_l"], f"mode-1 node {v['node_x_over_l']:.3f} L", "C4")
    ax.axhline(0.0, color="k", lw=0.6)
    ax.set(
        xlabel="impact position from the grip end x/L [-] (CG at "
        f"{v['cg_x_over_l']:.3f} L, left of this range)",
        ylabel="coefficient of restitution [-]",
        title=plot_title(data) + ("" if data.law else f" ({lossy} unless noted)"),
    )
    ax.grid(alpha=0.3)
    ax.legend(fontsize=9, loc="lower left")
    return fig


def contact_time_position(data: FigureData) -> Figure:
    """Fig 9: contact time against impact position."""
    plt = pyplot()
    c, v = data.tables["contact_time"], data.values
    x = c["position [x/L]"]
    lossy, lossless = loss_labels(data)
    fig, ax = plt.subplots(figsize=(9, 6), layout="constrained")
    if "contact time eq 11 rigid undamped [s]" in c:
        ax.plot(
            x,
            c["contact time eq 11 rigid undamped [s]"] * 1e3,
            "k-",
            lw=2.5,
            label="eq 11 (rigid frame, no damping)"
            if not data.law
            else "rigid frame, elastic counterpart (closed form)",
        )
    styles = {
        "standard": "C0o",
        "rigid": "C3s",
        "standard undamped": "C0^",
        "rigid undamped": "C3v",
    }
    labels = {
        "standard": f"standard, {lossy}",
        "rigid": f"rigid, {lossy}",
        "standard undamped": f"standard, {lossless}",
        "rigid undamped": f"rigid, {lossless}",
    }
    for k, st in styles.items():
        if f"contact time {k} [s]" not in c:
            continue
        ax.plot(x[::2], c[f"contact time {k} [s]"][::2] * 1e3, st, mfc="none", label=labels[k])
    mark_position(ax, v["node_x_over_l"], "mode-1 node", "C4")
    ax.set(
        xlabel="impact position from the grip end x/L [-]",
        ylabel="contact time [ms]",
        title=plot_title(data) + " (standard EI1 = 146, rigid 9999 N m²)",
    )
    ax.grid(alpha=0.3)
    ax.legend(fontsize=9)
    return fig
