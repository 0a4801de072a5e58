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
import json
import os
from collections.abc import Iterable
from pathlib import Path

__all__ = ["own_output", "replace_own"]

#: Files whose provenance lives in a sidecar ``<file>.json``.
SIDECAR_SUFFIXES = frozenset({".csv", ".vtu", ".gif", ".mp4"})
#: The marker files of output folders: the VTK series', the design study's.
FOLDER_MARKERS = ("provenance.json", "result.json")


def _json_is_ours(path: Path) -> bool:
    """A JSON file holding fem_racket's provenance, at its top or under ``"provenance"``."""
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, UnicodeDecodeError, ValueError):
        return False
    if not isinstance(data, dict):
        return False
    meta = data.get("provenance", data)
    return isinstance(meta, dict) and meta.get("software") == "fem_racket"


def _netcdf_is_ours(path: Path) -> bool:
    import netCDF4

    try:
        with netCDF4.Dataset(path) as ds:
            return getattr(ds, "software", None) == "fem_racket"
    except OSError:
        return False


def own_output(path: str | os.PathLike) -> bool:
    """True if the existing file or folder ``path`` is an output fem-racket wrote (see the
    module docstring); a path that cannot be read, or holds no provenance, is not."""
    from fem_racket.outputs import sidecar_path
    from fem_racket.paper.owned import written_by_fem_racket

    p = Path(path)
    if p.is_dir():
        return any(_json_is_ours(p / name) for name in FOLDER_MARKERS)
    suffix = p.suffix.lower()
    if suffix in SIDECAR_SUFFIXES:
        return _json_is_ours(sidecar_path(p))
    if suffix == ".nc":
        return _netcdf_is_ours(p)
    if suffix == ".json":
        return _json_is_ours(p)
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
