"""Wall time of the VTK export and of the offscreen animation, on the standard racket at 20 m/s.

Prints a table: exporting N steps as .pvd + .vtu (``write_vtk_series``), rendering a GIF and an
MP4 of M frames at 960x400 (``render_animation``), each the best of ``--repeat`` runs in a fresh
temporary folder. With ``--compare-hdf`` it also writes the same frame series as one transient
``.vtkhdf`` through VTK's ``vtkHDFWriter`` (chunk 1024, no compression, the fast settings of
DESIGN.md section 7) and reports the time errors of its float32 step values: the measurement
behind the choice of format in ``fem_racket/io/vtk.py``.

Run time here: ~30 s (200 steps, GIF and MP4 of 100 frames); --quick (20 steps, 5 frames, no
MP4, for tests) ~4 s.

Usage: python scripts/bench_vtk.py [--steps 200] [--frames 100] [--repeat 1] [--compare-hdf]
       [--quick]
"""

from __future__ import annotations

import argparse
import tempfile
import time
from pathlib import Path

import numpy as np

from fem_racket import impact_series, render_animation, simulate, write_vtk_series
from fem_racket.io.animate import AnimationOptions


def _folder_size(path: Path) -> int:
    return sum(p.stat().st_size for p in path.rglob("*") if p.is_file())


def _write_vtkhdf(series, path: Path) -> tuple[np.ndarray, list[str]]:
    """The frame series as one transient .vtkhdf; returns the step times [s] and the point
    field names read back."""
    from vtkmodules.util.vtkAlgorithm import VTKPythonAlgorithmBase
    from vtkmodules.vtkCommonCore import vtkLogger
    from vtkmodules.vtkCommonDataModel import vtkUnstructuredGrid
    from vtkmodules.vtkCommonExecutionModel import vtkStreamingDemandDrivenPipeline as SDDP
    from vtkmodules.vtkIOHDF import vtkHDFReader, vtkHDFWriter

    class Source(VTKPythonAlgorithmBase):
        def __init__(self) -> None:
            super().__init__(nInputPorts=0, nOutputPorts=1, outputType="vtkUnstructuredGrid")

        def RequestInformation(self, request, in_info, out_info):  # noqa: N802 (VTK API)
            info = out_info.GetInformationObject(0)
            info.Set(SDDP.TIME_STEPS(), list(series.t), series.n_steps)
            info.Set(SDDP.TIME_RANGE(), [series.t[0], series.t[-1]], 2)
            return 1

        def RequestData(self, request, in_info, out_info):  # noqa: N802 (VTK API)
            info = out_info.GetInformationObject(0)
            t = info.Get(SDDP.UPDATE_TIME_STEP())
            i = int(np.argmin(np.abs(series.t - t)))
            vtkUnstructuredGrid.GetData(out_info).ShallowCopy(series.frame_grid(i))
            return 1

    vtkLogger.SetStderrVerbosity(vtkLogger.VERBOSITY_ERROR)  # it warns about every '/' renamed
    source = Source()
    writer = vtkHDFWriter()
    writer.SetInputConnection(source.GetOutputPort())
    writer.SetFileName(str(path))
    writer.SetWriteAllTimeSteps(True)
    writer.SetChunkSize(1024)
    writer.SetCompressionLevel(0)
    writer.Write()
    reader = vtkHDFReader()
    reader.SetFileName(str(path))
    reader.Update()
    times = np.array(reader.GetOutputInformation(0).Get(SDDP.TIME_STEPS()))
    pd = reader.GetOutput().GetPointData()
    return times, [pd.GetArrayName(k) for k in range(pd.GetNumberOfArrays())]


def _best(fn, repeat: int) -> tuple[float, object]:
    best, out = float("inf"), None
    for _ in range(repeat):
        with tempfile.TemporaryDirectory() as tmp:
            t0 = time.perf_counter()
            out = fn(Path(tmp))
            best = min(best, time.perf_counter() - t0)
    return best, out


def main(argv: list[str] | None = None) -> list[dict]:
    """Run the benchmark and print the table; returns its rows."""
    ap = argparse.ArgumentParser(
        description=__doc__.splitlines()[0],
        epilog="Run time here: ~30 s; --quick ~4 s.",
    )
    ap.add_argument("--steps", type=int, default=200, help="VTK steps exported (default 200)")
    ap.add_argument("--frames", type=int, default=100, help="animation frames (default 100)")
    ap.add_argument("--repeat", type=int, default=1)
    ap.add_argument("--compare-hdf", action="store_true", help="also time a .vtkhdf export")
    ap.add_argument("--no-mp4", action="store_true", help="skip the MP4")
    ap.add_argument(
        "--quick", action="store_true", help="20 steps, 5 frames, no MP4 (for tests; ~4 s)"
    )
    args = ap.parse_args(argv)
    if args.quick:
        args.steps, args.frames, args.no_mp4 = 20, 5, True

    result = simulate(position=0.75, speed=20.0)
    rows = []

    def export(tmp: Path):
        write_vtk_series(result, tmp / "vtk", frames=args.steps)
        return _folder_size(tmp / "vtk")

    wall, size = _best(export, args.repeat)
    rows.append({"task": f"export .pvd+.vtu, {args.steps} steps", "wall_s": wall, "bytes": size})

    if args.compare_hdf:
        series = impact_series(result, frames=args.steps)

        def hdf(tmp: Path):
            times, names = _write_vtkhdf(series, tmp / "impact.vtkhdf")
            dt = float(np.abs(times - series.t).max())
            return (tmp / "impact.vtkhdf").stat().st_size, dt, names

        wall, (size, dt, names) = _best(hdf, args.repeat)
        renamed = sorted(set(names) - set(series.point_fields))
        rows.append(
            {
                "task": f"export .vtkhdf (frame only), {args.steps} steps",
                "wall_s": wall,
                "bytes": size,
                "note": f"max time error {dt:.1e} s (float32); fields read back as {renamed}",
            }
        )

    for suffix in (".gif",) if args.no_mp4 else (".gif", ".mp4"):

        def anim(tmp: Path, suffix=suffix):
            options = AnimationOptions(frames=args.frames)
            path = render_animation(result, tmp / f"impact{suffix}", options)
            return path.stat().st_size

        wall, size = _best(anim, args.repeat)
        rows.append({"task": f"animate {suffix[1:]}, {args.frames} frames 960x400", "wall_s": wall,
                     "bytes": size})  # fmt: skip

    print(f"{'task':<44} {'wall [s]':>9} {'size [MB]':>10}  note")
    for r in rows:
        print(f"{r['task']:<44} {r['wall_s']:>9.2f} {r['bytes'] / 1e6:>10.2f}  {r.get('note', '')}")
    return rows


if __name__ == "__main__":
    main()
