"""Plots of COR against frame rigidity (Fig 13)."""

from __future__ import annotations

from typing import TYPE_CHECKING

import numpy as np

from fem_racket.frame.segments import PAPER_EI1
from fem_racket.paper.plots.common import loss_labels, pyplot

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
    lossy, lossless = loss_labels(data)
    # the curves without losses: zeta = 0, or a law's elastic counterpart
    lossfree = c["zeta [-]"] == 0.0 if "zeta [-]" in c else c["elastic counterpart [-]"] == 1.0
    fig, ax = plt.subplots(1, pos.size, figsize=(5.2 * pos.size, 5.2), layout="constrained")
    for a, p in zip(np.atleast_1d(ax), pos, strict=True):
        for i, v in enumerate(speeds):
            for free, ls in ((True, "--"), (False, "-")):
                m = (c["position [x/L]"] == p) & (c["speed [m/s]"] == v) & (lossfree == free)
                if not np.any(m):  # a law without an elastic counterpart
                    continue
                lab = f"{v:g} m/s, " + (lossless if free else lossy)
                ei, cor = c["EI1 [N m^2]"][m], c["COR [-]"][m]
                a.plot(ei, cor, f"C{i}{ls}", label=lab)
                tag = f"{'undamped' if free else 'damped'}_{round(p * 100)}_{round(v)}"
                sat = data.values.get(f"ei_sat_{tag}", np.nan)
                if np.isfinite(sat):
                    a.plot(sat, np.interp(sat, ei, cor), f"C{i}o", mfc="none" if free else None)
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
