"""The batched impact engine against today's per-case exact path, all measured in one run.

Prints, on the 20-element standard racket (one BLAS thread), with the load average before and
after:

- us per impact, CPU and wall, of :func:`fem_racket.impacts` (the compiled engine) at COR
  tolerance 1e-6 and 3e-5, of the same engine in numpy (the path before the compiled kernels,
  :func:`numpy_engine`, at 1e-6) and of the per-case exact path (``exact_outcome`` with every
  mode, what sweeps ran before that), on the Fig 13 grid (7 impact points x 3 speeds x 60 EI1 =
  1 260 impacts) and on a 126 000-impact grid (70 x 30 x 60; the per-case path on a random 1 %
  of it), with the speed-ups;
- max |dCOR| and max relative dt_c of each against every mode (the engine with tolerance None,
  itself checked against the per-case path in tests/impact/exact/test_engine.py);
- the compiled kernels' first compile and their later load from the disk cache (fresh
  interpreters, an empty cache directory);
- us per impact of the engine at 1e-6 on the Fig 13 grid at 20, 80, 320 and 1 280 elements
  (the one-off mode solve and static solves apart);
- wall time of the command line: ``fem-racket --help``, ``fem-racket simulate --speed 20
  --position 0.75`` and ``fem-racket sweep`` of the Fig 13 grid, of the 126 000 grid and of a
  10^6 grid (``--speed 20:40:1000 --position 0.5:0.95:1000``).

This machine is shared: absolute times are noisy; the ratios within one run are what to read.

Usage: python scripts/bench_engine.py [--quick]
"""

from __future__ import annotations

import argparse
import os
import subprocess
import sys
import tempfile
import time

for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

import numpy as np  # noqa: E402

from fem_racket import (  # noqa: E402
    EngineOptions,
    FrameModel,
    impacts,
    kcb_from_speed,
    standard_frame,
)
from fem_racket.contact.linear import PAPER_CLAMPED_COR, zeta_from_cor  # noqa: E402
from fem_racket.frame.segments import PAPER_EI1  # noqa: E402
from fem_racket.impact.exact.outcome import exact_outcome  # noqa: E402
from fem_racket.impact.exact.roots import coupled_roots  # noqa: E402
from fem_racket.impact.exact.separation import impulse, separation_time  # noqa: E402
from fem_racket.impact.reduction import cutoff_factor, pole_blocks  # noqa: E402
from fem_racket.impact.system import modal_system  # noqa: E402

FIG13 = (7, 3, 60)
BIG = (70, 30, 60)
QUICK = {"fig13": (3, 2, 8), "big": (7, 3, 60), "elements": (20, 80)}
ELEMENTS = (20, 80, 320, 1280)


def grid(shape: tuple[int, int, int]) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Flat (position x/L, speed m/s, EI factor) of a position x speed x EI1 grid."""
    p = np.linspace(0.55, 0.95, shape[0])
    v = np.linspace(20.0, 40.0, shape[1])
    e = np.geomspace(50.0, 3000.0, shape[2]) / PAPER_EI1
    P, V, E = np.meshgrid(p, v, e, indexing="ij")
    return P.ravel(), V.ravel(), E.ravel()


def timed(fn):
    """(result, CPU s, wall s) of fn()."""
    c0, w0 = time.process_time(), time.perf_counter()
    out = fn()
    return out, time.process_time() - c0, time.perf_counter() - w0


def per_case(model: FrameModel, p, v, e) -> np.ndarray:
    """Today's per-case exact path (every mode): COR of each case."""
    fm = model.modes(None)
    zeta = zeta_from_cor(PAPER_CLAMPED_COR)
    out = np.empty(p.size)
    for i in range(p.size):
        k = kcb_from_speed(v[i])
        c = 2.0 * zeta * np.sqrt(0.057 * k)
        g = model.fe.point_vector(p[i] * model.mesh.length)
        omega = fm.all_omega * np.sqrt(np.r_[1.0, 1.0, np.full(fm.omega.size, e[i])])
        out[i] = -exact_outcome(
            modal_system(omega, fm.all_shapes, g, 0.057, k, c, 1.0)
        ).rebound_velocity
    return out


