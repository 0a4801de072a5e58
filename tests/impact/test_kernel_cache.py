"""numba's cache is dropped when any kernel file of a room changed (numba tracks a function's
own file only): :func:`fem_racket.impact.kernel_cache.guard`."""

from fem_racket.impact import kernel_cache
from fem_racket.impact.kernel_cache import guard


def _room(tmp_path):
    for name in ("a", "b"):
        (tmp_path / f"{name}.py").write_text(f"# kernel {name}\n")
    cache = tmp_path / "__pycache__"
    cache.mkdir()
    cached = [cache / "a.f-10.py311.nbi", cache / "a.f-10.py311.1.nbc", cache / "b.g-3.py311.nbi"]
    for path in cached:
        path.write_text("compiled")
    other = cache / "a.cpython-311.pyc"  # not numba's: never touched
    other.write_text("bytecode")
    return cached, other


def test_a_change_in_any_file_drops_the_room_cache(tmp_path, monkeypatch):
    cached, other = _room(tmp_path)
    monkeypatch.setattr(kernel_cache, "_CHECKED", set())
    assert guard(tmp_path, ("a", "b"))  # no stamp yet: a cache of unknown sources goes
    assert not any(p.exists() for p in cached) and other.exists()
    for path in cached:  # compiled again
        path.write_text("compiled")
    monkeypatch.setattr(kernel_cache, "_CHECKED", set())
    assert not guard(tmp_path, ("a", "b"))  # the same sources: kept
    assert all(p.exists() for p in cached)
    (tmp_path / "b.py").write_text("# kernel b, edited\n")  # only the callee's file changes
    monkeypatch.setattr(kernel_cache, "_CHECKED", set())
    assert guard(tmp_path, ("a", "b"))
    assert not any(p.exists() for p in cached) and other.exists()


def test_once_per_process(tmp_path, monkeypatch):
    cached, _ = _room(tmp_path)
    monkeypatch.setattr(kernel_cache, "_CHECKED", {tmp_path})
    assert not guard(tmp_path, ("a", "b"))  # already checked in this process
    assert all(p.exists() for p in cached)
