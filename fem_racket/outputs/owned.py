"""Which existing outputs fem-racket wrote itself, so that a command may replace them: the one
judgement of ``reproduce`` (:mod:`fem_racket.paper.owned`), of the commands writing to their
default location (:mod:`fem_racket.cli.options.rerun`) and of the run files' methods
(:mod:`fem_racket.io.config_rerun`).

A file counts as ours when it carries this project's provenance
(:func:`fem_racket.outputs.provenance`, ``"software": "fem_racket"``) where the format keeps it
(:func:`written_by_fem_racket`):

- PNG: the ``provenance`` text chunk; SVG: the metadata's ``<dc:description>``; PDF: the
  ``/Creator`` of the document information;
- ``values.json``: its ``"provenance"`` object;
- the Markdown report: its closing ``<!-- provenance: {...} -->`` comment;
- a CSV table of the reproduction: listed under ``"files"`` in the ``values.json`` of its
  folder, itself one of ours.

:func:`own_output` adds the other commands' outputs: a netCDF file by its global attributes, a
file that cannot hold provenance (CSV, VTU, GIF, MP4) by its sidecar ``<file>.json``, an output
folder by its marker file (``provenance.json`` of a VTK series, ``result.json`` of a design
study).
"""

from __future__ import annotations

import html
import json
import os
import re
from pathlib import Path

from fem_racket.outputs.provenance import sidecar_path

__all__ = ["FOLDER_MARKERS", "SIDECAR_SUFFIXES", "own_output", "written_by_fem_racket"]

#: The marker files of output folders: the VTK series', the design study's.
FOLDER_MARKERS = ("provenance.json", "result.json")
#: Files whose provenance lives in a sidecar ``<file>.json``.
SIDECAR_SUFFIXES = frozenset({".csv", ".vtu", ".gif", ".mp4"})

SOFTWARE = "fem_racket"
_REPORT_TAIL = re.compile(r"<!-- provenance: (\{.*\}) -->\s*\Z", re.S)


def _is_ours(meta: object) -> bool:
    return isinstance(meta, dict) and meta.get("software") == SOFTWARE


def _json(path: Path) -> object:
    try:
        return json.loads(path.read_text(encoding="utf-8"))
    except (OSError, UnicodeDecodeError, ValueError):
        return None


def _png(path: Path) -> bool:
    from PIL import Image, UnidentifiedImageError

    try:
        with Image.open(path) as im:
            im.load()
            text = im.text.get("provenance", "")
    except (OSError, UnidentifiedImageError):
        return False
    try:
        return _is_ours(json.loads(text))
    except ValueError:
        return False


def _head(path: Path, size: int = 1 << 16) -> bytes:
    try:
        with open(path, "rb") as fh:
            return fh.read(size)
    except OSError:
        return b""


def _tail(path: Path, size: int = 1 << 16) -> bytes:
    try:
        with open(path, "rb") as fh:
            fh.seek(max(path.stat().st_size - size, 0))
            return fh.read()
    except OSError:
        return b""


def _report(path: Path) -> bool:
    try:
        text = path.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError):
        return False
    m = _REPORT_TAIL.search(text)
    try:
        return bool(m) and _is_ours(json.loads(m.group(1)))
    except ValueError:
        return False


def _listed(path: Path) -> bool:
    values = path.parent / "values.json"
    data = _json(values)
    return (
        isinstance(data, dict)
        and _is_ours(data.get("provenance"))
        and path.name in (data.get("files") or [])
    )


def written_by_fem_racket(path: str | os.PathLike) -> bool:
    """True if the existing file ``path`` is one of the reproduction's own outputs.

    The check reads only the file's provenance (see the module docstring); a file that cannot
    be read, or holds none, is not ours.
    """
    path = Path(path)
    if not path.is_file():
        return False
    suffix = path.suffix.lower()
    if suffix == ".png":
        return _png(path)
    if suffix == ".svg":
        m = re.search(rb"<dc:description>(.*?)</dc:description>", _head(path), re.S)
        try:
            return bool(m) and _is_ours(json.loads(html.unescape(m.group(1).decode())))
        except (UnicodeDecodeError, ValueError):
            return False
    if suffix == ".pdf":
        return b"/Creator (fem_racket" in _tail(path)
    if suffix == ".json":
        data = _json(path)
        return isinstance(data, dict) and _is_ours(data.get("provenance"))
    if suffix == ".md":
        return _report(path)
    if suffix == ".csv":
        return _listed(path)
    return False


def own_output(path: str | os.PathLike) -> bool:
    """True if the existing file or folder ``path`` is an output fem-racket wrote (see the
    module docstring); a path that cannot be read, or holds no provenance, is not."""
    p = Path(path)
    suffix = p.suffix.lower()
    if p.is_dir():
        return any(_provenance_json(p / name) for name in FOLDER_MARKERS)
    if suffix == ".json":
        return _provenance_json(p)
    if suffix in SIDECAR_SUFFIXES:
        return _provenance_json(sidecar_path(p))
    if suffix == ".nc":
        return _netcdf(p)
    return written_by_fem_racket(p)


def _provenance_json(path: Path) -> bool:
    """A JSON file holding fem_racket's provenance, at its top or under ``"provenance"``."""
    data = _json(path)
    return _is_ours(data.get("provenance", data) if isinstance(data, dict) else None)


def _netcdf(path: Path) -> bool:
    import netCDF4

    try:
        with netCDF4.Dataset(path) as ds:
            return getattr(ds, "software", None) == SOFTWARE
    except (OSError, ValueError):
        return False
