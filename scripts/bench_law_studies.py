"""Wall time of sweeps and maps under a contact law, batched against one impact at a time.

On the paper's standard racket (20 elements) under the calibrated ``kawazoe-1997-nonlinear``
law, in one process (``backend="serial"``), prints per study the wall time and the time per
impact:

- a sweep over a law parameter (k2, N values around the preset's) at 0.75 L and 30 m/s;
- the same cases one ``simulate`` call each (the general integrator, no batch);
- a sweep over the racket's speed (N values, a hand pivot at 0.10 m) under the law;
- the map (e_A curve alone, and the whole ``racket_map`` with its refined maxima) under the law
  and under the paper's linear law (the batched engine), N points, a 25 m/s swing.

The first case of each study pays for the frame's assembly and modes (cached afterwards). On a
shared machine wall times vary: compare the rows of one run.

Usage: python scripts/bench_law_studies.py [--points N] [--quick]
"""

from __future__ import annotations

import argparse
import time

import numpy as np

from fem_racket import FrameModel, simulate
from fem_racket.contact.presets import PRESETS, get_law
from fem_racket.studies.racket_map import apparent_cor_along, racket_map
from fem_racket.studies.sweep import sweep

LAW = PRESETS["kawazoe-1997-nonlinear"]
SWING = {"speed": 20.0, "racket_speed": 25.0, "pivot": 0.10}


def _timed(fn) -> tuple[float, object]:
    t0 = time.perf_counter()
    out = fn()
    return time.perf_counter() - t0, out


def main(argv: list[str] | None = None) -> list[dict]:
    """Run the benchmark and print the table; returns its rows."""
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--points", type=int, default=50, help="values per study (default 50)")
    ap.add_argument("--quick", action="store_true", help="8 values per study")
    args = ap.parse_args(argv)
    n = 8 if args.quick else max(args.points, 3)
    model = FrameModel.build(None, 20)
    model.modes(None)
    sweep(law=LAW, position=0.75, speed=30.0, backend="serial")  # warm the per-process caches
    k2 = np.geomspace(0.5 * LAW.k2, 2.0 * LAW.k2, n)
    rows = []

    wall, ds = _timed(lambda: sweep(law=LAW, k2=k2, position=0.75, speed=30.0, backend="serial"))
    rows.append({"what": f"sweep k2 ({n} values)", "impacts": n, "wall_s": wall})

    def one_by_one() -> list[float]:
        return [
            simulate(
                model, position=0.75, speed=30.0, law=get_law("hysteretic", k2=v), output_step=None
            ).cor
            for v in k2
        ]

    wall, cors = _timed(one_by_one)
    rows.append({"what": "the same, one simulate each", "impacts": n, "wall_s": wall})
    worst = float(np.max(np.abs(ds.cor.values - np.asarray(cors))))

    speeds = np.linspace(0.0, 30.0, n)
    wall, _ = _timed(
        lambda: sweep(
            law=LAW, racket_speed=speeds, pivot=0.1, position=0.75, speed=20.0, backend="serial"
        )
    )
    rows.append({"what": f"sweep racket_speed ({n} values)", "impacts": n, "wall_s": wall})

    x = np.linspace(0.5, 1.0, n)
    v_r = (SWING["racket_speed"] / (0.75 * model.mesh.length - 0.1)) * (x * model.mesh.length - 0.1)
    closing = SWING["speed"] + v_r
    for label, law in (("law", LAW), ("linear", None)):
        wall, _ = _timed(lambda law=law: apparent_cor_along(model, x, closing, law=law))
        rows.append({"what": f"e_A curve, {label}", "impacts": n, "wall_s": wall})
        wall, _ = _timed(lambda law=law: racket_map(model, positions=x, law=law, **SWING))
        rows.append({"what": f"racket_map, {label}", "impacts": n, "wall_s": wall})

    print(f"kawazoe-1997-nonlinear law, standard racket, 20 elements; {n} values per study")
    print(f"{'what':<34} {'impacts':>8} {'wall [s]':>9} {'per impact [ms]':>16}")
    for r in rows:
        per = r["wall_s"] / r["impacts"] * 1e3
        print(f"{r['what']:<34} {r['impacts']:>8d} {r['wall_s']:>9.3f} {per:>16.2f}")
    print(f"largest |dCOR| sweep vs one simulate each: {worst:.1e}")
    rows.append({"what": "dcor", "value": worst})
    return rows


if __name__ == "__main__":
    main()
