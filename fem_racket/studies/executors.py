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
import signal
import sys
import threading
import time
from collections.abc import Callable, Sequence
from functools import partial
from typing import Any

import numpy as np

from fem_racket.extras import require
from fem_racket.validation import InputError, check_choice, show

__all__ = ["BACKENDS", "check_scheduler", "pin_blas_threads", "run_chunks"]

log = logging.getLogger(__name__)

BACKENDS = ("serial", "processes", "dask")

Work = Callable[..., np.ndarray]
Done = Callable[[np.ndarray, np.ndarray], None]

_ADDRESS = re.compile(r"^(tcp|tls|ucx|ws|wss)://[^\s/:]+:\d{1,5}$")


def pin_blas_threads() -> None:
    """Limit every BLAS library loaded in this process to one thread (threadpoolctl; persists
    for the life of the process)."""
    from threadpoolctl import threadpool_limits

    threadpool_limits(limits=1, user_api="blas")


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
    require("distributed", "a Dask scheduler (--scheduler)")
    return address


def _progress(total: int, enabled: bool | None, initial: int) -> Any:
    from tqdm import tqdm

    class Bar(tqdm):
        monitor_interval = 0  # no monitor thread: the process pool may fork

    if enabled is None:
        enabled = sys.stderr.isatty()
    return Bar(
        total=total,
        initial=initial,
        unit="impact",
        disable=not enabled,
        dynamic_ncols=True,
        smoothing=0.1,
        file=sys.stderr,
    )


def _serial(work: Work, chunks: Sequence[np.ndarray], kwargs: dict, done: Done, bar: Any) -> None:
    for chunk in chunks:
        done(chunk, work(chunk, **kwargs))
        bar.update(len(chunk))


#: ``prctl`` option asking for a signal when the parent process dies (linux/prctl.h).
_PR_SET_PDEATHSIG = 1


def _worker_init(parent: int) -> None:
    """Start of every pool worker: one BLAS thread (:func:`pin_blas_threads`), SIGINT left to
    the parent, and death with the parent ``parent`` (the kernel's parent-death signal when it
    forked us; else, under forkserver or spawn, a watch thread polling it once a second)."""
    pin_blas_threads()
    signal.signal(signal.SIGINT, signal.SIG_IGN)
    signal.signal(signal.SIGTERM, signal.SIG_DFL)
    if os.getppid() != parent:
        threading.Thread(target=_watch, args=(parent,), daemon=True).start()
    elif sys.platform.startswith("linux"):
        import ctypes

        try:
            libc = ctypes.CDLL(None, use_errno=True)
            libc.prctl(_PR_SET_PDEATHSIG, signal.SIGKILL, 0, 0, 0)
        except (OSError, AttributeError):  # no prctl: the watch thread instead
            threading.Thread(target=_watch, args=(parent,), daemon=True).start()
        if os.getppid() != parent:  # the parent died before prctl
            os._exit(1)


def _watch(parent: int) -> None:
    while _alive(parent):
        time.sleep(1.0)
    os._exit(1)


def _alive(pid: int) -> bool:
    """Whether ``pid`` runs; a zombie (dead, not yet reaped: a caller killed by SIGKILL whose
    own parent waits for our end of its stdout pipe first) counts as dead."""
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except PermissionError:
        return True
    try:
        with open(f"/proc/{pid}/stat", "rb") as f:
            return f.read().rsplit(b")", 1)[1].split()[0] != b"Z"
    except (OSError, IndexError):  # no /proc (not Linux): kill(pid, 0) is all we know
        return True


def _terminate(pool: Any) -> None:
    """Stop a ProcessPoolExecutor now: cancel the chunks not started, kill the workers."""
    procs = list((getattr(pool, "_processes", None) or {}).values())  # shutdown forgets them
    manager = getattr(pool, "_executor_manager_thread", None)
    pool.shutdown(wait=False, cancel_futures=True)
    for proc in procs:
        if proc.is_alive():
            proc.terminate()
    for proc in procs:
        proc.join(timeout=5)
        if proc.is_alive():
            proc.kill()
            proc.join(timeout=5)
    # Its manager thread closes the pool's wake-up pipe as it ends; at exit concurrent.futures
    # writes to that pipe (Python 3.11), and a thread still ending then printed "Exception
    # ignored ... Bad file descriptor" after the command's line. Let it end first.
    if manager is not None:
        manager.join(timeout=10)


def _pool_context() -> Any:
    """``fork`` when this process has no other thread (fast: no re-import, works from stdin and
    notebooks), else ``forkserver`` with the package preloaded (forking a threaded process is
    unsafe), else ``spawn``."""
    import multiprocessing as mp
    import threading

    methods = mp.get_all_start_methods()
    if "fork" in methods and threading.active_count() == 1:
        return mp.get_context("fork")
    if "forkserver" in methods:
        ctx = mp.get_context("forkserver")
        ctx.set_forkserver_preload(["fem_racket.studies.cases"])
        return ctx
    return mp.get_context("spawn")


def _processes(
    work: Work,
    chunks: Sequence[np.ndarray],
    kwargs: dict,
    done: Done,
    bar: Any,
    workers: int,
) -> None:
    import queue
    from concurrent.futures import ProcessPoolExecutor

    pool = ProcessPoolExecutor(
        max_workers=workers,
        mp_context=_pool_context(),
        initializer=_worker_init,
        initargs=(os.getpid(),),
    )
    # Finished futures arrive on a queue, not through concurrent.futures.wait(): wait() takes
    # every pending future's lock in a Python loop, and a signal landing inside that loop left
    # some locks held by this thread for ever; the pool's manager thread then blocked on them
    # and the interpreter hung at exit, joining it, after saying "interrupted".
    finished: queue.SimpleQueue = queue.SimpleQueue()
    try:
        pending = {}
        for c in chunks:
            fut = pool.submit(work, c, **kwargs)
            pending[fut] = c
            fut.add_done_callback(finished.put)
        while pending:
            try:
                fut = finished.get(timeout=1.0)  # a timeout: a signal is handled within 1 s
            except queue.Empty:
                continue
            chunk = pending.pop(fut)
            done(chunk, fut.result())
            bar.update(len(chunk))
    except BaseException:
        _terminate(pool)
        raise
    pool.shutdown(wait=True)


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
    total: int | None = None,
    initial: int = 0,
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
    total, initial : int
        Cases in the whole sweep and already finished (for the bar).
    """
    check_choice("backend", backend, BACKENDS)
    kwargs = kwargs or {}
    todo = sum(len(c) for c in chunks)
    total = todo + initial if total is None else total
    with _progress(total, progress, initial) as bar:
        if backend == "serial" or (backend == "processes" and len(chunks) <= 1):
            _serial(work, chunks, kwargs, done, bar)
        elif backend == "processes":
            n = (os.cpu_count() or 1) if workers is None else workers
            _processes(work, chunks, kwargs, done, bar, max(1, min(n, len(chunks))))
        else:
            if scheduler is None:
                raise InputError(
                    "scheduler = None is not allowed with backend 'dask': give tcp://HOST:PORT"
                )
            _dask(work, chunks, kwargs, done, bar, check_scheduler(scheduler))
