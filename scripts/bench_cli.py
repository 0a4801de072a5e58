"""Start-up of the command line: wall time of each command, and what its imports cost.

Runs each command ``--repeat`` times as ``python -m fem_racket ...`` in a fresh process (the
``fem-racket`` console script does the same import; a pyenv shim in front of it adds its own
~0.1 s) and prints the median and the fastest wall time per command; with several ``--tree``
(source trees, e.g. an export of an older commit) every tree runs each command in turn, so load
on the machine hits them alike: compare the columns of one run, not runs of different days.

Then, per command and tree, one run under ``python -X importtime``: the top-level packages whose
imports cost the most (the own time of every module of the package: ``scipy`` holds every
``scipy.*`` module the command imports, but not the numpy modules scipy imports).

Python's bytecode cache is written to a temporary folder (``PYTHONPYCACHEPREFIX``; the source
trees are not touched) and warmed by one untimed run, as after ``pip install``; ``--no-cache``
compiles every module at every start instead (what ``PYTHONDONTWRITEBYTECODE=1`` costs).

Beside the wall time, the CPU time [s] of the run with every process it started (its pool's
workers), the median over the runs, and the load average before and after.

Targets (issue 13): ``--help`` <= 0.3 s, ``simulate`` <= 0.35 s, the Fig 13 sweep <= 0.8 s;
(issue 27) a single ``simulate --law NAME`` <= 0.5 s (each law of :data:`LAWS`: its lone impact
runs the kernels interpreted), the 4 200-impact, 200-frame law sweep <= ~0.2 ms per impact
(0.84 s), and with ``--million`` the 10^6-impact sweep (``--speed 20:40:1000 --position
0.5:0.95:1000``, run ``--repeat`` times like the others) <= 10 s.

With ``--strung``, instead: ``config --check`` and ``simulate --config`` of a strung racket's run
file (:data:`STRUNG_RUN`): the string bed's reach check (its edge from the head outline, no
membrane) and one strung impact.

With ``--checks``, instead: ``config --check`` of a run file with every table (the example of
``config --example`` and :data:`CHECK_TABLES`), and each command's dry run of it alone (what
``config --check`` runs per command: its checks, no computation, no file), as
``python -c DRY_RUN NAME FILE`` (:data:`DRY_RUN`); the import table shows what each check loads.

With ``--help-commands``, instead: ``fem-racket --help`` and every ``fem-racket COMMAND --help``
(what a user waits for before the first line of help, or for a usage error: the same parser is
built), each with the package modules and the heavy libraries (:data:`HEAVY`) it imports (one
``-X importtime`` run), its median wall and CPU time, and both as a ratio to the top-level
``--help`` of the same tree in the same run.

Usage: python scripts/bench_cli.py [--quick] [--repeat N] [--tree DIR ...] [--no-cache]
       [--million] [--strung] [--checks] [--help-commands]
       (with --quick: --help and simulate once each; with --checks: config --check only)
"""

from __future__ import annotations

import argparse
import os
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
FIG13 = ["--position", "0.55:0.95:7", "--speed", "20,30,40", "--ei1", "50:3000:60:log"]
LAW = ["--law", "kawazoe-1997-nonlinear", "--position", "0.6:0.9:7", "--speed", "20,30,40"]
LAW += ["--ei1", "50:3000:200:log"]
BIG = ["--speed", "20:40:1000", "--position", "0.5:0.95:1000"]
#: label -> (arguments, target wall time [s] or None); {out} is a fresh temporary folder.
COMMANDS = {
    "--help": (["--help"], 0.3),
    "simulate": (["simulate", "--speed", "20", "--position", "0.75"], 0.35),
    "simulate --out (histories)": (["simulate", "--out", "{out}/r.json"], None),
    "sweep Fig 13 (1 260 impacts)": (["sweep", *FIG13, "--out", "{out}/s.nc", "--quiet"], 0.8),
    "law sweep (4 200, 200 frames)": (["sweep", *LAW, "--out", "{out}/l.nc", "--quiet"], 0.84),
}
#: The laws of ``simulate --law`` timed (issue 27), each a row.
LAWS = ("kawazoe-1997-nonlinear", "hunt-crossley", "hysteretic", "series", "itf-ball")
COMMANDS.update({f"simulate --law {law}": (["simulate", "--law", law], 0.5) for law in LAWS})
MILLION = {
    "sweep of 10^6 impacts": (["sweep", *BIG, "--out", "{out}/m.nc", "--quiet"], 10.0),
}
QUICK = {"--help": COMMANDS["--help"], "simulate": COMMANDS["simulate"]}
#: A strung racket's run file: the paper's racket as strung (246 N, 16x19; issue 25), 0.76 L.
STRUNG_RUN = '[strings]\ntension_n = 246.0\npattern = "16x19"\n[impact]\nposition_x_over_l = 0.76\n'


