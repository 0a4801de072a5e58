"""Start-up (issue 13, item 4): a command imports only what it needs.

Each check runs in a fresh interpreter and reads ``sys.modules`` after the command: no timings,
so load on the machine cannot fail it. What each command must not import, and why it need not:

- ``import fem_racket`` and ``fem-racket --help``: no numerical or file library at all, not
  even numpy (the public names are imported on first use; BLAS is pinned to one thread once the
  arguments are parsed), nor the installed metadata (the version is read when asked for);
- every ``fem-racket COMMAND --help``, and a usage error (the same parser is built): no scipy,
  file, plotting or solver library; numpy only through the contact laws' registry (the commands
  taking a law list each law's parameters from its class), none for the commands without one.
  The names, choices and defaults the parsers show live in small constant modules of the layers
  that own them (``frame/constants.py``, ``impact/constants.py``, ``studies/backends.py``,
  ``studies/design/methods.py`` ...).
- ``simulate`` without ``--out``: no scipy at all (the modes come from numpy's dense eigen-solver
  on the frame's diagonals, the engine is numpy), and it writes nothing (no xarray, netCDF,
  dask, plotting or VTK).
- ``sweep`` over the exact engine: netCDF4 writes its file from the arrays, without xarray
  (which imports dask, dask.array and through them scipy, and dask.distributed to write), so
  no xarray, pandas or dask, and of scipy only what numba (the engine's compiled kernels)
  imports itself; ``--help`` and ``simulate`` (one impact, the numpy path) no numba.
- ``config --check`` (every command's checks on a run file, no computation, no file): no scipy
  at all, and none of the libraries the commands' work uses - scipy.optimize for calibrate,
  pyvista and imageio for export-vtk and animate, SALib (and pandas) for sensitivity, distributed
  for a sweep on a Dask scheduler: the checks only find them (a missing one is still refused),
  the work imports them.
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]

#: Heavy libraries, and the commands that may import them.
PLOTTING = ("matplotlib", "pyvista", "vtk", "vtkmodules", "imageio")
FILES = ("xarray", "pandas", "netCDF4", "h5py", "meshio", "dask", "distributed")
SOLVERS = ("skfem", "scipy.sparse.linalg", "scipy.optimize", "scipy.integrate", "sksundae")
OTHERS = ("pymoo", "SALib", "tqdm", "numba")

PROBE = """
import json, sys
argv = json.loads(sys.argv[1])
if argv is None:
    import fem_racket
else:
    from fem_racket.cli import main
    code = main(argv)
    assert code == 0, code
print(json.dumps(sorted(sys.modules)))
"""


def probe(script: str, argv: list[str] | None, tmp_path: Path):
    """Run ``script`` with ``ARGV`` (as JSON) in a fresh interpreter in ``tmp_path``: the JSON
    of its last printed line."""
    env = dict(os.environ, PYTHONPATH=str(ROOT))
    done = subprocess.run(
        [sys.executable, "-c", script, json.dumps(argv)],
        cwd=tmp_path,
        env=env,
        capture_output=True,
        text=True,
        timeout=120,
    )
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout.splitlines()[-1])


def imported(argv: list[str] | None, tmp_path: Path) -> set[str]:
    """Modules loaded after ``fem-racket ARGV`` (after ``import fem_racket`` when None)."""
    return set(probe(PROBE, argv, tmp_path))


def loaded(modules: set[str], names: tuple[str, ...]) -> list[str]:
    """The ``names`` (packages or modules) of which anything is in ``modules``."""
    return [n for n in names if any(m == n or m.startswith(n + ".") for m in modules)]


@pytest.mark.parametrize(
    "argv", [None, ["--help"], ["simulate", "--help"]], ids=["import", "help", "simulate-help"]
)
def test_package_and_help_import_no_heavy_library(argv, tmp_path):
    modules = imported(argv, tmp_path)
    assert not loaded(modules, ("scipy", *SOLVERS, *FILES, *PLOTTING, *OTHERS))
    if argv is None:  # the package alone: its public names wait for first use
        assert {m for m in modules if m.startswith("fem_racket")} == {"fem_racket"}
    if argv != ["simulate", "--help"]:  # its --law options: the contact laws (numpy)
        assert "numpy" not in modules
    # the version (installed metadata) is looked up only when asked for
    assert "importlib.metadata" not in modules


def test_help_lists_the_commands_without_their_modules(tmp_path):
    """``fem-racket --help`` lists each command from its name and summary
    (:data:`fem_racket.cli.commands.COMMANDS`): no command's module, and of the package only the
    command line's own entry (its parser, signals, run-file hook) and the base layer it uses
    (validation, outputs) - none of the library the commands' option defaults import, nor the
    BLAS pinning of studies.executors (after the arguments are parsed)."""
    modules = imported(["--help"], tmp_path)
    rooms = ("frame", "contact", "strings", "impact", "studies", "io", "paper")
    assert not loaded(modules, tuple(f"fem_racket.{room}" for room in rooms))
    assert not [m for m in modules if m.startswith("fem_racket.cli.commands.")]


HELP_PROBE = """
import contextlib, io, json, sys, traceback

