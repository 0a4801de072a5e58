"""Reports of a mesh-refinement study: screen table, CSV and a log-log convergence plot.

Every writer takes the output path (written atomically, never silently replaced unless
``overwrite``); only the CLI and scripts default to ``output/``. Provenance
(:func:`fem_racket.outputs.provenance`: version, date, the study's settings and ``parameters``,
and under ``"used"`` what the impacts used: modes kept per mesh, K_CB, zeta, ...) goes into the
figure (PNG, SVG or PDF: :func:`fem_racket.io.figure_files.save_figure`) and, for the CSV, into
the sidecar ``<file>.csv.json``. :func:`write_outputs` writes the CSV, its sidecar and the
figure as one set: all three or none (:func:`refine_targets` lists them, to check before the
study runs).

The table gives each quantity in one unit (t_c and its change in ms). The Richardson estimate
(order 4) is printed only where the three finest meshes show that order (3-5); elsewhere the
line says why it is left out: the changes are at the floor set by the modal truncation and
round-off (~1e-8), or not yet in the asymptotic range.
"""

from __future__ import annotations

import csv
import json
import os
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import numpy as np

from fem_racket.display import plain
from fem_racket.io.figure_files import DEFAULT_DPI, save_figure
from fem_racket.outputs import Target, atomic_outputs, provenance, sidecar_path
from fem_racket.studies.refine import ASYMPTOTIC_ORDERS, RefinementStudy

__all__ = [
    "format_study",
    "plot_studies",
    "refine_targets",
    "study_provenance",
    "write_csv",
    "write_outputs",
]


def refine_targets(csv_path: str | os.PathLike, plot_path: str | os.PathLike) -> list[Target]:
    """The files :func:`write_outputs` writes: the CSV, its sidecar and the figure."""
    csv_path = Path(csv_path)
    return [
        Target(csv_path, name="csv"),
        Target(sidecar_path(csv_path), name="csv"),
        Target(Path(plot_path), name="plot"),
    ]


def write_outputs(
    studies: Mapping[str, RefinementStudy],
    csv_path: str | os.PathLike,
    plot_path: str | os.PathLike,
    *,
    overwrite: bool = False,
    parameters: Mapping[str, Any] | None = None,
    dpi: float = DEFAULT_DPI,
) -> list[Path]:
    """:func:`write_csv` and :func:`plot_studies` as one set: all their files or none."""
    targets = refine_targets(csv_path, plot_path)
    with atomic_outputs(targets, overwrite=overwrite) as (tmp_csv, tmp_side, tmp_plot):
        _write_table(studies, tmp_csv)
        _write_meta(studies, tmp_side, parameters)
        plot_studies(studies, tmp_plot, overwrite=True, parameters=parameters, dpi=dpi)
    return [Path(csv_path), Path(plot_path)]


def study_provenance(
    studies: Mapping[str, RefinementStudy], parameters: Mapping[str, Any] | None = None
) -> dict[str, Any]:
    """Provenance of a study's outputs: its settings plus ``parameters`` (e.g. the options)."""
    first = next(iter(studies.values()))
    settings = {
        "families": list(studies),
        "elements": sorted({int(n) for s in studies.values() for n in s.elements}),
        "positions_x_over_l": first.positions.tolist(),
        "speed_m_s": first.speed,
        "frequencies_compared": int(first.exact_frequencies_hz.size),
        "exact_frequencies_hz": first.exact_frequencies_hz.tolist(),
    }
    meta = provenance({**settings, **(parameters or {})})
    meta["used"] = {
        family: {**s.impact_settings, "modes_per_mesh": s.impact_modes_used.tolist()}
        for family, s in studies.items()
    }
    return meta


def format_study(study: RefinementStudy) -> str:
    """A fixed-width table of one family: errors, orders, COR and contact time, timings."""
    m = study.exact_frequencies_hz.size
    err, orders = study.relative_error, study.observed_order_pairs
    lines = [
        f"{study.family} meshes: exact frequencies [Hz] "
        + ", ".join(f"{f:.6f}" for f in study.exact_frequencies_hz)
    ]
    head = f"{'cells':>6}" + "".join(f" {'err f' + str(k + 1):>10} {'p':>5}" for k in range(m))
    head += f" {'build [s]':>9} {'impact [ms]':>11}"
    lines.append(head)
    for i, n in enumerate(study.elements):
        row = f"{n:>6}"
        for k in range(m):
            p = orders[i - 1, k] if i else np.nan
            row += f" {err[i, k]:>10.3e} {_num(p, '5.2f')}"
        row += f" {study.build_time_s[i]:>9.3f} {study.impact_time_s[i] * 1e3:>11.2f}"
        lines.append(row)
    lines.append(
        f"{'cells':>6} {'x/L':>6} {'COR':>12} {'|dCOR|':>9} {'t_c [ms]':>10} {'|dt_c| [ms]':>11}"
    )
    dc, dt = study.change(study.cor), study.change(study.contact_time_s)
    for j, x in enumerate(study.positions):
        for i, n in enumerate(study.elements):
            lines.append(
                f"{n:>6} {x:>6.3f} {study.cor[i, j]:>12.9f} {_num(dc[i, j], '9.2e')} "
                f"{study.contact_time_s[i, j] * 1e3:>10.6f} {_num(dt[i, j] * 1e3, '11.2e')}"
            )
        lines.append(_richardson_line(study, j))
    return "\n".join(lines)


