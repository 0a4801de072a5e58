"""Compiled kernels: issue 27's table of costs and accuracy, in one run (20 elements, 1 thread).

- a batch of two law impacts in a new process, compiling the kernels (an empty numba cache),
  then with them cached; ``fem-racket simulate --law kawazoe-1997-nonlinear`` (a lone impact:
  the kernels' code interpreted, numba not loaded) and a linear ``simulate`` in new processes,
  best of 5 (wall and CPU);
- CPU us per impact: the linear engine (``impacts``, tolerance 1e-6; reference), each law
  batched (positions 0.45-0.95 L, 20-40 m/s, tolerance 1e-6, vouched; max |dCOR| against CVODE
  at rtol 1e-10 on the first cases) and the OpenSeesPy peer (Newmark, average acceleration,
  dt = 1e-5 s, on a beam of the standard racket's stepped segments, the ball the paper's linear
  spring-dashpot; |dCOR| against the exact solution with every mode);
- the 4 200-impact, 200-frame law sweep (``fem-racket sweep --law kawazoe-1997-nonlinear
  --position 0.6:0.9:7 --speed 20,30,40 --ei1 50:3000:200:log``, serial, in process): wall and
  CPU per impact, against the peer;
- the worst |dCOR| against CVODE over seeded random laws per family (``--accuracy N`` each;
  the ranges of tests/strategies.py ``contact_laws``).

OpenSeesPy is a benchmark-only extra (``pip install -e ".[bench]"``); without it the peer's row
says so in one line. The machine is shared (the load is printed): read ratios within one run.

Usage: python scripts/bench_kernels.py [--quick] [--accuracy N] [--only-accuracy]
"""

from __future__ import annotations

import argparse
import math
import os
import subprocess
import sys
import tempfile
import time

