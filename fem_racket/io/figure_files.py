"""Figure files fit to publish: PNG, SVG or PDF at a chosen resolution, with their provenance.

Every figure the project draws (the paper's figures, ``refine``'s convergence plot, the figure
scripts) is saved by :func:`save_figure`:

- the format follows the file's suffix, one of :data:`FIGURE_FORMATS`; ``dpi`` (dots per inch,
  default :data:`DEFAULT_DPI`) sets a PNG's pixel size and the resolution of any raster part of
  an SVG or PDF (their lines and text stay vector);
- a PNG is stored with a 256-colour palette (line plots have few colours; files are ~3 times
  smaller, which keeps the reproduced figures small enough to commit) and carries the provenance
  in its text chunks (:func:`fem_racket.outputs.add_png_provenance`);
- an SVG carries it in its metadata (``<dc:description>``, the JSON, and ``<dc:creator>``), a PDF
  in its document information (``/Subject``, the JSON, and ``/Creator``).

The file is written atomically (:func:`fem_racket.outputs.atomic_output`). With
``keep_unchanged`` a PNG whose image (every chunk but the text ones) equals the existing file's
is left as it is, provenance included, so regenerating committed figures that did not change
leaves no difference for version control.
"""

from __future__ import annotations

import io
import json
import os
import struct
from collections.abc import Mapping
from pathlib import Path
from typing import Any

from fem_racket.outputs import add_png_provenance, atomic_output, provenance
from fem_racket.validation import InputError, show

__all__ = [
    "DEFAULT_DPI",
    "FIGURE_FORMATS",
    "check_dpi",
    "check_figure_format",
    "figure_format",
    "same_image",
    "save_figure",
    "save_map_png",
]

#: Formats a figure can be written in (the file suffix decides).
FIGURE_FORMATS = ("png", "svg", "pdf")
#: Default resolution [dots per inch]: print quality for figures of 8-15 inches.
DEFAULT_DPI = 150
#: Accepted resolutions [dots per inch].
DPI_RANGE = (50, 1200)


def check_figure_format(fmt: str) -> str:
    """``fmt`` (``"png"``, ``"svg"`` or ``"pdf"``, any case, leading dot allowed) in lower case."""
    value = str(fmt).lower().lstrip(".")
    if value not in FIGURE_FORMATS:
        raise InputError(
            f"format = {fmt!r} is not allowed: must be one of {', '.join(FIGURE_FORMATS)}"
        )
    return value


def figure_format(path: str | os.PathLike) -> str:
    """The format a figure file's suffix names (an InputError for any other suffix)."""
    suffix = Path(path).suffix.lower().lstrip(".")
    if suffix not in FIGURE_FORMATS:
        raise InputError(
            f"output = '{path}' is not allowed: a figure file must end in "
            + ", ".join(f".{f}" for f in FIGURE_FORMATS)
        )
    return suffix


def check_dpi(dpi: float) -> float:
    """``dpi`` if it is a number in :data:`DPI_RANGE` [dots per inch]."""
    low, high = DPI_RANGE
    try:
        ok = low <= float(dpi) <= high
    except (TypeError, ValueError):
        ok = False
    if not ok:
        raise InputError(f"dpi = {show(dpi)} is not allowed: must be a number in [{low}, {high}]")
    return float(dpi)


def _png(fig: Any, dpi: float) -> bytes:
    from PIL import Image

    buf = io.BytesIO()
    fig.savefig(buf, dpi=dpi, format="png")
    buf.seek(0)
    with Image.open(buf) as im:
        palette = im.convert("RGB").quantize(
            colors=256, method=Image.Quantize.MEDIANCUT, dither=Image.Dither.NONE
        )
    out = io.BytesIO()
    palette.save(out, format="png", optimize=True)
    return out.getvalue()


def _image_chunks(data: bytes) -> list[bytes]:
    """The chunks of a PNG file except its text and time chunks (what the image is)."""
    chunks, i = [], 8
    while i + 8 <= len(data):
        (size,) = struct.unpack(">I", data[i : i + 4])
        kind = data[i + 4 : i + 8]
        if kind not in (b"tEXt", b"zTXt", b"iTXt", b"tIME"):
            chunks.append(data[i : i + 12 + size])
        i += 12 + size
    return chunks


def same_image(path: Path, data: bytes) -> bool:
    """True if the PNG file ``path`` exists and holds the image of the PNG bytes ``data``
    (metadata such as the provenance aside)."""
    try:
        return _image_chunks(path.read_bytes()) == _image_chunks(data)
    except OSError:
        return False


def save_figure(
    fig: Any,
    path: str | os.PathLike,
    meta: Mapping[str, Any],
    *,
    dpi: float = DEFAULT_DPI,
    overwrite: bool = False,
    keep_unchanged: bool = False,
) -> Path:
    """Save the matplotlib figure ``fig`` to ``path`` (PNG, SVG or PDF by suffix) with ``meta``.

    Parameters
    ----------
    fig : matplotlib.figure.Figure
    path : path
        Ends in ``.png``, ``.svg`` or ``.pdf``.
    meta : mapping
        Provenance (:func:`fem_racket.outputs.provenance`), stored in the file.
    dpi : float
        Resolution [dots per inch], in :data:`DPI_RANGE`.
    overwrite : bool
        Replace an existing file.
    keep_unchanged : bool
        Leave an existing PNG (with ``overwrite``) whose image would not change.
    """
    fmt = figure_format(path)
    dpi = check_dpi(dpi)
    text = json.dumps(dict(meta), sort_keys=True, default=str)
    creator = f"{meta.get('software', 'fem_racket')} {meta.get('version', '')}".strip()
    png = _png(fig, dpi) if fmt == "png" else b""
    if png and keep_unchanged and overwrite and same_image(Path(path), png):
        return Path(path)
    with atomic_output(path, overwrite=overwrite) as tmp:
        if fmt == "png":
            tmp.write_bytes(png)
            add_png_provenance(tmp, meta)
        elif fmt == "svg":
            fig.savefig(
                tmp, dpi=dpi, format="svg", metadata={"Creator": creator, "Description": text}
            )
        else:
            fig.savefig(tmp, dpi=dpi, format="pdf", metadata={"Creator": creator, "Subject": text})
    return Path(path)


def save_map_png(fig: Any, tmp: Path, parameters: Mapping[str, Any] | None) -> None:
    """Save a map's figure (racket, face and spin maps) to the temporary file ``tmp``: a
    full-colour PNG at 96 dots per inch carrying the provenance of ``parameters``."""
    fig.savefig(tmp, dpi=96, format="png")
    add_png_provenance(tmp, provenance(parameters))
