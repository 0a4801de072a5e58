"""The local process pool of :mod:`fem_racket.studies.executors`: its workers and their end.

A :class:`concurrent.futures.ProcessPoolExecutor` on ``workers`` processes, started with
``forkserver`` where available (``fork`` is unsafe in a threaded parent), the package
preloaded. Pool workers ignore SIGINT (the terminal sends Ctrl-C to the whole process group; the
parent decides) and end when the command's process is gone: on Linux the kernel kills a forked
worker with its parent (``PR_SET_PDEATHSIG``); a worker started by the forkserver polls the
parent instead, so not even SIGKILL of the command leaves them behind. When the caller stops for
any reason the pool's processes are terminated before the exception goes on.
"""

from __future__ import annotations

import os
import signal
import sys
import threading
import time
from collections.abc import Callable, Sequence
from typing import Any

import numpy as np

__all__ = ["pin_blas_threads", "run_pool"]

Work = Callable[..., np.ndarray]
Done = Callable[[np.ndarray, np.ndarray], None]


def pin_blas_threads() -> None:
    """Limit every BLAS library loaded in this process to one thread (threadpoolctl; persists
    for the life of the process)."""
    from threadpoolctl import threadpool_limits

    threadpool_limits(limits=1, user_api="blas")


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


def run_pool(
    work: Work,
    chunks: Sequence[np.ndarray],
    kwargs: dict,
    done: Done,
    bar: Any,
    workers: int,
    prepare: Callable[[], Any] | None = None,
) -> None:
    """``work(chunk, **kwargs)`` of every chunk on ``workers`` processes, each result passed to
    ``done`` (and the progress ``bar``) as it arrives. ``prepare`` (optional) runs here first
    when the workers are forked, so that they inherit what it loads (compiled kernels) instead
    of each loading it; under forkserver or spawn they would not, and it does not run."""
    import queue
    from concurrent.futures import ProcessPoolExecutor

    context = _pool_context()
    if prepare is not None and context.get_start_method() == "fork":
        prepare()
    pool = ProcessPoolExecutor(
        max_workers=workers,
        mp_context=context,
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
