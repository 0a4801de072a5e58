"""Per-impact wall time of every integrator on the standard racket, at 20 and 80 elements.

Prints a table with the time of each path and its ratio to the default (exact, modal), all
measured in one run. Assembly and the free-free modes are built once per mesh, as a sweep does.

Run time here: ~12 minutes in full (CVODE and scipy BDF on the 80-element physical system
dominate); --quick (20 elements, the cheap paths only; add --repeat 1) ~13 s.

Usage: python scripts/bench_impact.py [--repeat N] [--quick]
"""

from __future__ import annotations

import argparse
import time

from fem_racket import FrameModel, simulate

CASES = (
    ("exact", "modal"),
    ("cvode", "modal"),
    ("bdf", "modal"),
    ("cvode", "physical"),
    ("bdf", "physical"),
)


def time_case(model: FrameModel, solver: str, basis: str, repeat: int) -> tuple[float, float]:
    """Best wall time of one impact [s] and its COR."""
    best, cor = float("inf"), float("nan")
    for _ in range(repeat):
        t0 = time.perf_counter()
        given = {} if solver == "exact" else {"basis": basis}  # exact is modal; refuses basis
        r = simulate(model, position=0.75, speed=20.0, solver=solver, **given)
        best = min(best, time.perf_counter() - t0)
        cor = r.cor
    return best, cor


def main(argv: list[str] | None = None) -> list[dict]:
    """Run the benchmark and print the table; returns its rows."""
    ap = argparse.ArgumentParser(
        description=__doc__.splitlines()[0],
        epilog="Run time here: ~12 minutes in full; --quick ~13 s.",
    )
    ap.add_argument("--repeat", type=int, default=3, help="runs per path, best kept (default 3)")
    ap.add_argument(
        "--quick", action="store_true", help="20 elements, cheap paths only (~13 s, for tests)"
    )
    args = ap.parse_args(argv)
    sizes = (20,) if args.quick else (20, 80)
    rows = []
    for n in sizes:
        model = FrameModel.build(None, n)
        model.modes()
        base = None
        for solver, basis in CASES:
            if args.quick and solver == "bdf":
                continue
            if basis == "physical" and n > 20 and solver == "bdf":
                continue  # minutes per impact (DESIGN.md section 3)
            wall, cor = time_case(model, solver, basis, 1 if basis == "physical" else args.repeat)
            base = wall if base is None else base
            rows.append(
                {
                    "elements": n,
                    "solver": solver,
                    "basis": basis,
                    "wall_s": wall,
                    "ratio": wall / base,
                    "cor": cor,
                }
            )
    print(
        f"{'elements':>8} {'solver':>6} {'basis':>9} {'ms/impact':>11} {'x exact':>9} {'COR':>12}"
    )
    for r in rows:
        print(
            f"{r['elements']:>8} {r['solver']:>6} {r['basis']:>9} {r['wall_s'] * 1e3:>11.2f} "
            f"{r['ratio']:>9.1f} {r['cor']:>12.9f}"
        )
    return rows


if __name__ == "__main__":
    main()
