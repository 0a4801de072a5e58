"""Sweep limits checked before any work (issue 12): grid size and memory, rigidity, elements,
tolerances; a failed case is NaN in every variable; BLAS pinned in pool workers."""

import time

import numpy as np
import pytest

from fem_racket import simulate, standard_frame, sweep
from fem_racket.frame.mesh import MAX_ELEMENTS
from fem_racket.studies import limits
from fem_racket.studies.executors import run_chunks
from fem_racket.studies.grid import SweepSpec
from fem_racket.validation import InputError


def test_huge_grids_refused_at_once():
    # Issue 12: a 1e8-point grid was accepted (7.9 GB after 2 minutes).
    t0 = time.process_time()  # CPU seconds: other processes on the machine do not count
    with pytest.raises(InputError, match="num must be an integer from 1 to 10000000"):
        sweep(position="0:1:100000000", progress=False)
    with pytest.raises(InputError, match=r"100000000 cases \(position 10000 x speed 10000\)"):
        sweep(position="0:1:10000", speed="10:40:10000", progress=False)
    assert time.process_time() - t0 < 2.0


def test_grid_memory_estimate_against_available_memory(monkeypatch):
    # 1e6 cases need ~0.2 GB by the estimate: refused when only 0.3 GB is available.
    monkeypatch.setattr(limits, "available_memory", lambda: 300_000_000)
    with pytest.raises(InputError, match=r"needs about 0.2 GB, more than half the 0.3 GB"):
        SweepSpec.build(position="0:1:1000", speed="10:40:1000")
    assert SweepSpec.build(position="0:1:100", speed="10:40:100").size == 10_000


def test_sweep_and_simulate_agree_on_rigidity():
    # Issue 12: sweep --ei1 1e-6,1e300 and simulate --ei1 1e300 disagreed; both refuse now,
    # naming the parameter given, and both answer (the same COR) inside the range.
    for call in (
        lambda: sweep(ei1=[1e-6, 1e300], progress=False),
        lambda: simulate(standard_frame(1e300)),
    ):
        with pytest.raises(InputError, match=r"ei1 = 1e\+300 N m\^2 is not allowed"):
            call()
    with pytest.raises(InputError, match="ei_factor = 1e-300 is not allowed"):
        sweep(ei_factor=[1e-300, 1.0], progress=False)
    ds = sweep(ei1=[1.0, 5e8], backend="serial", progress=False)
    for ei1 in (1.0, 5e8):
        r = simulate(standard_frame(ei1), output_step=None)
        assert float(ds.cor.sel(ei1=ei1)) == pytest.approx(r.cor, abs=1e-9)


def test_sweep_elements_and_tolerances_checked_up_front():
    with pytest.raises(InputError, match=f"elements = 100000000 .*from 2 to {MAX_ELEMENTS}"):
        sweep(elements=[20, 100000000], progress=False)
    with pytest.raises(InputError, match=r"rtol = 1 is not allowed: must lie in \[1e-12, 1e-06\]"):
        sweep(solver="cvode", rtol=1, progress=False)
    with pytest.raises(InputError, match="basis = 'physical' is not allowed with 80 elements"):
        sweep(solver="cvode", basis="physical", elements=[20, 80], progress=False)


def _blas_threads(chunk: np.ndarray) -> np.ndarray:
    from threadpoolctl import threadpool_info

    counts = [lib["num_threads"] for lib in threadpool_info() if lib["user_api"] == "blas"]
    return np.full((len(chunk), 1), max(counts, default=1), dtype=float)


def test_pool_workers_run_blas_on_one_thread():
    # Issue 12 item 7: OpenBLAS at 2 threads made small dense work 2-4x slower (10-60x under
    # load). Every pool worker pins one thread, whatever the parent's setting.
    from threadpoolctl import threadpool_limits

    got = []
    with threadpool_limits(limits=2, user_api="blas"):
        run_chunks(
            _blas_threads,
            [np.arange(2), np.arange(2, 4)],
            lambda chunk, values: got.append(values),
            backend="processes",
            workers=2,
            progress=False,
        )
    assert np.all(np.concatenate(got) == 1)


def test_failed_case_is_nan_in_every_variable(monkeypatch, caplog):
    # Issue 12: a failed case kept its contact time and peak force. A case refused by the
    # modes' residual check (made impossible here) is NaN in every variable and counted.
    from fem_racket.frame import curvature
    from fem_racket.studies.cases import clear_caches

    clear_caches()
    monkeypatch.setattr(curvature, "RESIDUAL_TOL", 0.0)
    try:
        ds = sweep(position=[0.6, 0.9], elements=300, backend="serial", progress=False)
    finally:
        clear_caches()
    for name in ds.data_vars:
        assert np.all(np.isnan(ds[name].values)), name
    assert ds.attrs["failed_cases"] == 2
    assert "failed its accuracy check" in caplog.text