def numpy_engine(model: FrameModel, p, v, e, tolerance: float) -> np.ndarray:
    """COR of the cases by the engine's numpy path (blocks of cases through the numpy roots and
    separation search, as the batch ran before its compiled kernels): every mode of the model
    given, the modes below the tolerance's cut-off kept."""
    fm = model.modes(None)
    mb, zeta = 0.057, zeta_from_cor(PAPER_CLAMPED_COR)
    k = np.array([kcb_from_speed(x) for x in v])
    c = 2.0 * zeta * np.sqrt(mb * k)
    g = model.fe.field_matrix(p * model.mesh.length, 0)
    values, rigid = g @ fm.shapes, ((g @ fm.rigid) ** 2).sum(axis=1)
    omega = fm.omega[None, :] * np.sqrt(e)[:, None]
    mu0 = 1.0 / mb + rigid
    wc = np.sqrt(k * mu0)
    zero = np.zeros(p.size)
    cor = np.full(p.size, np.nan)
    todo, beta = np.arange(p.size), cutoff_factor(tolerance)
    while todo.size:  # a near-touch is solved again with every mode, as the engine does
        touched = []
        blocks = pole_blocks(omega[todo], values[todo], mu0[todo], wc[todo], beta, zero, zero)
        for rows, d, w in blocks:
            for start in range(0, rows.size, 512):
                sub = todo[rows[start : start + 512]]
                ks, cs = k[sub], c[sub]
                for part, roots in coupled_roots(d[start : start + 512], w[start : start + 512],
                                                 ks, cs):  # fmt: skip
                    i = sub[part]
                    fw = (ks[part, None] + cs[part, None] * roots.lam) * roots.res
                    t_est = np.pi / wc[i]
                    t, touch = separation_time(roots, roots.res, t_est, 20.0 * t_est)
                    cor[i] = impulse(roots, fw, t) / mb - 1.0
                    touched.extend(i[touch])
        todo, beta = np.array(sorted(touched), dtype=int), np.inf
    return cor


def compile_seconds() -> tuple[float, float]:
    """(first call with an empty numba cache, first call once cached) [s, wall] of the engine in
    fresh interpreters."""
    code = (
        "import time; from fem_racket import impacts; t = time.perf_counter(); "
        "impacts(position=[0.7], speed=20.0); print(time.perf_counter() - t)"
    )
    out = []
    with tempfile.TemporaryDirectory() as cache:
        env = dict(os.environ, NUMBA_CACHE_DIR=cache)
        for _ in range(2):
            done = subprocess.run(
                [sys.executable, "-c", code], env=env, check=True, capture_output=True, text=True
            )
            out.append(float(done.stdout.split()[-1]))
    return out[0], out[1]


def cli_wall(args: list[str]) -> float:
    """Wall time [s] of ``python -m fem_racket ARGS``."""
    t0 = time.perf_counter()
    subprocess.run([sys.executable, "-m", "fem_racket", *args], check=True, capture_output=True)
    return time.perf_counter() - t0


