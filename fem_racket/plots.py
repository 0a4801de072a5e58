"""Matplotlib figures of the paper's analyses, drawn from :class:`~fem_racket.figures.FigureData`.

Each function takes the figure's data and an output path (PNG) and only draws: the numbers come
from :mod:`fem_racket.figures`. matplotlib is imported inside the functions (Agg backend), so
``import fem_racket`` stays light. Axes carry units; titles carry the paper's figure number.
"""

from __future__ import annotations

import os
from typing import TYPE_CHECKING

import numpy as np

from .params import DEFAULT_BALL_MASS, PAPER_EI1

if TYPE_CHECKING:
    from .figures.base import FigureData

__all__ = [
    "ball_string",
    "contact_time_position",
    "cor_position",
    "cor_rigidity",
    "frame_modes",
    "impact_behaviour",
    "modal_terms",
    "system_modes",
]

DPI = 110


def _pyplot():
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def _save(fig, path: str | os.PathLike) -> None:
    fig.savefig(path, dpi=DPI, format="png")
    _pyplot().close(fig)


def _mark(ax, x: float, label: str, color: str) -> None:
    ax.axvline(x, color=color, ls=":", lw=1.2)
    ax.annotate(
        label,
        (x, 1.0),
        xycoords=("data", "axes fraction"),
        xytext=(3, -12),
        textcoords="offset points",
        color=color,
        fontsize=8,
    )


def ball_string(data: FigureData, path: str | os.PathLike) -> None:
    """Figs 2-3 inputs: K_CB and C_CB, clamped COR and contact times against speed."""
    plt = _pyplot()
    c, pts = data.tables["curve"], data.tables["paper_points"]
    v = c["speed [m/s]"]
    fig, ax = plt.subplots(1, 3, figsize=(15, 4.6), layout="constrained")
    ax[0].plot(v, c["K_CB [N/m]"] / 1e4, "C0-", label="interpolation (piecewise power law)")
    ax[0].plot(pts["speed [m/s]"], pts["K_CB [N/m]"] / 1e4, "ko", label="paper, section 2.1.1")
    ax[0].set(
        xlabel="impact speed V_B0 [m/s]",
        ylabel="K_CB [10⁴ N/m]",
        title="(a) ball/string stiffness (Fig. 2)",
    )
    tw = ax[0].twinx()
    tw.plot(v, c["C_CB [N s/m]"], "C1--", label="C_CB (right axis)")
    tw.set_ylabel("C_CB [N s/m]", color="C1")
    h1, l1 = ax[0].get_legend_handles_labels()
    h2, l2 = tw.get_legend_handles_labels()
    ax[0].legend(h1 + h2, l1 + l2, loc="upper left", fontsize=8)
    ax[1].plot(v, c["clamped COR [-]"], "C0-", label=f"eq 2, ζ = {data.values['zeta']:.4f}")
    ax[1].axhline(0.83, color="k", ls=":", label="paper: 0.83 (eq 4)")
    ax[1].set(
        xlabel="impact speed V_B0 [m/s]",
        ylabel="COR, clamped frame [-]",
        ylim=(0, 1),
        title="(b) clamped-frame COR (Fig. 3)",
    )
    ax[1].legend(fontsize=8)
    ax[2].plot(v, c["clamped contact time [s]"] * 1e3, "k-", label="clamped frame, eq 1")
    for i, k in enumerate(k for k in c if k.startswith("free frame")):
        pos = k.split(" at ")[1].split(" [")[0]
        ax[2].plot(v, c[k] * 1e3, f"C{i}--", label=f"free standard frame, {pos}")
    ax[2].set(
        xlabel="impact speed V_B0 [m/s]", ylabel="contact time [ms]", title="(c) contact time"
    )
    ax[2].legend(fontsize=8)
    for a in ax:
        a.grid(alpha=0.3)
    fig.suptitle(data.title + f" (m_B = {DEFAULT_BALL_MASS} kg)")
    _save(fig, path)


def frame_modes(data: FigureData, path: str | os.PathLike) -> None:
    """Fig 4: modes 1-3 with their nodes."""
    plt = _pyplot()
    s, n = data.tables["shapes"], data.tables["nodes"]
    fig, ax = plt.subplots(3, 1, figsize=(8, 7.5), sharex=True, layout="constrained")
    for k in range(3):
        a = ax[k]
        a.plot(s["x/L [-]"], s[f"mode {k + 1} deflection [-]"], "C0-")
        a.axhline(0.0, color="k", lw=0.6)
        sel = n["mode [-]"] == k + 1
        xs = n["node x/L [-]"][sel]
        a.plot(xs, np.zeros_like(xs), "rv", ms=8, label="nodes")
        for xn in xs:
            a.annotate(
                f"{xn:.3f} L",
                (xn, 0.0),
                xytext=(0, 10),
                textcoords="offset points",
                ha="center",
                fontsize=8,
                color="r",
            )
        a.axvline(0.3, color="0.6", ls="--", lw=0.8)
        f = n["frequency [Hz]"][sel][0]
        a.set(ylabel="deflection [-]", ylim=(-1.25, 1.35), title=f"mode {k + 1}: {f:.1f} Hz")
        a.legend(loc="lower left", fontsize=8)
        a.grid(alpha=0.3)
    ax[-1].set_xlabel("position from the grip end x/L [-] (step at 0.3 L, dashed)")
    fig.suptitle(data.title)
    _save(fig, path)


