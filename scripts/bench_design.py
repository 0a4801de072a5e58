"""Design-study throughput: the three targets of the optimum-design issue, measured in one run.

1. An 8-variable constrained optimisation (EI and rhoA of 4 segments; mass kept, balance,
   swing weight and f1 windows) over a 20-position x 3-speed zone, SLSQP from the paper's racket
   (target <= 60 s);
2. NSGA-II, 50 designs x 100 generations, two objectives (mean e_A, mean v_out with a swing)
   from the same 60 impacts per design (target <= 3 min);
3. Sobol indices of mean e_A with about 10 000 designs (target <= 3 min).

Wall time and CPU time of this process (batches of 64+ designs run on a process pool of all
cores, whose CPU is not in that column: the Sobol row), designs evaluated, zone impacts (zone
points x speeds per design) and microseconds of wall time per zone impact (each design also
builds its frame and modes), how the SLSQP run ended (its message, iterations, mean e_A and
whether every constraint holds: its path, and so its design count, can change with round-off in
the objective), then the Sobol indices the third task found (first order S1
and total ST of mean e_A per variable). The machine is shared: compare rows of one run.

Run time here: ~2-3 minutes in full (a shared 2-core machine, load average 3-4); --quick ~3 s.

Usage: python scripts/bench_design.py [--quick]
"""

from __future__ import annotations

import argparse
import time

from fem_racket.studies.design.build import design_problem
from fem_racket.studies.design.evaluate import Evaluator
from fem_racket.studies.design.pareto import pareto_front
from fem_racket.studies.design.sensitivity import sobol_indices
from fem_racket.studies.design.solvers import optimize

TARGETS = {"SLSQP 8 variables": 60.0, "NSGA-II": 180.0, "Sobol": 180.0}


def problem(quick: bool, **kwargs):
    points = 4 if quick else 20
    speeds = (20.0, 40.0) if quick else (20.0, 30.0, 40.0)
    return design_problem(zone_points=points, speeds=speeds, **kwargs)


def main(argv: list[str] | None = None) -> list[dict]:
    """Run the benchmarks; returns one row per task."""
    ap = argparse.ArgumentParser(
        description=__doc__.splitlines()[0],
        epilog="Run time here: ~2-3 minutes in full; --quick ~3 s.",
    )
    ap.add_argument("--quick", action="store_true", help="tiny runs (tests)")
    args = ap.parse_args(argv)
    q = args.quick
    rows = []
    found = {}

    def run(task: str, p, call) -> None:
        ev = Evaluator(p)
        t0, c0 = time.perf_counter(), time.process_time()
        found[task] = call(p, ev)
        wall, cpu = time.perf_counter() - t0, time.process_time() - c0
        impacts = ev.computed * p.zone.positions.size * len(p.speeds)
        rows.append(
            {
                "task": task,
                "designs": ev.computed,
                "impacts": impacts,
                "wall_s": wall,
                "cpu_s": cpu,
                "us_per_impact": 1e6 * wall / max(impacts, 1),
                "target_s": TARGETS[task],
            }
        )

    cons = {
        "mass_kg": ("start",),
        "balance_m": (0.29, 0.33),
        "swing_weight_kg_cm2": (280.0, 330.0),
        "f1_hz": (100.0, 200.0),
    }
    run(
        "SLSQP 8 variables",
        problem(q, constraints=cons),
        lambda p, ev: optimize(p, evaluator=ev, maxiter=2 if q else 100, progress=False),
    )
    run(
        "NSGA-II",
        problem(q, objectives=("cor", "ball_speed"), racket_speed=20.0),
        lambda p, ev: pareto_front(
            p, evaluator=ev, pop_size=8 if q else 50, generations=2 if q else 100, progress=False
        ),
    )
    run(
        "Sobol",
        problem(q),
        lambda p, ev: sobol_indices(p, designs=40 if q else 10_000, evaluator=ev),
    )
    print(
        f"{'task':<20} {'designs':>8} {'impacts':>9} {'wall [s]':>9} {'own CPU [s]':>12} "
        f"{'us/impact':>10} {'target [s]':>11}"
    )
    for r in rows:
        print(
            f"{r['task']:<20} {r['designs']:>8} {r['impacts']:>9} {r['wall_s']:>9.2f} "
            f"{r['cpu_s']:>12.2f} {r['us_per_impact']:>10.1f} {r['target_s']:>11.0f}"
        )
    local = found["SLSQP 8 variables"]
    holds = all(c["holds"] for c in local.constraints())
    print(
        f"\nSLSQP: {local.message} after {local.iterations} iterations; mean e_A "
        f"{local.start_objective:.5f} -> {local.objective:.5f}; every constraint holds: {holds}"
    )
    sobol = found["Sobol"]
    print(f"\nSobol indices of mean e_A ({sobol.designs} designs)")
    print(f"{'variable':<10} {'S1':>8} {'ST':>8}")
    for name, s1, st in zip(sobol.names, sobol.s1, sobol.st, strict=True):
        print(f"{name:<10} {s1:>8.4f} {st:>8.4f}")
    return rows


if __name__ == "__main__":
    main()
