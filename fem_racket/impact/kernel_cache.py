"""numba's on-disk cache kept true to the kernels' sources, across the files of a room.

numba keys a cached function by its own file's timestamp and size only (numba's documentation,
"Notes on caching": changes in other files a function calls are not tracked). A kernel that
calls a compiled function of another file therefore keeps its old machine code when only that
other file changes, e.g. after a ``git pull`` that edits ``kernel_node.py`` but not
``kernel.py``: silently stale answers. :func:`guard` keeps a SHA-256 of all the kernel files of a
room, and of the options every kernel is compiled with (:data:`KERNEL_OPTIONS`), in its
``__pycache__/kernels.sha256``; when it differs from the sources', the room's cached numba files
(``*.nbi``, ``*.nbc``) are removed before anything compiles, so every kernel is compiled again
from the current sources. Once per room and process. It also keeps numba's internal helpers
apart per fastmath setting (:func:`fem_racket.impact.kernel_fastmath.isolate`)
before anything compiles, and stamps that recipe into the digest, so caches compiled without it
are compiled again.

**Loading cached code.** Before it reads a cached function, numba (0.68) refreshes its target
context: it imports and installs every lowering and typing registry it has (arrays, typed
containers, random generators, polynomials, jitclass, ...; with them scipy.linalg): 0.25-0.3 s
CPU (measured at load 3 on the 2-core machine; a process that runs a linear sweep of four cases
took 0.70-1.09 s CPU with it, 0.43-0.57 s without), all of it needed only to compile.
The machine code it reads needs numba's runtime (NRT: allocation, reference counts), which the
refresh also starts. :func:`light_loads` makes numba load a cached kernel of this package
(a function of a ``fem_racket.impact`` module) with the runtime started instead; the modules
the cached code's environments name (``numba.np.arraymath``, ...) are still imported as it is
read, and any other function's cache loads as numba loads it. A compile still refreshes first
(numba's compiler does), so a cache miss compiles exactly as before, and the code run is the
cached code either way (``tests/impact/test_kernel_cache.py``: the same answers, bit for bit,
and the registries left unloaded).
"""

from __future__ import annotations

import functools
import hashlib
import inspect
import logging
import os
from pathlib import Path

from fem_racket.impact.kernel_fastmath import RECIPE, isolate

__all__ = ["KERNEL_OPTIONS", "guard", "light_loads"]

log = logging.getLogger(__name__)

#: numba's options of every kernel (:mod:`fem_racket.impact.exact`'s and
#: :mod:`fem_racket.impact.general`'s): cached on disk (kept true by :func:`guard`, which stamps
#: them into its digest), released from the GIL, numpy's error model (inf and NaN, no exceptions).
KERNEL_OPTIONS = {"cache": True, "nogil": True, "error_model": "numpy"}
#: Rooms already checked in this process.
_CHECKED: set[Path] = set()
#: The parameters of numba's ``Cache.load_overload`` that :func:`light_loads` replaces.
_LOAD_PARAMETERS = ["self", "sig", "target_context"]
_LIGHT = {"on": False}
#: Whose cached functions :func:`light_loads` loads without the refresh: this package's kernels.
_OWN = "fem_racket.impact."


def light_loads() -> bool:
    """From now on numba loads a cached kernel of this package after starting its runtime only,
    not after refreshing (importing and installing) every compile-time registry; True when this
    is in force. Once per process; any compile still refreshes first.

    A numba whose ``Cache.load_overload`` is not the one this was written for keeps its own,
    with a warning (loads then cost the refresh again; the pinned numba is tested).
    """
    if _LIGHT["on"]:
        return True
    import numba
    from numba.core.caching import Cache
    from numba.core.runtime.nrt import rtsys

    original = Cache.load_overload
    known = list(inspect.signature(original).parameters) == _LOAD_PARAMETERS and all(
        hasattr(Cache, name) for name in ("_load_overload", "_guard_against_spurious_io_errors")
    )
    if not known:
        log.warning(
            "numba %s: Cache.load_overload is not the one fem_racket.impact.kernel_cache "
            "replaces; cached kernels load as numba loads them (slower start)",
            numba.__version__,
        )
        return False

    @functools.wraps(original)
    def load_overload(self, sig, target_context):
        module = getattr(getattr(self, "_py_func", None), "__module__", None) or ""
        if not module.startswith(_OWN):
            return original(self, sig, target_context)
        rtsys.initialize(target_context)  # the runtime the cached code calls
        with self._guard_against_spurious_io_errors():
            return self._load_overload(sig, target_context)
        return None  # the `with` swallowed an I/O error (as numba's own)

    Cache.load_overload = load_overload
    _LIGHT["on"] = True
    return True


def guard(folder: str | os.PathLike, modules: tuple[str, ...]) -> bool:
    """Remove the numba cache of the kernel ``modules`` (file stems) in ``folder`` if any of
    their sources changed since it was written; True when it was removed.

    A folder that cannot be written (a read-only install) is left as it is: numba then caches
    elsewhere or not at all.
    """
    isolate()
    light_loads()
    folder = Path(folder)
    if folder in _CHECKED:
        return False
    _CHECKED.add(folder)
    digest = hashlib.sha256(RECIPE.encode())
    digest.update(repr(KERNEL_OPTIONS).encode())
    for name in modules:
        digest.update((folder / f"{name}.py").read_bytes())
    cache = folder / "__pycache__"
    stamp = cache / "kernels.sha256"
    try:
        if stamp.read_text() == digest.hexdigest():
            return False
    except OSError:
        pass  # no stamp yet: the cache, if any, is of unknown sources
    try:
        for name in modules:
            for path in cache.glob(f"{name}.*.nb[ic]"):
                path.unlink(missing_ok=True)
        cache.mkdir(exist_ok=True)
        part = cache / f"kernels.sha256.{os.getpid()}.part"
        part.write_text(digest.hexdigest())
        os.replace(part, stamp)
    except OSError:
        return False
    return True
