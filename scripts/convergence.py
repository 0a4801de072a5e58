"""Mesh-refinement study of the standard racket: FE frequencies against the exact stepped beam.

Uniform and graded meshes of 5 ... 320 elements: the first four free-free frequencies, their
errors against the transfer-matrix solution and the observed order (4 for cubic Hermite
elements); COR and contact time at 0.6, 0.75 and 0.9 L with their change under refinement and a
Richardson estimate. Prints the tables and (re)writes convergence.csv and convergence.png
(or .svg, .pdf) in --out (default output/). ``--timing`` adds the per-impact wall time of the
default :func:`fem_racket.simulate` path (80 modes) on large meshes, to show it does not grow
with the mesh.

Run time here: ~4 s (--timing ~6 s); --quick (5-20 elements, for tests) ~3 s.

Usage: python scripts/convergence.py [--quick] [--timing] [--out DIR] [--format png|svg|pdf]
       [--dpi N]
"""

from __future__ import annotations

import argparse
import time
from pathlib import Path

from fem_racket import FrameModel, frame_mesh, simulate, standard_frame
from fem_racket.io.figure_files import DEFAULT_DPI, FIGURE_FORMATS
from fem_racket.io.refine_files import format_study, plot_studies, write_csv
from fem_racket.studies.refine import DEFAULT_ELEMENTS, FAMILIES, refinement_study

QUICK_ELEMENTS = (5, 10, 20)
TIMING_ELEMENTS = (20, 80, 320, 1280)


def impact_timing(sizes=TIMING_ELEMENTS, repeat: int = 3) -> list[dict]:
    """Build time (assembly + 80 modes) and best per-impact time with and without histories."""
    rows = []
    for n in sizes:
        t0 = time.perf_counter()
        model = FrameModel.build(frame_mesh(standard_frame(), n))
        model.modes()
        build = time.perf_counter() - t0
        best = {None: float("inf"), 1e-5: float("inf")}
        for step in best:
            for _ in range(repeat):
                t0 = time.perf_counter()
                r = simulate(model, position=0.75, speed=20.0, output_step=step)
                best[step] = min(best[step], time.perf_counter() - t0)
        rows.append(
            {
                "elements": n,
                "build_s": build,
                "impact_s": best[None],
                "impact_with_histories_s": best[1e-5],
                "cor": r.cor,
            }
        )
    return rows


def main(argv: list[str] | None = None) -> dict:
    """Run the study; returns the studies by family (and the timing rows with --timing)."""
    ap = argparse.ArgumentParser(
        description=__doc__.splitlines()[0],
        epilog="Run time here: ~4 s (--timing ~6 s); --quick ~3 s.",
    )
    ap.add_argument("--quick", action="store_true", help="5-20 elements only (for tests)")
    ap.add_argument("--timing", action="store_true", help="per-impact time on 20-1280 elements")
    ap.add_argument("--out", type=Path, default=Path("output"), metavar="DIR", help="output folder")
    ap.add_argument("--format", default="png", choices=FIGURE_FORMATS, help="plot format")
    ap.add_argument("--dpi", type=float, default=DEFAULT_DPI, help="plot resolution [dots/inch]")
    args = ap.parse_args(argv)
    elements = QUICK_ELEMENTS if args.quick else DEFAULT_ELEMENTS
    studies = {fam: refinement_study(None, elements, family=fam) for fam in FAMILIES}
    print("\n\n".join(format_study(s) for s in studies.values()))
    csv_path = write_csv(studies, args.out / "convergence.csv", overwrite=True)
    png_path = plot_studies(
        studies, args.out / f"convergence.{args.format}", overwrite=True, dpi=args.dpi
    )
    print(f"wrote {csv_path}\nwrote {png_path}")
    out: dict = {"studies": studies}
    if args.timing:
        rows = impact_timing((20, 80) if args.quick else TIMING_ELEMENTS)
        print(f"\n{'elements':>8} {'build [s]':>10} {'impact [ms]':>12} {'+histories [ms]':>16}")
        for r in rows:
            print(
                f"{r['elements']:>8} {r['build_s']:>10.3f} {r['impact_s'] * 1e3:>12.2f} "
                f"{r['impact_with_histories_s'] * 1e3:>16.2f}"
            )
        out["timing"] = rows
    return out


if __name__ == "__main__":
    main()
