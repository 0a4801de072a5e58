"""Where sweep chunks run: in this process, a local process pool, or a Dask cluster.

Every backend calls the same picklable function ``work(chunk, **kwargs) -> ndarray`` on
chunks of case indices and hands each finished chunk to ``done(chunk, values)`` in the calling
process (which checkpoints it) as soon as it arrives, in completion order.

- ``serial``: a plain loop.
- ``processes``: :class:`concurrent.futures.ProcessPoolExecutor` on ``workers`` processes
  (all cores by default), started with ``forkserver`` where available (``fork`` is unsafe in a
  threaded parent), with the package preloaded.
- ``dask``: ``distributed.Client(scheduler)`` - the very code path used on a cluster; each
  worker needs fem_racket installed.

Workers end with the command. When the caller stops for any reason (an error, Ctrl-C's
KeyboardInterrupt, SIGTERM turned into one by the CLI) the pool's processes are terminated
before the exception goes on, and the Dask client is closed, so that the scheduler drops the
tasks not yet run. Pool workers ignore SIGINT (the terminal sends Ctrl-C to the whole process
group; the parent decides) and end when the command's process is gone - on Linux the kernel
kills a forked worker with its parent (``PR_SET_PDEATHSIG``); a worker started by the forkserver
polls the parent instead - so not even SIGKILL of the command leaves them behind.

Every process that computes (the CLI, each pool worker, each Dask task) runs BLAS on one thread
(:func:`pin_blas_threads`): the work is many small dense products, which multithreaded OpenBLAS
makes 2-4x slower on an idle 2-core machine and 10-60x slower on a loaded one, and a fixed thread
count also keeps results bit-identical from run to run.
"""

from __future__ import annotations

import logging
import os
import re
import sys
from collections.abc import Callable, Sequence
from dataclasses import dataclass
from functools import partial
from typing import Any

import numpy as np

from fem_racket.extras import check_installed
from fem_racket.studies.backends import BACKENDS
from fem_racket.studies.pool import pin_blas_threads, run_pool
from fem_racket.validation import InputError, check_choice, show

__all__ = ["BACKENDS", "BarCounts", "check_scheduler", "pin_blas_threads", "run_chunks"]

log = logging.getLogger(__name__)

Work = Callable[..., np.ndarray]
Done = Callable[[np.ndarray, np.ndarray], None]

_ADDRESS = re.compile(r"^(tcp|tls|ucx|ws|wss)://[^\s/:]+:\d{1,5}$")


def _pinned(work: Work, chunk: np.ndarray, **kwargs: Any) -> np.ndarray:
    """``work(chunk, **kwargs)`` on one BLAS thread (the first call in a worker pins it)."""
    pin_blas_threads()
    return work(chunk, **kwargs)


def check_scheduler(address: str) -> str:
    """Validate a Dask scheduler address ``PROTOCOL://HOST:PORT``."""
    if not isinstance(address, str) or not _ADDRESS.match(address):
        raise InputError(
            f"scheduler = {show(address)} is not allowed: must look like tcp://HOST:PORT"
        )
    check_installed("distributed", "a Dask scheduler (--scheduler)")  # the run imports it
    return address


class _NoBar:
    """The progress bar when none is shown: counts nothing (tqdm is not even imported; a
    disabled tqdm bar still made a multiprocessing lock, ~10 ms)."""

    def __enter__(self) -> _NoBar:
        return self

    def __exit__(self, *exc: object) -> None:
        return None

    def update(self, n: int) -> None:
        return None


def _progress(total: int, enabled: bool | None, initial: int) -> Any:
    if enabled is None:
        enabled = sys.stderr.isatty()
    if not enabled:
        return _NoBar()
    from tqdm import tqdm

    class Bar(tqdm):
        monitor_interval = 0  # no monitor thread: the process pool may fork

    return Bar(
        total=total,
        initial=initial,
        unit="impact",
        dynamic_ncols=True,
        smoothing=0.1,
        file=sys.stderr,
    )


def _serial(work: Work, chunks: Sequence[np.ndarray], kwargs: dict, done: Done, bar: Any) -> None:
    for chunk in chunks:
        done(chunk, work(chunk, **kwargs))
        bar.update(len(chunk))


def _dask(
    work: Work,
    chunks: Sequence[np.ndarray],
    kwargs: dict,
    done: Done,
    bar: Any,
    scheduler: str,
) -> None:
    from distributed import Client, as_completed

    try:
        client = Client(scheduler, timeout="10s", set_as_default=False)
    except OSError as exc:
        raise InputError(f"scheduler = {show(scheduler)} is not reachable: {exc}") from None
    try:
        log.info("dask: %d workers at %s", len(client.scheduler_info()["workers"]), scheduler)
        futures = client.map(partial(_pinned, work), list(chunks), pure=False, **kwargs)
        index = {f.key: c for f, c in zip(futures, chunks, strict=True)}
        for fut in as_completed(futures, loop=client.loop):
            chunk = index[fut.key]
            done(chunk, fut.result())
            bar.update(len(chunk))
            fut.release()
    finally:
        client.close()  # the scheduler then drops every task of this sweep not yet run


@dataclass(frozen=True)
class BarCounts:
    """What the progress bar counts: the cases of the whole run and those already finished
    before it (a resumed sweep)."""

    total: int
    initial: int = 0


def run_chunks(
    work: Work,
    chunks: Sequence[np.ndarray],
    done: Done,
    *,
    kwargs: dict | None = None,
    backend: str = "processes",
    workers: int | None = None,
    scheduler: str | None = None,
    progress: bool | None = None,
    counts: BarCounts | None = None,
    prepare: Callable[[], Any] | None = None,
) -> None:
    """Run ``work(chunk, **kwargs)`` on every chunk and pass each result to ``done``.

    Parameters
    ----------
    backend : {"serial", "processes", "dask"}
    workers : int, optional
        Processes of the local pool (all cores when None).
    scheduler : str, optional
        Dask scheduler address (required by the ``dask`` backend).
    progress : bool, optional
        Show a progress bar (rate, ETA) on stderr; None: only when stderr is a terminal.
    counts : BarCounts, optional
        Cases in the whole run and already finished, for the bar (None: the chunks' cases,
        none finished).
    prepare : callable, optional
        Run in this process before a local pool forks its workers, which then inherit what it
        loaded (:func:`fem_racket.studies.pool.run_pool`); not run by the other backends.
    """
    check_choice("backend", backend, BACKENDS)
    kwargs = kwargs or {}
    todo = sum(len(c) for c in chunks)
    counts = BarCounts(todo) if counts is None else counts
    with _progress(counts.total, progress, counts.initial) as bar:
        if backend == "serial" or (backend == "processes" and len(chunks) <= 1):
            _serial(work, chunks, kwargs, done, bar)
        elif backend == "processes":
            n = (os.cpu_count() or 1) if workers is None else workers
            run_pool(work, chunks, kwargs, done, bar, max(1, min(n, len(chunks))), prepare)
        else:
            if scheduler is None:
                raise InputError(
                    "scheduler = None is not allowed with backend 'dask': give tcp://HOST:PORT"
                )
            _dask(work, chunks, kwargs, done, bar, check_scheduler(scheduler))
