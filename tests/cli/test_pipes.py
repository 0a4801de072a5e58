"""Output piped into a reader that stops early (``fem-racket modes | head -1``): no traceback,
exit code 141 (128 + SIGPIPE, as for a Unix tool), files already written are complete."""

import os
import subprocess
import sys
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]


def _env():
    # This checkout's package, whatever the working folder (python -m puts the cwd first).
    env = dict(os.environ)
    env["PYTHONPATH"] = os.pathsep.join([str(ROOT), env.get("PYTHONPATH", "")]).rstrip(os.pathsep)
    return env


def _closed_reader(*argv: str, cwd: Path) -> tuple[int, str]:
    """Run the CLI with its stdout a pipe whose only reader is closed before it writes."""
    proc = subprocess.Popen(
        [sys.executable, "-m", "fem_racket", *argv],
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        cwd=cwd,
        env=_env(),
    )
    proc.stdout.close()  # the reader is gone: any write to stdout raises EPIPE
    with proc.stderr:
        err = proc.stderr.read().decode()
    return proc.wait(timeout=120), err


def test_modes_into_a_closed_pipe(tmp_path):
    code, err = _closed_reader("modes", cwd=tmp_path)
    assert code == 141 and err == ""


def test_sweep_into_a_closed_pipe_still_writes_the_whole_file(tmp_path):
    import xarray as xr

    code, err = _closed_reader(
        "sweep", "--speed", "20,30", "--serial", "--quiet", "--out", "s.nc", cwd=tmp_path
    )
    assert code == 141 and err == ""
    with xr.open_dataset(tmp_path / "s.nc") as ds:
        assert ds.sizes == {"speed": 2} and int(ds.attrs["failed_cases"]) == 0
    assert sorted(p.name for p in tmp_path.iterdir()) == ["s.nc"]


def test_shell_pipe_into_head(tmp_path):
    # A real `| head -1`: head may exit before or after the writes, so 0 or 141.
    cmd = f'{sys.executable} -m fem_racket modes | head -1; echo "rc=${{PIPESTATUS[0]}}"'
    res = subprocess.run(
        ["bash", "-c", cmd], capture_output=True, text=True, cwd=tmp_path, env=_env(), timeout=120
    )
    lines = res.stdout.splitlines()
    assert lines[0].startswith("mass") and lines[1] in ("rc=0", "rc=141")
    assert res.stderr == ""


def _run_with_stdout(argv: list[str], cwd: Path, stdout) -> subprocess.CompletedProcess:
    return subprocess.run(
        [sys.executable, "-m", "fem_racket", *argv],
        stdout=stdout,
        stderr=subprocess.PIPE,
        text=True,
        cwd=cwd,
        env=_env(),
        timeout=120,
    )


def test_closed_stdout_is_refused_before_any_work(tmp_path):
    # `fem-racket modes >&-`: before, an AttributeError traceback.
    cmd = f"{sys.executable} -m fem_racket simulate --out r.json >&-"
    res = subprocess.run(
        ["bash", "-c", cmd], capture_output=True, text=True, cwd=tmp_path, env=_env(), timeout=120
    )
    assert res.returncode == 2
    assert res.stderr == (
        "fem-racket: error: standard output is closed: give it a file, a pipe or /dev/null "
        "(> /dev/null)\n"
    )
    assert list(tmp_path.iterdir()) == []


@pytest.mark.skipif(not Path("/dev/full").exists(), reason="no /dev/full here")
@pytest.mark.parametrize("argv", [["modes"], ["simulate", "--json"], ["config", "--example"]])
def test_stdout_on_a_full_device_is_one_line_exit_1(tmp_path, argv):
    with open("/dev/full", "w") as full:
        res = _run_with_stdout(argv, tmp_path, full)
    assert res.returncode == 1
    assert (
        res.stderr
        == "fem-racket: error: cannot write to standard output: No space left on device\n"
    )
