"""numba's cache is dropped when any kernel file of a room changed (numba tracks a function's
own file only): :func:`fem_racket.impact.kernel_cache.guard`."""

import json
import os
import subprocess
import sys

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


# A sweep of each room in a new process: the linear engine (exact) and a law's batch (general).
_CHILD = """
import json, sys
from fem_racket.impact import kernel_cache
if sys.argv[1] == "numba":
    kernel_cache._LIGHT["on"] = True  # never replaced: numba's own loads
from fem_racket.studies.sweep import sweep_result
runs = [sweep_result(position=[0.6, 0.8], speed=[20.0, 30.0], backend="serial")]
linalg = "scipy.linalg" in sys.modules  # the engine's cached kernels name no numba.np.arraymath
runs.append(sweep_result(law="hunt-crossley", position=[0.6, 0.8], speed=30.0, backend="serial"))
law_linalg = "scipy.linalg" in sys.modules  # nor the law's (kernel.march_cases: no .max())
print(json.dumps({
    "values": [[float(x).hex() for x in run.values.ravel()] for run in runs],
    "registries": "numba.np.polynomial.polynomial_core" in sys.modules,
    "linalg": linalg,
    "law_linalg": law_linalg,
}))
"""

# A function of another package, cached in NUMBA_CACHE_DIR: compiled, then loaded after guard().
_OTHER = """
import json, sys
import numpy as np
from numba import njit
from fem_racket.impact.kernel_cache import light_loads

@njit(cache=True)
def total(x):
    return np.sum(x * x)

if sys.argv[1] == "load":
    assert light_loads()
print(json.dumps({
    "value": total(np.arange(4.0)),
    "hits": sum(total.stats.cache_hits.values()),
    "registries": "numba.np.polynomial.polynomial_core" in sys.modules,
}))
"""


def _run(*args: str, env: dict | None = None) -> dict:
    """What the child ``python ARGS`` prints (JSON), the test's packages on its path."""
    env = dict(os.environ if env is None else env, PYTHONPATH=os.pathsep.join(sys.path))
    done = subprocess.run([sys.executable, *args], capture_output=True, text=True, env=env)
    assert done.returncode == 0, done.stderr
    return json.loads(done.stdout)


def test_cached_kernels_load_without_the_compile_registries():
    """The same answers, bit for bit, whether numba refreshes its registries before loading a
    cached kernel or only starts its runtime (which leaves its registries unloaded)."""
    numba = _run("-c", _CHILD, "numba")  # first: compiles and caches if the cache is empty
    light = _run("-c", _CHILD, "light")  # loads what the first cached
    assert light["values"] == numba["values"]
    assert numba["registries"] and not light["registries"]
    assert not light["linalg"]  # a linear sweep loads no scipy.linalg (kernel_events._argmax)
    assert not light["law_linalg"]  # nor a law's sweep (kernel.march_cases's longest case)


def test_other_functions_load_as_numba_loads_them(tmp_path):
    """A cached function that is not one of this package's kernels loads after numba's own
    refresh (its registries loaded), and gives its answer."""
    env = dict(os.environ, NUMBA_CACHE_DIR=str(tmp_path / "cache"))
    script = tmp_path / "other.py"  # numba caches the functions of files, not of -c
    script.write_text(_OTHER)
    assert _run(str(script), "compile", env=env)["hits"] == 0
    assert _run(str(script), "load", env=env) == {"value": 14.0, "hits": 1, "registries": True}
