"""Every design a study evaluates, kept on disk so that a rerun resumes where it stopped.

The folder holds ``problem.json`` (the problem's description and digest) and one
``batch-<n>.npy`` per evaluated batch: rows ``[design variables..., outputs...]``, each written
atomically. The solvers are deterministic (fixed seeds, same start), so a rerun of the same study
asks for the same designs in the same order; :class:`History` answers those from the folder and
only new designs are computed. A folder of another problem is refused.
"""

from __future__ import annotations

import json
import logging
import os
import shutil
from pathlib import Path
from typing import Any

import numpy as np

from fem_racket.outputs import atomic_output
from fem_racket.validation import InputError

__all__ = ["History"]

log = logging.getLogger(__name__)


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
    """

    def __init__(
        self,
        n_var: int,
        n_out: int,
        folder: str | os.PathLike | None = None,
        digest: str = "",
        description: dict[str, Any] | None = None,
    ) -> None:
        self.n_var, self.n_out = n_var, n_out
        self.rows: list[np.ndarray] = []
        self.batch: list[int] = []
        self._index: dict[bytes, int] = {}
        self._stored: dict[bytes, np.ndarray] = {}
        self.batches = 0
        self.folder = None if folder is None else Path(folder)
        self.loaded = 0
        if self.folder is None:
            return
        meta = self.folder / "problem.json"
        if self.folder.exists():
            try:
                stored = json.loads(meta.read_text())["digest"]
            except (OSError, ValueError, KeyError):
                stored = None
            if stored != digest:
                raise InputError(
                    f"history = '{self.folder}' belongs to a different design problem: rerun "
                    "with the settings it was started with, or remove it to start afresh"
                )
            self._load()
        else:
            self.folder.mkdir(parents=True)
            text = json.dumps({"digest": digest, "problem": description}, indent=1, default=str)
            with atomic_output(meta) as tmp:
                tmp.write_text(text)

    def _load(self) -> None:
        stored = self._stored
        for path in sorted(self.folder.glob("batch-*.npy")):
            rows = np.load(path, allow_pickle=False)
            if rows.ndim != 2 or rows.shape[1] != self.n_var + self.n_out:
                raise InputError(f"history file = '{path}' is not allowed: wrong shape")
            for row in rows:
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
            name = self.folder / f"batch-{len(list(self.folder.glob('batch-*.npy'))):07d}.npy"
            with atomic_output(name) as tmp, open(tmp, "wb") as fh:
                np.save(fh, rows, allow_pickle=False)

    def arrays(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(designs, outputs, batch index) of every design looked up or evaluated, in order."""
        if not self.rows:
            empty = np.empty((0, self.n_var))
            return empty, np.empty((0, self.n_out)), np.empty(0, int)
        rows = np.array(self.rows)
        return rows[:, : self.n_var], rows[:, self.n_var :], np.array(self.batch)

    def remove(self) -> None:
        """Delete the folder (after the study's results are written)."""
        if self.folder is not None:
            shutil.rmtree(self.folder, ignore_errors=True)
