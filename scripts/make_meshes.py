"""Write the example frame meshes in meshes/ (VTU, cell data EI [N m^2] and rhoA [kg/m]).

- ``standard_racket.vtu``: the paper's stepped beam (Kawazoe & Kanda 1997, section 2.2) with its
  20 elements: 6 cells on the 204 mm grip side (EI1 = 146 N m^2, rhoA1 = 0.696 kg/m) and 14 on the
  476 mm top side (EI2 = 128.48 N m^2, rhoA2 = 0.458 kg/m).
- ``tapered_racket.vtu``: a modern 685 mm frame, 8 segments of 3 cells: stiff, heavy handle;
  throat; head hoop whose rigidity falls towards the tip. Illustrative numbers (not a measured
  racket) giving 0.317 kg, balance 0.320 m and a first free-free mode at 145 Hz.
- ``head_heavy_racket.vtu``: the same length with a light handle and a heavy head (3 segments):
  0.322 kg, balance 0.374 m, first mode 128 Hz.
- ``fit_*_racket.vtu``: frames fitted to catalogue numbers (:func:`fem_racket.frame.specs.
  fit_racket`, as ``fem-racket fit`` does) for three illustrative rackets in :data:`SPECS`
  (typical figures of current frames, not a measured model); EI and rhoA rounded to 10
  significant digits so the files are reproducible to the bit.

Usage: python scripts/make_meshes.py [--out meshes] [--check]

``--check`` writes nothing and exits 1 if a committed file differs from what this script builds.
Run time here: ~2 s (start-up); it has no --quick (it is quick).
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numpy as np

from fem_racket import FrameMesh, frame_mesh, read_mesh, standard_frame, write_mesh
from fem_racket.frame.segments import Frame, Segment
from fem_racket.frame.specs import DEFAULT_ELEMENTS as FIT_ELEMENTS
from fem_racket.frame.specs import KG_CM2, fit_racket

MESH_DIR = Path(__file__).resolve().parent.parent / "meshes"

#: (length [m], EI [N m^2], rhoA [kg/m]) from the grip end; 3 cells each.
TAPERED = (
    (0.090, 220.0, 0.660),  # butt cap and handle
    (0.090, 210.0, 0.600),  # handle, top of grip
    (0.075, 190.0, 0.330),  # shaft
    (0.075, 175.0, 0.300),  # throat (open)
    (0.090, 160.0, 0.420),  # lower hoop + strings
    (0.090, 145.0, 0.460),  # hoop at the sweet spot
    (0.090, 125.0, 0.460),  # upper hoop
    (0.085, 105.0, 0.420),  # tip of the hoop
)

#: (length [m], EI [N m^2], rhoA [kg/m]); 6, 4 and 10 cells.
HEAD_HEAVY = (
    (0.200, 170.0, 0.400),
    (0.130, 160.0, 0.330),
    (0.355, 120.0, 0.560),
)


#: name -> (length [m], mass [kg], balance [m], swing weight [kg cm^2], f1 [Hz]); illustrative.
SPECS = {
    "fit_modern_racket.vtu": (0.685, 0.318, 0.320, 316.0, 150.0),  # 300 g class, strung
    "fit_light_racket.vtu": (0.690, 0.285, 0.340, 300.0, 160.0),  # light, head-heavy, long
    "fit_heavy_racket.vtu": (0.685, 0.340, 0.310, 325.0, 135.0),  # heavy, head-light, flexible
}


def _fitted(spec: tuple[float, ...]) -> FrameMesh:
    length, mass, balance, sw, f1 = spec
    frame = fit_racket(length, mass, balance, sw * KG_CM2, f1, elements=FIT_ELEMENTS)
    rounded = Frame(
        tuple(
            Segment(s.length, float(f"{s.EI:.10g}"), float(f"{s.rhoA:.10g}"))
            for s in frame.segments
        )
    )
    return frame_mesh(rounded, FIT_ELEMENTS)


def _frame(rows: tuple[tuple[float, float, float], ...]) -> Frame:
    return Frame(tuple(Segment(*r) for r in rows))


def build_meshes() -> dict[str, FrameMesh]:
    """The example meshes by file name."""
    return {
        "standard_racket.vtu": frame_mesh(standard_frame(), 20),
        "tapered_racket.vtu": frame_mesh(_frame(TAPERED), 3 * len(TAPERED)),
        "head_heavy_racket.vtu": frame_mesh(_frame(HEAD_HEAVY), 20),
        **{name: _fitted(spec) for name, spec in SPECS.items()},
    }


def same_mesh(a: FrameMesh, b: FrameMesh) -> bool:
    """Bit-for-bit equal points, EI and rhoA (and GJ, rhoIp, or both without them)."""
    if a.has_torsion != b.has_torsion:
        return False
    keys = ("points", "EI", "rhoA") + (("GJ", "rhoIp") if a.has_torsion else ())
    return all(np.array_equal(getattr(a, k), getattr(b, k)) for k in keys)


def main(argv: list[str] | None = None) -> int:
    """Write (or check) the meshes; returns the exit code."""
    ap = argparse.ArgumentParser(
        description=__doc__.splitlines()[0], epilog="Run time here: ~2 s; no --quick needed."
    )
    ap.add_argument(
        "--out", type=Path, default=MESH_DIR, metavar="DIR", help="output folder (default meshes/)"
    )
    ap.add_argument("--check", action="store_true", help="compare with the files, write nothing")
    args = ap.parse_args(argv)
    status = 0
    for name, mesh in build_meshes().items():
        path = args.out / name
        if args.check:
            ok = path.is_file() and same_mesh(read_mesh(path), mesh)
            print(f"{'ok' if ok else 'DIFFERS'}  {path}")
            status |= not ok
        else:
            write_mesh(mesh, path, overwrite=True)  # regenerating is this script's job
            print(f"wrote {path}")
    return int(status)


if __name__ == "__main__":
    sys.exit(main())
