"""Resumable sweeps: finished cases kept in a folder beside the output until it is written.

The folder ``<output>.checkpoint/`` holds ``spec.json`` (the sweep's description and its
SHA-256 digest), a ``lock`` file and one ``chunk-<first case>-<count>-<checksum>.npy`` per
finished chunk: an array of rows ``[case index, result values...]``. The checksum is the first
16 hex digits of SHA-256 over the sweep's digest and the file's bytes, so a chunk that is
truncated, empty, altered or from another sweep fails it: such a chunk is never merged - it is
deleted with a warning and its cases are computed again. A damaged ``spec.json`` is rewritten
(every chunk is checked on its own); a readable one of another sweep is refused, naming
``--restart``.

Every file is written to a temporary name and renamed into place, so a run killed at any moment
leaves only whole chunks (stray temporary files are removed on the next start). The lock
(``flock``, released by the kernel when the process ends, however it ends) stops a second sweep
on the same output while one runs. The folder is removed once the result file has been written.
"""

from __future__ import annotations

import hashlib
import io
import json
import logging
import os
import re
import shutil
import tempfile
from pathlib import Path
from typing import Any

import numpy as np

from fem_racket.outputs import OutputError
from fem_racket.validation import InputError, show_path

try:
    import fcntl
except ImportError:  # pragma: no cover - not POSIX: no lock
    fcntl = None  # type: ignore[assignment]

__all__ = [
    "Checkpoint",
    "acquire_lock",
    "checkpoint_path",
    "checksum",
    "make_folder",
    "stored_digest",
    "write_atomic",
]

log = logging.getLogger(__name__)

SPEC_NAME = "spec.json"
LOCK_NAME = "lock"
_CHUNK = re.compile(r"^chunk-(\d+)-(\d+)-([0-9a-f]{16})\.npy$")


def checkpoint_path(output: str | os.PathLike) -> Path:
    """The checkpoint folder of result file ``output``."""
    output = Path(output)
    return output.with_name(output.name + ".checkpoint")


def checksum(digest: str, data: bytes) -> str:
    """16 hex digits of SHA-256 over a study's ``digest`` and a file's bytes: a file truncated,
    emptied, altered or of another study fails it."""
    return hashlib.sha256(digest.encode() + b"\0" + data).hexdigest()[:16]


