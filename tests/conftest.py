"""Shared fixtures: the paper's standard and rigid frames, assembled once per session, and a
fresh working directory."""

import pytest
from threadpoolctl import threadpool_limits

from fem_racket import FrameModel, rigid_frame, standard_frame

# One BLAS thread in the test process, as the CLI and every pool worker pin it: results then do
# not depend on how many threads OpenBLAS picked (a dense product's sums split differently).
threadpool_limits(limits=1, user_api="blas")


@pytest.fixture(scope="session")
def standard_model() -> FrameModel:
    """The paper's standard racket, 20 elements (section 2.3)."""
    return FrameModel.build(standard_frame(), 20)


@pytest.fixture(scope="session")
def rigid_model() -> FrameModel:
    """The paper's 'rigid' racket, EI1 = 9999 N m^2, 20 elements."""
    return FrameModel.build(rigid_frame(), 20)


@pytest.fixture
def local_cluster():
    """Make a local Dask cluster: one single-threaded worker process on 127.0.0.1, no dashboard
    (a factory, so that a test can make it inside its own ``dask.config.set``); skip without
    ``distributed``. The scheduler's HTTP server (metrics) still starts without a dashboard, on
    port 8787 unless told otherwise: it takes a free port, so that another cluster on the
    machine cannot make the test fail ("Port 8787 is already in use", a warning made an error)."""
    distributed = pytest.importorskip("distributed")

    def make():
        return distributed.LocalCluster(
            n_workers=1,
            threads_per_worker=1,
            processes=True,
            host="127.0.0.1",
            dashboard_address=None,
            scheduler_kwargs={"dashboard_address": "127.0.0.1:0"},
        )

    return make


@pytest.fixture
def cwd(tmp_path, monkeypatch):
    """A fresh working directory (relative outputs land in it)."""
    monkeypatch.chdir(tmp_path)
    return tmp_path
