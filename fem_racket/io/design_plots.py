"""Figures of design studies: progress, e_A / v_out maps, Pareto front, Sobol indices.

matplotlib is imported inside the functions (Agg backend).
"""

from __future__ import annotations

import os

import numpy as np

from fem_racket.studies.design.problem import DesignProblem
from fem_racket.studies.design.variables import OBJECTIVES, sense

__all__ = ["plot_map", "plot_pareto", "plot_progress", "plot_sobol", "zoom_limits"]

DPI = 110


def _pyplot():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def _save(fig, path: str | os.PathLike) -> None:
    fig.savefig(path, dpi=DPI, format="png")
    _pyplot().close(fig)


def feasible(problem: DesignProblem, names: list[str], outputs: np.ndarray) -> np.ndarray:
    """Mask of the rows of ``outputs`` meeting every constraint to its tolerance."""
    ok = np.ones(len(outputs), dtype=bool)
    for c in problem.constraints:
        ok &= c.violation(outputs[:, names.index(c.name)]) <= c.tolerance
    return ok


def plot_progress(result, path: str | os.PathLike) -> None:
    """Objective of every evaluated design and the best feasible one so far, per batch."""
    plt = _pyplot()
    p = result.problem
    names = result.evaluator.names
    _, y, batch = result.evaluator.arrays()
    name = p.objectives[0]
    f = y[:, names.index(name)]
    ok = feasible(p, names, y)
    fig, ax = plt.subplots(figsize=(7, 4))
    ax.plot(batch[~ok], f[~ok], ".", color="0.8", ms=3, label="infeasible design")
    ax.plot(batch[ok], f[ok], ".", color="tab:blue", ms=3, alpha=0.5, label="feasible design")
    s = sense(name)  # best = largest s f
    best = np.full(batch.max() + 1, np.nan)
    run = -np.inf
    for b in range(batch.max() + 1):
        sel = ok & (batch == b)
        if sel.any():
            run = max(run, (s * f[sel]).max())
        best[b] = s * run if np.isfinite(run) else np.nan
    ax.step(np.arange(best.size), best, where="post", color="tab:red", label="best feasible")
    ax.axhline(result.start_objective, color="k", ls="--", lw=1, label="starting racket")
    ax.set_xlabel("batch (iteration or generation)")
    ax.set_ylabel(OBJECTIVES[name])
    ax.set_title(f"{result.method}: {len(f)} designs")
    ax.legend(fontsize=8)
    fig.tight_layout()
    _save(fig, path)


def plot_map(problem: DesignProblem, maps: dict, path: str | os.PathLike) -> None:
    """e_A and v_out along the frame of the optimum (solid) and the starting racket (dashed).

    ``maps`` holds ``"start"`` and ``"optimum"``: lists of
    :class:`~fem_racket.studies.racket_map.RacketMap`, one per ball speed; the optimum's mode-1
    node and (with a swing) maximum v_out at the first speed are marked.
    """
    plt = _pyplot()
    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    colors = plt.rcParams["axes.prop_cycle"].by_key()["color"]
    z = problem.zone.positions
    for ax, key, label in (
        (axes[0], "apparent_cor", "apparent COR e_A [-]"),
        (axes[1], "ball_speed_out", "ball speed v_out [m/s]"),
    ):
        ax.axvspan(z[0], z[-1], color="0.93", label="impact zone")
        for k, v in enumerate(problem.speeds):
            c = colors[k % len(colors)]
            for which, style in (("start", "--"), ("optimum", "-")):
                m = maps[which][k]
                ax.plot(m.positions, getattr(m, key), style, color=c, label=f"{which}, {v:g} m/s")
        ax.set_xlabel("impact position x/L [-]")
        ax.set_ylabel(label)
        spots = maps["optimum"][0].spots
        marks = [(spots.node, "node")]
        if problem.swing is not None:
            marks.append((spots.max_ball_speed, "max v_out"))
        for x, text in marks:
            if np.isfinite(x):
                ax.axvline(x, color="k", ls=":", lw=1)
                ax.annotate(
                    f"{text} (optimum)",
                    (x, 0.02),
                    xycoords=("data", "axes fraction"),
                    fontsize=8,
                    rotation=90,
                )
    axes[0].legend(fontsize=7)
    swing = (
        "stationary racket"
        if problem.swing is None
        else (
            f"swing {problem.swing.head_speed:g} m/s at {problem.swing.reference:g} L with the "
            "starting racket"
        )
    )
    fig.suptitle(f"Optimum vs starting racket ({swing})")
    fig.tight_layout()
    _save(fig, path)


#: The front gets a zoomed panel when it spans less than this fraction of the designs' range in
#: each objective.
ZOOM_BELOW = 0.25


