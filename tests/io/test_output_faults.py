"""Faults while writing: every output all-or-nothing, one line naming the path and the reason.

Class by class (issue 12, item 3): destinations checked before the work (exit 2), names too long
for the file system, temporary names that never exceed the limit, temporaries of killed runs
removed by the next run, sets of files moved into place together (old outputs kept), and a full
disk during the run (exit 1, nothing left behind). The full disk is a small tmpfs where the
machine lets the tests mount one (root on Linux), else skipped; the same paths are covered
without mounting by an ``OSError(ENOSPC)`` injected at the write.
"""

from __future__ import annotations

import contextlib
import errno
import os
import subprocess
import sys
import time
from pathlib import Path

import pytest
from clirun import run

from fem_racket import InputError
from fem_racket.cli import main
from fem_racket.outputs import (
    OutputError,
    Target,
    atomic_output,
    atomic_outputs,
    check_output_path,
)

NAME_MAX = os.pathconf("/", "PC_NAME_MAX") if hasattr(os, "pathconf") else 255


def listing(folder: Path) -> list[str]:
    return sorted(str(p.relative_to(folder)) for p in folder.rglob("*"))


# -- bad destinations, found before any work (exit 2) ----------------------------------------
@pytest.mark.skipif(not Path("/proc/self").is_dir(), reason="needs Linux's /proc")
@pytest.mark.parametrize(
    "argv",
    [
        ["simulate", "--out", "/proc/x.json"],
        ["simulate", "--out", "/proc/x.csv"],
        ["sweep", "--serial", "--quiet", "--out", "/proc/x.nc"],
        ["refine", "--family", "uniform", "--elements", "5", "--plot", "/proc/x.png"],
        ["animate", "--out", "/proc/x.gif"],
        ["export-vtk", "--out", "/proc/vtk"],
        ["reproduce", "--quick", "--out", "paper", "--report", "/proc/R.md"],
        ["config", "--example", "--out", "/proc/x.toml"],
    ],
    ids=lambda a: a[0] + ":" + a[-1],
)
def test_a_folder_that_takes_no_file_is_refused_before_the_work(
    capsys, tmp_path, monkeypatch, argv
):
    # /proc's permission bits say root may write: only creating a file tells the truth.
    monkeypatch.chdir(tmp_path)
    code, _, err = run(capsys, *argv)
    assert code == 2, err
    assert err.count("\n") == 1 and "Traceback" not in err
    assert "cannot create a file in '/proc'" in err and f"= '{argv[-1]}'" in err
    assert listing(tmp_path) == []


def test_a_name_longer_than_the_file_system_allows_is_refused(capsys, tmp_path):
    long = "a" * (NAME_MAX + 5)
    for argv in (["simulate", "--out", tmp_path / f"{long}.json"],
                 ["simulate", "--out", tmp_path / long / "r.json"],
                 ["export-vtk", "--out", tmp_path / long]):  # fmt: skip
        code, _, err = run(capsys, *argv)
        assert code == 2 and err.count("\n") == 1, err
        assert "bytes long: at most" in err and "..." in err  # the long name is shortened
    assert listing(tmp_path) == []


