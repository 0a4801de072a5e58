"""Default outputs that can be rerun: a command writing to its default location (``map`` to
``output/map.png``, ``sweep`` to ``output/sweep.nc`` ...) replaces its own earlier output there
and refuses to replace anything else, as ``reproduce`` does.

An existing output is this program's own when it carries fem_racket's provenance
(:func:`fem_racket.outputs.provenance`, ``"software": "fem_racket"``) where its format keeps it:
:func:`fem_racket.outputs.owned.own_output`, the judgement the run files' methods take too
(:func:`fem_racket.io.config_rerun.rerun_overwrite`). A destination named with ``--out`` is never
replaced without ``--overwrite``.
"""

from __future__ import annotations

import argparse
import os
from collections.abc import Iterable

from fem_racket.io.config_rerun import rerun_overwrite

__all__ = ["replace_own"]


def replace_own(
    args: argparse.Namespace, default: bool, files: Iterable[str | os.PathLike]
) -> bool:
    """The ``overwrite`` a command's writes take: ``--overwrite``, or, when its destination is
    its ``default`` one, True if every existing one of ``files`` (all it writes, sidecars
    included) is its own output; anything else stays refused, naming --overwrite
    (:func:`~fem_racket.io.config_rerun.rerun_overwrite`, as a run file's method)."""
    return rerun_overwrite(args.overwrite, default, files)
