"""Fig 11 of Kawazoe & Kanda (1997): the terms of eq 13 against time at 0.60 L and the mode-1 node.

Writes the figure's CSV tables (units in the column names) and its figure (PNG, SVG or PDF)
into --out (default output/figures/; `fem-racket reproduce` writes every figure into
output/paper/).

Usage: python scripts/fig11_modal_terms.py [--out DIR] [--quick] [--overwrite]
       [--format png|svg|pdf] [--dpi N]
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

from fem_racket.paper.figures.script import figure_main


def main(argv: Sequence[str] | None = None) -> list[Path]:
    """Compute and write the figure; returns the files written."""
    return figure_main(
        "fig11",
        __doc__.splitlines()[0],
        argv,
        default_out="output/figures",
        runtime="~2-4 s here, mostly start-up; --quick (coarse grids, for tests) about the same",
    )


if __name__ == "__main__":
    main()
