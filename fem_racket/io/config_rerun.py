"""Default outputs a run file's methods replace as their commands do.

``fem-racket fit``, ``customise``, ``compare``, ``export-vtk``, ``animate`` and ``optimize``
replace their own earlier output at their default location without ``--overwrite`` and refuse
to replace anything else there (:mod:`fem_racket.cli.options.rerun`); :meth:`RunConfig.fit`,
``.customise``, ``.compare``, ``.export_vtk``, ``.animate`` and ``.optimize`` take the same rule
(:func:`rerun_overwrite`), where the path they write to, given or from the file, is that default.

Which existing output is our own is one judgement for commands and methods alike
(:func:`fem_racket.outputs.owned.own_output`), by the provenance each format keeps.
"""

from __future__ import annotations

import os
from collections.abc import Iterable
from pathlib import Path

from fem_racket.outputs.owned import own_output

__all__ = ["rerun_overwrite"]


def rerun_overwrite(overwrite: bool, default: bool, files: Iterable[str | os.PathLike]) -> bool:
    """The ``overwrite`` a method's writes take, as its command's: ``overwrite`` (the file's
    ``overwrite`` keys), or, when its destination is the command's ``default`` one, True if
    some of ``files`` (all it writes, sidecars included) exist and every existing one is its
    own output (:func:`~fem_racket.outputs.owned.own_output`); anything else stays refused,
    naming --overwrite."""
    if overwrite:
        return True
    existing = [Path(p) for p in files if os.path.lexists(p)]
    return default and bool(existing) and all(own_output(p) for p in existing)
