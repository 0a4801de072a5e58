"""Outgoing spin and angle against incidence angle, for two friction values (README, "Oblique
impacts and spin").

A ball at 25 m/s without spin strikes a clamped head (eqs 1-3) and the free standard racket at
0.75 L (exact solver), at 0-85 deg from the face normal, with friction 0.2 and 0.4 (ball on
strings ~0.4, Cross 2003) and the defaults of fem_racket.impact.incidence (I/(m R^2) = 0.6,
R = 33 mm, eta^2 = 0.14). Writes the figure (PNG, SVG or PDF by suffix) with its provenance.

Run time here: ~8 s (--quick, for the tests: 4 angles, ~2 s).

Usage: python scripts/oblique_spin.py [--out FILE] [--quick] [--overwrite] [--dpi N]
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

import numpy as np

from fem_racket.io.figure_files import save_figure
from fem_racket.outputs import provenance
from fem_racket.paper.figures.script import figure_script_options
from fem_racket.studies.oblique_sweep import oblique_sweep

FRICTIONS = (0.2, 0.4)
SPEED = 25.0


def main(argv: Sequence[str] | None = None) -> Path:
    """Compute the sweeps and write the figure; returns its path."""
    args = figure_script_options(__doc__.splitlines()[0], "output/paper/oblique_spin.png", argv)
    import matplotlib.pyplot as plt

    angles = np.linspace(0, 85, 4) if args.quick else np.arange(0.0, 86.0, 2.5)
    runs = {
        "clamped head": oblique_sweep(
            angles=angles, frictions=FRICTIONS, speed=SPEED, clamped=True
        ),
        "free racket, 0.75 L": oblique_sweep(
            angles=angles, frictions=FRICTIONS, speed=SPEED, position=0.75
        ),
    }
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(11, 4.2), layout="constrained")
    for (name, sweep), style in zip(runs.items(), ("-", "--"), strict=True):
        for k, (mu, colour) in enumerate(zip(FRICTIONS, ("C0", "C3"), strict=True)):
            label = f"{name}, mu = {mu:g}"
            ax1.plot(angles, sweep["spin_out_rpm"][:, 0, k], style, color=colour, label=label)
            ax2.plot(angles, sweep["angle_out_deg"][:, 0, k], style, color=colour, label=label)
    ax2.plot(angles, angles, ":", color="0.5", label="angle out = angle in")
    ax1.set(
        xlabel="incidence angle from the face normal [deg]", ylabel="spin out [rpm] (+ topspin)"
    )
    ax2.set(xlabel="incidence angle from the face normal [deg]", ylabel="angle out [deg]")
    ax1.set_title(f"ball at {SPEED:g} m/s, no incoming spin", fontsize=10)
    ax2.set_title("outgoing angle from the face normal", fontsize=10)
    for ax in (ax1, ax2):
        ax.grid(alpha=0.3)
    ax1.legend(fontsize=8)
    ax2.legend(fontsize=8)
    meta = provenance(
        {
            "script": "scripts/oblique_spin.py",
            "speed_m_s": SPEED,
            "frictions": list(FRICTIONS),
            "angles_deg": angles.tolist(),
        }  # fmt: skip
    )
    path = save_figure(fig, args.out, meta, dpi=args.dpi, overwrite=args.overwrite)
    plt.close(fig)
    return path


if __name__ == "__main__":
    print(main())
