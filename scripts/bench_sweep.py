"""Sweep throughput: impacts/s of a plain loop of simulate() calls, the serial sweep and the
process pool, for every solver, all measured in one run on the 20-element standard racket.

The exact solver runs the Fig 13 grid of Kawazoe & Kanda (1997): 7 impact points x 3 speeds x
60 EI1 values (1 260 impacts); the BDF solvers, which take ~1 s (CVODE) and several seconds
(scipy) per impact, run a few corners of it. Caches are cleared before each sweep, so nothing
is reused between rows; the pool rows include starting the pool.

Run time here: ~12 minutes in full (the BDF rows dominate; measured on a busy machine);
--quick (small grid, exact and CVODE only, for tests) ~13 s.

Usage: python scripts/bench_sweep.py [--quick]
"""

from __future__ import annotations

import argparse
import logging
import os
import sys
import time

import numpy as np

from fem_racket import FrameModel, simulate, standard_frame, sweep

FIG13 = {"position": "0.55:0.95:7", "speed": "20,30,40", "ei1": "50:3000:60:log"}
#: Grid of each solver: the Fig 13 grid for exact, a few of its corners for the BDF solvers.
GRIDS = {
    "exact": FIG13,
    "cvode": {"position": "0.55,0.95", "speed": "20,40", "ei1": "50,3000"},
    "bdf": {"position": "0.75", "speed": "20,40", "ei1": "146"},
}
QUICK = {
    "exact": {"position": "0.55:0.95:3", "speed": "20,40", "ei1": "50:3000:8:log"},
    "cvode": {"position": "0.75", "speed": "20", "ei1": "146"},
}


def _cases(grid: dict) -> list[tuple[float, ...]]:
    from fem_racket.studies.grid import parse_values

    p, v, e = (np.atleast_1d(parse_values(k, grid[k])) for k in ("position", "speed", "ei1"))
    return [(a, b, c) for a in p for b in v for c in e]


def plain_loop(cases: list, solver: str) -> float:
    """Wall time [s] of simulate(frame) per case, building each frame (what a user writes)."""
    t0 = time.perf_counter()
    for position, speed, ei1 in cases:
        simulate(
            standard_frame(ei1), position=position, speed=speed, solver=solver, output_step=None
        )
    return time.perf_counter() - t0


def reused_loop(cases: list, solver: str) -> float:
    """Wall time [s] of simulate(model.scaled(...)) per case, one assembly and eigen-solve."""
    t0 = time.perf_counter()
    base = FrameModel.build(standard_frame(146.0), 20)
    base.modes()
    for position, speed, ei1 in cases:
        simulate(
            base.scaled(ei1 / 146.0),
            position=position,
            speed=speed,
            solver=solver,
            output_step=None,
        )
    return time.perf_counter() - t0


def sweep_time(grid: dict, solver: str, backend: str) -> float:
    """Wall time [s] of fem_racket.sweep over ``grid``, nothing cached beforehand."""
    from fem_racket.studies.cases import clear_caches

    clear_caches()
    t0 = time.perf_counter()
    sweep(**grid, solver=solver, backend=backend, progress=False)
    return time.perf_counter() - t0


def main(argv: list[str] | None = None) -> list[dict]:
    """Run the benchmark and print the table; returns its rows."""
    ap = argparse.ArgumentParser(
        description=__doc__.splitlines()[0],
        epilog="Run time here: ~12 minutes in full; --quick ~13 s.",
    )
    ap.add_argument(
        "--quick", action="store_true", help="small grid, exact and CVODE only (~13 s, for tests)"
    )
    args = ap.parse_args(argv)
    logging.getLogger("fem_racket").setLevel(logging.WARNING)
    sweep(position=0.75, progress=False)  # warm-up: imports xarray
    rows = []
    for solver, grid in (QUICK if args.quick else GRIDS).items():
        cases = _cases(grid)
        base = plain_loop(cases, solver)
        for method, wall in (
            ("plain loop: simulate(frame)", base),
            ("plain loop: simulate(model reused)", reused_loop(cases, solver)),
            ("sweep, serial", sweep_time(grid, solver, "serial")),
            (
                f"sweep, process pool ({os.cpu_count()} cores)",
                sweep_time(grid, solver, "processes"),
            ),
        ):
            rows.append(
                {
                    "solver": solver,
                    "method": method,
                    "impacts": len(cases),
                    "wall_s": wall,
                    "rate": len(cases) / wall,
                    "speedup": base / wall,
                }
            )
    print(
        f"{'solver':>6}  {'method':<36} {'impacts':>7} {'wall [s]':>9} {'impacts/s':>10} "
        f"{'x loop':>7}"
    )
    for r in rows:
        print(
            f"{r['solver']:>6}  {r['method']:<36} {r['impacts']:>7} {r['wall_s']:>9.2f} "
            f"{r['rate']:>10.1f} {r['speedup']:>7.1f}"
        )
    sys.stdout.flush()
    return rows


if __name__ == "__main__":
    main()
