"""The run times the README states, measured on this machine: a table of ranges with the load.

Each documented command runs ``--repeat`` times in a fresh process (``python -m fem_racket``
or the script under ``python``, one BLAS thread as the CLI pins it), in a scratch folder (its
``output/`` there), and the table gives the fastest and slowest wall time beside what the README
says, with the 1-minute load average before and after each command (2 shared cores here: the
load is what makes a range of a stated time). ``--suite`` adds the default test suite and the
slow tests (minutes).

Usage: python scripts/bench_docs.py [--quick] [--repeat N] [--only TEXT] [--suite]
"""

from __future__ import annotations

import argparse
import os
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
FIG13 = ["--position", "0.55:0.95:7", "--speed", "20,30,40", "--ei1", "50:3000:60:log"]
CLI = [sys.executable, "-m", "fem_racket"]
#: label -> (command, what the README states); {out} is the scratch folder.
COMMANDS = {
    "fem-racket --help": ([*CLI, "--help"], "~1 s"),
    "fem-racket simulate": ([*CLI, "simulate", "--speed", "20", "--position", "0.75"], "~2 s"),
    "fem-racket modes": ([*CLI, "modes", "--quiet"], "~2 s"),
    "fem-racket modes --elements 1000 --count 2000": (
        [*CLI, "modes", "--elements", "1000", "--count", "2000", "--quiet"],
        "~20 s",
    ),
    "fem-racket sweep (Fig 13, 1 260 impacts)": ([*CLI, "sweep", *FIG13, "--quiet"], "~10 s"),
    "fem-racket refine": ([*CLI, "refine", "--quiet"], "~3 s"),
    "fem-racket map": ([*CLI, "map", "--speed", "20", "--racket-speed", "25"], "~2 s"),
    "fem-racket export-vtk": ([*CLI, "export-vtk", "--quiet"], "~4 s"),
    "fem-racket animate (100 frames)": ([*CLI, "animate", "--quiet"], "~20 s"),
    "fem-racket reproduce": (
        [*CLI, "reproduce", "--out", "{out}/paper", "--report", "{out}/R.md", "--quiet"],
        "~15 s",
    ),
    "fem-racket reproduce --law kawazoe-1997-nonlinear": (
        [*CLI, "reproduce", "--law", "kawazoe-1997-nonlinear", "--out", "{out}/law", "--quiet"],
        "~20 s",
    ),
    "fem-racket config --example": ([*CLI, "config", "--example"], "< 1 s"),
    "scripts/convergence.py": (
        [sys.executable, str(ROOT / "scripts/convergence.py"), "--out", "{out}/conv"],
        "~4 s",
    ),
    "scripts/design_study.py --quick": (
        [sys.executable, str(ROOT / "scripts/design_study.py"), "--quick", "--out", "{out}/d"],
        "~11 s",
    ),
    "scripts/tour.py --quick": ([sys.executable, str(ROOT / "scripts/tour.py"), "--quick"], "~5 s"),
}
QUICK = ("fem-racket --help", "fem-racket simulate", "fem-racket config --example")
PYTEST = [sys.executable, "-m", "pytest", "-q", "-p", "no:cacheprovider"]
SUITE = {"pytest (default suite)": (PYTEST, ""), "pytest -m slow": ([*PYTEST, "-m", "slow"], "")}


def load() -> float:
    """The 1-minute load average."""
    return os.getloadavg()[0]


def timed(command: list[str], scratch: Path) -> float:
    """Wall time [s] of one run of ``command`` in ``scratch``; a failure stops the bench."""
    env = dict(os.environ, PYTHONPATH=str(ROOT), MPLBACKEND="Agg")
    env.update(OPENBLAS_NUM_THREADS="1", OMP_NUM_THREADS="1")
    argv = [a.format(out=scratch) for a in command]
    cwd = ROOT if "pytest" in argv else scratch  # the suites run in the repository
    t0 = time.perf_counter()
    done = subprocess.run(argv, cwd=cwd, env=env, capture_output=True, text=True)
    wall = time.perf_counter() - t0
    if done.returncode != 0:
        raise SystemExit(f"bench_docs: {' '.join(argv)} failed:\n{done.stderr[-2000:]}")
    return wall


def main(argv: list[str] | None = None) -> list[dict[str, object]]:
    """Run the commands, print the table, return its rows."""
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="only the sub-second commands")
    parser.add_argument("--repeat", type=int, default=1, help="runs per command (default 1)")
    parser.add_argument("--only", default=None, help="only commands whose label has TEXT")
    parser.add_argument("--suite", action="store_true", help="also time the test suites")
    args = parser.parse_args(argv)
    todo = {k: v for k, v in COMMANDS.items() if not args.quick or k in QUICK}
    if args.suite:
        todo.update(SUITE)
    if args.only:
        todo = {k: v for k, v in todo.items() if args.only in k}
    rows = []
    print(f"{'command':<52} {'README':>8} {'measured [s]':>14} {'load':>10}")
    for label, (command, stated) in todo.items():
        times, loads = [], [load()]
        for _ in range(args.repeat):
            with tempfile.TemporaryDirectory() as tmp:
                times.append(timed(command, Path(tmp)))
            loads.append(load())
        low, high = min(times), max(times)
        span = f"{low:.1f}" if high - low < 0.05 else f"{low:.1f}-{high:.1f}"
        seen = f"{min(loads):.1f}-{max(loads):.1f}"
        print(f"{label:<52} {stated:>8} {span:>14} {seen:>10}", flush=True)
        rows.append({"command": label, "stated": stated, "seconds": times, "load": loads})
    print(f"{os.cpu_count()} cores; load = 1-minute load average before and after each run")
    return rows


if __name__ == "__main__":
    main()
