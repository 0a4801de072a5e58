"""Cost and accuracy of the general integrator for every contact law, against CVODE.

For each law on the paper's standard racket (20 elements, every mode available), prints one
table: the wall time of one impact by CVODE (rtol 1e-11, the reference; 1e-9 with --quick) and
by the general integrator at a COR tolerance (1e-5 by default, the issue's target): a single
impact (best of 3; every node solved at once) and per impact in one batch of positions x
speeds (marched, vectorised across cases), and the largest |dCOR| and relative contact-time
error of the general integrator against CVODE. Ratios are measured in one run; on a shared
machine absolute times vary (DESIGN section 9). The project has no fixed-step Newmark code: the
last line quotes the one measured for DESIGN section 9 (~10 ms per impact, OpenSeesPy,
dt = 1e-5 s).

With ``--against DIR`` (another checkout of fem_racket, e.g. ``git worktree add /tmp/base
main``) it instead prints issue 27's comparison of the batched laws: CPU us per impact at
tolerance 1e-6 (positions 0.45-0.95 L, 20-40 m/s, the kernels compiled and cached first) in
this tree and in DIR, each in its own processes, alternated ``--repeat`` times (best kept: the
machine is shared), the nodes marched per impact (to separation, summed over the vouching runs
at every step count; counted in an untimed repeat of the batch), with the largest |dCOR|
between the two trees and against CVODE (rtol 1e-10, first 4 cases), and the load.

Usage: python scripts/bench_laws.py [--quick] [--batch N] [--tolerance TOL]
       python scripts/bench_laws.py --against DIR [--batch N] [--repeat R]
"""

from __future__ import annotations

import argparse
import json
import os
import subprocess
import sys
import time
from pathlib import Path

import numpy as np

from fem_racket import FrameModel, LinearContact
from fem_racket.contact.hysteretic import Hysteretic
from fem_racket.contact.presets import PRESETS, get_law
from fem_racket.impact.general.integrator import solve_general
from fem_racket.impact.law_impact import LawOptions, receptance, solve_law_impact


def laws() -> dict:
    """The laws benchmarked: the paper's (K_CB at 30 m/s), the families' defaults, presets."""
    return {
        "linear (30 m/s)": LinearContact.for_speed(30.0),
        "hunt-crossley": get_law("hunt-crossley"),
        "kawazoe-1997-nonlinear": PRESETS["kawazoe-1997-nonlinear"],
        "series": get_law("series"),
    }


#: The batched laws of the comparison (issue 27's table), built in the child processes.
BATCHED = {
    "kawazoe-1997-nonlinear": "PRESETS['kawazoe-1997-nonlinear']",
    "hunt-crossley (default)": "get_law('hunt-crossley')",
    "series (default)": "get_law('series')",
    "hysteretic n = 1": "Hysteretic.from_cor(5e4, 0.83, 1.0)",
    "itf-ball": "PRESETS['itf-ball']",
}
#: One child: every law batched once (after a batch of two that loads the kernels), then again
#: untimed with the vouching runs' nodes counted; prints {law: [CPU us per impact, CORs, nodes
#: per impact]}.
CHILD = """
import json, sys, time
import numpy as np
import fem_racket.impact.general.vouch as vouch
from fem_racket import FrameModel
from fem_racket.contact.hysteretic import Hysteretic
from fem_racket.contact.presets import PRESETS, get_law
from fem_racket.impact.general.integrator import solve_general
from fem_racket.impact.law_impact import receptance
n = int(sys.argv[1])
rng = np.random.default_rng(1)
x, v = rng.uniform(0.45, 0.95, n), rng.uniform(20.0, 40.0, n)
model = FrameModel.build(None, 20)
model.modes(None)
rec = receptance(model, x, 0.057)
marched, nodes = vouch.march_compiled, []
def counted(*args):
    run = marched(*args)
    nodes.append(int(np.sum(run[0].last + 1)))
    return run
out = {}
for name, code in json.loads(sys.argv[2]).items():
    law = eval(code)
    solve_general(law, receptance(model, x[:2], 0.057), v[:2], tolerance=1e-6)
    c0 = time.process_time()
    cor = -solve_general(law, rec, v, tolerance=1e-6).ball_velocity / v
    us = 1e6 * (time.process_time() - c0) / n
    nodes.clear()
    vouch.march_compiled = counted
    solve_general(law, rec, v, tolerance=1e-6)
    vouch.march_compiled = marched
    out[name] = [us, cor.tolist(), sum(nodes) / n]
print(json.dumps(out))
"""


