"""numba's on-disk cache kept true to the kernels' sources, across the files of a room.

numba keys a cached function by its own file's timestamp and size only (numba's documentation,
"Notes on caching": changes in other files a function calls are not tracked). A kernel that
calls a compiled function of another file therefore keeps its old machine code when only that
other file changes, e.g. after a ``git pull`` that edits ``kernel_node.py`` but not
``kernel.py``: silently stale answers. :func:`guard` keeps a SHA-256 of all the kernel files of a
room in its ``__pycache__/kernels.sha256``; when it differs from the sources', the room's cached
numba files (``*.nbi``, ``*.nbc``) are removed before anything compiles, so every kernel is
compiled again from the current sources. Once per room and process. It also keeps numba's
internal helpers apart per fastmath setting (:func:`fem_racket.impact.kernel_fastmath.isolate`)
before anything compiles, and stamps that recipe into the digest, so caches compiled without it
are compiled again.
"""

from __future__ import annotations

import hashlib
import os
from pathlib import Path

from fem_racket.impact.kernel_fastmath import RECIPE, isolate

__all__ = ["guard"]

#: Rooms already checked in this process.
_CHECKED: set[Path] = set()


def guard(folder: str | os.PathLike, modules: tuple[str, ...]) -> bool:
    """Remove the numba cache of the kernel ``modules`` (file stems) in ``folder`` if any of
    their sources changed since it was written; True when it was removed.

    A folder that cannot be written (a read-only install) is left as it is: numba then caches
    elsewhere or not at all.
    """
    isolate()
    folder = Path(folder)
    if folder in _CHECKED:
        return False
    _CHECKED.add(folder)
    digest = hashlib.sha256(RECIPE.encode())
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