def strung_commands(run_file: Path) -> dict[str, tuple[list[str], None]]:
    """The commands of ``--strung`` on the run file ``run_file``."""
    return {
        "config --check (strung run file)": (["config", "--check", str(run_file)], None),
        "simulate --config (strung run file)": (["simulate", "--config", str(run_file)], None),
    }


#: What the example run file leaves commented out that some checks need (fit and customise
#: refuse a file without their targets, closest and compare check their tables' values), and a
#: sweep on a Dask scheduler (its check finds distributed, the sweep would import it).
CHECK_TABLES = """
[sweep]
scheduler = "tcp://127.0.0.1:8786"
[fit]
length = 0.685
mass = 0.3
balance = 0.33
swing_weight = 320.0
[customise]
swing_weight = 330.0
[closest]
swing_weight = "300:330"
[compare]
point = 0.7
"""
#: One command's dry run on a run file: ``python -c DRY_RUN NAME FILE``.
DRY_RUN = "import sys; from fem_racket.cli.commands.config import _dry_run; _dry_run(*sys.argv[1:])"


def check_commands(env: dict[str, str], scratch: Path, quick: bool) -> dict[str, tuple]:
    """``config --check`` of the run file of ``--checks`` (written to ``scratch``) and each
    command's dry run of it (``quick``: the check alone); ``env``: the tree naming them."""

    def output(code: str) -> str:
        argv = [sys.executable, "-c", code]
        done = subprocess.run(
            argv, env=env, cwd=scratch, capture_output=True, text=True, check=True
        )
        return done.stdout

    run_file = scratch / "checked.toml"
    run_file.write_text(output("from fem_racket.cli import main; main(['config', '--example'])"))
    with run_file.open("a") as f:
        f.write(CHECK_TABLES)
    names = output("from fem_racket.cli.commands.config import _commands; print(*_commands())")
    commands = {"config --check (every table)": (["config", "--check", str(run_file)], None)}
    for name in [] if quick else names.split():
        commands[f"dry run of {name}"] = (["-c", DRY_RUN, name, str(run_file)], None)
    return commands


#: Third-party libraries too heavy for a command's ``--help`` (each with its submodules).
HEAVY = ("numpy", "scipy", "skfem", "meshio", "pyvista", "sksundae", "matplotlib", "xarray")
HEAVY += ("dask", "numba")


def environment(tree: Path, cache: Path | None) -> dict[str, str]:
    """The environment of a run of ``tree``: its package first on the path, one BLAS thread."""
    env = dict(os.environ, PYTHONPATH=str(tree))
    env.update(OPENBLAS_NUM_THREADS="1", OMP_NUM_THREADS="1", MKL_NUM_THREADS="1")
    env.pop("PYTHONPYCACHEPREFIX", None)
    if cache is None:
        env["PYTHONDONTWRITEBYTECODE"] = "1"
    else:
        env.pop("PYTHONDONTWRITEBYTECODE", None)
        env["PYTHONPYCACHEPREFIX"] = str(cache)
    return env


def _children_cpu() -> float:
    """CPU time [s] (user + system) of this process's finished children so far."""
    use = resource.getrusage(resource.RUSAGE_CHILDREN)
    return use.ru_utime + use.ru_stime


def run(
    args: list[str], env: dict[str, str], scratch: Path, flags: tuple[str, ...] = ()
) -> tuple[float, str, float]:
    """(wall time [s], stderr, CPU time [s] of the run and its own children) of
    ``python FLAGS -m fem_racket ARGS`` (``python FLAGS -c ...`` for ``ARGS = ["-c", ...]``) in
    a fresh output folder."""
    with tempfile.TemporaryDirectory(dir=scratch) as out:
        argv = [a.format(out=out) for a in args]
        cpu0 = _children_cpu()
        t0 = time.perf_counter()
        done = subprocess.run(
            [sys.executable, *flags, *([] if argv[0] == "-c" else ["-m", "fem_racket"]), *argv],
            env=env,
            cwd=out,  # not the repository: python puts the working directory first on the path
            capture_output=True,
            text=True,
        )
        wall = time.perf_counter() - t0
        cpu = _children_cpu() - cpu0
    if done.returncode != 0:
        raise SystemExit(f"bench_cli: {' '.join(argv)} failed:\n{done.stderr}")
    return wall, done.stderr, cpu


