"""Wall time of a power map (e_A and v_out along the frame with sweet spots) and its parts.

Times, in one run: the e_A curve alone (``apparent_cor_along``), the whole ``racket_map``
(curve, nodes, refined maxima) and the command ``fem-racket map`` end to end in a fresh
process (imports, map and PNG), for the standard racket at 20 m/s with a 25 m/s swing about a
hand 0.10 m from the butt; prints a table. On a shared machine wall times are noisy: compare
the rows of one run.

Usage: python scripts/bench_map.py [--points N] [--repeat N] [--quick]
"""

from __future__ import annotations

import argparse
import os
import subprocess
import sys
import tempfile
import time

import numpy as np

from fem_racket import FrameModel
from fem_racket.studies.racket_map import apparent_cor_along, racket_map

SWING = {"speed": 20.0, "racket_speed": 25.0, "pivot": 0.10}


def _best(fn, repeat: int) -> float:
    best = float("inf")
    for _ in range(repeat):
        t0 = time.perf_counter()
        fn()
        best = min(best, time.perf_counter() - t0)
    return best


def main(argv: list[str] | None = None) -> list[dict]:
    """Run the benchmark and print the table; returns its rows."""
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--points", type=int, default=200, help="grid points (default 200)")
    ap.add_argument("--repeat", type=int, default=3, help="best of N (default 3)")
    ap.add_argument("--quick", action="store_true", help="20 points, one repeat, no CLI run")
    args = ap.parse_args(argv)
    points, repeat = (20, 1) if args.quick else (args.points, args.repeat)
    x = np.linspace(0.5, 1.0, points)
    model = FrameModel.build(None, 20)
    model.modes()
    rows = [
        {
            "what": f"e_A curve, {points} points",
            "wall_s": _best(lambda: apparent_cor_along(model, x, SWING["speed"]), repeat),
        },
        {
            "what": f"racket_map, {points} points",
            "wall_s": _best(lambda: racket_map(model, positions=x, **SWING), repeat),
        },
    ]
    if not args.quick:
        with tempfile.TemporaryDirectory() as tmp:
            cmd = [
                sys.executable,
                "-m",
                "fem_racket",
                "map",
                "--speed",
                "20",
                "--racket-speed",
                "25",
                "--pivot",
                "0.1",
                "--positions",
                f"0.5:1.0:{points}",
                "--out",
                os.path.join(tmp, "map.png"),
                "--overwrite",
            ]
            wall = _best(lambda: subprocess.run(cmd, check=True, capture_output=True), repeat)
        rows.append({"what": "fem-racket map end to end (PNG)", "wall_s": wall})
    print(f"{'what':<36} {'wall [s]':>10} {'per point [ms]':>15}")
    for r in rows:
        per = r["wall_s"] / points * 1e3
        print(f"{r['what']:<36} {r['wall_s']:>10.3f} {per:>15.2f}")
    return rows


if __name__ == "__main__":
    main()