def impact_behaviour(data: FigureData, path: str | os.PathLike) -> None:
    """Figs 5-7: histories and deformed shapes, standard (a), rigid (b), difference (c)."""
    plt = _pyplot()
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
        cmap = plt.get_cmap("viridis")
        for j, tt in enumerate(times):
            m = s_sel & (sh["time [s]"] == tt)
            color = cmap(j / max(len(times) - 1, 1))
            a.plot(
                sh["x [m]"][m] * 1e3,
                sh["deflection [m]"][m] * 1e3,
                color=color,
                label=f"{tt * 1e3:.2f} ms",
            )
            ub = ins["ball displacement [m]"][i_sel][j]
            a.plot(xi, ub * 1e3, "o", color=color, ms=6, mfc="none")
        a.set(
            xlabel="x from the grip end [mm] (o: ball)",
            ylabel="deflection [mm]",
            title=f"{tag}: frame and ball at six instants",
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
            color=plt.get_cmap("viridis")(j / max(len(times) - 1, 1)),
            label=f"{tt * 1e3:.2f} ms",
        )
    a.axvline(xi, color="k", ls=":", lw=1)
    a.set(
        xlabel="x from the grip end [mm] (dotted: impact point)",
        ylabel="deflection difference [mm]",
        title="(c) standard minus rigid deflection (EI1 146 − 9999 N m²)",
    )
    a.grid(alpha=0.3)
    a.legend(fontsize=8, ncol=6)
    fig.suptitle(data.title + " (displacements positive in the ball's incoming direction)")
    _save(fig, path)


def cor_position(data: FigureData, path: str | os.PathLike) -> None:
    """Fig 8: COR against impact position."""
    plt = _pyplot()
    c, v = data.tables["cor"], data.values
    x = c["position [x/L]"]
    fig, ax = plt.subplots(figsize=(9, 6), layout="constrained")
    ax.plot(x, c["COR standard [-]"], "C0-", lw=2, label="standard, EI1 = 146 N m²")
    ax.plot(x, c["COR rigid [-]"], "C3-", lw=2, label="rigid, EI1 = 9999 N m²")
    ax.plot(x, c["COR standard undamped [-]"], "C0--", label="standard, no damping (ζ = 0)")
    ax.plot(x, c["COR rigid undamped [-]"], "C3--", label="rigid, no damping (ζ = 0)")
    ax.plot(
        x[::2],
        c["COR eq 12 rigid undamped [-]"][::2],
        "kx",
        label="rigid closed form, eq 12 (no damping)",
    )
    ax.plot(
        x,
        c["COR standard rigid modes + mode 1 [-]"],
        "C2:",
        lw=2,
        label="standard, rigid modes + mode 1 only",
    )
    _mark(ax, v["node_x_over_l"], f"mode-1 node {v['node_x_over_l']:.3f} L", "C4")
    ax.axhline(0.0, color="k", lw=0.6)
    ax.set(
        xlabel="impact position from the grip end x/L [-] (CG at "
        f"{v['cg_x_over_l']:.3f} L, left of this range)",
        ylabel="coefficient of restitution [-]",
        title=data.title + " (ζ = 0.059 unless noted)",
    )
    ax.grid(alpha=0.3)
    ax.legend(fontsize=9, loc="lower left")
    _save(fig, path)


def contact_time_position(data: FigureData, path: str | os.PathLike) -> None:
    """Fig 9: contact time against impact position."""
    plt = _pyplot()
    c, v = data.tables["contact_time"], data.values
    x = c["position [x/L]"]
    fig, ax = plt.subplots(figsize=(9, 6), layout="constrained")
    ax.plot(
        x,
        c["contact time eq 11 rigid undamped [s]"] * 1e3,
        "k-",
        lw=2.5,
        label="eq 11 (rigid frame, no damping)",
    )
    styles = {
        "standard": "C0o",
        "rigid": "C3s",
        "standard undamped": "C0^",
        "rigid undamped": "C3v",
    }
    labels = {
        "standard": "standard, ζ = 0.059",
        "rigid": "rigid, ζ = 0.059",
        "standard undamped": "standard, ζ = 0",
        "rigid undamped": "rigid, ζ = 0",
    }
    for k, st in styles.items():
        ax.plot(x[::2], c[f"contact time {k} [s]"][::2] * 1e3, st, mfc="none", label=labels[k])
    _mark(ax, v["node_x_over_l"], "mode-1 node", "C4")
    ax.set(
        xlabel="impact position from the grip end x/L [-]",
        ylabel="contact time [ms]",
        title=data.title + " (standard EI1 = 146, rigid 9999 N m²)",
    )
    ax.grid(alpha=0.3)
    ax.legend(fontsize=9)
    _save(fig, path)


def modal_terms(data: FigureData, path: str | os.PathLike) -> None:
    """Fig 11: the terms of eq 13 against time."""
    plt = _pyplot()
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
    _save(fig, path)


def system_modes(data: FigureData, path: str | os.PathLike) -> None:
    """Fig 12: first system modes (frame deflection and ball) at two impact points."""
    plt = _pyplot()
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
    _save(fig, path)


def cor_rigidity(data: FigureData, path: str | os.PathLike) -> None:
    """Fig 13: COR against EI1, a panel per impact point."""
    plt = _pyplot()
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
    _save(fig, path)
