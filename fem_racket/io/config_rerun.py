"""Default outputs a run file's methods replace as their commands do.

``fem-racket fit``, ``customise``, ``compare``, ``export-vtk``, ``animate`` and ``optimize``
replace their own earlier output at their default location without ``--overwrite`` and refuse
to replace anything else there (:mod:`fem_racket.cli.options.rerun`); :meth:`RunConfig.fit`,
``.customise``, ``.compare``, ``.export_vtk``, ``.animate`` and ``.optimize`` take the same rule
(:func:`rerun_overwrite`), where the path they write to, given or from the file, is that default.

The outputs of these commands keep their provenance (:func:`fem_racket.outputs.provenance`,
``"software": "fem_racket"``) in JSON: a mesh file or an animation in its sidecar
``<file>.json``, a VTK series or a design study in the marker file of its folder
(``provenance.json``, ``result.json``); a PNG figure in its ``provenance`` text chunk, a netCDF
file in its global attributes (:func:`own_output_file`).
"""

from __future__ import annotations

import json
import os
from collections.abc import Iterable
from pathlib import Path

__all__ = ["FOLDER_MARKERS", "own_json_output", "own_output_file", "rerun_overwrite"]

#: The marker files of output folders: the VTK series', the design study's.
FOLDER_MARKERS = ("provenance.json", "result.json")


def _holds_our_provenance(path: Path) -> bool:
    """A JSON file holding fem_racket's provenance, at its top or under ``"provenance"``."""
    try:
        data = json.loads(path.read_text(encoding="utf-8"))
    except (OSError, UnicodeDecodeError, ValueError):
        return False
    meta = data.get("provenance", data) if isinstance(data, dict) else None
    return isinstance(meta, dict) and meta.get("software") == "fem_racket"


def own_json_output(path: str | os.PathLike) -> bool:
    """True if the existing ``path`` is an output fem-racket wrote, by its JSON provenance: a
    folder holding one of :data:`FOLDER_MARKERS`, a JSON file, or a file with its sidecar
    ``<file>.json`` (a mesh file, an animation). A path without such provenance is not."""
    from fem_racket.outputs import sidecar_path

    p = Path(path)
    if p.is_dir():
        return any(_holds_our_provenance(p / name) for name in FOLDER_MARKERS)
    return _holds_our_provenance(p if p.suffix.lower() == ".json" else sidecar_path(p))


def own_output_file(path: str | os.PathLike) -> bool:
    """True if the existing ``path`` is an output fem-racket wrote, as the commands judge it
    (:func:`fem_racket.cli.options.rerun.own_output`): a PNG by its ``provenance`` text chunk,
    a netCDF file by its global attributes, anything else as :func:`own_json_output`."""
    p = Path(path)
    suffix = p.suffix.lower()
    try:
        if suffix == ".png" and p.is_file():
            from PIL import Image

            with Image.open(p) as im:
                im.load()
                meta = json.loads(im.text.get("provenance", "null"))
            return isinstance(meta, dict) and meta.get("software") == "fem_racket"
        if suffix == ".nc" and p.is_file():
            import netCDF4

            with netCDF4.Dataset(p) as ds:
                return getattr(ds, "software", None) == "fem_racket"
    except (OSError, ValueError):
        return False
    return own_json_output(p)


def rerun_overwrite(overwrite: bool, default: bool, files: Iterable[str | os.PathLike]) -> bool:
    """The ``overwrite`` a method's writes take, as its command's: ``overwrite`` (the file's
    ``overwrite`` keys), or, when its destination is the command's ``default`` one, True if
    some of ``files`` (all it writes, sidecars included) exist and every existing one is its
    own output (:func:`own_output_file`); anything else stays refused, naming --overwrite."""
    if overwrite:
        return True
    existing = [Path(p) for p in files if os.path.lexists(p)]
    return default and bool(existing) and all(own_output_file(p) for p in existing)