def import_costs(stderr: str) -> dict[str, float]:
    """Import time [s] per top-level package from ``-X importtime`` output: the sum of the own
    (self) times of its modules, so a package is not charged for what it imports from others."""
    costs: dict[str, float] = {}
    for line in stderr.splitlines():
        if not line.startswith("import time:") or line.count("|") != 2:
            continue
        own, _, name = line.removeprefix("import time:").split("|")
        if not own.strip().isdigit():
            continue  # the header
        root = name.strip().split(".")[0]
        costs[root] = costs.get(root, 0.0) + int(own) * 1e-6
    return costs


def imported(stderr: str) -> list[str]:
    """The modules a run imported, from its ``-X importtime`` output, in import order."""
    names = [line.rsplit("|", 1)[1].strip() for line in stderr.splitlines()]
    return [n for n in names if n and n != "imported package"]


def help_rows(
    trees: list[Path], envs: dict[Path, dict[str, str]], scratch: Path, repeat: int, quick: bool
) -> list[dict]:
    """Time ``--help`` and every ``COMMAND --help`` (``quick``: the first command's only)
    ``repeat`` times per tree (trees in turn), and count what one ``-X importtime`` run of each
    imports; print the table, return its rows."""
    names = subprocess.run(
        [sys.executable, "-c", "from fem_racket.cli import COMMANDS; print(*COMMANDS)"],
        env=envs[trees[0]],
        cwd=scratch,
        capture_output=True,
        text=True,
        check=True,
    ).stdout.split()[: 1 if quick else None]
    commands = {"--help": ["--help"], **{f"{n} --help": [n, "--help"] for n in names}}
    walls: dict[tuple[str, Path], list[float]] = {}
    cpus: dict[tuple[str, Path], list[float]] = {}
    for _ in range(max(repeat, 1)):
        for label, cmd in commands.items():
            for tree in trees:
                wall, _, cpu = run(cmd, envs[tree], scratch)
                walls.setdefault((label, tree), []).append(wall)
                cpus.setdefault((label, tree), []).append(cpu)
    width = max(map(len, commands))
    print(f"{'command':<{width}} tree modules heavy  wall [s] (x help) CPU [s] (x help)")
    rows: list[dict] = []
    for label, cmd in commands.items():
        for i, tree in enumerate(trees):
            names = imported(run(cmd, envs[tree], scratch, ("-X", "importtime"))[1])
            heavy = [h for h in HEAVY if any(n == h or n.startswith(h + ".") for n in names)]
            wall, cpu = (statistics.median(t[(label, tree)]) for t in (walls, cpus))
            top = [statistics.median(t[("--help", tree)]) for t in (walls, cpus)]
            own = sum(n == "fem_racket" or n.startswith("fem_racket.") for n in names)
            rows.append(dict(command=label, tree=str(tree), modules=own, heavy=heavy))
            rows[-1].update(
                wall_s=wall, cpu_s=cpu, wall_ratio=wall / top[0], cpu_ratio=cpu / top[1]
            )
            print(
                f"{label:<{width}} [{i}]  {own:7d} {','.join(heavy) or '-':<6}{wall:8.3f} "
                f"({wall / top[0]:4.2f}) {cpu:7.3f} ({cpu / top[1]:4.2f})"
            )
    return rows


