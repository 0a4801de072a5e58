"""How large a sweep may be: a memory estimate checked before any case runs.

A sweep keeps, per case, its result values (5 float64), the done flags and the to-do indices,
the checkpoint's copy of both, the dataset built at the end and the netCDF writer's buffer:
about :data:`BYTES_PER_CASE` bytes (measured peaks stay below it). A grid is refused before
anything is allocated when it has more than :data:`MAX_CASES` cases or its estimate exceeds half
the memory available now (``MemAvailable`` of ``/proc/meminfo``, else free pages).
"""

from __future__ import annotations

import os
from collections.abc import Sequence

from fem_racket.validation import InputError

__all__ = ["BYTES_PER_CASE", "MAX_CASES", "available_memory", "check_grid_size"]

#: Most cases of one sweep (~2 GB by the estimate; ~5 min per million on the exact path).
MAX_CASES = 10_000_000
#: Estimated peak memory per case of a sweep [bytes].
BYTES_PER_CASE = 200


def available_memory() -> int | None:
    """Memory available to this process now [bytes], or None when the system does not say."""
    try:
        with open("/proc/meminfo", encoding="ascii") as f:
            for line in f:
                if line.startswith("MemAvailable:"):
                    return int(line.split()[1]) * 1024
    except (OSError, ValueError, IndexError):
        pass
    try:
        return int(os.sysconf("SC_AVPHYS_PAGES") * os.sysconf("SC_PAGE_SIZE"))
    except (ValueError, OSError, AttributeError):
        return None


def check_grid_size(shape: Sequence[int], dims: Sequence[str]) -> int:
    """Return the number of cases of a grid of ``shape`` (dimension names ``dims``), or raise
    :class:`InputError` when it is over :data:`MAX_CASES` or its memory estimate over half the
    available memory."""
    size = 1
    for n in shape:
        size *= int(n)
    grid = " x ".join(f"{d} {n}" for d, n in zip(dims, shape, strict=True)) or "one case"
    need = size * BYTES_PER_CASE
    avail = available_memory()
    if size > MAX_CASES:
        raise InputError(
            f"sweep grid of {size} cases ({grid}) is not allowed: at most {MAX_CASES} cases "
            f"(about {need / 1e9:.3g} GB at {BYTES_PER_CASE} bytes per case)"
        )
    if avail is not None and need > avail / 2:
        raise InputError(
            f"sweep grid of {size} cases ({grid}) is not allowed: it needs about "
            f"{need / 1e9:.3g} GB, more than half the {avail / 1e9:.3g} GB of memory available"
        )
    return size
