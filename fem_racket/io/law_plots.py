"""Plots of a contact law: force-deflection loops and force histories on a rigid support."""

from __future__ import annotations

import os
from collections.abc import Sequence
from pathlib import Path
from typing import Any

import numpy as np

from fem_racket.outputs import add_png_provenance, atomic_output

__all__ = ["plot_law_loops"]


def plot_law_loops(
    histories: Sequence[tuple[np.ndarray, np.ndarray, np.ndarray]],
    speeds: Sequence[float],
    path: str | os.PathLike,
    *,
    title: str,
    meta: dict[str, Any],
    overwrite: bool = False,
) -> Path:
    """Two panels, one curve per speed: force against deflection, and force against time.

    ``histories``: (time [s], deflection [m], force [N]) per speed, e.g. from
    :func:`fem_racket.studies.calibrate.clamped_histories`.
    """
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(9.0, 3.6))
    for (t, d, f), v in zip(histories, speeds, strict=True):
        ax1.plot(1e3 * d, f, label=f"{v:g} m/s")
        ax2.plot(1e3 * t, f, label=f"{v:g} m/s")
    ax1.set_xlabel("deflection [mm]")
    ax1.set_ylabel("contact force [N]")
    ax1.set_title("force-deflection loops")
    ax2.set_xlabel("time [ms]")
    ax2.set_ylabel("contact force [N]")
    ax2.set_title("force histories")
    for ax in (ax1, ax2):
        ax.grid(True, alpha=0.3)
        ax.legend(fontsize=7)
    fig.suptitle(title, fontsize=9)
    fig.tight_layout()
    with atomic_output(path, overwrite=overwrite) as tmp:
        fig.savefig(tmp, dpi=100, format="png")
        add_png_provenance(tmp, meta)
    plt.close(fig)
    return Path(path)