def acquire_lock(folder: Path, busy: str) -> Any:
    """Take the ``lock`` file of ``folder`` (``flock``, released by the kernel when the process
    ends, however it ends) and write this process's id in it; the open file holds the lock.

    Raises :class:`InputError` ``busy.format(pid=<the holder's id>)`` when another holds it.
    """
    fh = open(folder / LOCK_NAME, "a+")  # noqa: SIM115 - held until closed
    if fcntl is not None:
        try:
            fcntl.flock(fh.fileno(), fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            fh.seek(0)
            other = fh.read().strip() or "unknown"
            fh.close()
            raise InputError(busy.format(pid=other)) from None
    fh.seek(0)
    fh.truncate()
    fh.write(f"{os.getpid()}\n")
    fh.flush()
    return fh


def make_folder(folder: Path, refusal: str) -> None:
    """Make ``folder`` and its parents, or refuse in one line: ``refusal`` followed by the
    system's reason in parentheses."""
    try:
        folder.mkdir(parents=True, exist_ok=True)
    except OSError as exc:
        raise InputError(f"{refusal} ({exc.strerror})") from None


def stored_digest(folder: Path, record: Path, restart: bool, kind: str, piece: str) -> str | None:
    """Clear ``folder`` of stray temporaries (of everything but its lock with ``restart``) and
    read the digest kept in its ``record`` file: None when there is none, or when the file is
    damaged (a warning: the ``kind`` file is rewritten, every ``piece`` checked on its own)."""
    for entry in folder.iterdir():
        if entry.name.startswith(".tmp-") or (restart and entry.name != LOCK_NAME):
            (shutil.rmtree if entry.is_dir() else Path.unlink)(entry)
    if not record.exists():
        return None
    try:
        stored = json.loads(record.read_text())["digest"]
        if not isinstance(stored, str):
            raise TypeError("digest is not a string")
    except (OSError, ValueError, KeyError, TypeError) as exc:
        log.warning(
            f"{kind} file %s is damaged (%s): rewritten; every {piece} is checked on its own",
            show_path(record),
            " ".join(str(exc).split())[:80] or type(exc).__name__,
        )
        return None
    return stored


def write_atomic(path: Path, data: bytes) -> None:
    """Write ``data`` to ``path`` through a temporary (``.tmp-*``) renamed into place."""
    try:
        fd, tmp = tempfile.mkstemp(prefix=".tmp-", suffix=path.suffix, dir=path.parent)
    except OSError as exc:
        raise OutputError(exc.errno, f"cannot write {show_path(path)}: {exc.strerror}") from None
    try:
        with os.fdopen(fd, "wb") as fh:
            fh.write(data)
            fh.flush()
            os.fsync(fh.fileno())
        os.replace(tmp, path)
    except OSError as exc:
        raise OutputError(exc.errno, f"cannot write {show_path(path)}: {exc.strerror}") from None
    finally:
        if os.path.exists(tmp):
            os.unlink(tmp)


class Checkpoint:
    """The finished cases of one sweep, stored beside its output file; holds its lock.

    Parameters
    ----------
    output : path
        The sweep's result file; the checkpoint is ``<output>.checkpoint/``.
    digest : str
        The sweep specification's digest (:attr:`fem_racket.studies.grid.SweepSpec.digest`).
    description : dict
        Written to ``spec.json`` for people reading the folder.
    n_cases, n_values : int
        Number of cases and of result values per case.
    restart : bool
        Discard the finished cases of an earlier run (after taking the lock).

    Raises
    ------
    InputError
        Another sweep holds the lock, or the folder belongs to a different sweep.
    """

    def __init__(
        self,
        output: str | os.PathLike,
        digest: str,
        description: dict[str, Any],
        n_cases: int,
        n_values: int,
        *,
        restart: bool = False,
    ) -> None:
        self.output = Path(output)
        self.folder = checkpoint_path(output)
        self.digest = digest
        self.n_cases, self.n_values = n_cases, n_values
        self.cases = 0  # finished cases stored
        self._lock: Any = None
        make_folder(
            self.folder,
            f"out = {show_path(self.output)} is not allowed: its checkpoint folder "
            f"{show_path(self.folder)} cannot be made",
        )
        self._lock = self._acquire()
        try:
            self._prepare(description, restart)
        except BaseException:
            self.close()
            raise

    def _acquire(self) -> Any:
        lock = show_path(self.folder / LOCK_NAME).replace("{", "{{").replace("}", "}}")
        out = show_path(self.output).replace("{", "{{").replace("}", "}}")
        return acquire_lock(
            self.folder,
            f"out = {out} is not allowed now: another sweep (process {{pid}}) is writing it "
            f"(lock {lock}); wait for it to finish or stop it",
        )

    def _prepare(self, description: dict[str, Any], restart: bool) -> None:
        spec_file = self.folder / SPEC_NAME
        stored = stored_digest(self.folder, spec_file, restart, "checkpoint", "chunk")
        if stored is not None and stored != self.digest:
            raise InputError(
                f"out = {show_path(self.output)} is not allowed: its checkpoint "
                f"{show_path(self.folder)} belongs to a different sweep; rerun with the options "
                "it was started with, or pass --restart to discard it"
            )
        if stored is None:
            text = json.dumps({"digest": self.digest, "sweep": description}, indent=1)
            write_atomic(spec_file, text.encode())

    def close(self) -> None:
        """Release the lock (the folder stays for a later run to resume)."""
        if self._lock is not None and not self._lock.closed:
            self._lock.close()

    def _read(self, path: Path) -> np.ndarray | None:
        """The rows of chunk ``path``, or None (with a warning, the file deleted) if damaged."""
        m = _CHUNK.match(path.name)
        why = None
        rows = None
        if m is None:
            why = "no checksum in its name: not written by this version of a sweep"
        else:
            data = path.read_bytes()
            if checksum(self.digest, data) != m.group(3):
                why = "checksum mismatch: damaged, or from a different sweep"
            else:
                rows = np.load(io.BytesIO(data), allow_pickle=False)
                first, count = int(m.group(1)), int(m.group(2))
                shape_ok = rows.ndim == 2 and rows.shape == (count, self.n_values + 1)
                idx = rows[:, 0] if shape_ok else np.array([-1.0])
                if not shape_ok or idx[0] != first or np.any((idx < 0) | (idx >= self.n_cases)):
                    why = "its content does not fit this sweep"
        if why is None:
            return rows
        log.warning(
            "checkpoint file %s is not used (%s); its cases are computed again",
            show_path(path),
            why,
        )
        path.unlink()
        return None

    def load(self) -> tuple[np.ndarray, np.ndarray]:
        """Finished cases: a boolean mask (n_cases,) and the results (n_cases, n_values),
        NaN where not finished."""
        done = np.zeros(self.n_cases, dtype=bool)
        values = np.full((self.n_cases, self.n_values), np.nan)
        for path in sorted(self.folder.glob("chunk-*")):
            rows = self._read(path)
            if rows is None:
                continue
            idx = rows[:, 0].astype(np.int64)
            done[idx] = True
            values[idx] = rows[:, 1:]
        self.cases = int(done.sum())
        return done, values

    def save(self, indices: np.ndarray, values: np.ndarray) -> None:
        """Record finished cases ``indices`` with their ``values`` (one atomic file)."""
        rows = np.column_stack([np.asarray(indices, dtype=float), values])
        buf = io.BytesIO()
        np.save(buf, rows, allow_pickle=False)
        data = buf.getvalue()
        name = f"chunk-{int(indices[0]):012d}-{len(indices)}-{checksum(self.digest, data)}.npy"
        write_atomic(self.folder / name, data)
        self.cases += len(indices)

    def remove(self) -> None:
        """Delete the checkpoint folder (after the result file is written) and release the lock."""
        shutil.rmtree(self.folder, ignore_errors=True)
        self.close()
        log.debug("removed checkpoint %s", self.folder)
