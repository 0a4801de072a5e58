"""A design study's history is a checkpoint (issue 22.4), as a sweep's: a batch truncated,
emptied, altered, deleted or from another problem is never merged - it is dropped with a note
and its designs computed again, giving the clean run's answer; a damaged ``problem.json`` is
rewritten; names never collide; a lock stops a second study on the same output."""

import logging
import os
import subprocess
import sys
import time

import numpy as np
import pytest
from planted import planted

from fem_racket.cli import main
from fem_racket.studies.design.evaluate import Evaluator
from fem_racket.studies.design.options import VariableOptions
from fem_racket.studies.design.paper_problem import paper_problem
from fem_racket.studies.design.solvers import optimize
from fem_racket.studies.design.variables import Constraint
from fem_racket.validation import InputError


def problem(**kwargs):
    return paper_problem(
        None,
        VariableOptions(boundaries=(0.3,)),
        constraints=(Constraint("mass_kg", high=1.5),),
        **kwargs,
    )


def study(folder, p=None):
    """Optimise with the history in ``folder``: (result, designs computed, evaluator)."""
    p = p or problem()
    ev = Evaluator(p, history=folder, function=planted)
    try:
        r = optimize(p, evaluator=ev, maxiter=30, progress=False)
    finally:
        ev.history.close()
    return r, ev.computed


@pytest.fixture
def clean(tmp_path):
    """The answer of a clean run, and a history folder a first run left behind."""
    r, computed = study(tmp_path / "h")
    assert computed > 0
    return r, computed, tmp_path / "h"


def _batches(folder):
    return sorted(folder.glob("batch-*.npy"))


def _damage(kind, path, other):
    if kind == "truncated":
        path.write_bytes(path.read_bytes()[:-40])
    elif kind == "emptied":
        path.write_bytes(b"")
    elif kind == "altered":
        data = bytearray(path.read_bytes())
        data[-3] ^= 0x01  # one bit of one output
        path.write_bytes(bytes(data))
    elif kind == "deleted":
        path.unlink()
    elif kind == "foreign":  # a batch of another problem copied in under a valid-looking name
        other_batch = _batches(other)[0]
        path.write_bytes(other_batch.read_bytes())
        path.rename(path.with_name(f"batch-0000099-{other_batch.name.split('-')[2]}"))


@pytest.mark.parametrize("kind", ["truncated", "emptied", "altered", "deleted", "foreign"])
def test_a_damaged_batch_is_dropped_and_its_designs_computed_again(clean, tmp_path, kind, caplog):
    r0, computed0, folder = clean
    other = tmp_path / "other"
    if kind == "foreign":
        study(other, problem(speeds=(20.0,)))
    batches = _batches(folder)
    assert len(batches) > 2
    _damage(kind, batches[1], other)
    with caplog.at_level(logging.WARNING):
        r, computed = study(folder)
    # the clean run's answer, bit for bit; only the dropped batch's designs computed again
    assert np.array_equal(r.x, r0.x) and r.objective == r0.objective
    assert 0 < computed < computed0
    if kind != "deleted":
        assert "is not used" in caplog.text and "computed again" in caplog.text
    # a third run finds everything on disk, the new batch's name not colliding with any
    assert study(folder)[1] == 0


def test_a_damaged_problem_file_is_rewritten_not_called_another_problem(clean, caplog):
    r0, _, folder = clean
    (folder / "problem.json").write_text('{"digest": ')
    with caplog.at_level(logging.WARNING):
        r, computed = study(folder)
    assert "problem.json' is damaged" in caplog.text and "rewritten" in caplog.text
    assert computed == 0 and np.array_equal(r.x, r0.x)


def test_a_readable_history_of_another_problem_is_refused(clean):
    with pytest.raises(InputError, match="belongs to a different design problem"):
        study(clean[2], problem(speeds=(20.0,)))


def test_restart_discards_the_history(clean):
    _, computed0, folder = clean
    p = problem()
    ev = Evaluator(p, history=folder, function=planted, restart=True)
    optimize(p, evaluator=ev, maxiter=30, progress=False)
    ev.history.close()
    assert ev.computed == computed0


_HOLD = """
import fcntl, sys, time
folder = sys.argv[1]
f = open(folder + "/lock", "a+")
fcntl.flock(f.fileno(), fcntl.LOCK_EX)
f.seek(0); f.truncate(); f.write("4242\\n"); f.flush()
print("held", flush=True)
time.sleep(60)
"""


@pytest.fixture
def held(tmp_path):
    """``out.history`` locked by another process (as a running optimize holds it)."""
    folder = tmp_path / "out.history"
    folder.mkdir()
    proc = subprocess.Popen(
        [sys.executable, "-c", _HOLD, str(folder)], stdout=subprocess.PIPE, text=True
    )
    try:
        assert proc.stdout.readline().strip() == "held"
        yield folder
    finally:
        proc.kill()
        proc.wait()
        proc.stdout.close()


@pytest.mark.skipif(os.name != "posix", reason="flock")
def test_two_studies_on_one_output_cannot_both_run(capsys, held, monkeypatch):
    # Before: both ran and the first failed late.
    monkeypatch.chdir(held.parent)
    t0 = time.perf_counter()
    code = main(["optimize", "--maxiter", "1", "--zone-points", "3", "--out", "out"])
    err = capsys.readouterr().err
    assert code == 2 and err.count("\n") == 1, err
    assert "another design study (process 4242) is using it" in err
    assert time.perf_counter() - t0 < 15 and not (held.parent / "out").exists()


def test_evaluators_of_one_process_share_the_lock(tmp_path):
    p = problem()
    a = Evaluator(p, history=tmp_path / "h", function=planted)
    b = Evaluator(p, history=tmp_path / "h", function=planted)
    b.history.close()
    a.history.close()
    assert (tmp_path / "h" / "lock").exists()
