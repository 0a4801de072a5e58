"""numba's internal helpers kept apart per fastmath setting: a kernel's machine code must not
depend on what the process compiled before it.

numba compiles many operations (complex products and quotients, integer powers, complex
``abs``, ...) as small internal functions (``BaseContext.compile_internal``) and keeps each in
one table per process, ``cached_internal_func``, keyed by the function's code, its signature and
the error model, but not by the fastmath flags it was compiled with (numba 0.68 still). So the
first function of a process that needs a helper decides the helper's flags for every later
function: after one compiled with ``fastmath`` (the linear engine's
:func:`~fem_racket.impact.exact.kernel_roots.case_roots` with ``contract``, a library's
``@jit(fastmath=True)``), the complex products of kernels without fastmath were contracted into
fused multiply-adds too, and cached on disk so (issue 27: after a linear batch compiled on an
empty cache, the hysteretic ball's COR at 30 m/s was 0.1846719513970374, not the interpreted
kernels' 0.18467195139703765). :func:`isolate` gives the helpers compiled under each fastmath
setting their own table and empties the shared one, so every function is compiled with the
helpers of its own flags, whatever ran before it in the process.
"""

from __future__ import annotations

import functools
import inspect

__all__ = ["RECIPE", "isolate"]

#: Stamped into the kernel caches' digest (:func:`fem_racket.impact.kernel_cache.guard`):
#: caches compiled before the helpers were kept apart are compiled again, once.
RECIPE = "fastmath-helpers-apart-1"
#: numba's method this module wraps, with the parameters it passes on.
_PARAMETERS = ["self", "builder", "impl", "sig", "locals", "flags", "caching"]
_STATE = {"isolated": False}


class _FastTable(dict):
    """The helpers compiled under one fastmath setting, for the table ``shared``."""

    def __init__(self, shared: dict, key: frozenset) -> None:
        super().__init__()
        self.shared, self.key = shared, key


#: (id of a shared table, fastmath flags) -> its helpers' table (which keeps the shared alive).
_TABLES: dict[tuple[int, frozenset], _FastTable] = {}


def _table(shared: dict, fastmath: object) -> _FastTable:
    """The helpers' table for a context with ``fastmath`` flags whose own table is ``shared``."""
    key = frozenset(getattr(fastmath, "flags", ("fast",)))
    if isinstance(shared, _FastTable):
        if shared.key == key:
            return shared
        shared = shared.shared
    return _TABLES.setdefault((id(shared), key), _FastTable(shared, key))


def isolate() -> None:
    """From now on, numba compiles the helpers of a function with fastmath flags into a table
    of those flags only (the shared table, emptied now, holds only helpers without).

    Raises
    ------
    RuntimeError
        When numba's ``BaseContext.compile_subroutine`` is not the one this was written for.
    """
    if _STATE["isolated"]:
        return
    import numba
    from numba.core.base import BaseContext
    from numba.core.registry import cpu_target

    original = BaseContext.compile_subroutine
    if list(inspect.signature(original).parameters) != _PARAMETERS:
        raise RuntimeError(
            f"numba {numba.__version__}: BaseContext.compile_subroutine is not the one "
            "fem_racket.impact.kernel_fastmath keeps apart per fastmath setting"
        )

    @functools.wraps(original)
    def compile_subroutine(self, builder, impl, sig, locals=None, flags=None, caching=True):
        if not self.fastmath:
            return original(self, builder, impl, sig, locals, flags, caching)
        shared = self.cached_internal_func
        self.cached_internal_func = _table(shared, self.fastmath)
        try:
            return original(self, builder, impl, sig, locals, flags, caching)
        finally:
            self.cached_internal_func = shared

    BaseContext.compile_subroutine = compile_subroutine
    # helpers already compiled in this process may carry another function's fastmath flags
    cpu_target.target_context.cached_internal_func.clear()
    _STATE["isolated"] = True