def test_the_temporary_name_of_the_longest_allowed_name_fits(tmp_path):
    # Before: the temporary was 15 bytes longer than the name checked, so the longest names failed
    for stem in ("b" * (NAME_MAX - 5), "\u00e9" * ((NAME_MAX - 5) // 2)):  # 2-byte characters
        path = tmp_path / f"{stem}.json"
        with atomic_output(path) as tmp:
            assert len(os.fsencode(tmp.name)) <= NAME_MAX
            tmp.write_text("{}")
        assert path.read_text() == "{}"
        path.unlink()


def test_library_check_names_the_option(tmp_path):
    (tmp_path / "x.csv").write_text("old")
    with pytest.raises(InputError, match=r"^csv = '.*x\.csv' is not allowed: it already exists"):
        check_output_path(tmp_path / "x.csv", name="csv")


# -- temporaries of killed runs ---------------------------------------------------------------
def _dead_pid() -> int:
    proc = subprocess.Popen([sys.executable, "-c", "pass"])
    proc.wait()
    return proc.pid


def test_the_next_run_removes_temporaries_of_a_killed_run(tmp_path):
    path = tmp_path / "r.json"
    dead, alive = _dead_pid(), os.getppid()
    stale = tmp_path / f".r.json.{dead}-0123abcd.part.json"
    stale_dir = tmp_path / f".r.json.{dead}-89abcdef.old.json"
    other_run = tmp_path / f".r.json.{alive}-0123abcd.part.json"  # a run still going: kept
    unrelated = tmp_path / f".r.json.x.{dead}-0123abcd.part.json"  # another target's: kept
    for p in (stale, other_run, unrelated):
        p.write_text("{")
    stale_dir.mkdir()
    with atomic_output(path) as tmp:
        tmp.write_text("{}")
    assert listing(tmp_path) == sorted(p.name for p in (path, other_run, unrelated))


def test_export_killed_by_sigkill_leaves_a_part_folder_the_next_run_removes(tmp_path):
    env = dict(os.environ, PYTHONPATH=str(Path(__file__).resolve().parents[2]))
    argv = [
        sys.executable,
        "-m",
        "fem_racket",
        "export-vtk",
        "--out",
        "vtk",
        "--output-step",
        "5e-7",
    ]
    proc = subprocess.Popen(argv, cwd=tmp_path, env=env, stderr=subprocess.DEVNULL)
    try:
        start = time.monotonic()
        while not any(p.name.startswith(".vtk.") for p in tmp_path.iterdir()):
            assert time.monotonic() - start < 60 and proc.poll() is None, "no temporary"
            time.sleep(0.01)
        proc.kill()
    finally:
        proc.wait()
    assert [p.name.endswith(".part") for p in tmp_path.iterdir()] == [True]
    code = main(["export-vtk", "--out", str(tmp_path / "vtk"), "--frames", "3"])
    assert code == 0
    assert listing(tmp_path)[0] == "vtk" and all(not n.startswith(".") for n in listing(tmp_path))


# -- sets of outputs ------------------------------------------------------------------------------
def test_a_set_moves_into_place_together_and_a_failure_keeps_every_old_file(tmp_path, monkeypatch):
    a, b = tmp_path / "a.csv", tmp_path / "a.csv.json"
    a.write_text("old a")
    b.write_text("old b")
    real = os.replace
    moved = []

    def replace_failing_on_b(src, dst):  # the second move into place fails
        if Path(dst) == b and Path(src).name.endswith(".part.json"):
            raise OSError(errno.EIO, "Input/output error", str(dst))
        moved.append(dst)
        return real(src, dst)

    monkeypatch.setattr(os, "replace", replace_failing_on_b)
    with pytest.raises(OutputError, match=r"cannot write '.*a\.csv\.json': Input/output error"):
        with atomic_outputs([a, b], overwrite=True) as (ta, tb):
            ta.write_text("new a")
            tb.write_text("new b")
    assert a.read_text() == "old a" and b.read_text() == "old b"  # a was put back
    assert listing(tmp_path) == ["a.csv", "a.csv.json"]


def test_a_failure_inside_the_block_leaves_nothing_not_even_new_folders(tmp_path):
    targets = [Target(tmp_path / "new" / "deep" / "x.png", name="plot"),
               Target(tmp_path / "new" / "vtk", folder=True)]  # fmt: skip
    with pytest.raises(OutputError) as info, atomic_outputs(targets) as (png, folder):
        (folder / "frame_0000.vtu").write_text("half")
        raise OSError(errno.ENOSPC, "No space left on device", str(png))
    assert (
        str(info.value) == f"[Errno 28] cannot write '{targets[0].path}': No space left on device"
    )
    assert listing(tmp_path) == []


# -- a full disk during the run (exit 1) -----------------------------------------------------
def _full_disk_cases(folder: Path) -> list[list[str]]:
    return [
        ["simulate", "--output-step", "1e-7", "--out", f"{folder}/r.csv"],
        ["export-vtk", "--out", f"{folder}/vtk"],
        ["animate", "--frames", "20", "--size", "320x160", "--out", f"{folder}/a.gif"],
        ["sweep", "--serial", "--quiet", "--position", "0.5:0.9:1500", "--out", f"{folder}/s.nc"],
        ["refine", "--family", "uniform", "--elements", "5", "10", "--csv", f"{folder}/r2.csv",
         "--plot", f"{folder}/r2.png", "--dpi", "600"],
    ]  # fmt: skip


@contextlib.contextmanager
def _tmpfs(tmp_path: Path, size: str):
    """A tmpfs of ``size`` at ``tmp_path/mnt``, or skip where mounting is not permitted (not
    root, no tmpfs, a container without CAP_SYS_ADMIN)."""
    mnt = tmp_path / "mnt"
    mnt.mkdir()
    res = subprocess.run(["mount", "-t", "tmpfs", "-o", f"size={size}", "tmpfs", str(mnt)],
                         capture_output=True, text=True)  # fmt: skip
    if res.returncode != 0:
        pytest.skip(f"cannot mount a tmpfs here: {res.stderr.strip() or res.returncode}")
    try:
        yield mnt
    finally:
        subprocess.run(["umount", str(mnt)], check=True)


@pytest.fixture
def tiny_tmpfs(tmp_path):
    """A 64 KiB tmpfs (too small for any of these outputs) with ``old.txt`` (see ``_tmpfs``)."""
    with _tmpfs(tmp_path, "64k") as mnt:
        (mnt / "old.txt").write_text("kept")
        yield mnt


@pytest.mark.parametrize(
    "case", range(5), ids=["simulate", "export-vtk", "animate", "sweep", "refine"]
)
def test_full_disk_gives_one_line_exit_1_and_leaves_nothing(capsys, tiny_tmpfs, case):
    argv = _full_disk_cases(tiny_tmpfs)[case]
    code, _, err = run(capsys, *argv)
    assert code == 1, err
    assert "Traceback" not in err and err.startswith(f"fem-racket {argv[0]}: error: cannot write")
    assert "No space left on device" in err.splitlines()[0]
    left = [n for n in listing(tiny_tmpfs) if not n.startswith("s.nc.checkpoint")]
    assert left == ["old.txt"] and (tiny_tmpfs / "old.txt").read_text() == "kept"


def test_full_disk_without_mounting(capsys, tmp_path, monkeypatch):
    # The same class without a tmpfs: ENOSPC injected where Python writes the outputs' bytes.
    import pathlib

    real = pathlib.Path.write_bytes

    def full(self, data):
        if any(p.startswith(".") and ".part" in p for p in self.parts):  # an output's temporary
            raise OSError(errno.ENOSPC, "No space left on device", str(self))
        return real(self, data)

    monkeypatch.setattr(pathlib.Path, "write_bytes", full)
    (tmp_path / "vtk").mkdir()
    (tmp_path / "vtk" / "provenance.json").write_text("{}")  # an old export
    for argv in (
        ["export-vtk", "--out", tmp_path / "vtk", "--overwrite"],
        ["animate", "--frames", "5", "--size", "320x160", "--out", tmp_path / "a.gif"],
    ):
        code, _, err = run(capsys, *argv)
        assert code == 1 and err.count("\n") == 1, err
        assert f"cannot write '{argv[-1 if argv[0] == 'animate' else 2]}': No space left" in err
    assert listing(tmp_path) == ["vtk", "vtk/provenance.json"]


# -- round 3 (issue 22.5): every command's outputs as one set, faults named as what they are ---
@pytest.fixture
def small_tmpfs(tmp_path):
    """A 128 KiB tmpfs, or skip where mounting is not permitted (see ``_tmpfs``)."""
    with _tmpfs(tmp_path, "128k") as mnt:
        yield mnt


def _fill(folder: Path, leave: int) -> None:
    """Fill ``folder``'s file system but about ``leave`` bytes."""
    st = os.statvfs(folder)
    (folder / "fill").write_bytes(b"\0" * max(0, st.f_bavail * st.f_frsize - leave))


def test_map_writes_its_outputs_as_one_set_on_a_full_disk(capsys, small_tmpfs):
    # Before: a.png stayed and the netCDF fault read "Permission denied".
    _fill(small_tmpfs, 40_000)
    outs = [small_tmpfs / "a.png", small_tmpfs / "b.nc", small_tmpfs / "c.csv"]
    code, out, err = run(capsys, "map", "--out", *outs)
    assert code == 1 and out == "" and err.count("\n") == 1, err
    assert "No space left on device" in err and ".part" not in err
    assert any(f"cannot write '{p}'" in err for p in outs), err
    assert listing(small_tmpfs) == ["fill"]


def test_optimize_on_a_full_disk_gives_one_line_not_a_netcdf_traceback(capsys, small_tmpfs):
    # The history's batches fit, the study's folder does not (before: 52 lines ending in
    # "RuntimeError: NetCDF: HDF error" when history.nc met the full disk). The history stays
    # for a rerun to resume.
    _fill(small_tmpfs, 28_000)
    out = small_tmpfs / "d"
    code, _, err = run(capsys, "optimize", "--maxiter", "1", "--zone-points", "3", "--out", out)
    assert code == 1 and err.count("\n") == 1 and "Traceback" not in err, err
    assert f"cannot write '{out}': No space left on device" in err
    assert not out.exists() and not [n for n in listing(small_tmpfs) if ".part" in n]


def test_fit_on_a_full_disk_names_the_mesh_not_its_temporary(capsys, small_tmpfs):
    # Before: exit 2 (bad input) naming '.r.vtu.<pid>-<hex>.part.vtu'.
    _fill(small_tmpfs, 1_000)
    out = small_tmpfs / "r.vtu"
    argv = ["--length", "0.685", "--mass", "0.318", "--balance", "0.32", "--swing-weight", "316"]
    code, _, err = run(capsys, "fit", *argv, "--out", out)
    assert code == 1 and err.count("\n") == 1, err
    assert f"cannot write '{out}': No space left on device" in err and ".part" not in err
    assert listing(small_tmpfs) == ["fill"]


@pytest.mark.parametrize(
    "argv",
    [
        ["simulate", "--out", "link.json"],
        ["sweep", "--serial", "--quiet", "--out", "link.nc"],
        ["map", "--out", "link.png"],
        ["export-vtk", "--out", "link"],
        ["optimize", "--maxiter", "1", "--out", "link"],
        ["sensitivity", "--designs", "40", "--out", "link.png"],
    ],
    ids=lambda a: a[0],
)
def test_a_dangling_link_at_out_is_refused_before_any_work(capsys, tmp_path, monkeypatch, argv):
    # Before: accepted by the check, then "it was created during the run" after all the work.
    monkeypatch.chdir(tmp_path)
    os.symlink(tmp_path / "gone" / "x", tmp_path / argv[-1])
    t0 = time.perf_counter()
    code, _, err = run(capsys, *argv)
    assert code == 2 and err.count("\n") == 1, err
    assert f"out = '{argv[-1]}' is not allowed: it is a symbolic link to" in err
    assert "which does not exist" in err and time.perf_counter() - t0 < 10
    assert listing(tmp_path) == [argv[-1]] and (tmp_path / argv[-1]).is_symlink()


def test_overwrite_replaces_a_dangling_link(capsys, tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    os.symlink("nowhere.json", "r.json")
    assert run(capsys, "simulate", "--out", "r.json", "--overwrite")[0] == 0
    assert not Path("r.json").is_symlink() and Path("r.json").stat().st_size > 0


@pytest.mark.parametrize(
    "argv",
    [["map", "--out", "m.png", "m.png"], ["map", "--out", "m.csv", "./m.csv"]],
    ids=["same", "same-spelled-otherwise"],
)
def test_the_same_output_twice_is_refused_before_any_work(capsys, tmp_path, monkeypatch, argv):
    # Before: the second write refused the first one's file after the work.
    monkeypatch.chdir(tmp_path)
    code, _, err = run(capsys, *argv)
    assert code == 2 and err.count("\n") == 1, err
    assert "the same path is given for two outputs of this command" in err
    assert listing(tmp_path) == []


def test_sensitivity_writes_its_chart_and_json_as_one_set(capsys, small_tmpfs):
    _fill(small_tmpfs, 20_000)
    out = small_tmpfs / "s.png"
    code, _, err = run(capsys, "sensitivity", "--designs", "40", "--zone-points", "3", "--out", out)
    assert code == 1 and err.count("\n") == 1, err
    assert f"cannot write '{out}': No space left on device" in err
    assert listing(small_tmpfs) == ["fill"]
