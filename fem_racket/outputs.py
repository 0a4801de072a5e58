"""Safe output files: atomic writes, no silent overwrite, provenance.

Every file the library or CLI writes goes through :func:`atomic_output`: the content is written
to a temporary name in the destination folder and renamed into place only when complete, so an
interrupted run never leaves a half-written file. :func:`provenance` is the metadata every output
carries (package version, date, parameters, solver and tolerances).

The conventions, the same for every command (README, "Outputs, --overwrite and provenance"):

1. Library functions take the output path; only the CLI and scripts default to ``output/``.
   Commands take ``--out PATH`` and ``--overwrite``
   (:func:`fem_racket.cli.common.add_output_options`).
2. Check the path with :func:`check_output_path` *before* the work, so a long run does not fail
   at the end: an existing file is refused unless ``overwrite``; a folder that cannot be created
   or written is an :class:`~fem_racket.validation.InputError`. Nothing is created by the check:
   the folder is made when the file is written, so a failed run leaves no empty folder.
3. Write inside ``with atomic_output(path, overwrite=...) as tmp:``; on any exception the
   temporary file is removed and an existing file is left as it was.
4. Put ``provenance(parameters)`` in the file, with ``parameters`` holding every setting of the
   run (:func:`fem_racket.cli.common.run_parameters` gives the parsed options, run file
   applied): JSON a ``"provenance"`` object; netCDF global attributes; PNG text chunks
   (:func:`add_png_provenance`); a folder (VTK series) a ``provenance.json`` in it; formats that
   cannot hold it (CSV, GIF, MP4) a sidecar ``<file>.json`` (:func:`write_sidecar`).
"""

from __future__ import annotations

import datetime as _dt
import os
import platform
import shutil
import tempfile
from collections.abc import Iterator, Mapping
from contextlib import contextmanager
from pathlib import Path
from typing import Any

from fem_racket.validation import InputError

__all__ = [
    "add_png_provenance",
    "atomic_folder",
    "atomic_output",
    "check_output_folder",
    "check_output_path",
    "provenance",
    "sidecar_path",
    "write_sidecar",
]


def _umask_mode(mode: int) -> int:
    """``mode`` less the process umask (tempfile creates 0600 files and 0700 folders)."""
    mask = os.umask(0)
    os.umask(mask)
    return mode & ~mask


def _writable_folder(folder: Path, what: str = "output folder") -> None:
    """Raise unless ``folder`` exists and is writable, or could be created: its nearest
    existing ancestor is a writable folder. Creates nothing (a bad run leaves no folder)."""
    probe = folder
    while not probe.exists() and probe != probe.parent:
        probe = probe.parent
    if not probe.is_dir():
        raise InputError(
            f"{what} = '{folder}' cannot be created ('{probe}' is not a folder): "
            "must be a folder you can write to"
        )
    if not os.access(probe, os.W_OK | os.X_OK):
        raise InputError(f"{what} = '{folder}' is not writable: must be a folder you can write to")


def check_output_path(path: str | os.PathLike, *, overwrite: bool = False) -> Path:
    """Validate an output file path before any work is done.

    Raises :class:`InputError` if the file exists and ``overwrite`` is False, or if its folder
    cannot be created or written. Creates nothing: :func:`atomic_output` makes the folder when it
    writes, so a run that fails before that leaves no empty folder behind.
    """
    path = Path(path)
    if path.is_dir():
        raise InputError(f"output = '{path}' is a folder: must be a file path")
    if path.exists() and not overwrite:
        raise InputError(f"output = '{path}' already exists: pass --overwrite to replace it")
    _writable_folder(path.parent if str(path.parent) else Path("."))
    return path


