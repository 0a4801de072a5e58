"""Outputs written all-or-nothing: :func:`atomic_outputs` and its one-target forms.

Each target of a command is written to a temporary beside it,
``.<name>.<pid>-<random>.part<suffix>`` (never longer than the folder allows: a long name is cut
and completed by a hash), and all are moved into place together once every one is complete; an
old output is kept aside until then and put back if a move fails. On any failure the
temporaries and the folders made for them are removed, and an ``OSError`` comes out as
:class:`~fem_racket.outputs.checks.OutputError` naming the target. Temporaries of a run that was
killed (its process is gone) are removed by the next run writing the same target.
"""

from __future__ import annotations

import hashlib
import logging
import os
import re
import secrets
import shutil
from collections.abc import Iterator, Sequence
from contextlib import contextmanager
from pathlib import Path

from fem_racket.outputs.checks import Target, check_targets, name_max, refuse
from fem_racket.outputs.faults import as_output_error

__all__ = [
    "atomic_folder",
    "atomic_output",
    "atomic_outputs",
    "deferred_interrupts",
    "deferring",
    "record_interrupt",
]

log = logging.getLogger(__name__)

#: An interruption already raised (by a signal handler) that may have been swallowed: raised in a
#: ``__del__`` or a weakref callback, Python prints and drops it. No set of outputs is moved into
#: place once one is recorded (:func:`record_interrupt`), so "interrupted" always means "nothing
#: written", however the interruption was delivered.
_interrupted: type[BaseException] | None = None


# -- temporary names ------------------------------------------------------------------------
_TAIL_ROOM = len(".4294967295-00000000.part")  # pid (at most 10 digits), token, kind


def _suffix(path: Path) -> str:
    # Writers choose the format by suffix (xarray, matplotlib, Pillow): keep a short one.
    return path.suffix if len(os.fsencode(path.suffix)) <= 16 else ""


def _key(path: Path, limit: int) -> str:
    """The target's name, cut (and completed by a hash) to leave room for the temporary tail."""
    room = limit - 1 - _TAIL_ROOM - len(os.fsencode(_suffix(path)))
    raw = os.fsencode(path.name)
    if len(raw) <= room:
        return path.name
    digest = hashlib.sha256(raw).hexdigest()[:12]
    cut = raw[: room - 13].decode("utf-8", "ignore")  # never half a character
    return f"{cut}~{digest}"


def _temp_path(path: Path, kind: str) -> Path:
    folder = path.absolute().parent
    key = _key(path, name_max(folder))
    return folder / f".{key}.{os.getpid()}-{secrets.token_hex(4)}.{kind}{_suffix(path)}"


def _alive(pid: int) -> bool:
    if pid == os.getpid():
        return True
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except (PermissionError, OverflowError):
        return True
    return True


def _remove(path: Path) -> None:
    try:
        if path.is_dir() and not path.is_symlink():
            shutil.rmtree(path)
        else:
            path.unlink()
    except FileNotFoundError:
        pass


def _remove_stale(path: Path) -> None:
    """Remove temporaries of ``path`` left by runs whose process is gone."""
    folder = path.absolute().parent
    if not folder.is_dir():
        return
    key = _key(path, name_max(folder))
    pattern = re.compile(
        re.escape(f".{key}.") + r"(\d+)-[0-9a-f]{8}\.(?:part|old)" + re.escape(_suffix(path)) + "$"
    )
    for entry in folder.iterdir():
        m = pattern.match(entry.name)
        if m and not _alive(int(m.group(1))):
            log.info("removing %s, left by an interrupted run", entry)
            try:
                _remove(entry)
            except OSError:  # not ours to fix here; the new run does not need it gone
                pass


# -- writing a set of outputs -----------------------------------------------------------------
def _umask_mode(mode: int) -> int:
    """``mode`` less the process umask."""
    mask = os.umask(0)
    os.umask(mask)
    return mode & ~mask


def _make_folders(folder: Path, made: list[Path]) -> None:
    missing = []
    probe = folder.absolute()
    while not probe.exists():
        missing.append(probe)
        probe = probe.parent
    for f in reversed(missing):
        f.mkdir()
        made.append(f)


def _make_temp(tmp: Path, folder: bool) -> None:
    if folder:
        tmp.mkdir(mode=0o777)
    else:
        os.close(os.open(tmp, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o666))


def record_interrupt(kind: type[BaseException] | None) -> None:
    """Record an interruption raised by a signal handler (None clears it): every later
    :func:`atomic_outputs` raises ``kind`` instead of moving its outputs into place."""
    global _interrupted
    _interrupted = kind


