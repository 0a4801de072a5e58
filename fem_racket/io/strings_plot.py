"""The tension study's files: a CSV table and a figure of e_A and contact time against tension."""

from __future__ import annotations

import csv
import json
from pathlib import Path

import numpy as np

from fem_racket.io.figure_files import save_figure
from fem_racket.outputs import atomic_outputs, provenance, sidecar_path
from fem_racket.studies.strings_sweep import COLUMNS

__all__ = ["write_tension_study"]


def write_tension_study(
    rows: np.ndarray,
    folder: str | Path,
    parameters: dict,
    *,
    name: str = "strings_tension",
    overwrite: bool = False,
) -> list[Path]:
    """Write ``<name>.csv`` (with its provenance sidecar ``<name>.csv.json``) and ``<name>.png``
    (COR and contact time against tension, one line per pattern) into ``folder``; returns the
    paths."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    folder = Path(folder)
    table = folder / f"{name}.csv"
    meta = provenance(parameters)
    with atomic_outputs([table, sidecar_path(table)], overwrite=overwrite) as (tmp, side):
        with open(tmp, "w", newline="") as fh:
            writer = csv.writer(fh)
            writer.writerow(COLUMNS)
            writer.writerows([[repr(float(x)) for x in r] for r in rows])
        side.write_text(json.dumps(meta, indent=1, sort_keys=True, default=str))
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(9.0, 3.8), layout="constrained")
    for mains, crosses in sorted({(int(r[0]), int(r[1])) for r in rows}):
        sel = (rows[:, 0] == mains) & (rows[:, 1] == crosses)
        label = f"{mains}x{crosses}"
        ax1.plot(rows[sel, 2], rows[sel, 3], "o-", ms=3, label=label)
        ax2.plot(rows[sel, 2], rows[sel, 4] * 1e3, "o-", ms=3, label=label)
    ax1.set_xlabel("tension per string [N]")
    ax1.set_ylabel("apparent COR e_A [-]")
    ax2.set_xlabel("tension per string [N]")
    ax2.set_ylabel("contact time [ms]")
    ax1.legend(title="pattern")
    speed, position = parameters.get("speed_m_s"), parameters.get("position_x_l")
    fig.suptitle(f"kawazoe-1997-ball on the strung racket, {speed} m/s at {position} x/L")
    try:
        figure = save_figure(fig, folder / f"{name}.png", meta, overwrite=overwrite)
    finally:
        plt.close(fig)
    return [table, sidecar_path(table), figure]
