"""Calibrate the engine's mode cut-off: the largest COR error against every mode, per beta.

The engine keeps the modes below beta x omega_c (eq 11) plus one residual pseudo-mode
(:mod:`fem_racket.impact.reduction`). This script draws random frames (1-4 segments of a
0.5-0.8 m frame, EI 50-3000 N m^2, rhoA 0.2-1.2 kg/m, 20 and 40 cells) and random impacts on
them (impact point 0.05-1 L, speed 5-60 m/s, zeta 0-0.2, ball mass 40-80 g, EI factor 0.3-20),
and prints, per separation criterion and beta, the largest |COR - COR_all modes| and the
largest relative contact-time error; then, per COR tolerance, the smallest beta whose largest
error is at most tolerance / SAFETY: the table :data:`fem_racket.impact.reduction.CALIBRATION`.
The force criterion needs more modes: its event includes the dashpot's C_CB delta', which
carries the high modes' ripple.

Usage: python scripts/calibrate_engine.py [--quick] [--frames N] [--seed S]
"""

from __future__ import annotations

import argparse

import numpy as np

from fem_racket import Frame, FrameModel, Segment
from fem_racket.contact.linear import kcb_from_speed
from fem_racket.impact.exact.batch import Cases, SolveOptions, solve_cases
from fem_racket.impact.point import frame_modal_data

BETAS = (4.0, 6.0, 8.0, 12.0, 16.0, 24.0, 32.0, 48.0, 64.0, 96.0, 128.0, 192.0, 256.0, 384.0, 512.0)
TOLERANCES = (1e-3, 1e-4, 1e-5, 2e-6, 1e-6, 1e-7, 1e-8)
#: Safety factor between the calibrated largest error and the tolerance.
SAFETY = 1.5
#: Largest damping ratio calibrated (the paper's is 0.059).
ZETA_MAX = 0.2


def random_frame(rng: np.random.Generator) -> Frame:
    n = int(rng.integers(1, 5))
    shares = rng.uniform(0.2, 1.0, n)
    lengths = rng.uniform(0.5, 0.8) * shares / shares.sum()
    return Frame(
        tuple(
            Segment(float(h), float(rng.uniform(50, 3000)), float(rng.uniform(0.2, 1.2)))
            for h in lengths
        )
    )


def errors(rng: np.random.Generator, frames: int, cases: int) -> dict[str, np.ndarray]:
    """Largest COR error and relative t_c error per criterion and beta, (2, len(BETAS))."""
    out = {sep: np.zeros((2, len(BETAS))) for sep in ("displacement", "force")}
    for f in range(frames):
        model = FrameModel.build(random_frame(rng), 20 if f % 2 == 0 else 40)
        pos = rng.uniform(0.05, 1.0, cases)
        data = frame_modal_data(model, pos, None)
        speed = rng.uniform(5.0, 60.0, cases)
        k = np.array([kcb_from_speed(v) for v in speed])
        zeta = rng.uniform(0.0, ZETA_MAX, cases)
        mb = rng.uniform(0.04, 0.08, cases)
        scale = np.exp(rng.uniform(np.log(0.3), np.log(20.0), cases))
        c = 2.0 * zeta * np.sqrt(mb * k)
        omega = data.omega[None, :] * np.sqrt(scale)[:, None]
        zero = np.zeros(cases)
        for sep in ("displacement", "force"):
            cs = Cases(omega, data.values, data.rigid, zero, zero, k, c, mb)
            ref = solve_cases(cs, SolveOptions(np.inf, sep))
            ok = np.isfinite(ref[0])
            for i, beta in enumerate(BETAS):
                cor, tc, _, _ = solve_cases(cs, SolveOptions(beta, sep))
                e = out[sep][:, i]
                e[0] = max(e[0], np.nanmax(np.abs(cor - ref[0])[ok]))
                e[1] = max(e[1], np.nanmax(np.abs(tc / ref[1] - 1.0)[ok]))
    return out


def main(argv: list[str] | None = None) -> dict:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="2 frames x 50 impacts")
    parser.add_argument("--frames", type=int, default=40, help="random frames (default 40)")
    parser.add_argument("--seed", type=int, default=2026, help="random seed")
    args = parser.parse_args(argv)
    rng = np.random.default_rng(args.seed)
    frames, cases = (2, 50) if args.quick else (args.frames, 400)
    err = errors(rng, frames, cases)
    print(f"{frames} random frames x {cases} impacts per separation criterion")
    print(f"{'beta':>6} " + " ".join(f"{'|dCOR| ' + s[:5]:>14} {'|dt_c|/t_c':>11}" for s in err))
    for i, b in enumerate(BETAS):
        cells = " ".join(f"{e[0, i]:14.2e} {e[1, i]:11.2e}" for e in err.values())
        print(f"{b:6g} {cells}")
    table: dict = {}
    print(
        f"\n{'tolerance':>10} "
        + " ".join(f"{s:>13}" for s in err)
        + f"  (beta: error <= tol/{SAFETY:g})"
    )
    for tol in TOLERANCES:
        row = []
        for sep, e in err.items():
            ok = [b for b, x in zip(BETAS, e[0], strict=True) if x <= tol / SAFETY]
            table[sep, tol] = ok[0] if ok else float("nan")
            row.append(f"{table[sep, tol]:13g}")
        print(f"{tol:10.0e} " + " ".join(row))
    return table


if __name__ == "__main__":
    main()
