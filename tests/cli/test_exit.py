"""The command's end (issue 27): run as the command, its objects are frozen for the garbage
collector at exit (:func:`fem_racket.cli._end_lightly`), so that Python's teardown does not walk
numba's objects again and again; what it wrote is whole, and a caller of :func:`main` in its
own process (a test, a notebook) keeps its collector as it was."""

from __future__ import annotations

import json
import os
import subprocess
import sys

import netCDF4
import numpy as np

import fem_racket.cli as cli
from fem_racket.cli import main
from fem_racket.studies.sweep import sweep_result

PROBE = """
import atexit, gc, sys
from fem_racket.cli import main
sys.argv = ["fem-racket", "--help"]
code = main()
before = gc.get_freeze_count()
atexit._run_exitfuncs()
print(code, before, gc.get_freeze_count() > 0)
"""


def test_the_command_freezes_its_objects_at_exit(capsys):
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(sys.path))
    done = subprocess.run(
        [sys.executable, "-c", PROBE], capture_output=True, text=True, check=True, env=env
    )
    assert done.stdout.split()[-3:] == ["0", "0", "True"]  # at exit, not before


def test_main_called_in_a_process_leaves_its_collector(monkeypatch, capsys):
    registered = []
    monkeypatch.setattr(cli.atexit, "register", registered.append)
    assert main(["--help"]) == 0
    assert registered == []


def test_a_sweep_run_as_the_command_writes_its_whole_file(tmp_path):
    """The netCDF file of ``python -m fem_racket sweep`` (a law's compiled batch) holds every
    value of the same sweep run here, bit for bit."""
    out = tmp_path / "law.nc"
    argv = ["sweep", "--law", "hunt-crossley", "--position", "0.6,0.8", "--speed", "20,30"]
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(sys.path))
    subprocess.run(
        [sys.executable, "-m", "fem_racket", *argv, "--out", str(out), "--quiet", "--json"],
        cwd=tmp_path, env=env, check=True, capture_output=True,
    )  # fmt: skip
    here = sweep_result(law="hunt-crossley", position=[0.6, 0.8], speed=[20, 30], progress=False)
    with netCDF4.Dataset(out) as ds:
        for name, (_, values, _) in here.data_variables().items():
            assert np.array_equal(ds[name][:].filled(np.nan), values, equal_nan=True), name
        assert json.loads(ds.getncattr("run_parameters"))["law"] == "hunt-crossley"
