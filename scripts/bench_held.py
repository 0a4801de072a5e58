"""Cost of one impact on the hand-held racket: CVODE in physical coordinates against the exact
modal path (fem_racket.impact.held.modal), and how closely they agree.

For each grip preset (loose, firm) and impact point (0.6-0.9 L at 30 m/s) on the paper's racket
(20 elements): fem_racket.simulate_held (CVODE, rtol 1e-10, 44 DOFs + ball), then the exact
path with every mode and with the engine's default mode cut-off (COR tolerance 1e-6), each run
once. The exact rows also count the handle-shock measures (vibration RMS and peak over 50 ms)
and, once per grip, the modes of frame + hand (as a design study pays them once per design).
Columns: wall time per impact, its ratio to CVODE, and the largest differences from CVODE in
COR, contact time and peak grip force (at CVODE's output times, every 10 us). The machine is
shared: compare rows of one run.

Usage: python scripts/bench_held.py [--quick]
"""

from __future__ import annotations

import argparse
import time

import numpy as np

from fem_racket.frame.hand import GRIPS
from fem_racket.frame.model import FrameModel
from fem_racket.impact.held.basis import held_basis
from fem_racket.impact.held.grip import simulate_held
from fem_racket.impact.held.modal import held_contact
from fem_racket.impact.held.shock import grip_peak, vibration_rms
from fem_racket.impact.problem import ImpactProblem

SPEED = 30.0


def main(argv: list[str] | None = None) -> list[dict]:
    """Run the benchmark; returns one row per method."""
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="one grip, one impact point (tests)")
    args = ap.parse_args(argv)
    positions = [0.75] if args.quick else [0.6, 0.7, 0.8, 0.9]
    grips = ["firm"] if args.quick else list(GRIPS)
    model = FrameModel.build(None, 20)
    methods = {
        "CVODE (simulate_held)": None,
        "exact, every mode": 0.0,
        "exact, tolerance 1e-6": 1e-6,
    }
    time_s = dict.fromkeys(methods, 0.0)
    diff = {m: np.zeros(3) for m in methods}
    n = 0
    for grip in grips:
        hand = GRIPS[grip]
        t0 = time.perf_counter()
        basis = held_basis(model.fe, hand)
        t_basis = time.perf_counter() - t0
        for m in methods:
            if methods[m] is not None:
                time_s[m] += t_basis
        for x in positions:
            n += 1
            t0 = time.perf_counter()
            ref = simulate_held(ImpactProblem.build(model, hand=hand, position=x, speed=SPEED))
            time_s["CVODE (simulate_held)"] += time.perf_counter() - t0
            peak_ref = np.max(np.abs(ref.grip_force))
            for m, tol in methods.items():
                if tol is None:
                    continue
                t0 = time.perf_counter()
                c = held_contact(basis, position=x, speed=SPEED, tolerance=tol or None)
                vibration_rms(c), grip_peak(c)
                time_s[m] += time.perf_counter() - t0
                t = np.append(ref.t[:-1], c.contact_time)
                peak = np.max(np.abs(c.grip_force(t)[0]))
                d = [
                    abs(c.cor - ref.cor),
                    abs(c.contact_time / ref.contact_time - 1),
                    abs(peak / peak_ref - 1),
                ]
                diff[m] = np.maximum(diff[m], d)
    cvode = time_s["CVODE (simulate_held)"] / n
    rows = [
        {
            "method": m,
            "impacts": n,
            "ms_per_impact": 1e3 * time_s[m] / n,
            "speedup": cvode / (time_s[m] / n),
            "cor_diff": float(diff[m][0]),
            "contact_time_rel_diff": float(diff[m][1]),
            "peak_grip_rel_diff": float(diff[m][2]),
        }
        for m in methods
    ]
    print(
        f"{'method':<24} {'impacts':>7} {'ms/impact':>10} {'speed-up':>9} {'|dCOR|':>9} "
        f"{'|dt_c|/t_c':>10} {'|dF_peak|/F':>11}"
    )
    for r in rows:
        print(
            f"{r['method']:<24} {r['impacts']:>7} {r['ms_per_impact']:>10.2f} "
            f"{r['speedup']:>9.0f} {r['cor_diff']:>9.1e} {r['contact_time_rel_diff']:>10.1e} "
            f"{r['peak_grip_rel_diff']:>11.1e}"
        )
    return rows


if __name__ == "__main__":
    main()