def _child(tree: Path, n: int) -> dict:
    """{law: [CPU us per impact, CORs, nodes per impact]} of the batched laws run in a new
    process on ``tree``."""
    env = dict(os.environ, PYTHONPATH=str(tree), OPENBLAS_NUM_THREADS="1", OMP_NUM_THREADS="1")
    args = [sys.executable, "-c", CHILD, str(n), json.dumps(BATCHED)]
    run = subprocess.run(args, env=env, capture_output=True, text=True, check=True, cwd=tree)
    return json.loads(run.stdout.splitlines()[-1])


def against(other: Path, n: int, repeat: int) -> list[dict]:
    """Print and return the comparison of the batched laws, this tree ("after") against
    ``other`` ("before"); see the module docstring."""
    here = Path(__file__).resolve().parents[1]
    load0 = os.getloadavg()[0]
    best: dict = {}
    for _ in range(repeat):
        for tag, tree in (("before", other), ("after", here)):
            for name, (us, cor, nodes) in _child(tree, n).items():
                if us < best.get((tag, name), (np.inf,))[0]:
                    best[tag, name] = (us, np.array(cor), nodes)
    model = FrameModel.build(None, 20)
    model.modes(None)
    rng = np.random.default_rng(1)
    x, v = rng.uniform(0.45, 0.95, n), rng.uniform(20.0, 40.0, n)
    options = LawOptions("cvode", output_step=None, rtol=1e-10, atol=1e-13)
    print(
        f"batched laws, tolerance 1e-6, {n} impacts, 20 elements: CPU us per impact, best of "
        f"{repeat} (load {load0:.1f} -> {os.getloadavg()[0]:.1f}, 2 cores shared)\n"
        f"before: {other}\nafter:  {here}"
    )
    print(f"{'law':24s} {'before':>8s} {'after':>8s} {'ratio':>6s} {'nodes b':>8s} "
          f"{'nodes a':>8s} {'max |dCOR| a-b':>15s} {'max |dCOR| vs CVODE':>20s}")  # fmt: skip
    rows = []
    for name, code in BATCHED.items():
        (b, cor_b, nodes_b), (a, cor_a, nodes_a) = best["before", name], best["after", name]
        law = eval(code, {"PRESETS": PRESETS, "get_law": get_law, "Hysteretic": Hysteretic})
        ref = [solve_law_impact(law, model, x[i], 0.057, v[i], options=options) for i in range(4)]
        cvode = max(abs(cor_a[i] + r.ball_velocity[-1] / v[i]) for i, r in enumerate(ref))
        diff = float(np.max(np.abs(cor_a - cor_b)))
        rows.append(
            {
                "law": name,
                "before_us": b,
                "after_us": a,
                "before_nodes": nodes_b,
                "after_nodes": nodes_a,
                "dcor": diff,
                "cvode": cvode,
            }
        )
        print(
            f"{name:24s} {b:8.1f} {a:8.1f} {a / b:6.2f} {nodes_b:8.1f} {nodes_a:8.1f} "
            f"{diff:15.1e} {cvode:20.1e}"
        )
    return rows