class FirstNumpy:
    # the package module whose import statement first imports numpy (None: none did)
    by = None

    def find_spec(self, name, path=None, target=None):
        if name == "numpy" and FirstNumpy.by is None:
            names = (f.f_globals.get("__name__", "") for f, _ in traceback.walk_stack(None))
            FirstNumpy.by = next((n for n in names if n.startswith("fem_racket")), "?")
        return None

sys.meta_path.insert(0, FirstNumpy())
from fem_racket.cli import main
out = io.StringIO()
with contextlib.redirect_stdout(out):
    code = main(json.loads(sys.argv[1]))
print(json.dumps(dict(code=code, out=out.getvalue(), numpy_by=FirstNumpy.by,
                      modules=sorted(sys.modules))))
"""


def parse_only(argv: list[str], tmp_path: Path) -> dict:
    """``fem-racket ARGV`` in a fresh interpreter: its exit code, standard output, the package
    module that first imported numpy (None: none did) and every module loaded."""
    return probe(HELP_PROBE, argv, tmp_path)


#: The commands whose parsers take no contact law: no numpy at all for their ``--help``.
LAWLESS = ("modes", "fit", "customise", "closest", "compare", "refine", "config")


def _commands() -> list[str]:
    from fem_racket.cli import COMMANDS

    return list(COMMANDS)


@pytest.mark.parametrize("name", _commands())
def test_command_help_and_usage_error_import_no_heavy_library(name, tmp_path):
    """``COMMAND --help`` prints its help and ``COMMAND --no-such-option`` is refused (exit 2),
    each importing no scipy, file, plotting or solver library (the values the parser shows come
    from the layers' constant modules); numpy only through the contact laws' registry, whose
    classes the ``--law`` options list, and not at all for a command taking no law."""
    shown = parse_only([name, "--help"], tmp_path)
    assert shown["code"] == 0 and shown["out"].startswith(f"usage: fem-racket {name} ")
    wrong = parse_only([name, "--no-such-option"], tmp_path)
    assert wrong["code"] == 2 and wrong["out"] == ""
    for run in (shown, wrong):
        assert not loaded(set(run["modules"]), ("scipy", *SOLVERS, *FILES, *PLOTTING, *OTHERS))
        if name in LAWLESS:
            assert run["numpy_by"] is None
        else:
            assert run["numpy_by"] is None or run["numpy_by"].startswith("fem_racket.contact.")


#: What a command's ``--help`` needs not import: the run-file reader (``--config`` is read after
#: parsing), mesh files read and written, the plausibility checks, and each command's own
#: run-time modules.
RUN_ONLY = (
    "fem_racket.io.config",
    "fem_racket.io.config_file",
    "fem_racket.io.config_unused",
    "fem_racket.io.mesh_files",
    "fem_racket.io.racket_files",
    "fem_racket.io.customise_files",
    "fem_racket.frame.plausible",
)
RUN_ONLY_OF = {
    "simulate": ("fem_racket.impact.simulate", "fem_racket.io.impact_provenance"),
    "modes": ("fem_racket.frame.catalogue", "fem_racket.io.config_keys"),
    "fit": ("fem_racket.io.config_keys",),
    "customise": ("fem_racket.io.map_files",),
    "map": ("fem_racket.io.map_files", "fem_racket.studies.grid"),
    "sweep": ("fem_racket.studies.sweep", "fem_racket.studies.checkpoint"),
}


@pytest.mark.parametrize("name", sorted(RUN_ONLY_OF))
def test_command_help_imports_no_run_time_module(name, tmp_path):
    modules = imported([name, "--help"], tmp_path)
    assert not loaded(modules, (*RUN_ONLY, *RUN_ONLY_OF[name]))


@pytest.mark.parametrize("swing", [[], ["--racket-speed", "10"]], ids=["at-rest", "swing"])
def test_simulate_imports_only_the_engine(swing, tmp_path):
    modules = imported(["simulate", "--speed", "20", "--position", "0.75", *swing], tmp_path)
    assert "fem_racket.impact.exact.single" in modules  # the engine path did run
    assert not loaded(modules, ("scipy", *SOLVERS, *FILES, *PLOTTING, *OTHERS))
    # nor the other commands, nor the library's drawing and study modules
    others = (
        "fem_racket.cli.commands.sweep",
        "fem_racket.cli.commands.vtk",
        "fem_racket.cli.commands.reproduce",
    )
    assert not loaded(modules, (*others, "fem_racket.io.plotting", "fem_racket.paper"))


def test_simulate_with_histories_writes_without_file_libraries(tmp_path):
    modules = imported(["simulate", "--out", str(tmp_path / "r.csv")], tmp_path)
    assert (tmp_path / "r.csv").is_file()
    assert not loaded(modules, ("skfem", *FILES, *PLOTTING, *OTHERS))


@pytest.mark.parametrize(
    "law", [[], ["--law", "kawazoe-1997-nonlinear"]], ids=["engine", "law-kernels"]
)
def test_sweep_writes_without_xarray_or_dask(law, tmp_path):
    out = tmp_path / "s.nc"
    argv = ["sweep", "--position", "0.6,0.8", *law, "--out", str(out), "--quiet"]
    modules = imported(argv, tmp_path)
    assert out.is_file() and "netCDF4" in modules
    # numba (the engine's compiled kernels, issue 27) imports scipy and scipy.linalg itself (its
    # version check and LAPACK bindings); the rest of scipy stays out
    heavy = ("xarray", "pandas", "dask", "distributed", "scipy.sparse", *SOLVERS, *PLOTTING)
    assert "numba" in modules and not loaded(modules, heavy)


#: A run file with a table for each command whose work uses a heavy library (calibrate:
#: scipy.optimize; export-vtk, animate: pyvista, imageio; sensitivity: SALib; sweep on a Dask
#: scheduler: distributed), not the default values, so its check takes the paths these choose.
CHECKED_RUN = """[impact]
position_x_over_l = 0.7
[sweep]
position = "0.6:0.9:4"
scheduler = "tcp://127.0.0.1:1"
[calibrate]
family = "hunt-crossley"
targets = "itf"
[vtk]
frames = 11
[animate]
out = "impact.mp4"
[sensitivity]
designs = 64
"""


def test_run_file_check_imports_no_library_of_the_commands_work(tmp_path):
    run_file = tmp_path / "run.toml"
    run_file.write_text(CHECKED_RUN)
    modules = imported(["config", "--check", str(run_file)], tmp_path)
    # the checks did run: calibrate's (its study module), the animation's targets, the design
    assert {"fem_racket.studies.calibrate", "fem_racket.io.animate"} <= modules
    assert "fem_racket.studies.design.problem" in modules
    heavy = ("scipy", *SOLVERS, *FILES, *PLOTTING, *OTHERS)
    assert not loaded(modules, heavy) and list(tmp_path.iterdir()) == [run_file]


@pytest.mark.parametrize(
    ("module", "needs"),
    [
        ("imageio", "fem-racket animate"),
        ("SALib", "fem-racket sensitivity"),
        ("distributed", "fem-racket sweep would refuse it: a Dask scheduler (--scheduler)"),
    ],
)
def test_run_file_check_still_refuses_a_missing_library(
    capsys, monkeypatch, tmp_path, module, needs
):
    """The checks find a library without importing it, and refuse one that is missing as the
    command would (``fem_racket.extras.check_installed``; tests/cli/test_extras.py: the command)."""
    from tests.clirun import run

    run_file = tmp_path / "run.toml"
    run_file.write_text(CHECKED_RUN)
    monkeypatch.setitem(sys.modules, module, None)  # import fails as if not installed
    code, out, err = run(capsys, "config", "--check", run_file)
    assert (code, out) == (2, "") and err.count("\n") == 1
    assert f"{needs} needs {module}, which is not installed: pip install" in err


def test_version_is_looked_up_when_asked(capsys):
    from importlib.metadata import version

    import fem_racket
    from fem_racket.cli import main

    assert main(["--version"]) == 0
    assert capsys.readouterr().out == f"fem-racket {version('fem_racket')}\n"
    assert fem_racket.__version__ == version("fem_racket")


def test_the_command_table_names_each_commands_module():
    from fem_racket.cli import COMMANDS, build_parser

    def commands(parser) -> set[str]:
        subs = next(a for a in parser._actions if hasattr(a, "choices") and a.choices)
        return set(subs.choices)

    assert commands(build_parser()) == set(COMMANDS)  # every module's commands are listed
    for name in COMMANDS:  # and each name's module registers it
        assert name in commands(build_parser([name, "--help"]))
    assert commands(build_parser(["-v", "sweep"])) == {"sweep"}
    assert commands(build_parser(["simulat"])) == set(COMMANDS)  # a typo sees every choice


def test_bench_of_the_checks_runs(capsys):
    """``scripts/bench_cli.py --checks`` (here ``--quick``: the check alone, once): its run file
    (the example and the tables it leaves commented out) passes ``config --check``, whose
    imports it lists; tests/paper/test_figure_scripts.py runs its other modes."""
    from script_loader import load_script

    rows = load_script("bench_cli").main(["--checks", "--quick"])
    assert [r["command"] for r in rows] == ["config --check (every table)"]
    assert "fem_racket" in rows[0]["imports_s"] and "scipy" not in rows[0]["imports_s"]
    assert "import time [s] by package" in capsys.readouterr().out
