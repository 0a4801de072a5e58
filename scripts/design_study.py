"""Optimum design of the paper's racket: the README's worked study.

Keeping the paper's racket's length (0.68 m) and mass (0.359992 kg from its stated rhoA), with
EI and rhoA free on 4 segments (grip 0-0.3 L, three equal parts of the head side: 8 variables,
EI 50-3000 N m^2 as Fig 13, rhoA 0.2-1.2 kg/m):

1. ``DIR/`` (optimum.vtu, result.json, history.nc, PNGs): maximise the mean apparent COR e_A over
   0.6-0.9 L (20 points) at 20, 30 and 40 m/s, SLSQP from the paper's racket;
2. ``DIR/same_specs/``: the same with the balance point and the swing weight kept too (a racket
   a player would feel as the same: only EI and the mass distribution's higher moments change);
3. ``DIR/ball_speed/``: maximise the mean ball speed v_out over the same zone for a ball at
   20 m/s and a swing of 20 m/s at 0.75 L about a hand 0.10 m from the butt, slowing as
   I^-0.27 with the swing weight (Cross & Bower 2006);
4. ``DIR/pareto/``: NSGA-II Pareto front of mean v_out against the power-region length (where
   v_out is within 90 % of its maximum) for that swing, mass within 1 % of the paper's;
5. ``DIR/shock/``: NSGA-II Pareto front of mean v_out for that swing against the mean handle
   shock (RMS of the grip force's vibration part over 50 ms, minimised) of the racket held
   by a firm grip (fem_racket.frame.hand.FIRM_GRIP, an assumption), mass within 1 %;
6. ``DIR/smooth/``: study 1 with EI(x) a smooth profile (monotone cubic, PCHIP) through control
   points at 0, 0.25, 0.5, 0.75 and 1 L instead of one EI per segment (rhoA still per segment:
   9 variables); it starts from the paper's racket smoothed the same way. When studies 1 and 6
   both run, ``DIR/smooth/profiles.png`` draws EI(x) and rhoA(x) of the paper's racket and of
   both optima.

Prints a table: each study's objective for its starting racket and the optimum, the gain, the
designs evaluated and the wall time. ``--quick`` runs a coarse version (5 zone points, a few
iterations, a tiny NSGA-II) for the tests.

Run time here: ~3-3.5 minutes in full (2-3 of them study 5; a shared 2-core machine, load
average 3-4); --quick ~11 s.

Usage: python scripts/design_study.py [--quick] [--out DIR] [--overwrite] [--only STUDY]
"""

from __future__ import annotations

import argparse
import sys
import time
from pathlib import Path

import numpy as np

from fem_racket.io.design_study import OptimizationRun, OutputOptions, run_optimization
from fem_racket.io.figure_files import save_figure
from fem_racket.outputs import provenance
from fem_racket.studies.design.build import design_problem
from fem_racket.studies.design.options import ExecutionOptions, SearchOptions
from fem_racket.studies.design.profiles import cell_means
from fem_racket.validation import InputError

MASS = 0.359992
#: Control stations x/L of study 6's smooth EI(x).
SMOOTH_EI = (0.0, 0.25, 0.5, 0.75, 1.0)


def studies(quick: bool) -> list[tuple[str, dict, dict]]:
    """(sub-folder, problem settings, solver settings) of each study."""
    zone = {"zone_points": 5 if quick else 20}
    swing = {"speeds": (20.0,), "racket_speed": 20.0, "reference": 0.75, "pivot": 0.10}
    keep = {"mass_kg": ("start",)}
    same = {name: ("start",) for name in ("mass_kg", "balance_m", "swing_weight_kg_cm2")}
    local = {"method": "SLSQP", "maxiter": 3 if quick else 100}
    nsga2 = {"method": "nsga2", "pop_size": 8 if quick else 50, "generations": 3 if quick else 100}
    return [
        ("", {**zone, "objectives": ("cor",), "constraints": keep}, local),
        ("same_specs", {**zone, "objectives": ("cor",), "constraints": same}, local),
        (
            "ball_speed",
            {**zone, **swing, "objectives": ("ball_speed",), "constraints": keep},
            local,
        ),
        (
            "pareto",
            {
                **zone,
                **swing,
                "objectives": ("ball_speed", "power_region"),
                "constraints": {"mass_kg": (0.99 * MASS, 1.01 * MASS)},
            },
            nsga2,
        ),
        (
            "shock",
            {
                **zone,
                **swing,
                "objectives": ("ball_speed", "handle_shock"),
                "grip": "firm",
                "constraints": {"mass_kg": (0.99 * MASS, 1.01 * MASS)},
            },
            nsga2,
        ),
        (
            "smooth",
            {**zone, "objectives": ("cor",), "constraints": keep, "ei_points": SMOOTH_EI},
            local,
        ),
    ]


