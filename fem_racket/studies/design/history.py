"""Every design a study evaluates, kept on disk so that a rerun resumes where it stopped.

The folder is a checkpoint as a sweep's (:mod:`fem_racket.studies.checkpoint`): it holds
``problem.json`` (the problem's description and digest), a ``lock`` file and one
``batch-<n>-<checksum>.npy`` per evaluated batch: rows ``[design variables..., outputs...]``,
each written to a temporary and renamed into place. The checksum (SHA-256 over the problem's
digest and the file's bytes) makes a batch that is truncated, emptied, altered or from another
problem fail: it is never merged - deleted with a warning, its designs are computed again when
the solver asks for them. A damaged ``problem.json`` is rewritten (each batch is checked on its
own); a readable one of another problem is refused. The lock (``flock``) stops a second study on
the same output while one runs (several evaluators of one process share it); ``n`` follows the
largest number on disk, so a name is never reused.

The solvers are deterministic (fixed seeds, same start), so a rerun of the same study asks for
the same designs in the same order; :class:`History` answers those from the folder and only new
designs are computed.
"""

from __future__ import annotations

import io
import json
import logging
import os
import re
import shutil
import weakref
from pathlib import Path
from typing import Any

import numpy as np

from fem_racket.studies.checkpoint import (
    LOCK_NAME,
    acquire_lock,
    checksum,
    make_folder,
    stored_digest,
    write_atomic,
)
from fem_racket.validation import InputError, show_path

__all__ = ["History"]

log = logging.getLogger(__name__)

META_NAME = "problem.json"
_BATCH = re.compile(r"^batch-(\d+)-([0-9a-f]{16})\.npy$")
#: Locks this process holds: folder -> [open lock file, holders].
_LOCKS: dict[Path, list[Any]] = {}


def _lock(folder: Path) -> None:
    key = folder.absolute()
    if key in _LOCKS:
        _LOCKS[key][1] += 1
        return
    lock = show_path(folder / LOCK_NAME).replace("{", "{{").replace("}", "}}")
    busy = (
        f"history = {show_path(folder)} is not allowed now: another design study (process "
        f"{{pid}}) is using it (lock {lock}); wait for it to finish or stop it"
    )
    _LOCKS[key] = [acquire_lock(folder, busy), 1]


def _unlock(folder: Path) -> None:
    key = folder.absolute()
    held = _LOCKS.get(key)
    if held is None:
        return
    held[1] -= 1
    if held[1] == 0:
        held[0].close()
        del _LOCKS[key]