#: Depth of :func:`deferred_interrupts` blocks around the current code.
_deferring = 0


@contextmanager
def deferred_interrupts() -> Iterator[None]:
    """A block that a signal handler does not interrupt (see :func:`deferring`): an
    interruption recorded meanwhile (:func:`record_interrupt`) is raised when it ends. For code
    that cannot stop halfway: an import of a compiled library (VTK's, interrupted, fails later
    with an ImportError or a crash) or Python called back from C++ (VTK logs the exception)."""
    global _deferring
    _deferring += 1
    try:
        yield
    finally:
        _deferring -= 1
    if _deferring == 0 and _interrupted is not None:
        raise _interrupted()


def deferring() -> bool:
    """True inside :func:`deferred_interrupts`: a signal handler should only record."""
    return _deferring > 0


def _commit(targets: Sequence[Target], temps: Sequence[Path], overwrite: bool) -> None:
    """Move every temporary into place; on a failure put every old output back."""
    if _interrupted is not None:
        raise _interrupted()
    moved: list[tuple[Target, Path | None]] = []
    try:
        for t, tmp in zip(targets, temps, strict=True):
            if not (tmp.exists() or tmp.is_symlink()):  # removed by the block: left as it is
                continue
            if not t.folder:
                os.chmod(tmp, _umask_mode(0o666))
            old = None
            if t.path.exists() or t.path.is_symlink():
                if not overwrite:
                    raise refuse(t, "it was created during the run: pass --overwrite to replace it")
                old = _temp_path(t.path, "old")
            moved.append((t, old))  # listed first, so the roll-back sees any step done
            if old is not None:
                os.replace(t.path, old)
            os.replace(tmp, t.path)
    except BaseException:
        for t, old in reversed(moved):
            if old is None:
                if t.path.exists():
                    _remove(t.path)
            elif old.exists():
                if t.path.exists():
                    _remove(t.path)
                os.replace(old, t.path)
        raise
    for _, old in moved:
        if old is not None:
            _remove(old)


@contextmanager
def atomic_outputs(
    targets: Sequence[Target | str | os.PathLike], *, overwrite: bool = False
) -> Iterator[list[Path]]:
    """Yield one temporary path per target; move them all into place when the block succeeds.

    Files keep the suffix of their target so writers that pick a format by suffix work
    unchanged; folder targets get an empty temporary folder; a temporary the block removes
    leaves its target as it is (an output that would not change). Every target is checked first
    (:func:`check_targets`). On any exception - or a failure while moving - the temporaries and
    the folders created for them are removed and every existing output is kept; an ``OSError``
    comes out as :class:`OutputError` naming the target.
    """
    items = check_targets(targets, overwrite=overwrite)
    made: list[Path] = []
    temps: list[Path] = []
    ok = False
    try:
        for t in items:
            _make_folders(t.path.parent, made)
            _remove_stale(t.path)
            temps.append(_temp_path(t.path, "part"))  # listed before it exists: the
            _make_temp(temps[-1], t.folder)  # clean-up finds it whenever an interruption comes
        yield list(temps)
        _commit(items, temps, overwrite)
        ok = True
    except (OSError, RuntimeError) as exc:
        fault = as_output_error(exc, items, temps)
        if fault is exc:
            raise
        raise fault from None
    finally:
        for tmp in temps:
            if tmp.exists() or tmp.is_symlink():
                try:
                    _remove(tmp)
                except OSError:
                    log.warning("could not remove the temporary %s", tmp)
        if not ok:
            for f in reversed(made):
                try:
                    f.rmdir()
                except OSError:
                    break


@contextmanager
def atomic_output(
    path: str | os.PathLike, *, overwrite: bool = False, name: str = "out"
) -> Iterator[Path]:
    """One file written all-or-nothing: see :func:`atomic_outputs`."""
    with atomic_outputs([Target(Path(path), name=name)], overwrite=overwrite) as (tmp,):
        yield tmp


@contextmanager
def atomic_folder(
    path: str | os.PathLike,
    *,
    overwrite: bool = False,
    marker: str | None = None,
    name: str = "out",
) -> Iterator[Path]:
    """One folder (e.g. a VTK series) written all-or-nothing: see :func:`atomic_outputs` and,
    for ``marker``, :func:`check_output_folder`."""
    target = Target(Path(path), folder=True, marker=marker, name=name)
    with atomic_outputs([target], overwrite=overwrite) as (tmp,):
        yield tmp
