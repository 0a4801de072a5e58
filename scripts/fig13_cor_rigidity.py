"""Fig 13 of Kawazoe & Kanda (1997): COR against frame rigidity EI1 at 20, 30 and 40 m/s.

Writes the figure's CSV tables (units in the column names) and its figure (PNG, SVG or PDF)
into --out (default output/figures/; `fem-racket reproduce` writes every figure into
output/paper/).

Usage: python scripts/fig13_cor_rigidity.py [--out DIR] [--quick] [--overwrite]
       [--format png|svg|pdf] [--dpi N]
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

from fem_racket.paper.figures.script import figure_main


def main(argv: Sequence[str] | None = None) -> list[Path]:
    """Compute and write the figure; returns the files written."""
    return figure_main(
        "fig13",
        __doc__.splitlines()[0],
        argv,
        default_out="output/figures",
        runtime="~5 s here (up to ~15 s on a busy machine); --quick (coarse grid, for tests) ~3 s",
    )


if __name__ == "__main__":
    main()
