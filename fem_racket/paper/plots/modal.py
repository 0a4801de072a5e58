"""Plots of the modal split of the ball velocity and the coupled modes (Figs 11-12)."""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from fem_racket.paper.plots.common import pyplot

if TYPE_CHECKING:
    from matplotlib.figure import Figure

    from fem_racket.paper.figures.data import FigureData

__all__ = ["modal_terms", "system_modes"]


def modal_terms(data: FigureData) -> Figure:
    """Fig 11: the terms of eq 13 against time."""
    plt = pyplot()
    c = data.tables["terms"]
    pos = np.unique(c["position [x/L]"])
    fig, ax = plt.subplots(1, 2, figsize=(14, 5.5), layout="constrained", sharey=True)
    for a, p, tag in zip(ax, pos, "ab", strict=True):
        m = c["position [x/L]"] == p
        t = c["time [s]"][m] * 1e3
        for i, k in enumerate(k for k in c if k.startswith("V_")):
            a.plot(t, c[k][m], f"C{i}-", label=k.replace(" [m/s]", "").replace("Omega", "Ω"))
        a.plot(t, c["eq 13 sum [m/s]"][m], "k-", lw=2, label="sum (eq 13)")
        a.plot(
            t[::10],
            c["simulated ball velocity, zeta = 0 [m/s]"][m][::10],
            "ko",
            mfc="none",
            label="simulated ball velocity, ζ = 0",
        )
        a.axhline(0.0, color="k", lw=0.6)
        name = f"{p:.2f} L" if abs(p - 0.6) < 1e-9 else f"{p:.4f} L (mode-1 node)"
        a.set(xlabel="time [ms]", ylabel="velocity [m/s]", title=f"({tag}) impact at {name}")
        a.grid(alpha=0.3)
        a.legend(fontsize=8, ncol=2)
    fig.suptitle(data.title)
    return fig


def system_modes(data: FigureData) -> Figure:
    """Fig 12: first system modes (frame deflection and ball) at two impact points."""
    plt = pyplot()
    md, sh = data.tables["modes"], data.tables["shapes"]
    pos = np.unique(md["position [x/L]"])
    nm = int(md["system mode [-]"].max())
    mm = data.values["length_m"] * 1e3  # frame length [mm]
    fig, ax = plt.subplots(nm, 2, figsize=(12, 2.3 * nm + 1), sharex=True, layout="constrained")
    for col, p in enumerate(pos):
        for j in range(nm):
            a = ax[j, col]
            m = (sh["position [x/L]"] == p) & (sh["system mode [-]"] == j + 1)
            r = (md["position [x/L]"] == p) & (md["system mode [-]"] == j + 1)
            a.plot(sh["x [m]"][m] * 1e3, sh["frame deflection [-]"][m], "C0-", label="frame")
            a.plot([p * mm], md["ball amplitude [-]"][r], "ko", ms=9, label="ball")
            a.axhline(0.0, color="k", lw=0.6)
            a.axvline(p * mm, color="0.5", ls=":", lw=1)
            f, vi = md["frequency [Hz]"][r][0], md["V_i [m/s]"][r][0]
            vtxt = f"{vi:.3g}" if vi > 1e-12 else "0"  # below round-off: exactly 0
            name = f"{p:.2f} L" if abs(p - 0.6) < 1e-9 else f"{p:.4f} L (node)"
            a.set(ylim=(-1.2, 1.2), ylabel="amplitude [-]")
            a.set_title(
                f"impact {name}: mode {j + 1}, {f:.1f} Hz, V_{j + 1} = {vtxt} m/s", fontsize=10
            )
            a.grid(alpha=0.3)
            if j == 0:
                a.legend(fontsize=8, loc="lower left")
        ax[-1, col].set_xlabel("x from the grip end [mm] (dotted: impact point)")
    fig.suptitle(data.title + f" (frame alone: {data.values['frame_f1_hz']:.1f} Hz)")
    return fig