def zoom_limits(front: np.ndarray, cloud: np.ndarray) -> np.ndarray | None:
    """Limits ``[[x0, x1], [y0, y1]]`` of the zoomed panel of a Pareto front (two objectives
    per row), or None when there is nothing to zoom into: a front of one point, or one spanning
    :data:`ZOOM_BELOW` or more of the ``cloud``'s (every design's) range in an objective. The
    margin is 15 % of the front's extent, or 2 % of the cloud's along an objective where the
    front has none."""
    span, whole = np.ptp(front, axis=0), np.ptp(cloud, axis=0)
    if not (np.any(span > 0) and np.all(span < ZOOM_BELOW * whole)):
        return None
    pad = np.where(span > 0, 0.15 * span, 0.02 * whole)
    return np.column_stack([front.min(axis=0) - pad, front.max(axis=0) + pad])


def plot_pareto(result, path: str | os.PathLike) -> None:
    """Every evaluated design, the Pareto front (zoomed in a second panel when it is small),
    and EI(x), rhoA(x) of three front designs."""
    plt = _pyplot()
    p = result.problem
    names = result.evaluator.names
    _, y, _ = result.evaluator.arrays()
    k0, k1 = names.index(p.objectives[0]), names.index(p.objectives[1])
    ok = feasible(p, names, y)
    f = result.pareto_f
    s0 = [result.start_outputs[o] for o in p.objectives[:2]]
    cloud = np.vstack([y[:, [k0, k1]], [s0]])
    limits = zoom_limits(f[:, :2], cloud)
    zoom = limits is not None
    fig, axes = plt.subplots(1, 4 if zoom else 3, figsize=(18 if zoom else 14, 4.2))
    picks = sorted({0, len(f) // 2, len(f) - 1})
    colors = ["tab:blue", "tab:green", "tab:purple"]
    for ax in axes[: 2 if zoom else 1]:
        ax.plot(y[~ok, k0], y[~ok, k1], ".", color="0.85", ms=3, label="infeasible")
        ax.plot(y[ok, k0], y[ok, k1], ".", color="0.55", ms=3, label="feasible")
        ax.plot(f[:, 0], f[:, 1], "o-", color="tab:red", ms=4, label="Pareto front")
        ax.plot(*s0, "k*", ms=12, label="starting racket")
        for c, i in zip(colors, picks, strict=False):
            ax.plot(f[i, 0], f[i, 1], "s", color=c, ms=8, mfc="none", mew=2)
        ax.set_xlabel(OBJECTIVES[p.objectives[0]])
        ax.set_ylabel(OBJECTIVES[p.objectives[1]])
    axes[0].legend(fontsize=7)
    if zoom:
        axes[1].set_xlim(*limits[0])
        axes[1].set_ylim(*limits[1])
        axes[1].set_title("the front, zoomed", fontsize=9)
        axes[1].locator_params(axis="x", nbins=5)
        axes[1].ticklabel_format(useOffset=False)  # the values themselves, not "1e-11+0.229"
        axes = axes[[0, 2, 3]]
    for c, i in zip(colors, picks, strict=False):
        mesh = p.mesh(result.pareto_x[i])
        xs = np.repeat(mesh.points, 2)[1:-1] / mesh.length
        axes[1].plot(xs, np.repeat(mesh.EI, 2), color=c)
        axes[2].plot(xs, np.repeat(mesh.rhoA, 2), color=c)
    start = p.mesh(p.x_start)
    xs = np.repeat(start.points, 2)[1:-1] / start.length
    axes[1].plot(xs, np.repeat(start.EI, 2), "k--", label="start")
    axes[2].plot(xs, np.repeat(start.rhoA, 2), "k--", label="start")
    axes[1].set_yscale("log")
    axes[1].set_ylabel("EI [N m^2]")
    axes[2].set_ylabel("rhoA [kg/m]")
    for ax in axes[1:]:
        ax.set_xlabel("x/L [-]")
        ax.legend(fontsize=7)
    fig.suptitle(f"NSGA-II Pareto front: {len(f)} design{'s' if len(f) != 1 else ''}")
    fig.tight_layout()
    _save(fig, path)


def plot_sobol(indices, path: str | os.PathLike) -> None:
    """First-order and total Sobol indices with their 95 % confidence half-widths."""
    plt = _pyplot()
    n = len(indices.names)
    pos = np.arange(n)
    fig, ax = plt.subplots(figsize=(max(5, 0.8 * n + 2), 4))
    ax.bar(pos - 0.2, indices.s1, 0.4, yerr=indices.s1_conf, label="first order S1", capsize=3)
    ax.bar(pos + 0.2, indices.st, 0.4, yerr=indices.st_conf, label="total ST", capsize=3)
    ax.set_xticks(pos, indices.names)
    ax.set_ylabel("Sobol index [-]")
    ax.set_title(f"Sensitivity of {indices.output} ({indices.designs} designs)")
    ax.legend(fontsize=8)
    fig.tight_layout()
    _save(fig, path)
