"""Plots of COR against frame rigidity (Fig 13)."""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from fem_racket.frame.segments import PAPER_EI1
from fem_racket.paper.plots.common import pyplot

if TYPE_CHECKING:
    from matplotlib.figure import Figure

    from fem_racket.paper.figures.data import FigureData

__all__ = ["cor_rigidity"]


def cor_rigidity(data: FigureData) -> Figure:
    """Fig 13: COR against EI1, a panel per impact point."""
    plt = pyplot()
    c = data.tables["cor"]
    pos = np.unique(c["position [x/L]"])
    speeds = np.unique(c["speed [m/s]"])
    fig, ax = plt.subplots(1, pos.size, figsize=(5.2 * pos.size, 5.2), layout="constrained")
    for a, p in zip(np.atleast_1d(ax), pos, strict=True):
        for i, v in enumerate(speeds):
            for z, ls in ((0.0, "--"), (None, "-")):
                m = (c["position [x/L]"] == p) & (c["speed [m/s]"] == v)
                m &= (c["zeta [-]"] == 0.0) if z == 0.0 else (c["zeta [-]"] > 0.0)
                lab = f"{v:g} m/s, " + ("ζ = 0" if z == 0.0 else "ζ = 0.059")
                ei, cor = c["EI1 [N m^2]"][m], c["COR [-]"][m]
                a.plot(ei, cor, f"C{i}{ls}", label=lab)
                tag = f"{'undamped' if z == 0.0 else 'damped'}_{round(p * 100)}_{round(v)}"
                sat = data.values.get(f"ei_sat_{tag}", np.nan)
                if np.isfinite(sat):
                    a.plot(sat, np.interp(sat, ei, cor), f"C{i}o", mfc="none" if z == 0.0 else None)
        a.axvline(PAPER_EI1, color="0.5", ls=":", lw=1)
        a.set(
            xscale="log",
            xlabel="EI1 [N m²] (dotted: standard 146; o: saturation)",
            ylabel="coefficient of restitution [-]",
            title=f"impact at {p:.2f} L",
        )
        a.grid(alpha=0.3, which="both")
        a.legend(fontsize=8)
    fig.suptitle(data.title)
    return fig