def main(argv: list[str] | None = None) -> list[dict]:
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument(
        "--quick",
        action="store_true",
        help="a smoke test: --help and simulate once each, under -X importtime, not warmed up",
    )
    parser.add_argument("--repeat", type=int, default=None, help="runs per command (default 7)")
    parser.add_argument(
        "--tree",
        action="append",
        type=Path,
        default=None,
        help="source tree holding fem_racket/ (repeatable; default: this repository)",
    )
    parser.add_argument("--no-cache", action="store_true", help="no bytecode cache")
    parser.add_argument("--top", type=int, default=6, help="packages listed per command")
    parser.add_argument(
        "--million", action="store_true", help="also the 10^6-impact sweep (~10-40 s a run)"
    )
    parser.add_argument(
        "--strung", action="store_true", help="instead: a strung run file's check and simulate"
    )
    parser.add_argument(
        "--checks", action="store_true", help="instead: each command's checks of a run file"
    )
    parser.add_argument(
        "--help-commands",
        action="store_true",
        help="instead: --help of every command, what each imports and its time",
    )
    args = parser.parse_args(argv)
    trees = [t.resolve() for t in args.tree or [ROOT]]
    commands = QUICK if args.quick else {**COMMANDS, **(MILLION if args.million else {})}
    load_before = os.getloadavg()
    repeat = 0 if args.quick else args.repeat or 7
    rows: list[dict] = []
    with tempfile.TemporaryDirectory() as tmp:
        scratch = Path(tmp)
        if args.strung:
            (scratch / "strung.toml").write_text(STRUNG_RUN)
            commands = strung_commands(scratch / "strung.toml")
        if args.checks:
            commands = check_commands(environment(trees[0], None), scratch, args.quick)
        envs = {}
        for i, tree in enumerate(trees):
            envs[tree] = environment(tree, None if args.no_cache else scratch / f"pyc{i}")
            found = subprocess.run(
                [sys.executable, "-c", "import fem_racket; print(fem_racket.__file__)"],
                env=envs[tree],
                cwd=scratch,
                capture_output=True,
                text=True,
                check=True,
            ).stdout.strip()
            if not Path(found).is_relative_to(tree):
                raise SystemExit(f"bench_cli: {tree} is not imported first (got {found})")
            if args.help_commands:
                continue
            for cmd, _ in () if args.quick else commands.values():  # writes the bytecode cache
                run(cmd, envs[tree], scratch)
        if args.help_commands:
            for tree in trees:  # writes the bytecode cache
                run(["--help"], envs[tree], scratch)
            rows = help_rows(trees, envs, scratch, repeat, args.quick)
            load = os.getloadavg()
            print(f"load average (1 min) {load_before[0]:.1f} before, {load[0]:.1f} after")
            for i, tree in enumerate(trees):
                print(f"  [{i}] {tree}")
            return rows
        walls: dict[tuple[str, Path], list[float]] = {}
        cpus: dict[tuple[str, Path], list[float]] = {}
        costs: dict[tuple[str, Path], dict[str, float]] = {}
        for _ in range(repeat):
            for label, (cmd, _) in commands.items():
                for tree in trees:
                    wall, _, cpu = run(cmd, envs[tree], scratch)
                    walls.setdefault((label, tree), []).append(wall)
                    cpus.setdefault((label, tree), []).append(cpu)
        for label, (cmd, _) in commands.items():
            for tree in trees:
                wall, err, cpu = run(cmd, envs[tree], scratch, ("-X", "importtime"))
                costs[(label, tree)] = import_costs(err)
                if args.quick:  # the smoke test times this run alone
                    walls[(label, tree)], cpus[(label, tree)] = [wall], [cpu]
    cache = "no bytecode cache" if args.no_cache else "bytecode cached"
    if args.quick and not args.no_cache:
        cache = "bytecode cache not warmed up"
    runs = "1 run under -X importtime" if args.quick else f"median (fastest) of {repeat}"
    load = os.getloadavg()
    print(f"load average (1 min) {load_before[0]:.1f} before, {load[0]:.1f} after")
    print(f"wall time [s] of python -m fem_racket, {runs}, {cache}; CPU [s] median, all processes")
    for i, tree in enumerate(trees):
        print(f"  [{i}] {tree}")
    head = "".join(f"{f'[{i}]':>28}" for i in range(len(trees)))
    width = max(30, *map(len, commands))
    print(f"{'command':<{width}}{head}{'target':>8}")
    for label, (_, target) in commands.items():
        cells = ""
        for tree in trees:
            w = walls[(label, tree)]
            cpu = statistics.median(cpus[(label, tree)])
            rows.append(
                dict(
                    command=label,
                    tree=str(tree),
                    wall_s=statistics.median(w),
                    fastest_s=min(w),
                    cpu_s=cpu,
                    target_s=target,
                    imports_s=costs[(label, tree)],
                )
            )
            cells += f"{statistics.median(w):9.3f} ({min(w):.3f}) cpu {cpu:.3f}"[-28:].rjust(28)
        print(f"{label:<{width}}{cells}{'' if target is None else f'{target:8.2f}'}")
    print(f"\nimport time [s] by package, own time of its modules (one -X importtime run; {cache})")
    for label in commands:
        for i, tree in enumerate(trees):
            top = sorted(costs[(label, tree)].items(), key=lambda kv: -kv[1])[: args.top]
            shown = ", ".join(f"{name} {s:.3f}" for name, s in top)
            print(f"{label:<{width}}[{i}] {shown}")
    return rows


if __name__ == "__main__":
    main()
