"""Plots of impact histories at one position (Figs 5-7)."""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from fem_racket.paper.plots.common import pyplot

if TYPE_CHECKING:
    from matplotlib.figure import Figure

    from fem_racket.paper.figures.data import FigureData

__all__ = ["impact_behaviour"]


def _colour(plt, j: int, n: int):
    """Colour of instant ``j`` of ``n``: viridis up to 0.85, so the last stays visible on white."""
    return plt.get_cmap("viridis")(0.85 * j / max(n - 1, 1))


def impact_behaviour(data: FigureData) -> Figure:
    """Figs 5-7: histories and deformed shapes, standard (a), rigid (b), difference (c)."""
    plt = pyplot()
    h, sh, ins, df = (data.tables[k] for k in ("histories", "shapes", "instants", "difference"))
    eis = np.unique(h["EI1 [N m^2]"])
    fig = plt.figure(figsize=(12, 13), layout="constrained")
    gs = fig.add_gridspec(4, 2)
    points = ("ball", "impact point", "grip end", "top end")
    styles = ("k-", "C3-", "C0--", "C2-.")
    xi = data.values["position_x_over_l"] * data.values["length_m"] * 1e3  # impact point [mm]
    for col, ei in enumerate(sorted(eis)):
        tag = "(a) standard" if col == 0 else "(b) rigid"
        sel = h["EI1 [N m^2]"] == ei
        t = h["time [s]"][sel] * 1e3
        for row, (q, unit, scale) in enumerate(
            (("displacement", "mm", 1e3), ("velocity", "m/s", 1.0))
        ):
            a = fig.add_subplot(gs[row, col])
            for p, st in zip(points, styles, strict=True):
                a.plot(
                    t,
                    h[f"{p} {q} [{'m' if q == 'displacement' else 'm/s'}]"][sel] * scale,
                    st,
                    label=p,
                )
            a.set(
                xlabel="time [ms]", ylabel=f"{q} [{unit}]", title=f"{tag}, EI1 = {ei:g} N m²: {q}"
            )
            a.grid(alpha=0.3)
            a.legend(fontsize=8, ncol=2)
        a = fig.add_subplot(gs[2, col])
        s_sel = sh["EI1 [N m^2]"] == ei
        i_sel = ins["EI1 [N m^2]"] == ei
        times = np.unique(sh["time [s]"][s_sel])
        for j, tt in enumerate(times):
            m = s_sel & (sh["time [s]"] == tt)
            color = _colour(plt, j, len(times))
            end = " (end)" if j == len(times) - 1 else ""
            a.plot(
                sh["x [m]"][m] * 1e3,
                sh["deflection [m]"][m] * 1e3,
                color=color,
                label=f"{tt * 1e3:.2f} ms{end}",
            )
            ub = ins["ball displacement [m]"][i_sel][j]
            a.plot(xi, ub * 1e3, "o", color=color, ms=6, mfc="none")
        a.set(
            xlabel="x from the grip end [mm] (o: ball)",
            ylabel="deflection [mm]",
            title=f"{tag}: frame and ball at six instants of its contact",
        )
        a.grid(alpha=0.3)
        a.legend(fontsize=7, ncol=3)
    a = fig.add_subplot(gs[3, :])
    times = np.unique(df["time [s]"])
    for j, tt in enumerate(times):
        m = df["time [s]"] == tt
        a.plot(
            df["x [m]"][m] * 1e3,
            df["standard minus rigid deflection [m]"][m] * 1e3,
            color=_colour(plt, j, len(times)),
            label=f"{tt * 1e3:.2f} ms",
        )
    a.axvline(xi, color="k", ls=":", lw=1)
    a.set(
        xlabel="x from the grip end [mm] (dotted: impact point)",
        ylabel="deflection difference [mm]",
        title="(c) standard minus rigid deflection (EI1 146 − 9999 N m²) at common times, "
        f"up to the shorter contact ({times[-1] * 1e3:.2f} ms)",
    )
    a.grid(alpha=0.3)
    a.legend(fontsize=8, loc="center left", bbox_to_anchor=(1.0, 0.5))  # off the curves
    fig.suptitle(data.title + " (displacements positive in the ball's incoming direction)")
    return fig
