"""``load_config(f).sweep()`` runs the cases where ``fem-racket sweep --config f`` runs them
(issue 21.7): ``[sweep]``'s ``serial``, ``workers`` and ``scheduler`` are taken as the command
takes them (they were dropped: the dataset said another backend), the method's ``workers`` and
``backend`` winning as the command line's options do; and every run key is checked as the
command checks it (a bad one was accepted)."""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
from clirun import file_refused_alike, run

from fem_racket import load_config

SWEEP = "[frame]\nelements = 6\n[sweep]\nposition = [0.6, 0.7]\nspeed = [20.0, 30.0]\n"


@pytest.mark.parametrize(
    ("keys", "argv", "kwargs", "backend"),
    [
        ("workers = 2\n", (), {}, "processes"),  # a local pool of 2
        ("serial = true\n", ("--workers", "2"), {"workers": 2}, "processes"),  # the caller's
        ("", ("--serial",), {"backend": "serial"}, "serial"),
    ],
    ids=["workers", "caller-workers", "caller-serial"],  # (serial and workers: refused, see
    # tests/cli/test_refusals_solver.py; the file's workers used to be dropped)
)
def test_the_cases_run_where_the_command_runs_them(cwd, capsys, keys, argv, kwargs, backend):
    xr = pytest.importorskip("xarray")
    Path("run.toml").write_text(SWEEP + keys)
    code, _, err = run(capsys, "sweep", "--config", "run.toml", *argv, "--out", "s.nc", "--quiet")
    assert code == 0, err
    ds = load_config("run.toml").sweep(**kwargs)
    with xr.open_dataset("s.nc") as theirs:
        assert ds.attrs["backend"] == theirs.attrs["backend"] == backend
        for name in ("cor", "contact_time_s"):
            np.testing.assert_array_equal(ds[name].values, theirs[name].values)


@pytest.mark.parametrize(
    ("keys", "words"),
    [
        ("workers = 1.5\n", "sweep.workers = 1.5 is not allowed: must be an integer"),
        ("workers = 0\n", "workers = 0 is not allowed: must be an integer >= 1"),
        ("serial = 3\n", "sweep.serial = 3 is not allowed: must be true or false"),
        ("scheduler = 3\n", "scheduler = '3' is not allowed: must look like tcp://HOST:PORT"),
        ("restart = 3\n", "sweep.restart = 3 is not allowed: must be true or false"),
        ("overwrite = 2\n", "sweep.overwrite = 2 is not allowed: must be true or false"),
        ("json = 2\n", "sweep.json = 2 is not allowed: must be true or false"),
    ],
)
def test_the_run_keys_are_refused_alike(cwd, capsys, keys, words):
    argv = ("sweep", "--config", "run.toml", "--out", "s.nc", "--quiet")
    file_refused_alike(capsys, SWEEP + keys, argv, lambda c: c.sweep(), words, start=True)