def main(argv: list[str] | None = None) -> list[dict]:
    """Run the benchmark and print the table; returns its rows."""
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument(
        "--quick", action="store_true", help="1 reference case at rtol 1e-9, a batch of 8"
    )
    ap.add_argument("--batch", type=int, default=100, help="impacts in the batch run")
    ap.add_argument("--tolerance", type=float, default=1e-5, help="COR tolerance [-]")
    ap.add_argument("--against", type=Path, help="compare the batched laws with this checkout")
    ap.add_argument("--repeat", type=int, default=3, help="alternations with --against")
    args = ap.parse_args(argv)
    if args.against is not None:
        if args.quick or args.tolerance != 1e-5:
            ap.error("--against compares at tolerance 1e-6 on --batch impacts: no --quick or "
                     "--tolerance")  # fmt: skip
        return against(args.against, args.batch, args.repeat)
    model = FrameModel.build(None, 20)
    model.modes(None)
    n = 8 if args.quick else max(args.batch, 4)
    rng = np.random.default_rng(1)
    positions = rng.uniform(0.45, 0.95, n)
    speeds = rng.uniform(20.0, 40.0, n)
    checked = range(1 if args.quick else 8)
    rtol = 1e-9 if args.quick else 1e-11  # the reference's COR error stays far below 1e-5
    rows = []
    for name, law in laws().items():
        ref, t_cvode = [], 0.0
        for i in checked:
            t0 = time.perf_counter()
            r = solve_law_impact(
                law,
                model,
                positions[i],
                0.057,
                speeds[i],
                options=LawOptions("cvode", output_step=None, rtol=rtol, atol=rtol * 1e-3),
            )
            t_cvode += time.perf_counter() - t0
            ref.append((-r.ball_velocity[-1] / speeds[i], r.t[-1]))
        tol = args.tolerance
        single, t_single = [], []
        for i in checked:
            rec1 = receptance(model, positions[i], 0.057)
            best = np.inf
            for _ in range(3):
                t0 = time.perf_counter()
                one = solve_general(law, rec1, speeds[i], tolerance=tol)
                best = min(best, time.perf_counter() - t0)
            t_single.append(best)
            single.append(one)
        rec = receptance(model, positions, 0.057)
        t0 = time.perf_counter()
        out = solve_general(law, rec, speeds, tolerance=tol)
        t_batch = (time.perf_counter() - t0) / n
        cor = -out.ball_velocity / speeds
        dcor = max(abs(cor[i] - ref[k][0]) for k, i in enumerate(checked))
        dcor1 = max(
            abs(-o.ball_velocity[0] / speeds[i] - ref[k][0])
            for k, (i, o) in enumerate(zip(checked, single, strict=True))
        )
        dtc = max(abs(out.contact_time[i] / ref[k][1] - 1) for k, i in enumerate(checked))
        rows.append(
            {
                "law": name,
                "cvode_ms": 1e3 * t_cvode / len(ref),
                "single_ms": 1e3 * float(np.median(t_single)),
                "batch_ms": 1e3 * t_batch,
                "dcor": max(dcor, dcor1),
                "dtc_rel": dtc,
            }
        )
    print(
        f"general integrator (COR tolerance {args.tolerance:g}) vs CVODE (rtol {rtol:g}), "
        f"batch of {n} impacts, 20 elements; single: median over {len(checked)} impacts"
    )
    print(
        f"{'law':24s} {'CVODE [ms]':>11s} {'single [ms]':>12s} {'batch [ms/impact]':>18s} "
        f"{'max |dCOR|':>11s} {'max |dt_c|/t_c':>15s}"
    )
    for r in rows:
        print(
            f"{r['law']:24s} {r['cvode_ms']:11.1f} {r['single_ms']:12.2f} {r['batch_ms']:18.3f} "
            f"{r['dcor']:11.1e} {r['dtc_rel']:15.1e}"
        )
    print(f"{'Newmark, dt = 1e-5 s':24s} {'':11s} {'~10':>12s}   (DESIGN section 9, not run here)")
    return rows


if __name__ == "__main__":
    main()