def main(argv: list[str] | None = None) -> list[dict]:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument(
        "--quick",
        action="store_true",
        help="small grids, two meshes, no CLI sweep of the big grids, no compile from scratch",
    )
    args = parser.parse_args(argv)
    print("load average (1, 5, 15 min): {:.1f} {:.1f} {:.1f}".format(*os.getloadavg()))
    model = FrameModel.build(standard_frame(), 20)
    model.modes(None)
    rows: list[dict] = []
    grids = {
        "Fig 13": QUICK["fig13"] if args.quick else FIG13,
        "126k": QUICK["big"] if args.quick else BIG,
    }
    rng = np.random.default_rng(1)
    print(
        f"{'grid':>8} {'impacts':>8} {'path':>18} {'CPU us':>9} {'wall us':>9} "
        f"{'speed-up':>9} {'max|dCOR|':>10} {'max dt_c/t_c':>13}"
    )
    for name, shape in grids.items():
        p, v, e = grid(shape)
        n = p.size
        kw = dict(position=p, speed=v, ei_factor=e)
        every = impacts(model, options=EngineOptions(tolerance=None), **kw)
        sample = rng.choice(n, size=min(n, 1260 if not args.quick else 60), replace=False)
        cor_old, c_old, w_old = timed(
            lambda p=p[sample], v=v[sample], e=e[sample]: per_case(model, p, v, e)
        )
        old_us = 1e6 * c_old / sample.size
        d_old = float(np.max(np.abs(cor_old - every.cor[sample])))
        rows.append(
            dict(
                grid=name,
                n=n,
                path="per-case exact",
                cpu_us=old_us,
                wall_us=1e6 * w_old / sample.size,
                dcor=d_old,
                dtc=float("nan"),
            )
        )
        cor_np, c_np, w_np = timed(lambda p=p, v=v, e=e: numpy_engine(model, p, v, e, 1e-6))
        rows.append(
            dict(
                grid=name,
                n=n,
                path="numpy engine 1e-06",
                cpu_us=1e6 * c_np / n,
                wall_us=1e6 * w_np / n,
                dcor=float(np.max(np.abs(cor_np - every.cor))),
                dtc=float("nan"),
            )
        )
        for tol in (1e-6, 3e-5):
            impacts(
                model, options=EngineOptions(tolerance=tol), **{k: x[:50] for k, x in kw.items()}
            )  # warm caches
            b, c, w = timed(
                lambda tol=tol, kw=kw: impacts(model, options=EngineOptions(tolerance=tol), **kw)
            )
            rows.append(
                dict(
                    grid=name,
                    n=n,
                    path=f"engine {tol:g}",
                    cpu_us=1e6 * c / n,
                    wall_us=1e6 * w / n,
                    dcor=float(np.max(np.abs(b.cor - every.cor))),
                    dtc=float(np.max(np.abs(b.contact_time / every.contact_time - 1))),
                )
            )
        for r in rows[-4:]:
            r["speedup"] = old_us / r["cpu_us"]
            print(
                f"{r['grid']:>8} {r['n']:>8} {r['path']:>18} {r['cpu_us']:9.1f} "
                f"{r['wall_us']:9.1f} {r['speedup']:9.0f} {r['dcor']:10.1e} {r['dtc']:13.1e}"
            )
    print("\nper-case path: a random sample of each grid (1 260 cases, 60 with --quick)")
    if not args.quick:  # a compile from scratch takes ~10-30 s
        first, cached = compile_seconds()
        rows.append(dict(compile_s=first, cached_s=cached))
        print(f"\nfirst engine call: {first:.1f} s with an empty numba cache, {cached:.2f} s later")
    print(f"\n{'elements':>8} {'modes+static s':>15} {'CPU us/impact':>14} {'modes kept':>11}")
    p, v, e = grid(grids["Fig 13"])
    for cells in QUICK["elements"] if args.quick else ELEMENTS:
        fine = FrameModel.build(standard_frame(), cells)
        _, c0, _ = timed(
            lambda fine=fine: impacts(fine, position=p[:1], speed=20.0, ei_factor=e.min())
        )
        b, c, _ = timed(lambda fine=fine: impacts(fine, position=p, speed=v, ei_factor=e))
        rows.append(dict(elements=cells, setup_s=c0, cpu_us=1e6 * c / p.size))
        print(f"{cells:>8} {c0:15.2f} {1e6 * c / p.size:14.1f} {b.modes.mean():11.1f}")
    print(f"\n{'command line':>52} {'wall s':>8}")
    with tempfile.TemporaryDirectory() as tmp:
        fig = ["--position", "0.55:0.95:7", "--speed", "20,30,40", "--ei1", "50:3000:60:log"]
        big = ["--position", "0.55:0.95:70", "--speed", "20:40:30", "--ei1", "50:3000:60:log"]
        cmds = {
            "fem-racket --help": ["--help"],
            "fem-racket simulate --speed 20 --position 0.75": [
                "simulate",
                "--speed",
                "20",
                "--position",
                "0.75",
            ],
        }
        if not args.quick:
            cmds["fem-racket sweep (Fig 13, 1 260 impacts)"] = [
                "sweep",
                *fig,
                "--out",
                f"{tmp}/a.nc",
                "--quiet",
            ]
            cmds["fem-racket sweep (126 000 impacts)"] = [
                "sweep",
                *big,
                "--out",
                f"{tmp}/b.nc",
                "--quiet",
            ]
            cmds["fem-racket sweep (10^6 impacts)"] = [
                "sweep",
                *["--speed", "20:40:1000", "--position", "0.5:0.95:1000"],
                *["--out", f"{tmp}/c.nc", "--quiet"],
            ]
        for label, cmd in cmds.items():
            wall = cli_wall(cmd)
            rows.append(dict(command=label, wall_s=wall))
            print(f"{label:>52} {wall:8.2f}")
    print("load average (1, 5, 15 min): {:.1f} {:.1f} {:.1f}".format(*os.getloadavg()))
    return rows


if __name__ == "__main__":
    main()