@contextmanager
def atomic_output(path: str | os.PathLike, *, overwrite: bool = False) -> Iterator[Path]:
    """Yield a temporary path beside ``path``; rename it to ``path`` when the block succeeds.

    The temporary file keeps the suffix of ``path`` so writers that pick a format by suffix
    (meshio, xarray, matplotlib) work unchanged. On any exception it is removed.
    """
    path = check_output_path(path, overwrite=overwrite)
    path.parent.mkdir(parents=True, exist_ok=True)
    fd, tmp_name = tempfile.mkstemp(
        prefix=f".{path.stem}.", suffix=f".part{path.suffix}", dir=path.parent
    )
    os.close(fd)
    tmp = Path(tmp_name)
    try:
        yield tmp
        os.chmod(tmp, _umask_mode(0o666))
        os.replace(tmp, path)
    finally:
        if tmp.exists():
            tmp.unlink()


def check_output_folder(
    path: str | os.PathLike, *, overwrite: bool = False, marker: str | None = None
) -> Path:
    """Validate an output folder path before any work is done.

    Raises :class:`InputError` if ``path`` is a file, if it exists and ``overwrite`` is False, if
    it exists, is not empty and lacks the file ``marker`` (so ``--overwrite`` never deletes a
    folder this program did not write), or if its parent cannot be created or written. Creates
    nothing (:func:`atomic_folder` makes the parent when it writes).
    """
    path = Path(path)
    if path.exists() and not path.is_dir():
        raise InputError(f"output = '{path}' is a file: must be a folder path")
    if path.is_dir():
        if not overwrite:
            raise InputError(f"output = '{path}' already exists: pass --overwrite to replace it")
        if marker is not None and any(path.iterdir()) and not (path / marker).is_file():
            raise InputError(
                f"output = '{path}' is a folder without '{marker}', so not one this program "
                "wrote: refusing to replace it"
            )
    _writable_folder(path.absolute().parent)
    return path


@contextmanager
def atomic_folder(
    path: str | os.PathLike, *, overwrite: bool = False, marker: str | None = None
) -> Iterator[Path]:
    """Yield a temporary folder beside ``path``; rename it to ``path`` when the block succeeds.

    For outputs made of many files (a VTK time series): readers never see a half-written
    folder, and on any exception the temporary folder is removed and an existing ``path`` is left
    as it was. An existing ``path`` is replaced only with ``overwrite`` (see
    :func:`check_output_folder` for ``marker``).
    """
    path = check_output_folder(path, overwrite=overwrite, marker=marker)
    parent = path.resolve().parent
    parent.mkdir(parents=True, exist_ok=True)
    tmp = Path(tempfile.mkdtemp(prefix=f".{path.name}.", suffix=".part", dir=parent))
    try:
        yield tmp
        os.chmod(tmp, _umask_mode(0o777))
        if path.exists():
            old = Path(tempfile.mkdtemp(prefix=f".{path.name}.", suffix=".old", dir=parent))
            os.replace(path, old / path.name)
            os.replace(tmp, path)
            shutil.rmtree(old, ignore_errors=True)
        else:
            os.replace(tmp, path)
    finally:
        if tmp.exists():
            shutil.rmtree(tmp, ignore_errors=True)


def provenance(parameters: Mapping[str, Any] | None = None) -> dict[str, Any]:
    """Metadata for an output file: package version, UTC date, platform and ``parameters``."""
    from fem_racket.version import __version__

    out: dict[str, Any] = {
        "software": "fem_racket",
        "version": __version__,
        "created_utc": _dt.datetime.now(_dt.UTC).isoformat(timespec="seconds"),
        "python": platform.python_version(),
        "source": "Kawazoe & Kanda (1997), JSME Int. J. C 40(1)",
    }
    if parameters:
        out["parameters"] = dict(parameters)
    return out


def sidecar_path(path: str | os.PathLike) -> Path:
    """The provenance file beside an output that cannot hold it (CSV, GIF, MP4): ``<path>.json``."""
    path = Path(path)
    return path.with_name(path.name + ".json")


def write_sidecar(
    path: str | os.PathLike, meta: Mapping[str, Any], *, overwrite: bool = False
) -> Path:
    """Write the provenance ``meta`` to :func:`sidecar_path` of ``path`` (atomically)."""
    import json

    side = sidecar_path(path)
    with atomic_output(side, overwrite=overwrite) as tmp:
        tmp.write_text(json.dumps(dict(meta), indent=2, default=str) + "\n", encoding="utf-8")
    return side


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