class History:
    """Evaluated designs in order, with a lookup by exact design vector.

    Parameters
    ----------
    n_var, n_out : int
        Design variables and outputs per row.
    folder : path, optional
        Where batches are kept (none: in memory only).
    digest : str
        The problem's digest (a folder of another problem is refused).
    description : dict
        Written to ``problem.json``.
    restart : bool
        Discard the designs of an earlier run (after taking the lock).

    Raises
    ------
    InputError
        Another process's study holds the lock, or the folder belongs to another problem.
    """

    def __init__(
        self,
        n_var: int,
        n_out: int,
        folder: str | os.PathLike | None = None,
        digest: str = "",
        description: dict[str, Any] | None = None,
        *,
        restart: bool = False,
    ) -> None:
        self.n_var, self.n_out = n_var, n_out
        self.rows: list[np.ndarray] = []
        self.batch: list[int] = []
        self._index: dict[bytes, int] = {}
        self._stored: dict[bytes, np.ndarray] = {}
        self.batches = 0
        self.folder = None if folder is None else Path(folder)
        self.loaded = 0
        self.digest = digest
        self._next = 0
        self._locked = False
        if self.folder is None:
            return
        make_folder(
            self.folder, f"history = {show_path(self.folder)} is not allowed: it cannot be made"
        )
        _lock(self.folder)
        self._locked = True
        # released when the history is closed, or forgotten (an evaluator a script drops)
        self._release = weakref.finalize(self, _unlock, self.folder)
        try:
            self._prepare(description, restart)
            self._load()
        except BaseException:
            self.close()
            raise

    def _prepare(self, description: dict[str, Any] | None, restart: bool) -> None:
        """Remove stale temporaries (everything with ``restart``); check ``problem.json``."""
        meta = self.folder / META_NAME
        stored = stored_digest(self.folder, meta, restart, "history", "batch")
        if stored is not None and stored != self.digest:
            raise InputError(
                f"history = '{self.folder}' belongs to a different design problem: rerun "
                "with the settings it was started with, or remove it (--restart) to start afresh"
            )
        if stored is None:
            text = json.dumps(
                {"digest": self.digest, "problem": description}, indent=1, default=str
            )
            write_atomic(meta, text.encode())

    def _read(self, path: Path) -> np.ndarray | None:
        """The rows of batch ``path``, or None (a warning, the file deleted) if it is damaged."""
        m = _BATCH.match(path.name)
        rows, why = None, None
        if m is None:
            why = "no checksum in its name: not written by this version of a study"
        else:
            self._next = max(self._next, int(m.group(1)) + 1)
            data = path.read_bytes()
            if checksum(self.digest, data) != m.group(2):
                why = "checksum mismatch: damaged, or from a different design problem"
            else:
                rows = np.load(io.BytesIO(data), allow_pickle=False)
                if rows.ndim != 2 or rows.shape[1] != self.n_var + self.n_out:
                    why, rows = "its rows do not fit this problem", None
        if why is not None:
            log.warning(
                "history file %s is not used (%s); its designs are computed again",
                show_path(path),
                why,
            )
            path.unlink()
        return rows

    def _load(self) -> None:
        stored = self._stored
        for path in sorted(self.folder.glob("batch-*")):
            rows = self._read(path)
            for row in () if rows is None else rows:
                stored[row[: self.n_var].tobytes()] = row
        self.loaded = len(stored)
        log.info("history %s: %d designs on disk", self.folder, self.loaded)

    def lookup(self, x: np.ndarray) -> np.ndarray | None:
        """Outputs of design ``x`` if evaluated before (this run or a stored one)."""
        key = np.ascontiguousarray(x, dtype=float).tobytes()
        if key in self._index:
            return self.rows[self._index[key]][self.n_var :]
        row = self._stored.get(key)
        if row is not None:
            self._add(row)
            return row[self.n_var :]
        return None

    def _add(self, row: np.ndarray) -> None:
        self._index[row[: self.n_var].tobytes()] = len(self.rows)
        self.rows.append(row)
        self.batch.append(self.batches)

    def next_batch(self) -> None:
        """Start a new batch (a solver iteration or generation)."""
        self.batches += 1

    def record(self, designs: np.ndarray, outputs: np.ndarray) -> None:
        """Add newly evaluated designs and save them as one batch file."""
        rows = np.column_stack([np.asarray(designs, float), np.asarray(outputs, float)])
        for row in rows:
            self._add(row)
        if self.folder is not None and len(rows):
            buf = io.BytesIO()
            np.save(buf, rows, allow_pickle=False)
            data = buf.getvalue()
            write_atomic(
                self.folder / f"batch-{self._next:07d}-{checksum(self.digest, data)}.npy", data
            )
            self._next += 1

    def arrays(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(designs, outputs, batch index) of every design looked up or evaluated, in order."""
        if not self.rows:
            empty = np.empty((0, self.n_var))
            return empty, np.empty((0, self.n_out)), np.empty(0, int)
        rows = np.array(self.rows)
        return rows[:, : self.n_var], rows[:, self.n_var :], np.array(self.batch)

    def close(self) -> None:
        """Release the lock (the folder stays for a later run to resume)."""
        if self._locked:
            self._release()
            self._locked = False

    def remove(self) -> None:
        """Delete the folder (after the study's results are written) and release the lock."""
        if self.folder is not None:
            shutil.rmtree(self.folder, ignore_errors=True)
        self.close()
