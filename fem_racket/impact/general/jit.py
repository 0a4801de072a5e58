"""Which march runs: the kernels compiled by numba, or their own code interpreted for a lone impact.

The kernel modules (:mod:`~fem_racket.impact.general.kernel_laws`,
:mod:`~fem_racket.impact.general.kernel_modes`, :mod:`~fem_racket.impact.general.kernel_node`,
:mod:`~fem_racket.impact.general.kernel`) take their decorator from here: numba's ``njit`` once
the process compiles them, the function itself until then. Loading numba and its cached code costs
~0.3-0.5 s CPU per process (numba's import, the modules the cached code names, the cache:
:mod:`fem_racket.impact.kernel_cache`), ~3-10 times what one impact costs when interpreted
(~40-100 ms). Interpreted, the kernels
do the same floating-point operations (integer powers, square roots and complex divisions are
written out as numba computes them), so the answers are the same, bit for bit
(``tests/impact/general/test_jit.py``). So
the first solve of a process, when it is a lone impact (``fem-racket simulate --law``, one
:func:`fem_racket.simulate`), runs interpreted, run by run while a run has at most
:data:`INTERPRETED_NODES` nodes; any other solve, and any run longer than that, loads the compiled
kernels (reloading the kernel modules once, with numba's decorator) and keeps them for the rest
of the process.
"""

from __future__ import annotations

import importlib
import sys
from collections.abc import Callable, Iterator
from contextlib import contextmanager
from pathlib import Path

__all__ = ["INTERPRETED_NODES", "lone_solve", "njit", "prepare"]

#: The most nodes a run of an interpreted lone impact has (~0.1 ms a node at ~30 modes);
#: a longer run compiles.
INTERPRETED_NODES = 1024
#: The kernel modules, each after those it imports.
_MODULES = tuple(
    f"fem_racket.impact.general.{name}"
    for name in ("kernel_laws", "kernel_modes", "kernel_node", "kernel")
)
_STATE = {"compiled": False, "solved": False, "interpreted": False}


def njit(*args: object, **options: object) -> Callable:
    """numba's ``njit`` (with ``options``) once the kernels are compiled; else the function."""
    if _STATE["compiled"]:
        from numba import njit as numba_njit

        return numba_njit(*args, **options)
    if args and callable(args[0]):
        return args[0]
    return lambda function: function


@contextmanager
def lone_solve(ncase: int) -> Iterator[None]:
    """A solve of ``ncase`` impacts: interpreted runs if it is the process's first and
    ``ncase`` is 1 (the kernels not compiled yet)."""
    first = not _STATE["solved"]
    _STATE["solved"] = True
    _STATE["interpreted"] = first and ncase == 1 and not _STATE["compiled"]
    try:
        yield
    finally:
        _STATE["interpreted"] = False


def prepare(nodes: int) -> None:
    """Before a run of ``nodes`` nodes per case: the kernels stay interpreted inside a lone
    first solve (up to :data:`INTERPRETED_NODES`), else they are compiled."""
    if not (_STATE["interpreted"] and nodes <= INTERPRETED_NODES):
        _compile()


def _compile() -> None:
    """Decorate the kernels with numba's njit from now on (reloading those imported)."""
    if _STATE["compiled"]:
        return
    from fem_racket.impact.kernel_cache import guard

    guard(Path(__file__).parent, tuple(name.rsplit(".", 1)[1] for name in _MODULES))
    _STATE["compiled"] = True
    _STATE["interpreted"] = False
    for name in _MODULES:
        module = sys.modules.get(name)
        if module is not None:
            importlib.reload(module)
