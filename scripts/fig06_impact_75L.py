"""Fig 6 of Kawazoe & Kanda (1997): impact behaviour at 0.75 L, 20 m/s, standard and rigid frames.

Writes the figure's CSV tables (units in the column names) and its figure (PNG, SVG or PDF)
into --out (default output/figures/; `fem-racket reproduce` writes every figure into
output/paper/).

Usage: python scripts/fig06_impact_75L.py [--out DIR] [--quick] [--overwrite]
       [--format png|svg|pdf] [--dpi N]
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

from fem_racket.paper.figures.script import figure_main


def main(argv: Sequence[str] | None = None) -> list[Path]:
    """Compute and write the figure; returns the files written."""
    return figure_main(
        "fig06",
        __doc__.splitlines()[0],
        argv,
        default_out="output/figures",
        runtime="~2-4 s here, mostly start-up; --quick (coarse grids, for tests) about the same",
    )


if __name__ == "__main__":
    main()
