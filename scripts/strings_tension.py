"""The string bed: apparent COR and contact time against string tension for two patterns.

The kawazoe-1997-ball strikes the paper's standard racket, strung with nylon on the default
645 cm^2 head, at its centre (0.74 x/L) at 30 m/s; tensions 180-300 N for 16x19 and 18x20.
Writes strings_tension.csv (+ .json provenance) and strings_tension.png into --out (default
output/figures/; the README's figure is output/paper/strings_tension.png).

Usage: python scripts/strings_tension.py [--out DIR] [--quick] [--overwrite]
"""

from __future__ import annotations

import argparse
from collections.abc import Sequence
from pathlib import Path

import numpy as np

from fem_racket.io.strings_plot import write_tension_study
from fem_racket.studies.strings_sweep import tension_sweep

PATTERNS = ("16x19", "18x20")
POSITION = 0.74
SPEED = 30.0


def main(argv: Sequence[str] | None = None) -> list[Path]:
    """Compute the sweep and write its table and figure; returns the files written."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default="output/figures", help="output folder")
    parser.add_argument("--quick", action="store_true", help="3 tensions (for tests)")
    parser.add_argument("--overwrite", action="store_true", help="replace existing files")
    args = parser.parse_args(argv)
    tensions = np.linspace(180.0, 300.0, 3 if args.quick else 13)
    rows = tension_sweep(tensions, PATTERNS, position=POSITION, speed=SPEED)
    params = {
        "patterns": list(PATTERNS),
        "tensions_n": tensions.tolist(),
        "position_x_l": POSITION,
        "speed_m_s": SPEED,
        "ball": "kawazoe-1997-ball",
        "string": "nylon",
    }
    files = write_tension_study(rows, args.out, params, overwrite=args.overwrite)
    for f in files:
        print(f)
    return files


if __name__ == "__main__":
    main()
