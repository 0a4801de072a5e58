"""Checkpoints that cannot be trusted (issue 12, item 4): a truncated, empty, altered or foreign
chunk is never merged - it is recomputed with a note and the result equals a clean run; a
damaged spec.json is rewritten, not called "a different sweep"; a readable spec of another sweep
is refused naming --restart; the lock stops a second sweep on the same output."""

from __future__ import annotations

import logging

import numpy as np
import pytest
import xarray as xr

from fem_racket import InputError, sweep
from fem_racket.studies.cases import COLUMNS
from fem_racket.studies.checkpoint import Checkpoint, checkpoint_path
from fem_racket.studies.grid import SweepSpec
from fem_racket.studies.sweep import sweep_result

GRID = {"position": "0.55:0.95:6", "ei1": [60.0, 146.0, 2000.0]}


@pytest.fixture(scope="module")
def reference():
    """The clean result (no checkpoint)."""
    return sweep(**GRID, backend="serial", progress=False)


def _checkpoint(tmp_path, chunk: int = 6):
    """A checkpoint holding every case of GRID, in chunks of ``chunk`` (as a killed run leaves
    it when the file was not yet written), and the result file's path."""
    out = tmp_path / "s.nc"
    spec = SweepSpec.build(None, **GRID)
    # every column (the peak force, not asked, is NaN in the checkpoint; the modes kept last)
    values = sweep_result(**GRID, backend="serial", progress=False).values
    ckpt = Checkpoint(out, spec.digest, spec.describe(), spec.size, len(COLUMNS))
    for start in range(0, spec.size, chunk):
        idx = np.arange(start, min(start + chunk, spec.size))
        ckpt.save(idx, values[idx])
    ckpt.close()
    return out, sorted(checkpoint_path(out).glob("chunk-*.npy"))


def _resume(out, caplog):
    with caplog.at_level(logging.WARNING, logger="fem_racket.studies.checkpoint"):
        ds = sweep(**GRID, backend="serial", progress=False, output=out)
    return ds, [r.getMessage() for r in caplog.records]


def _damage(kind: str, path) -> None:
    data = path.read_bytes()
    if kind == "truncated":
        path.write_bytes(data[:100])
    elif kind == "empty":
        path.write_bytes(b"")
    elif kind == "altered":  # one COR changed by 0.1, the file still a valid .npy
        rows = np.load(path)
        rows[0, 1] += 0.1
        import io

        buf = io.BytesIO()
        np.save(buf, rows)
        path.write_bytes(buf.getvalue())
    elif kind == "foreign":  # a valid chunk of another sweep under a plausible name
        rows = np.load(path)
        rows[:, 1:] = 0.5
        path.unlink()
        np.save(path.with_name("chunk-000000000000-6.npy"), rows)


@pytest.mark.parametrize("kind", ["truncated", "empty", "altered", "foreign"])
def test_a_bad_chunk_is_recomputed_with_a_note_never_merged(tmp_path, caplog, reference, kind):
    out, chunks = _checkpoint(tmp_path)
    _damage(kind, chunks[0])
    ds, notes = _resume(out, caplog)
    assert len(notes) == 1 and "is not used" in notes[0] and "computed again" in notes[0]
    why = "no checksum" if kind == "foreign" else "checksum mismatch"
    assert why in notes[0]
    xr.testing.assert_equal(ds.drop_attrs(), reference.drop_attrs())
    assert out.exists() and not checkpoint_path(out).exists()


def test_a_damaged_spec_file_is_rewritten_not_called_a_different_sweep(tmp_path, caplog, reference):
    out, _ = _checkpoint(tmp_path)
    spec_file = checkpoint_path(out) / "spec.json"
    spec_file.write_bytes(spec_file.read_bytes()[:30])
    ds, notes = _resume(out, caplog)
    assert len(notes) == 1 and "spec.json' is damaged" in notes[0] and "rewritten" in notes[0]
    xr.testing.assert_equal(ds.drop_attrs(), reference.drop_attrs())


def test_another_sweeps_checkpoint_is_refused_naming_restart(tmp_path, reference):
    out, _ = _checkpoint(tmp_path)
    with pytest.raises(InputError, match="belongs to a different sweep.*--restart"):
        sweep(**{**GRID, "speed": 30.0}, backend="serial", progress=False, output=out)
    ds = sweep(**GRID, backend="serial", progress=False, output=out, restart=True)
    xr.testing.assert_equal(ds.drop_attrs(), reference.drop_attrs())


def test_the_lock_stops_a_second_sweep_on_the_same_output(tmp_path):
    out = tmp_path / "s.nc"
    spec = SweepSpec.build(None, **GRID)
    holder = Checkpoint(out, spec.digest, spec.describe(), spec.size, len(COLUMNS))
    try:
        with pytest.raises(InputError, match=r"another sweep \(process \d+\) is writing it"):
            sweep(**GRID, backend="serial", progress=False, output=out)
        with pytest.raises(InputError, match="another sweep"):  # --restart does not break it
            sweep(**GRID, backend="serial", progress=False, output=out, restart=True)
    finally:
        holder.close()
    sweep(**GRID, backend="serial", progress=False, output=out)  # released: runs
    assert out.exists()
