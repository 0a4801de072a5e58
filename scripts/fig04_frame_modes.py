"""Fig 4 of Kawazoe & Kanda (1997): free-free modes 1-3 of the stepped beam with their nodes.

Writes the figure's CSV tables (units in the column names) and its PNG into --out.

Usage: python scripts/fig04_frame_modes.py [--out DIR] [--quick] [--overwrite]
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

from fem_racket.paper.figures.script import figure_main


def main(argv: Sequence[str] | None = None) -> list[Path]:
    """Compute and write the figure; returns the files written."""
    return figure_main("fig04", __doc__.splitlines()[0], argv, default_out="output/paper")


if __name__ == "__main__":
    main()
