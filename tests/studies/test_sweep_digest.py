"""A sweep's checkpoint key stays as it was (issue 21, D3: SweepSpec now derives its solving
fields from SweepSolving): the digests below were computed by main's code before that change
(commit 1e1970f, version pinned to "pinned"), and a checkpoint keyed by one of them resumes."""

from __future__ import annotations

import logging

import numpy as np
import pytest
import xarray as xr

import fem_racket.version
from fem_racket import sweep
from fem_racket.contact.presets import get_law
from fem_racket.studies.cases import COLUMNS
from fem_racket.studies.checkpoint import Checkpoint, checkpoint_path
from fem_racket.studies.grid import SweepSpec
from fem_racket.studies.sweep import sweep_result
from fem_racket.validation import InputError

GRID = {"position": "0.55:0.95:6", "ei1": [60.0, 146.0, 2000.0]}
OPTIONS = {
    "position": [0.6, 0.7],
    "speed": 25.0,
    "ei2": 120.0,
    "solver": "cvode",
    "separation": "force",
    "modes": 12,
    "rtol": 1e-9,
    "atol": 1e-11,
    "peak_force": True,
}
# SHA-256 hex digests written by main's SweepSpec (before it derived from SweepSolving);
# "options" without the tolerance=None it took before (cvode refuses a tolerance given since
# issue 21.3's one rule; main's code at 1e1970f wrote cdb42357... with it, 6a21f8d7... without)
PINNED = {
    "paper": "98b85e9dade318734f38a605465eebab8ab5a02132a718b14a252e90fadece14",
    "options": "6a21f8d7957309584f41b11bdcb9a151a75a02503ff13a3e9ad7ce6b2a22b7c6",
    "law": "c4b809003bafe93bb222cdd468cd1e12e8d23bc76c5f7ba901a40b6a3f9e042a",
}


@pytest.fixture
def pinned_version(monkeypatch):
    """The package version in every description is "pinned" (the digest covers it)."""
    monkeypatch.setattr(fem_racket.version, "__version__", "pinned")


def _spec(kind: str) -> SweepSpec:
    if kind == "paper":
        return SweepSpec.build(None, **GRID)
    if kind == "options":
        return SweepSpec.build(None, **OPTIONS)
    return SweepSpec.build(None, position=[0.6, 0.7], law=get_law("kawazoe-1997-nonlinear"))


@pytest.mark.parametrize("kind", sorted(PINNED))
def test_the_digest_is_the_one_main_wrote(pinned_version, kind):
    assert _spec(kind).digest == PINNED[kind]


def test_cvode_refuses_the_tolerance_it_took_as_neutral():
    # tolerance=None (every mode, which cvode keeps anyway) passed before; given, it is refused
    with pytest.raises(InputError, match="^tolerance = None is not allowed with solver 'cvode'"):
        SweepSpec.build(None, **OPTIONS, tolerance=None)


def test_a_checkpoint_keyed_by_mains_digest_resumes(pinned_version, tmp_path, caplog):
    out = tmp_path / "s.nc"
    spec = SweepSpec.build(None, **GRID)
    values = sweep_result(**GRID, backend="serial", progress=False).values
    ckpt = Checkpoint(out, PINNED["paper"], spec.describe(), spec.size, len(COLUMNS))
    for start in range(0, spec.size, 6):  # as main left it: every case, in chunks of 6
        idx = np.arange(start, start + 6)
        ckpt.save(idx, values[idx])
    ckpt.close()
    with caplog.at_level(logging.INFO, logger="fem_racket.studies"):
        ds = sweep(**GRID, backend="serial", progress=False, output=out)
    notes = [r.getMessage() for r in caplog.records]
    assert any("18 from the checkpoint, 0 to compute" in n for n in notes), notes
    assert not any("is not used" in n or "different sweep" in n for n in notes), notes
    reference = sweep(**GRID, backend="serial", progress=False)
    xr.testing.assert_equal(ds.drop_attrs(), reference.drop_attrs())
    assert out.exists() and not checkpoint_path(out).exists()
