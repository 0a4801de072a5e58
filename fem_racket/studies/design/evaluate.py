"""Batches of designs evaluated once each: history lookup, then the sweep executors.

Solvers hand the :class:`Evaluator` a whole batch (SLSQP's point and its finite-difference
neighbours, a differential-evolution population, an NSGA-II generation, a Sobol sample). Designs
already in the :class:`~.history.History` are answered from it; the others are split into chunks
and run where a sweep runs (:func:`fem_racket.studies.executors.run_chunks`: serial, a local
process pool or a Dask scheduler), each chunk evaluating its designs in turn.
"""

from __future__ import annotations

import logging
import math
import os
from collections.abc import Callable
from typing import Any

import numpy as np

from fem_racket.studies.design.history import History
from fem_racket.studies.design.objectives import evaluate_rows, output_names
from fem_racket.studies.design.problem import DesignProblem
from fem_racket.studies.executors import BACKENDS, check_scheduler, run_chunks
from fem_racket.validation import InputError, check_choice, check_integer, show

__all__ = ["Evaluator", "Function"]

#: ``f(problem, designs) -> outputs``: rows of design variables [SI] to rows of outputs
#: (columns :func:`.objectives.output_names`); picklable for the process pool.
Function = Callable[[DesignProblem, np.ndarray], np.ndarray]

log = logging.getLogger(__name__)

#: Below this many new designs in a batch the default backend is serial (each batch starts a
#: process pool: ~0.1-0.5 s here, more than a generation of 50 designs costs).
SERIAL_BELOW = 64


def evaluate_chunk(
    chunk: np.ndarray, *, problem: DesignProblem, designs: np.ndarray, function: Function
) -> np.ndarray:
    """Outputs of ``designs[chunk]`` (picklable work for the executors)."""
    return function(problem, designs[chunk])


class Evaluator:
    """Evaluate design batches for one problem, remembering every design.

    Parameters
    ----------
    problem : DesignProblem
    history : path, optional
        Folder keeping the evaluated designs (resume on rerun); memory only when None.
    backend : {"serial", "processes", "dask"}, optional
        Default: "dask" with a scheduler, else "processes" for batches of at least
        :data:`SERIAL_BELOW` new designs on a machine with several cores, else "serial".
    workers : int, optional
        Processes of the local pool (all cores when None).
    scheduler : str, optional
        Dask scheduler address ``tcp://HOST:PORT``.
    function : callable, optional
        What a design's outputs are (:data:`Function`): the racket physics
        (:func:`.objectives.evaluate_rows`) by default; another function gives the same columns
        from a model of the user's (e.g. a synthetic objective with a known optimum).
    restart : bool
        Discard the designs an earlier run left in ``history``.
    """

    def __init__(
        self,
        problem: DesignProblem,
        *,
        history: str | os.PathLike | None = None,
        backend: str | None = None,
        workers: int | None = None,
        scheduler: str | None = None,
        function: Function = evaluate_rows,
        restart: bool = False,
    ) -> None:
        if backend is not None:
            check_choice("backend", backend, BACKENDS)
        if workers is not None:
            check_integer("workers", workers)  # as the sweep refuses it
        for name, value, users in (("workers", workers, ("processes",)),
                                   ("scheduler", scheduler, ("dask",))):  # fmt: skip
            if value is not None and backend is not None and backend not in users:
                raise InputError(
                    f"{name} = {show(value)} is not allowed with backend {backend!r}: only "
                    f"backend {users[0]!r} uses it"
                )
        if scheduler is not None:
            check_scheduler(scheduler)
        self.problem = problem
        self.function = function
        self.names = output_names(problem)
        self.backend, self.workers, self.scheduler = backend, workers, scheduler
        self.history = History(
            problem.n_var,
            len(self.names),
            history,
            problem.digest,
            problem.describe(),
            restart=restart,
        )
        self.computed = 0

    def column(self, name: str) -> int:
        """Index of output ``name`` in the rows this evaluator returns."""
        return self.names.index(name)

    def _backend(self, n: int) -> str:
        if self.backend is not None:
            return self.backend
        if self.scheduler is not None:
            return "dask"
        cores = self.workers or os.cpu_count() or 1
        return "processes" if n >= SERIAL_BELOW and cores > 1 else "serial"

    def __call__(self, designs: np.ndarray) -> np.ndarray:
        """Outputs (columns :attr:`names`) of each row of ``designs`` [SI], shape (n, n_out)."""
        x = np.atleast_2d(np.asarray(designs, dtype=float))
        out = np.empty((x.shape[0], len(self.names)))
        todo: dict[bytes, list[int]] = {}
        for i, row in enumerate(x):
            known = self.history.lookup(row)
            if known is None:
                todo.setdefault(row.tobytes(), []).append(i)
            else:
                out[i] = known
        if todo:
            first = np.array([rows[0] for rows in todo.values()])
            new = x[first]
            values = np.empty((len(new), len(self.names)))

            def done(chunk: np.ndarray, result: np.ndarray) -> None:
                values[chunk] = result

            backend = self._backend(len(new))
            workers = 1 if backend == "serial" else (self.workers or os.cpu_count() or 1)
            size = max(1, math.ceil(len(new) / (2 * workers)))
            chunks = [np.arange(k, min(k + size, len(new))) for k in range(0, len(new), size)]
            run_chunks(
                evaluate_chunk,
                chunks,
                done,
                kwargs={"problem": self.problem, "designs": new, "function": self.function},
                backend=backend,
                workers=self.workers,
                scheduler=self.scheduler,
                progress=False,
            )
            self.history.record(new, values)
            self.computed += len(new)
            for k, rows in enumerate(todo.values()):
                out[rows] = values[k]
        self.history.next_batch()
        return out

    def arrays(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Every design seen, its outputs and its batch index (see :meth:`History.arrays`)."""
        return self.history.arrays()

    def describe(self) -> dict[str, Any]:
        """How many designs were computed and how many came from the history."""
        return {"designs_computed": self.computed, "designs_from_history": self.history.loaded}