for _var in ("OPENBLAS_NUM_THREADS", "OMP_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_var, "1")

import numpy as np  # noqa: E402

from fem_racket import FrameModel  # noqa: E402
from fem_racket.contact.hunt_crossley import HuntCrossley, damping_from_cor  # noqa: E402
from fem_racket.contact.hysteretic import Hysteretic  # noqa: E402
from fem_racket.contact.law import power_contact_time  # noqa: E402
from fem_racket.contact.presets import PRESETS, get_law  # noqa: E402
from fem_racket.contact.series import SeriesBallString  # noqa: E402
from fem_racket.impact.general.integrator import solve_general  # noqa: E402
from fem_racket.impact.law_impact import LawOptions, receptance, solve_law_impact  # noqa: E402

SIMULATE = "from fem_racket.cli import main; main(['simulate'{}])"
#: A batch of two impacts in a new process: the kernels compiled (or loaded from the cache).
BATCH = (
    "from fem_racket import FrameModel; from fem_racket.contact.presets import PRESETS; "
    "from fem_racket.impact.general.integrator import solve_general; "
    "from fem_racket.impact.law_impact import receptance; "
    "solve_general(PRESETS['kawazoe-1997-nonlinear'], "
    "receptance(FrameModel.build(None, 20), [0.6, 0.8], 0.057), 30.0)"
)


def _process(code: str, env: dict[str, str]) -> tuple[float, float]:
    """(wall s, CPU s) of ``python -c code`` in a new process."""
    import resource

    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    w0 = time.perf_counter()
    subprocess.run([sys.executable, "-c", code], env=env, capture_output=True, check=True)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime
    return time.perf_counter() - w0, cpu


def first_runs(repeat: int = 5) -> dict[str, tuple[float, float]]:
    """(wall s, CPU s) in new processes: a batch compiling the kernels (an empty numba cache)
    and loading them from it; the best of ``repeat`` of ``fem-racket simulate --law
    kawazoe-1997-nonlinear`` (a lone impact: the kernels interpreted) and of a linear
    ``simulate``."""
    with tempfile.TemporaryDirectory() as cache:
        env = dict(os.environ, NUMBA_CACHE_DIR=cache)
        out = {"compile": _process(BATCH, env), "cached": _process(BATCH, env)}
        for key, args in (("law", ", '--law', 'kawazoe-1997-nonlinear'"), ("linear", "")):
            runs = [_process(SIMULATE.format(args), env) for _ in range(repeat)]
            out[key] = (min(r[0] for r in runs), min(r[1] for r in runs))
    return out


def cvode_cor(law, model, position, speed) -> float:
    options = LawOptions("cvode", output_step=None, rtol=1e-10, atol=1e-13)
    run = solve_law_impact(law, model, position, 0.057, speed, options=options)
    return float(-run.ball_velocity[-1] / speed)


def stiffness_for(t_c: float, n: float) -> float:
    """k of k delta^n whose rigid contact time at 30 m/s (0.057 kg) is t_c (bisection)."""
    lo, hi = 1.0, 1e40
    for _ in range(200):
        k = math.sqrt(lo * hi)
        if power_contact_time(k, n, 0.057, 30.0) > t_c:
            lo = k
        else:
            hi = k
    return math.sqrt(lo * hi)


def random_law(family: str, rng: np.random.Generator):
    """A law in the ranges of tests/strategies.py contact_laws."""
    if family == "series":
        k_b, c_b, cubic = 10 ** rng.uniform(4, 6), 10 ** rng.uniform(math.log10(0.5), 1.7), 0.0
        k_s = 10 ** rng.uniform(3, 5)
        cubic = float(rng.choice([0.0, 1e8, 1e9, 1e10]))
        return SeriesBallString(k_b, c_b, max(k_s, 1e4) if cubic == 0.0 else k_s, cubic)
    n = 1.0 if rng.random() < 0.3 else rng.uniform(1.0, 10.0)
    k = stiffness_for(10 ** rng.uniform(math.log10(2e-3), math.log10(8e-3)), n)
    e = rng.uniform(0.5, 0.95)
    if family == "hysteretic":
        return Hysteretic.from_cor(k, e, n)
    return HuntCrossley(k, n, 0.0 if rng.random() < 0.5 else damping_from_cor(e, 30.0))


def accuracy(model: FrameModel, count: int) -> list[tuple[str, float, str]]:
    """(family, worst |dCOR| vs CVODE, its case) over ``count`` random cases per family."""
    rows = []
    for family in ("hunt-crossley", "hysteretic", "series"):
        rng = np.random.default_rng(27)
        worst, where = 0.0, ""
        for _ in range(count):
            law = random_law(family, rng)
            x, v = rng.uniform(0.4, 0.95), rng.uniform(10.0, 40.0)
            ref = cvode_cor(law, model, x, v)
            try:
                out = solve_general(law, receptance(model, x, 0.057), v)
                cor = float(-out.ball_velocity[0] / v)
                err = abs(cor - ref)
            except Exception as exc:  # a refusal is not an error in COR: say so
                err, cor = math.nan, type(exc).__name__
            if not err <= worst:
                worst = err if np.isfinite(err) else worst
                where = f"{law} at {x:.3f} L, {v:.1f} m/s: {cor} vs {ref:.8f}"
        rows.append((family, worst, where))
    return rows


def law_batches(model: FrameModel, n: int, checked: int) -> list[tuple[str, float, float]]:
    """(law, CPU us per impact batched, max |dCOR| vs CVODE on the first ``checked``)."""
    rng = np.random.default_rng(1)
    x, v = rng.uniform(0.45, 0.95, n), rng.uniform(20.0, 40.0, n)
    laws = {
        "kawazoe-1997-nonlinear": PRESETS["kawazoe-1997-nonlinear"],
        "hunt-crossley (default)": get_law("hunt-crossley"),
        "series (default)": get_law("series"),
        "hysteretic n = 1": Hysteretic.from_cor(5e4, 0.83, 1.0),
        "itf-ball": PRESETS["itf-ball"],
    }
    rows = []
    rec = receptance(model, x, 0.057)
    for name, law in laws.items():
        solve_general(law, receptance(model, x[:2], 0.057), v[:2])  # load the kernels
        c0 = time.process_time()
        out = solve_general(law, rec, v)
        cpu = (time.process_time() - c0) / n
        err = max(
            abs(-out.ball_velocity[i] / v[i] - cvode_cor(law, model, x[i], v[i]))
            for i in range(checked)
        )
        rows.append((name, 1e6 * cpu, err))
    return rows


def law_sweep() -> tuple[int, float, float]:
    """(impacts, wall s, CPU s) of issue 27's 200-frame law sweep, in process."""
    from fem_racket.studies.sweep import sweep

    c0, w0 = time.process_time(), time.perf_counter()
    ds = sweep(
        law="kawazoe-1997-nonlinear", position="0.6:0.9:7", speed=[20.0, 30.0, 40.0],
        ei1="50:3000:200:log", backend="serial",
    )  # fmt: skip
    return int(ds.cor.size), time.perf_counter() - w0, time.process_time() - c0


def linear_engine(model: FrameModel, shape: tuple[int, int, int]) -> tuple[int, float]:
    """(impacts, CPU us per impact) of the linear engine at 1e-6 on a position x speed x EI
    grid."""
    from fem_racket import impacts

    p = np.linspace(0.55, 0.95, shape[0])
    s = np.linspace(20.0, 40.0, shape[1])
    e = np.geomspace(50.0, 3000.0, shape[2]) / 146.0
    P, S, E = (a.ravel() for a in np.meshgrid(p, s, e, indexing="ij"))
    impacts(model, position=P[:10], speed=S[:10], ei_factor=E[:10])
    c0 = time.process_time()
    impacts(model, position=P, speed=S, ei_factor=E)
    return P.size, 1e6 * (time.process_time() - c0) / P.size


def opensees_cor(model: FrameModel, position: float, speed: float, dt: float = 1e-5) -> float:
    """COR of the OpenSeesPy peer: Newmark on elastic beam-columns (consistent mass) at the
    model's cells and the impact point, the ball a mass on a zero-length spring-dashpot (the
    paper's K_CB, zeta at ``speed``), until the spring's compression returns to zero."""
    import openseespy.opensees as ops

    from fem_racket.contact.linear import LinearContact, kcb_from_speed

    law = LinearContact(kcb_from_speed(speed))
    x = model.mesh.points
    pts = np.unique(np.append(x, position * x[-1]))
    cell = np.clip(np.searchsorted(x, 0.5 * (pts[:-1] + pts[1:])) - 1, 0, x.size - 2)
    ops.wipe()
    ops.model("basic", "-ndm", 2, "-ndf", 3)
    ops.geomTransf("Linear", 1)
    for k, p in enumerate(pts):
        ops.node(k + 1, float(p), 0.0)
    for k, c in enumerate(cell):
        EI, rhoA = float(model.mesh.EI[c]), float(model.mesh.rhoA[c])
        ops.element("elasticBeamColumn", k + 1, k + 1, k + 2, 1.0, EI, 1.0, 1, "-mass", rhoA,
                    "-cMass")  # fmt: skip
    hit, ball = int(np.searchsorted(pts, position * x[-1])) + 1, pts.size + 1
    ops.node(ball, position * x[-1], 0.0)
    ops.fix(ball, 1, 0, 1)
    ops.mass(ball, 0.0, 0.057, 0.0)
    ops.uniaxialMaterial("Elastic", 1, float(law.stiffness), float(law.damping()))
    ops.element("zeroLength", pts.size, hit, ball, "-mat", 1, "-dir", 2)
    ops.setNodeVel(ball, 2, -speed, "-commit")
    for name, *rest in (("constraints", "Plain"), ("numberer", "RCM"), ("system", "BandGeneral"),
                        ("algorithm", "Linear"), ("integrator", "Newmark", 0.5, 0.25),
                        ("analysis", "Transient")):  # fmt: skip
        getattr(ops, name)(*rest)
    ops.analyze(1, 1e-9 * dt)  # a tiny first step: accelerations consistent with C_CB V_0
    d0, v0 = 0.0, -speed
    for _ in range(200000):
        ops.analyze(1, dt)
        d, v = ops.nodeDisp(hit, 2) - ops.nodeDisp(ball, 2), ops.nodeVel(ball, 2)
        if d0 > 0 and d <= 0:  # the compression returned to zero in this step: interpolate
            return (v0 + d0 / (d0 - d) * (v - v0)) / speed
        d0, v0 = d, v
    raise RuntimeError("the OpenSeesPy peer did not separate")


def opensees_peer(model: FrameModel, n: int) -> tuple[float, float] | None:
    """(CPU us per impact, max |dCOR| against the exact solution with every mode) of the
    OpenSeesPy peer over ``n`` impacts; None without openseespy."""
    try:
        import openseespy.opensees  # noqa: F401
    except (ImportError, RuntimeError):  # RuntimeError: installed without its BLAS/LAPACK
        return None
    from fem_racket import EngineOptions, impacts

    rng = np.random.default_rng(3)
    x, v = rng.uniform(0.45, 0.95, n), rng.choice([20.0, 30.0, 40.0], n)
    c0 = time.process_time()
    cors = np.array([opensees_cor(model, x[i], v[i]) for i in range(n)])
    cpu = (time.process_time() - c0) / n
    exact = impacts(model, position=x, speed=v, options=EngineOptions(tolerance=None)).cor
    return 1e6 * cpu, float(np.max(np.abs(cors - exact)))


def main(argv: list[str] | None = None) -> list[tuple[str, float, str]]:
    """Run the benchmark and print its tables; returns the accuracy rows (family, worst
    |dCOR|, its case)."""
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--quick", action="store_true", help="small batches, no 4 200-impact sweep")
    ap.add_argument("--accuracy", type=int, default=12, help="random cases per law family")
    ap.add_argument("--only-accuracy", action="store_true", help="the random set only")
    args = ap.parse_args(argv)
    model = FrameModel.build(None, 20)
    model.modes(None)
    print(f"load: {os.getloadavg()[0]:.1f} (2 cores shared)")
    if not args.only_accuracy:
        t = first_runs()
        print(
            "a batch in a new process: compiling the kernels (empty numba cache) "
            f"{t['compile'][0]:.1f} s wall, {t['compile'][1]:.1f} s CPU; cached "
            f"{t['cached'][0]:.2f} s wall, {t['cached'][1]:.2f} s CPU"
        )
        print(
            "simulate --law kawazoe-1997-nonlinear (a lone impact, interpreted), best of 5: "
            f"{t['law'][0]:.2f} s wall, {t['law'][1]:.2f} s CPU; linear simulate "
            f"{t['linear'][0]:.2f} s wall, {t['linear'][1]:.2f} s CPU"
        )
        n = 200 if args.quick else 2000
        count, us = linear_engine(model, (7, 3, 60) if args.quick else (70, 30, 60))
        print(f"\n{'path (tolerance 1e-6)':44s} CPU [us/impact]   max |dCOR|")
        print(f"  {'linear engine (' + str(count) + ' impacts)':42s} {us:12.1f}")
        for name, us, err in law_batches(model, n, 4):
            print(f"  {name + ' (' + str(n) + ' batched)':42s} {us:12.0f} {err:14.1e} vs CVODE")
        peer = opensees_peer(model, 4 if args.quick else 12)
        if peer is None:
            print("  OpenSeesPy peer: not installed (pip install -e '.[bench]')")
        else:
            name = "OpenSeesPy Newmark, linear law"
            print(f"  {name:42s} {peer[0]:12.0f} {peer[1]:14.1e} vs exact")
        if not args.quick:
            count, wall, cpu = law_sweep()
            ratio = (
                "" if peer is None else f" ({peer[0] / (1e6 * cpu / count):.0f}x the peer's CPU)"
            )
            print(
                f"\nlaw sweep, 200 frames: {count} impacts, {wall:.1f} s wall, "
                f"{1e3 * wall / count:.2f} ms wall and {1e6 * cpu / count:.0f} us CPU per impact"
                f"{ratio}"
            )
    print(f"\nworst |dCOR| vs CVODE over {args.accuracy} random laws per family (tolerance 1e-6)")
    rows = accuracy(model, args.accuracy)
    for family, worst, where in rows:
        print(f"  {family:14s} {worst:9.1e}   {where}")
    return rows


if __name__ == "__main__":
    main()
