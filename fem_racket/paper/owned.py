"""Which existing files ``reproduce`` wrote itself, so that it may replace them.

``fem-racket reproduce`` rewrites its own outputs without ``--overwrite`` (a fresh clone holds the
committed figures of ``output/paper/`` and ``REPRODUCTION.md``) but never a file it did not
write. A file counts as its own when it carries this project's provenance
(:func:`fem_racket.outputs.provenance`, ``"software": "fem_racket"``) where the format keeps it:

- PNG: the ``provenance`` text chunk; SVG: the metadata's ``<dc:description>``; PDF: the
  ``/Creator`` of the document information;
- ``values.json``: its ``"provenance"`` object;
- the Markdown report: its closing ``<!-- provenance: {...} -->`` comment;
- a CSV table (CSV has no room for provenance): listed under ``"files"`` in the ``values.json``
  of its folder, itself one of ours.
"""

from __future__ import annotations

import html
import json
import os
import re
from collections.abc import Iterable
from pathlib import Path

from fem_racket.outputs import Target, check_output_path
from fem_racket.outputs.checks import as_target, refuse

__all__ = ["check_replaceable", "written_by_fem_racket"]

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
