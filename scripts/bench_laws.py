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

Usage: python scripts/bench_laws.py [--quick] [--batch N] [--tolerance TOL]
"""

from __future__ import annotations

import argparse
import time

import numpy as np

from fem_racket import FrameModel, LinearContact
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


def main(argv: list[str] | None = None) -> list[dict]:
    """Run the benchmark and print the table; returns its rows."""
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument(
        "--quick", action="store_true", help="1 reference case at rtol 1e-9, a batch of 8"
    )
    ap.add_argument("--batch", type=int, default=100, help="impacts in the batch run")
    ap.add_argument("--tolerance", type=float, default=1e-5, help="COR tolerance [-]")
    args = ap.parse_args(argv)
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