def _richardson_line(study: RefinementStudy, j: int) -> str:
    """The Richardson row of impact point ``j``, or why it is left out."""
    cor, tc = study.richardson(study.cor)[j], study.richardson(study.contact_time_s)[j]
    p_cor = _num(study.observed_order_of(study.cor)[j], ".2f").strip()
    p_tc = _num(study.observed_order_of(study.contact_time_s)[j], ".2f").strip()
    line = f"{'Richardson':>13} {_num(cor, '12.9f')} {'':>9} {_num(tc * 1e3, '10.6f')}"
    line += f"   (observed order: COR {p_cor}, t_c {p_tc}"
    if np.isfinite(cor) and np.isfinite(tc):
        return line + ")"
    low, high = ASYMPTOTIC_ORDERS
    return line + f": '-' where outside {low:g}-{high:g}, not extrapolated)"


def _num(v: float, fmt: str) -> str:
    width = int(fmt.split(".")[0] or 0)
    return f"{'-':>{width}}" if not np.isfinite(v) else format(v, fmt)


def write_csv(
    studies: Mapping[str, RefinementStudy],
    path: str | os.PathLike,
    *,
    overwrite: bool = False,
    parameters: Mapping[str, Any] | None = None,
) -> Path:
    """One row per family and mesh: frequencies, errors, orders, COR and t_c per impact point.

    The provenance (with ``parameters``) goes to ``<path>.json`` beside it (both files or
    neither)."""
    targets = [Target(Path(path), name="csv"), Target(sidecar_path(path), name="csv")]
    with atomic_outputs(targets, overwrite=overwrite) as (tmp, side):
        _write_table(studies, tmp)
        _write_meta(studies, side, parameters)
    return Path(path)


def _write_meta(
    studies: Mapping[str, RefinementStudy], path: Path, parameters: Mapping[str, Any] | None
) -> None:
    meta = study_provenance(studies, parameters)
    path.write_text(json.dumps(meta, indent=2, default=str) + "\n", encoding="utf-8")


def _write_table(studies: Mapping[str, RefinementStudy], path: Path) -> None:
    rows = []
    for family, s in studies.items():
        m = s.exact_frequencies_hz.size
        orders = np.vstack([np.full((1, m), np.nan), s.observed_order_pairs])
        for i, n in enumerate(s.elements):
            row = {"family": family, "elements": int(n)}
            for k in range(m):
                row[f"f{k + 1}_hz"] = s.frequencies_hz[i, k]
                row[f"f{k + 1}_exact_hz"] = s.exact_frequencies_hz[k]
                row[f"f{k + 1}_relative_error"] = s.relative_error[i, k]
                row[f"f{k + 1}_observed_order"] = orders[i, k]
            for j, x in enumerate(s.positions):
                row[f"cor_at_{x:g}L"] = s.cor[i, j]
                row[f"contact_time_s_at_{x:g}L"] = s.contact_time_s[i, j]
            row["build_time_s"] = s.build_time_s[i]
            row["impact_time_s"] = s.impact_time_s[i]
            rows.append(row)
    fields = list(dict.fromkeys(k for r in rows for k in r))
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=fields)
        w.writeheader()
        for r in rows:
            w.writerow({k: (repr(v) if isinstance(v, float) else v) for k, v in plain(r).items()})


def plot_studies(
    studies: Mapping[str, RefinementStudy],
    path: str | os.PathLike,
    *,
    overwrite: bool = False,
    parameters: Mapping[str, Any] | None = None,
    dpi: float = DEFAULT_DPI,
) -> Path:
    """Log-log plot: frequency errors and COR changes against the number of elements.

    ``path`` ends in .png, .svg or .pdf (``dpi``: resolution [dots per inch]); the figure
    carries the provenance (with ``parameters``). The legends sit below the axes, off the data."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from fem_racket.io.plotting import element_ticks

    styles = {"uniform": "-", "graded": "--"}
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 5.5), layout="constrained")
    for family, s in studies.items():
        ls = styles.get(family, ":")
        for k in range(s.exact_frequencies_hz.size):
            ax1.loglog(
                s.elements,
                np.abs(s.relative_error[:, k]),
                ls,
                marker="o",
                ms=4,
                color=f"C{k}",
                label=f"mode {k + 1}, {family}",
            )
        dc = s.change(s.cor)
        for j, x in enumerate(s.positions):
            ax2.loglog(
                s.elements[1:],
                dc[1:, j],
                ls,
                marker="s",
                ms=4,
                color=f"C{j}",
                label=f"{x:g} L, {family}",
            )
    first = next(iter(studies.values()))
    n = first.elements.astype(float)
    ref = 0.2 * np.abs(first.relative_error[-1, 0]) * (n / n[-1]) ** -4
    ax1.loglog(n, ref, "k-", lw=0.8, label="slope -4")
    ax1.set_ylabel("relative frequency error |f_FE / f_exact - 1| [-]")
    ax1.set_title("Frequencies against the exact stepped beam")
    ax2.set_ylabel("|COR(N) - COR(previous N)| [-]")
    ax2.set_title(f"COR change under refinement ({first.speed:g} m/s)")
    every = np.unique(np.concatenate([s.elements for s in studies.values()]))
    for ax in (ax1, ax2):
        element_ticks(ax, every)
        ax.set_xlabel("elements")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7, ncol=3, loc="upper center", bbox_to_anchor=(0.5, -0.14))
    try:
        save_figure(fig, path, study_provenance(studies, parameters), dpi=dpi, overwrite=overwrite)
    finally:
        plt.close(fig)
    return Path(path)
