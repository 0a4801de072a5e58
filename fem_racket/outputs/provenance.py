"""Provenance: the metadata every output carries, and where it goes in formats that cannot
hold it (a sidecar ``<file>.json``; PNG text chunks)."""

from __future__ import annotations

import datetime as _dt
import os
import platform
from collections.abc import Mapping
from pathlib import Path
from typing import Any

from fem_racket.display import plain

__all__ = ["add_png_provenance", "provenance", "sidecar_path"]


def provenance(parameters: Mapping[str, Any] | None = None) -> dict[str, Any]:
    """Metadata for an output file: package version, UTC date, platform and ``parameters``
    (numpy scalars and arrays in them as Python numbers and lists,
    :func:`fem_racket.display.plain`)."""
    from fem_racket.version import __version__

    out: dict[str, Any] = {
        "software": "fem_racket",
        "version": __version__,
        "created_utc": _dt.datetime.now(_dt.UTC).isoformat(timespec="seconds"),
        "python": platform.python_version(),
        "source": "Kawazoe & Kanda (1997), JSME Int. J. C 40(1)",
    }
    if parameters:
        out["parameters"] = plain(dict(parameters))
    return out


def sidecar_path(path: str | os.PathLike) -> Path:
    """The provenance file beside an output that cannot hold it (CSV, GIF, MP4): ``<path>.json``."""
    path = Path(path)
    return path.with_name(path.name + ".json")


def add_png_provenance(path: str | os.PathLike, meta: Mapping[str, Any]) -> None:
    """Add the provenance ``meta`` to a PNG file as text chunks, in place (no re-encoding).

    Chunks: ``Software`` (``fem_racket <version>``), ``Creation Time`` and ``provenance`` (the
    whole dict as JSON). Readers: ``PIL.Image.open(path).text["provenance"]``, ``exiftool``.
    """
    import json
    import struct
    import zlib

    path = Path(path)
    data = path.read_bytes()
    if not data.startswith(b"\x89PNG\r\n\x1a\n") or data[-12:-8] != b"\x00\x00\x00\x00":
        raise ValueError(f"{path} is not a PNG file ending in IEND")
    texts = {
        "Software": f"{meta.get('software', 'fem_racket')} {meta.get('version', '')}".strip(),
        "Creation Time": str(meta.get("created_utc", "")),
        "provenance": json.dumps(dict(meta), sort_keys=True, default=str),
    }
    chunks = b""
    for key, text in texts.items():
        body = key.encode("latin-1") + b"\x00" + text.encode("latin-1", "backslashreplace")
        crc = zlib.crc32(b"tEXt" + body) & 0xFFFFFFFF
        chunks += struct.pack(">I", len(body)) + b"tEXt" + body + struct.pack(">I", crc)
    path.write_bytes(data[:-12] + chunks + data[-12:])
