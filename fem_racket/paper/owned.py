"""Which existing files ``reproduce`` may replace: its own outputs, by their provenance
(:func:`fem_racket.outputs.owned.written_by_fem_racket`).

``fem-racket reproduce`` rewrites its own outputs without ``--overwrite`` (a fresh clone holds the
committed figures of ``output/paper/`` and ``REPRODUCTION.md``) but never a file it did not
write.
"""

from __future__ import annotations

import os
from collections.abc import Iterable

from fem_racket.outputs import Target, check_output_path
from fem_racket.outputs.checks import as_target, refuse
from fem_racket.outputs.owned import written_by_fem_racket

__all__ = ["check_replaceable"]


def check_replaceable(
    targets: Iterable[Target | str | os.PathLike], *, overwrite: bool = False
) -> None:
    """Before any work: each existing target must be one of our own outputs, unless
    ``overwrite``; an InputError names the first that is not (and any unwritable place), with
    the option that named it (a plain path: ``out``)."""
    for target in targets:
        t = as_target(target)
        p = t.path
        if overwrite or not p.exists() or p.is_dir() or written_by_fem_racket(p):
            check_output_path(p, overwrite=True, name=t.name)  # a folder, an unwritable place
            continue
        raise refuse(
            t, "it already exists and is not a file fem-racket reproduce wrote (no fem_racket "
            "provenance in it): pass --overwrite to replace it",
        )  # fmt: skip