def plot_profiles(steps, smooth, path: Path, quick: bool) -> None:
    """EI(x) and rhoA(x) of the paper's racket, study 1's optimum (4 segments) and study 6's
    (smooth EI: its cells, the profile itself and its control points), to ``path`` (PNG)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, (ax_ei, ax_ra) = plt.subplots(1, 2, figsize=(11, 4.2))
    start = steps.problem.mesh(steps.problem.x_start)
    curves = [
        (start, "k--", "paper's racket"),
        (
            steps.problem.mesh(steps.x),
            "tab:blue",
            f"study 1: 4 segments, e_A {steps.objective:.4f}",
        ),
        (
            smooth.problem.mesh(smooth.x),
            "tab:red",
            f"study 6: smooth EI, e_A {smooth.objective:.4f}",
        ),
    ]
    for mesh, style, label in curves:
        xs = np.repeat(mesh.points, 2)[1:-1] / mesh.length
        ax_ei.plot(xs, np.repeat(mesh.EI, 2), style, label=label)
        ax_ra.plot(xs, np.repeat(mesh.rhoA, 2), style)
    sp = smooth.problem
    stations = np.asarray(sp.ei_stations)
    values = sp.parameters(smooth.x)[: sp.n_ei]
    fine = np.linspace(0.0, sp.length, 401)
    mid = 0.5 * (fine[1:] + fine[:-1]) / sp.length
    profile = cell_means(stations, values, fine, sp.interpolation)
    ax_ei.plot(
        mid, profile, ":", color="tab:red", label=f"study 6: the profile ({sp.interpolation})"
    )
    ax_ei.plot(stations, values, "o", color="tab:red", label="study 6: control points")
    ax_ei.set_yscale("log")
    ax_ei.set_ylabel("EI [N m^2]")
    ax_ra.set_ylabel("rhoA [kg/m]")
    for ax in (ax_ei, ax_ra):
        ax.set_xlabel("x/L [-]")
    ax_ra.legend(*ax_ei.get_legend_handles_labels(), fontsize=8, loc="upper left")
    speeds = ", ".join(f"{v:g}" for v in sp.speeds)
    fig.suptitle(
        f"Maximum mean e_A ({sp.zone.description}; {speeds} m/s), mass kept: the optima's profiles"
    )
    fig.tight_layout()
    meta = provenance({"script": "design_study", "study": "smooth", "quick": quick})
    save_figure(fig, path, meta, overwrite=True)
    plt.close(fig)


def main(argv: list[str] | None = None) -> list[dict]:
    """Run the studies; returns one row per study."""
    ap = argparse.ArgumentParser(
        description=__doc__.splitlines()[0],
        epilog="Run time here: ~3-3.5 minutes in full (2-3 of them study 5); --quick ~11 s.",
    )
    ap.add_argument("--quick", action="store_true", help="coarse, fast variant (tests)")
    ap.add_argument("--out", default="output/design_study", help="output folder")
    ap.add_argument("--overwrite", action="store_true", help="replace the output folder")
    ap.add_argument(
        "--only",
        choices=[sub or "cor" for sub, _, _ in studies(True)],
        default=None,
        help="run only this study (default: all)",
    )
    args = ap.parse_args(argv)
    out = Path(args.out)
    rows = []
    results = {}
    try:
        for sub, settings, solver in studies(args.quick):
            if args.only not in (None, sub or "cor"):
                continue
            problem = design_problem(**settings)
            t0 = time.perf_counter()
            files = OutputOptions(
                out / sub if sub else out,
                args.overwrite or bool(sub),
                {"script": "design_study", "study": sub or "cor", "quick": args.quick},
            )
            run = OptimizationRun(
                problem, SearchOptions(**solver), ExecutionOptions(progress=False), files
            )
            r = run_optimization(run)
            results[sub or "cor"] = r
            rows.append(
                {
                    "study": sub or "cor",
                    "objective": problem.objectives[0],
                    "start": r.start_objective,
                    "optimum": r.objective,
                    "designs": r.evaluator.computed,
                    "wall_s": time.perf_counter() - t0,
                }
            )
        if {"cor", "smooth"} <= set(results):
            plot_profiles(
                results["cor"], results["smooth"], out / "smooth" / "profiles.png", args.quick
            )
    except InputError as exc:
        print(f"design_study: error: {exc}", file=sys.stderr)
        raise SystemExit(2) from None
    print(
        f"{'study':<12} {'objective':<12} {'start':>13} {'optimum':>10} {'gain':>9} "
        f"{'designs':>8} {'wall [s]':>9}"
    )
    for r in rows:
        print(
            f"{r['study']:<12} {r['objective']:<12} {r['start']:>13.5g} {r['optimum']:>10.5g} "
            f"{r['optimum'] - r['start']:>+9.4g} {r['designs']:>8} {r['wall_s']:>9.1f}"
        )
    print(f"wrote {out}")
    return rows


if __name__ == "__main__":
    main()
