"""Resumable sweeps: finished cases kept in a folder beside the output until it is written.

The folder ``<output>.checkpoint/`` holds ``spec.json`` (the sweep's description and its
SHA-256 digest) and one ``chunk-<first case>-<count>.npy`` per finished chunk: an array of
rows ``[case index, result values...]``. Every file is written to a temporary name and renamed
into place, so a run killed at any moment leaves only whole chunks (stray temporary files are
removed on the next start). A restarted sweep with the same specification loads the finished
cases and computes only the others; a different specification is refused. The folder is
removed once the result file has been written.
"""

from __future__ import annotations

import json
import logging
import os
import shutil
import tempfile
from pathlib import Path
from typing import Any

import numpy as np

from fem_racket.validation import InputError

__all__ = ["Checkpoint", "checkpoint_path"]

log = logging.getLogger(__name__)


def checkpoint_path(output: str | os.PathLike) -> Path:
    """The checkpoint folder of result file ``output``."""
    output = Path(output)
    return output.with_name(output.name + ".checkpoint")


def _write_atomic(path: Path, write: Any) -> None:
    fd, tmp = tempfile.mkstemp(prefix=".tmp-", suffix=path.suffix, dir=path.parent)
    try:
        with os.fdopen(fd, "wb") as fh:
            write(fh)
            fh.flush()
            os.fsync(fh.fileno())
        os.replace(tmp, path)
    finally:
        if os.path.exists(tmp):
            os.unlink(tmp)


class Checkpoint:
    """The finished cases of one sweep, stored beside its output file.

    Parameters
    ----------
    output : path
        The sweep's result file; the checkpoint is ``<output>.checkpoint/``.
    digest : str
        The sweep specification's digest (:attr:`fem_racket.grid.SweepSpec.digest`).
    description : dict
        Written to ``spec.json`` for people reading the folder.
    n_cases, n_values : int
        Number of cases and of result values per case.
    """

    def __init__(
        self,
        output: str | os.PathLike,
        digest: str,
        description: dict[str, Any],
        n_cases: int,
        n_values: int,
    ) -> None:
        self.folder = checkpoint_path(output)
        self.digest = digest
        self.n_cases, self.n_values = n_cases, n_values
        spec_file = self.folder / "spec.json"
        if self.folder.exists():
            try:
                stored = json.loads(spec_file.read_text())["digest"]
            except (OSError, ValueError, KeyError):
                stored = None
            if stored != digest:
                raise InputError(
                    f"checkpoint = '{self.folder}' belongs to a different sweep: rerun with the "
                    "options it was started with, or remove it (--restart) to start afresh"
                )
            for tmp in self.folder.glob(".tmp-*"):
                tmp.unlink()
        else:
            self.folder.mkdir(parents=True)
            text = json.dumps({"digest": digest, "sweep": description}, indent=1).encode()
            _write_atomic(spec_file, lambda fh: fh.write(text))

    @staticmethod
    def discard(output: str | os.PathLike) -> None:
        """Delete the checkpoint of ``output``, if any."""
        shutil.rmtree(checkpoint_path(output), ignore_errors=True)

    def load(self) -> tuple[np.ndarray, np.ndarray]:
        """Finished cases: a boolean mask (n_cases,) and the results (n_cases, n_values),
        NaN where not finished."""
        done = np.zeros(self.n_cases, dtype=bool)
        values = np.full((self.n_cases, self.n_values), np.nan)
        for path in sorted(self.folder.glob("chunk-*.npy")):
            rows = np.load(path, allow_pickle=False)
            if rows.ndim != 2 or rows.shape[1] != self.n_values + 1:
                raise InputError(f"checkpoint file = '{path}' is not allowed: wrong shape")
            idx = rows[:, 0].astype(np.int64)
            if np.any((idx < 0) | (idx >= self.n_cases)):
                raise InputError(f"checkpoint file = '{path}' is not allowed: bad case index")
            done[idx] = True
            values[idx] = rows[:, 1:]
        return done, values

    def save(self, indices: np.ndarray, values: np.ndarray) -> None:
        """Record finished cases ``indices`` with their ``values`` (one atomic file)."""
        rows = np.column_stack([np.asarray(indices, dtype=float), values])
        name = f"chunk-{int(indices[0]):012d}-{len(indices)}.npy"
        _write_atomic(self.folder / name, lambda fh: np.save(fh, rows, allow_pickle=False))

    def remove(self) -> None:
        """Delete the checkpoint folder (after the result file is written)."""
        shutil.rmtree(self.folder, ignore_errors=True)
        log.debug("removed checkpoint %s", self.folder)
