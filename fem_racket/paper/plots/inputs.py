"""Plots of the inputs of the analysis: the ball/string law (Figs 2-3) and the frame's modes (Fig
4)."""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from fem_racket.contact.linear import DEFAULT_BALL_MASS
from fem_racket.paper.plots.common import pyplot

if TYPE_CHECKING:
    from matplotlib.figure import Figure

    from fem_racket.paper.figures.data import FigureData

__all__ = ["ball_string", "frame_modes"]


def ball_string(data: FigureData) -> Figure:
    """Figs 2-3 inputs: K_CB and C_CB, clamped COR and contact times against speed."""
    if data.law:
        return _ball_string_law(data)
    fig, ax, c = _panels(data)
    v = c["speed [m/s]"]
    ax[0].plot(v, c["K_CB [N/m]"] / 1e4, "C0-", label="interpolation (piecewise power law)")
    _stiffness_panel(ax[0], data, "(a) ball/string stiffness (Fig. 2)")
    tw = ax[0].twinx()
    tw.plot(v, c["C_CB [N s/m]"], "C1--", label="C_CB (right axis)")
    tw.set_ylabel("C_CB [N s/m]", color="C1")
    h1, l1 = ax[0].get_legend_handles_labels()
    h2, l2 = tw.get_legend_handles_labels()
    ax[0].legend(h1 + h2, l1 + l2, loc="upper left", fontsize=8)
    _cor_panel(ax[1], v, c["clamped COR [-]"], f"eq 2, ζ = {data.values['zeta']:.4f}")
    ax[2].plot(v, c["clamped contact time [s]"] * 1e3, "k-", label="clamped frame, eq 1")
    return _finish(fig, ax, data, "free standard frame")


def _ball_string_law(data: FigureData) -> Figure:
    """Figs 2-3 under a contact law: its equivalent K_CB, clamped COR and contact times beside
    the paper's linear K_CB, with the paper's 6-3 ms for real impacts."""
    fig, ax, c = _panels(data)
    v = c["speed [m/s]"]
    ax[0].plot(v, c["equivalent K_CB [N/m]"] / 1e4, "C0-", label=f"{data.law}: m_B (π/T_c)²")
    ax[0].plot(v, c["paper K_CB [N/m]"] / 1e4, "k:", label="paper's interpolation")
    _stiffness_panel(ax[0], data, "(a) equivalent ball/string stiffness (Fig. 2)")
    ax[0].legend(loc="upper left", fontsize=8)
    _cor_panel(ax[1], v, c["clamped COR [-]"], data.law)
    ax[2].axhspan(3.0, 6.0, color="0.9", label="paper: 6-3 ms for real impacts")
    ax[2].plot(v, c["paper clamped contact time [s]"] * 1e3, "k:", label="paper's K_CB, clamped")
    ax[2].plot(v, c["clamped contact time [s]"] * 1e3, "k-", label=f"{data.law}, clamped")
    return _finish(fig, ax, data, f"{data.law}, free standard frame")


def _panels(data: FigureData) -> tuple[Figure, np.ndarray, dict[str, np.ndarray]]:
    """The figure of Figs 2-3, its three panels (a)-(c) and the table of its curves."""
    fig, ax = pyplot().subplots(1, 3, figsize=(15, 4.6), layout="constrained")
    return fig, ax, data.tables["curve"]


def _stiffness_panel(ax, data: FigureData, title: str) -> None:
    """Panel (a), after its curves: the paper's K_CB points (section 2.1.1) and the labels."""
    pts = data.tables["paper_points"]
    ax.plot(pts["speed [m/s]"], pts["K_CB [N/m]"] / 1e4, "ko", label="paper, section 2.1.1")
    ax.set(xlabel="impact speed V_B0 [m/s]", ylabel="K_CB [10⁴ N/m]", title=title)


def _cor_panel(ax, v: np.ndarray, cor: np.ndarray, label: str) -> None:
    """Panel (b): the clamped frame's COR against speed, with the paper's 0.83."""
    ax.plot(v, cor, "C0-", label=label)
    ax.axhline(0.83, color="k", ls=":", label="paper: 0.83 (eq 4)")
    ax.set(
        xlabel="impact speed V_B0 [m/s]",
        ylabel="COR, clamped frame [-]",
        ylim=(0, 1),
        title="(b) clamped-frame COR (Fig. 3)",
    )
    ax.legend(fontsize=8)


def _finish(fig: Figure, ax, data: FigureData, free_label: str) -> Figure:
    """Panel (c)'s free-frame contact times and labels, grids and the title."""
    c = data.tables["curve"]
    for i, k in enumerate(k for k in c if k.startswith("free frame")):
        pos = k.split(" at ")[1].split(" [")[0]
        ax[2].plot(c["speed [m/s]"], c[k] * 1e3, f"C{i}--", label=f"{free_label}, {pos}")
    ax[2].set(
        xlabel="impact speed V_B0 [m/s]", ylabel="contact time [ms]", title="(c) contact time"
    )
    ax[2].legend(fontsize=8)
    for a in ax:
        a.grid(alpha=0.3)
    fig.suptitle(data.title + f" (m_B = {DEFAULT_BALL_MASS} kg)")
    return fig


def frame_modes(data: FigureData) -> Figure:
    """Fig 4: modes 1-3 with their nodes."""
    plt = pyplot()
    s, n = data.tables["shapes"], data.tables["nodes"]
    fig, ax = plt.subplots(3, 1, figsize=(8, 7.5), sharex=True, layout="constrained")
    for k in range(3):
        a = ax[k]
        xc, yc = s["x/L [-]"], s[f"mode {k + 1} deflection [-]"]
        a.plot(xc, yc, "C0-")
        a.axhline(0.0, color="k", lw=0.6)
        sel = n["mode [-]"] == k + 1
        xs = n["node x/L [-]"][sel]
        a.plot(xs, np.zeros_like(xs), "rv", ms=8, label="nodes")
        slope = np.interp(xs, xc, np.gradient(yc, xc))
        for xn, sl in zip(xs, slope, strict=True):
            # The curve crosses zero rising (or falling): its upper-left (upper-right) is free.
            a.annotate(
                f"{xn:.3f} L",
                (xn, 0.0),
                xytext=(-5, 7) if sl > 0 else (5, 7),
                textcoords="offset points",
                ha="right" if sl > 0 else "left",
                fontsize=8,
                color="r",
                bbox={"boxstyle": "square,pad=0.1", "fc": "white", "ec": "none", "alpha": 0.8},
            )
        a.axvline(0.3, color="0.6", ls="--", lw=0.8)
        f = n["frequency [Hz]"][sel][0]
        a.set(ylabel="deflection [-]", ylim=(-1.25, 1.35), title=f"mode {k + 1}: {f:.1f} Hz")
        a.legend(loc="lower left", fontsize=8)
        a.grid(alpha=0.3)
    ax[-1].set_xlabel("position from the grip end x/L [-] (step at 0.3 L, dashed)")
    fig.suptitle(data.title)
    return fig
