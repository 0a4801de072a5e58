"""Default outputs that can be rerun: a command writing to its default location (``map`` to
``output/map.png``, ``sweep`` to ``output/sweep.nc`` ...) replaces its own earlier output there
and refuses to replace anything else, as ``reproduce`` does.

An existing output is this program's own when it carries fem_racket's provenance
(:func:`fem_racket.outputs.provenance`, ``"software": "fem_racket"``) where its format keeps it:
the formats :func:`fem_racket.paper.owned.written_by_fem_racket` reads (PNG, SVG, PDF, JSON,
Markdown), a netCDF file's global attributes, the sidecar ``<file>.json`` of a file that cannot
hold it (CSV, VTU, GIF, MP4), or the marker file of an output folder (``provenance.json`` of a
VTK series, ``result.json`` of a design study). A destination named with ``--out`` is never
replaced without ``--overwrite``.
"""

from __future__ import annotations

import argparse
import os
from collections.abc import Iterable
from pathlib import Path

from fem_racket.io.config_rerun import own_json_output

__all__ = ["own_output", "replace_own"]

#: Files whose provenance lives in a sidecar ``<file>.json``.
SIDECAR_SUFFIXES = frozenset({".csv", ".vtu", ".gif", ".mp4"})


def _netcdf_is_ours(path: Path) -> bool:
    import netCDF4

    try:
        with netCDF4.Dataset(path) as ds:
            return getattr(ds, "software", None) == "fem_racket"
    except OSError:
        return False


def own_output(path: str | os.PathLike) -> bool:
    """True if the existing file or folder ``path`` is an output fem-racket wrote (see the
    module docstring); a path that cannot be read, or holds no provenance, is not. Folders, JSON
    files and files with a sidecar are read as the run files' methods read them
    (:func:`fem_racket.io.config_rerun.own_json_output`)."""
    from fem_racket.paper.owned import written_by_fem_racket

    p = Path(path)
    suffix = p.suffix.lower()
    if p.is_dir() or suffix in SIDECAR_SUFFIXES or suffix == ".json":
        return own_json_output(p)
    if suffix == ".nc":
        return _netcdf_is_ours(p)
    return written_by_fem_racket(p)


def replace_own(
    args: argparse.Namespace, default: bool, files: Iterable[str | os.PathLike]
) -> bool:
    """The ``overwrite`` a command's writes take: ``--overwrite``, or, when its destination is
    its ``default`` one, True if every existing one of ``files`` (all it writes, sidecars
    included) is its own output; anything else stays refused, naming --overwrite."""
    if args.overwrite:
        return True
    existing = [Path(p) for p in files if os.path.lexists(p)]
    return default and bool(existing) and all(own_output(p) for p in existing)
