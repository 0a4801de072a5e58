"""Plotting helpers for notebooks: each draws on a matplotlib Axes and returns it.

- :func:`plot_impact`: one impact's contact force, displacements or velocities against time;
- :func:`plot_refinement`: a refinement study's frequency errors or COR / contact-time changes
  against the number of elements (log-log);
- :func:`plot_sweep`: a swept result (an ``xarray.DataArray`` of :func:`fem_racket.sweep`)
  against one coordinate, one line per value of another, with readable labels: the axes
  ``long_name [units]`` (:mod:`fem_racket.outputs.labels`: "apparent COR e_A [-]"), the lines'
  values rounded (:func:`coordinate_labels`: ``0.617``, not ``0.6166666666666667``).

Pass ``ax`` to draw into an existing figure; without it a new figure (constrained layout, so
no label is clipped) is made. matplotlib is imported inside the functions.

Why the contact force is not zero at t = 0 and negative at the end: F = K_CB delta +
C_CB delta' (the paper's spring-dashpot). At t = 0, delta = 0 but delta' = V_B0, so the dashpot
already pushes with C_CB V_B0. With the paper's end of contact (delta back to zero, the default
``separation="displacement"``) the spring is relaxed at the end while delta' < 0, so the
dashpot pulls: F = C_CB delta'(t_c) < 0. ``separation="force"`` ends the contact where F
returns to zero instead (about 1 % higher COR).
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import TYPE_CHECKING, Any

import numpy as np

from fem_racket.outputs.labels import Label, label

if TYPE_CHECKING:
    from matplotlib.axes import Axes

    from fem_racket.impact.simulate import ImpactResult
    from fem_racket.studies.refine import RefinementStudy

__all__ = [
    "IMPACT_QUANTITIES",
    "coordinate_labels",
    "force_note",
    "plot_impact",
    "plot_refinement",
    "plot_sweep",
]

#: What :func:`plot_impact` can draw.
IMPACT_QUANTITIES = ("force", "displacement", "velocity")
#: What :func:`plot_refinement` can draw.
REFINEMENT_QUANTITIES = ("frequency", "cor", "contact_time")


def _axes(ax: Axes | None, figsize: tuple[float, float] = (7.0, 4.2)) -> Axes:
    if ax is not None:
        return ax
    import matplotlib.pyplot as plt

    _, ax = plt.subplots(figsize=figsize, layout="constrained")
    return ax


def force_note(result: ImpactResult) -> str:
    """Two lines saying why F(0) > 0 and (displacement criterion) F(t_c) < 0."""
    f0 = result.damping * result.impact.speed
    text = f"F(0) = C_CB V_B0 = {f0:.0f} N: the dashpot acts at once"
    if result.separation == "displacement":
        text += (
            f"\nF(t_c) = {result.force[-1]:.0f} N: the dashpot pulls while delta returns to 0"
            "\n(the paper's end of contact; separation='force' ends at F = 0)"
        )
    return text


def plot_impact(result: ImpactResult, quantity: str = "force", *, ax: Axes | None = None) -> Axes:
    """Draw one impact's history against time [ms] and return the Axes.

    Parameters
    ----------
    result : ImpactResult
        A simulation with histories (an ``output_step``).
    quantity : {"force", "displacement", "velocity"}
        Contact force [N] (annotated: why it is not zero at t = 0 and, with the paper's
        criterion, negative at the end); ball and impact-point displacement [mm]; or their
        velocities [m/s].
    ax : matplotlib Axes, optional
    """
    from fem_racket.validation import check_choice

    check_choice("quantity", quantity, IMPACT_QUANTITIES)
    ax = _axes(ax)
    t = result.t * 1e3
    if quantity == "force":
        ax.plot(t, result.force, "k-", label="contact force F = K_CB δ + C_CB δ'")
        ax.axhline(0.0, color="0.5", lw=0.8)
        ax.annotate(
            force_note(result),
            (0.5, 0.04),
            xycoords="axes fraction",
            fontsize=8,
            ha="center",
            va="bottom",
            bbox={"boxstyle": "round", "fc": "white", "ec": "0.7", "alpha": 0.9},
        )
        ax.set_ylabel("contact force [N]")
    else:
        scale, unit = (1e3, "mm") if quantity == "displacement" else (1.0, "m/s")
        ball = result.ball_displacement if quantity == "displacement" else result.ball_velocity
        frame = (
            result.impact_point_displacement
            if quantity == "displacement"
            else result.impact_point_velocity
        )
        ax.plot(t, ball * scale, "k-", label="ball")
        ax.plot(t, frame * scale, "C3-", label="frame at the impact point")
        ax.set_ylabel(f"{quantity} [{unit}] (towards the frame > 0)")
    ax.set_xlabel("time [ms]")
    ax.set_title(
        f"{result.impact.speed:g} m/s at {result.impact.position:g} L: COR {result.cor:.4f}, "
        f"t_c {result.contact_time * 1e3:.3f} ms",
        fontsize=10,
    )
    ax.grid(alpha=0.3)
    ax.legend(fontsize=8, loc="best")
    return ax


def plot_refinement(
    study: RefinementStudy, quantity: str = "frequency", *, ax: Axes | None = None
) -> Axes:
    """Draw a refinement study against the number of elements (log-log); return the Axes.

    Parameters
    ----------
    study : RefinementStudy
    quantity : {"frequency", "cor", "contact_time"}
        Relative frequency errors against the exact beam (one line per mode, with a slope -4
        guide), or the change of COR [-] or contact time [s] from the previous mesh (one line
        per impact point).
    ax : matplotlib Axes, optional
    """
    from fem_racket.validation import check_choice

    check_choice("quantity", quantity, REFINEMENT_QUANTITIES)
    ax = _axes(ax)
    n = study.elements.astype(float)
    if quantity == "frequency":
        for k in range(study.exact_frequencies_hz.size):
            ax.loglog(
                n, np.abs(study.relative_error[:, k]), "-o", ms=4, color=f"C{k}",
                label=f"mode {k + 1} ({study.exact_frequencies_hz[k]:.1f} Hz)",
            )  # fmt: skip
        ref = 0.2 * np.abs(study.relative_error[-1, 0]) * (n / n[-1]) ** -4
        ax.loglog(n, ref, "k-", lw=0.8, label="slope -4")
        ax.set_ylabel("relative frequency error |f_FE / f_exact - 1| [-]")
    else:
        values = study.cor if quantity == "cor" else study.contact_time_s
        change = study.change(values)
        for j, x in enumerate(study.positions):
            ax.loglog(n[1:], change[1:, j], "-s", ms=4, color=f"C{j}", label=f"{x:g} L")
        ax.set_ylabel(
            "|COR(N) - COR(previous N)| [-]"
            if quantity == "cor"
            else "|t_c(N) - t_c(previous N)| [s]"
        )
    element_ticks(ax, n)
    ax.set_xlabel("elements")
    ax.set_title(f"{study.family} meshes", fontsize=10)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    return ax


def element_ticks(ax: Axes, n: np.ndarray) -> None:
    """Label the log x axis with the element counts themselves (5, 10, 20 ...)."""
    from matplotlib.ticker import FixedLocator, NullLocator, ScalarFormatter

    ax.xaxis.set_major_locator(FixedLocator(n))
    ax.xaxis.set_major_formatter(ScalarFormatter())
    ax.xaxis.set_minor_locator(NullLocator())


def coordinate_labels(values: Sequence[float], digits: int = 3) -> list[str]:
    """Short labels for coordinate values: the fewest significant digits (at least ``digits``)
    that keep every value distinct, e.g. ``0.617`` for 0.6166666666666667."""
    vals = [float(v) for v in values]
    for d in range(digits, 18):
        labels = [f"{v:.{d}g}" for v in vals]
        if len(set(labels)) == len(set(vals)):
            return labels
    return [repr(v) for v in vals]


def _label(da: Any) -> Label:
    """A variable's or coordinate's label: its own ``long_name`` and ``units`` (a sweep file's,
    :mod:`fem_racket.outputs.labels`; CF's ``"1"`` shown as ``-``), else the table's entry for
    its name."""
    table = label(str(da.name), str(da.attrs.get("units", "-")))
    if "long_name" not in da.attrs:
        return table
    units = str(da.attrs.get("units", table.units))
    return Label(str(da.attrs["long_name"]), "-" if units in ("1", "") else units)


def _fixed(lab: Label, value: float) -> str:
    """``ball speed v_in = 30 m/s`` (no unit for a dimensionless value)."""
    unit = "" if lab.units == "-" else f" {lab.units}"
    return f"{lab.long_name} = {coordinate_labels([value])[0]}{unit}"


def plot_sweep(
    data: Any, x: str, *, hue: str | None = None, ax: Axes | None = None, **select: Any
) -> Axes:
    """Draw a sweep's variable against coordinate ``x``, one line per value of ``hue``.

    Parameters
    ----------
    data : xarray.DataArray
        One variable of a :func:`fem_racket.sweep` dataset (``ds.cor``).
    x : str
        The swept coordinate on the horizontal axis (log-scaled when its values span more
        than a factor 20, as a ``:log`` grid of EI1).
    hue : str, optional
        Another swept coordinate: one line per value, labelled with :func:`coordinate_labels`.
    ax : matplotlib Axes, optional
    **select
        Values of the remaining coordinates (nearest point), e.g. ``speed=30``.
    """
    from fem_racket.validation import InputError

    da = data.sel(**select, method="nearest") if select else data
    extra = [d for d in da.dims if d not in (x, hue)]
    if extra:
        raise InputError(
            f"dims = {extra} are not allowed: select them (e.g. {extra[0]}=...) or pass hue"
        )
    ax = _axes(ax)
    xs = da[x].values
    lines = [(None, da)] if hue is None else [(v, da.sel({hue: v})) for v in da[hue].values]
    labels = coordinate_labels(da[hue].values) if hue is not None else [None]
    for (_, line), text in zip(lines, labels, strict=True):
        ax.plot(xs, line.transpose(x).values, "-o", ms=3, label=text)
    if xs.size > 1 and xs.min() > 0 and xs.max() / xs.min() > 20:
        ax.set_xscale("log")
    ax.set_xlabel(_label(da[x]).text)
    ax.set_ylabel(_label(da).text)
    fixed = [
        _fixed(_label(da[c]), float(da[c]))
        for c in da.coords
        if da[c].ndim == 0 and c not in (x, hue)
    ]
    if fixed:
        ax.set_title(", ".join(fixed), fontsize=10)
    if hue is not None:
        # Beside the axes, so that it never covers a line.
        ax.legend(
            title=_label(da[hue]).text,
            fontsize=8,
            title_fontsize=8,
            loc="center left",
            bbox_to_anchor=(1.01, 0.5),
        )
    ax.grid(alpha=0.3, which="both")
    return ax
