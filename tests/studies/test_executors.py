"""Every worker of a sweep runs its BLAS on one thread, whatever it was started with.

On this 2-core machine two OpenBLAS threads make the small dense work of a case 2-4x slower
(DESIGN §9), so :func:`fem_racket.studies.executors.run_chunks` pins BLAS in each pool worker and
in each Dask task. The workers here are started with two BLAS threads on purpose, so the pin is
what brings them to one.
"""

from __future__ import annotations

import os
import subprocess
import sys

import numpy as np
import pytest

from fem_racket.studies.executors import run_chunks


def _blas_threads(chunk: np.ndarray) -> np.ndarray:
    """The largest thread count of any BLAS library in this process, once per case."""
    from threadpoolctl import threadpool_info

    threads = max(i["num_threads"] for i in threadpool_info() if i["user_api"] == "blas")
    return np.full(len(chunk), threads)


def _collect(backend: str, **options) -> np.ndarray:
    seen: list[np.ndarray] = []
    chunks = [np.arange(i, i + 2) for i in range(0, 6, 2)]
    run_chunks(
        _blas_threads,
        chunks,
        lambda c, r: seen.append(r),
        backend=backend,
        progress=False,
        **options,
    )
    return np.concatenate(seen)


needs_two_cores = pytest.mark.skipif(
    (os.cpu_count() or 1) < 2, reason="OpenBLAS runs one thread on one core anyway"
)


@needs_two_cores
def test_pool_workers_run_one_blas_thread(monkeypatch):
    # Workers started by fork inherit this process's BLAS (pinned by other tests, or by the
    # environment); forkserver/spawn workers read the environment: ask for two threads.
    monkeypatch.setenv("OPENBLAS_NUM_THREADS", "2")
    monkeypatch.setenv("OMP_NUM_THREADS", "2")
    assert np.all(_collect("processes", workers=2) == 1)


@needs_two_cores
def test_dask_tasks_run_one_blas_thread(monkeypatch, local_cluster):
    distributed = pytest.importorskip("distributed")
    import dask

    # Dask's nannies start workers with one thread unless the caller's environment says
    # otherwise; say otherwise, in both places.
    two = {"OMP_NUM_THREADS": 2, "MKL_NUM_THREADS": 2, "OPENBLAS_NUM_THREADS": 2}
    for name, value in two.items():
        monkeypatch.setenv(name, str(value))
    with dask.config.set({"distributed.nanny.pre-spawn-environ": two}):
        with local_cluster() as cluster:
            with distributed.Client(cluster) as client:
                # Without the pin the worker would use both threads: the test can fail.
                before = client.submit(_blas_threads, np.arange(1), pure=False).result()
                assert before[0] == 2
            threads = _collect("dask", scheduler=cluster.scheduler_address)
    assert np.all(threads == 1)


#: Set by :func:`_prepare` in the process it runs in.
_PREPARED: list[int] = []


def _prepare() -> None:
    _PREPARED.append(os.getpid())


def _prepared_in(chunk: np.ndarray) -> np.ndarray:
    """The process that ran :func:`_prepare` before this one's work (-1: none), per case."""
    return np.full(len(chunk), _PREPARED[-1] if _PREPARED else -1)


def test_prepare_runs_once_in_the_caller_before_a_forked_pool(monkeypatch):
    import multiprocessing as mp

    from fem_racket.studies import pool

    if "fork" not in mp.get_all_start_methods():
        pytest.skip("no fork here: prepare never runs")
    monkeypatch.setattr(pool, "_pool_context", lambda: mp.get_context("fork"))
    _PREPARED.clear()
    seen: list[np.ndarray] = []
    chunks = [np.arange(i, i + 2) for i in range(0, 6, 2)]
    run_chunks(_prepared_in, chunks, lambda c, r: seen.append(r), workers=2, progress=False,
               prepare=_prepare)  # fmt: skip
    # once, here; the workers inherit it (they ran nothing of their own)
    assert _PREPARED == [os.getpid()]
    assert np.all(np.concatenate(seen) == os.getpid())
    _PREPARED.clear()
    seen.clear()
    run_chunks(_prepared_in, chunks, lambda c, r: seen.append(r), backend="serial",
               progress=False, prepare=_prepare)  # fmt: skip
    assert _PREPARED == [] and np.all(np.concatenate(seen) == -1)  # serial: not needed


_QUIET = """
import sys
import numpy as np
from fem_racket.studies.executors import run_chunks
seen = []
run_chunks(lambda c: c * 2.0, [np.arange(3.0)], lambda c, r: seen.append(r), backend="serial",
           progress=False)
assert np.array_equal(seen[0], [0.0, 2.0, 4.0])
print("tqdm" in sys.modules)
"""


def test_no_progress_bar_is_made_when_none_is_shown():
    """Without a bar (--quiet, not a terminal) tqdm is not imported: a disabled tqdm bar still
    cost its import and a multiprocessing lock."""
    env = dict(os.environ, PYTHONPATH=os.pathsep.join(sys.path))
    done = subprocess.run(
        [sys.executable, "-c", _QUIET], capture_output=True, text=True, check=True, env=env
    )
    assert done.stdout.strip() == "False"
