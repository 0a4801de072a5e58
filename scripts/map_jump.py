"""Why the nonlinear power map jumps near 0.963 L: a second contact (README, "Power maps and
sweet spots").

The README's map under the calibrated nonlinear law (``fem-racket map --speed 20 --racket-speed
25 --pivot 0.1 --law kawazoe-1997-nonlinear``) is struck, at each point, at the closing speed
v_in + v_r on the stationary free racket. Near the tip e_A jumps from -0.31 to -0.12 and the
contact time from 4.2 to 7.1 ms between two neighbouring points. The figure shows e_A along the
head and the histories on either side of the jump (0.960 and 0.965 L): the contact force and the
deflection delta = ball - impact point with the law's zero-force set delta_0 of its unloading
branch k2 (delta - delta_0)^n.

Run time here: ~3 s (``--quick``, for the tests: a coarser e_A curve).

Usage: python scripts/map_jump.py [--out FILE] [--quick] [--overwrite] [--dpi N]
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

import numpy as np

import fem_racket as fr
from fem_racket.impact.closing import closing_speed
from fem_racket.impact.swing import Swing
from fem_racket.io.figure_files import save_figure
from fem_racket.outputs import provenance
from fem_racket.paper.figures.script import figure_script_options

LAW = "kawazoe-1997-nonlinear"
#: The README's map: ball at 20 m/s, the racket turning about 0.1 m from the butt with its
#: 0.75 L point at 25 m/s.
SPEED, RACKET_SPEED, PIVOT = 20.0, 25.0, 0.1
#: Either side of the jump [x/L].
SIDES = (0.960, 0.965)


def impact(position: float, solver: str = "general", output_step: float | None = 1e-5) -> object:
    """The map's impact at ``position`` (x/L): the stationary standard racket struck at the
    closing speed of the README's swing under the nonlinear law."""
    length = fr.standard_frame().length
    swing = Swing.from_speed(RACKET_SPEED, length, pivot=PIVOT)
    v = closing_speed(SPEED, swing.speed_at(position * length))
    return fr.simulate(position=position, speed=v, law=LAW, solver=solver, output_step=output_step)


def zero_force_set(result: object) -> float:
    """delta_0 [m] of the unloading branch after the largest deflection of ``result``."""
    law = fr.get_law(LAW)
    delta = result.ball_displacement - result.impact_point_displacement
    return float(delta.max() * (1.0 - (law.k1 / law.k2) ** (1.0 / law.exponent)))


def jump_position(low: float = 0.960, high: float = 0.965, tol: float = 1e-5) -> float:
    """Where the contact time jumps (x/L, to ``tol``): bisection between a point ending at the
    first separation (``low``) and one with a second contact (``high``)."""
    split = 5.5e-3  # [s], between the two branches (about 4 and 7 ms)
    if not impact(low, output_step=None).contact_time < split < impact(high).contact_time:
        raise ValueError(f"no jump between {low} and {high}")
    while high - low > tol:
        mid = 0.5 * (low + high)
        low, high = (
            (mid, high) if impact(mid, output_step=None).contact_time < split else (low, mid)
        )
    return 0.5 * (low + high)


def main(argv: Sequence[str] | None = None) -> Path:
    """Compute the curve and the two histories, write the figure; returns its path."""
    args = figure_script_options(__doc__.splitlines()[0], "output/paper/map_jump.png", argv)
    import matplotlib.pyplot as plt

    grid = np.linspace(0.90, 1.0, 26 if args.quick else 201)
    m = fr.racket_map(speed=SPEED, racket_speed=RACKET_SPEED, pivot=PIVOT, law=LAW, positions=grid)
    x_jump = jump_position()
    fig, (ax0, ax1, ax2) = plt.subplots(3, 1, figsize=(7.5, 9.0), layout="constrained")
    ax0.plot(m.positions, m.apparent_cor, "k-", lw=1)
    ax0.axvline(x_jump, color="0.5", ls="--", lw=1, label=f"jump at {x_jump:.4f} L")
    runs = [impact(x) for x in SIDES]
    for x, c, r in zip(SIDES, ("C0", "C3"), runs, strict=True):
        ax0.plot([x], [r.cor], "o", color=c, label=f"{x:.3f} L: t_c {r.contact_time * 1e3:.2f} ms")
        t = r.t * 1e3
        ax1.plot(t, r.force, color=c, label=f"{x:.3f} L")
        delta = (r.ball_displacement - r.impact_point_displacement) * 1e3
        ax2.plot(t, delta, color=c, label=f"{x:.3f} L: delta")
        ax2.axhline(zero_force_set(r) * 1e3, color=c, ls=":", lw=1, label=f"{x:.3f} L: delta_0")
    ax0.set(xlabel="impact point x/L [-]", ylabel="apparent COR e_A [-]")
    ax0.set_title(
        f"{LAW} law, ball at {SPEED:g} m/s, racket at {RACKET_SPEED:g} m/s at 0.75 L "
        f"turning about {PIVOT:g} m",
        fontsize=9,
    )
    ax1.set(xlabel="time [ms]", ylabel="contact force [N]")
    ax1.set_yscale("symlog", linthresh=1.0)
    ax1.set_title("force: one pulse, then ~0 N while the ball rides on the strings", fontsize=9)
    ax2.set(xlabel="time [ms]", ylabel="deflection delta [mm]")
    second = runs[1].t[np.argmax(np.where(runs[1].t > 4e-3, runs[1].force, 0.0))] * 1e3
    ax2.set_title(
        f"contact ends where delta falls through delta_0: at {SIDES[0]:.3f} L it does "
        f"({runs[0].contact_time * 1e3:.2f} ms); at {SIDES[1]:.3f} L it stays\nabove, and the "
        f"frame swinging back strikes the ball again (force peak at {second:.1f} ms)",
        fontsize=9,
    )
    for ax in (ax0, ax1, ax2):
        ax.grid(alpha=0.3)
        ax.legend(fontsize=8)
    meta = provenance(
        {
            "script": "scripts/map_jump.py",
            "law": LAW,
            "speed_m_s": SPEED,
            "racket_speed_m_s": RACKET_SPEED,
            "pivot_m": PIVOT,
            "positions_x_over_l": list(SIDES),
        }
    )
    path = save_figure(fig, args.out, meta, dpi=args.dpi, overwrite=args.overwrite)
    plt.close(fig)
    return path


if __name__ == "__main__":
    print(main())
