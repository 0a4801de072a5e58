"""Safe output files: checked before the work, written all-or-nothing, with provenance.

Every file or folder the library or CLI writes goes through :func:`atomic_outputs` (or its
one-target forms :func:`atomic_output` and :func:`atomic_folder`): each output of a command -
main file, sidecars, reports, plots - is written to a temporary name beside its target, and all
of them are moved into place only when every one is complete. On any failure (an exception in the
block, a full disk, an interruption) the temporaries are removed, folders the write created are
removed again and every old output is left as it was. :func:`provenance` is the metadata every
output carries (package version, date, parameters, solver and tolerances).

The conventions, the same for every command (README, "Outputs, --overwrite and provenance"):

1. Library functions take the output path; only the CLI and scripts default to ``output/``.
2. Check every destination with :func:`check_output_path` (or :func:`check_targets`) *before*
   the work: an existing file is refused unless ``overwrite``; a name longer than the file
   system allows, a folder that cannot be created and a folder that does not take a new file
   (tested by creating and deleting one: the permission bits alone do not tell, e.g. as root or
   under ``/proc``) are an :class:`~fem_racket.validation.InputError` naming the option, the path
   and the reason. Nothing is left by the check.
3. Write inside ``with atomic_outputs([...], overwrite=...) as temporaries:``. An ``OSError``
   while writing becomes an :class:`OutputError` naming the target (not the temporary) and the
   reason.
4. Temporary names are ``.<name>.<pid>-<random>.part<suffix>``, never longer than the target's
   folder allows (a long name is cut and completed by a hash). Temporaries left by a run that
   was killed (its process is gone) are removed by the next run writing the same target.
5. Put ``provenance(parameters)`` in the output: JSON a ``"provenance"`` object; netCDF global
   attributes; PNG text chunks (:func:`add_png_provenance`); a folder a ``provenance.json`` in
   it; formats that cannot hold it (CSV, GIF, MP4) a sidecar ``<file>.json``
   (:func:`sidecar_path`), written in the same :func:`atomic_outputs` set as the file.
"""

from __future__ import annotations

import datetime as _dt
import hashlib
import logging
import os
import platform
import re
import secrets
import shutil
import tempfile
from collections.abc import Iterator, Mapping, Sequence
from contextlib import contextmanager
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from fem_racket.validation import InputError, show, show_path

__all__ = [
    "OutputError",
    "Target",
    "add_png_provenance",
    "atomic_folder",
    "atomic_output",
    "atomic_outputs",
    "check_output_folder",
    "check_output_path",
    "check_targets",
    "provenance",
    "record_interrupt",
    "sidecar_path",
]

log = logging.getLogger(__name__)

#: An interruption already raised (by a signal handler) that may have been swallowed: raised in a
#: ``__del__`` or a weakref callback, Python prints and drops it. No set of outputs is moved into
#: place once one is recorded (:func:`record_interrupt`), so "interrupted" always means "nothing
#: written", however the interruption was delivered.
_interrupted: type[BaseException] | None = None


class OutputError(OSError):
    """Writing an output failed during the run (no space left, I/O error, ...).

    The message names the output path the user gave and the reason; the command-line interface
    reports it in one line with exit code 1 (a bad destination found before the work is an
    :class:`~fem_racket.validation.InputError`, exit code 2).
    """


@dataclass(frozen=True)
class Target:
    """One output of a command.

    Attributes
    ----------
    path : Path
        The file or folder to write.
    folder : bool
        True for a folder written as a whole (a VTK series).
    marker : str, optional
        For a folder: an existing one is replaced only if it holds this file (so
        ``overwrite`` never deletes a folder this program did not write).
    name : str
        The option that named the path (``out``, ``csv``, ``report``), for messages.
    """

    path: Path
    folder: bool = False
    marker: str | None = None
    name: str = "out"


def _reason(exc: OSError) -> str:
    return exc.strerror or str(exc) or type(exc).__name__


def _name_max(folder: Path) -> int:
    try:
        return int(os.pathconf(folder, "PC_NAME_MAX"))
    except (OSError, ValueError, AttributeError):
        return 255


def _exists(path: Path) -> bool:
    try:
        return path.exists()
    except OSError:  # a name too long for the file system: certainly not there
        return False


def _existing_ancestor(path: Path) -> Path:
    """The nearest existing one of ``path`` and its parents, in the form the user gave."""
    for probe in (path, *path.parents):
        if _exists(probe):
            return probe
    return Path(path.anchor or ".")


def _quoted(path: Path) -> str:
    return show_path(path)


def _refuse(t: Target, why: str) -> InputError:
    return InputError(f"{t.name} = {_quoted(t.path)} is not allowed: {why}")


def _check_names(t: Target) -> Path:
    """Raise unless every missing part of ``t.path`` fits the file system's name length;
    return the nearest existing folder."""
    base = _existing_ancestor(t.path)
    limit = _name_max(base if base.is_dir() else base.parent)
    for part in t.path.relative_to(base).parts:
        size = len(os.fsencode(part))
        if size > limit:
            raise _refuse(t, f"the name {show(part)} is {size} bytes long: at most {limit} here")
    return base


def _check_writable(t: Target) -> None:
    """Raise unless every missing folder of ``t.path`` can be created and the folder takes a new
    file; creates and deletes a probe file in the nearest existing folder."""
    base = _existing_ancestor(t.path.parent)
    if not base.is_dir():
        raise _refuse(t, f"its folder cannot be created: {_quoted(base)} is a file")
    try:
        fd, probe = tempfile.mkstemp(prefix=".fem_racket-probe-", dir=base)
    except OSError as exc:
        raise _refuse(t, f"cannot create a file in {_quoted(base)} ({_reason(exc)})") from None
    os.close(fd)
    os.unlink(probe)


def check_output_path(
    path: str | os.PathLike, *, overwrite: bool = False, name: str = "out"
) -> Path:
    """Validate an output file path before any work is done; return it as a Path.

    Raises :class:`InputError` (naming the option ``name``) if the path is a folder, if the file
    exists and ``overwrite`` is False, if a name is longer than the file system allows, or if the
    folder cannot be created or does not take a new file. Creates nothing.
    """
    t = Target(Path(path), name=name)
    _check_names(t)
    if t.path.is_dir():
        raise _refuse(t, "it is a folder: must be a file path")
    if t.path.exists() and not overwrite:
        raise _refuse(t, "it already exists: pass --overwrite to replace it")
    _check_writable(t)
    return t.path


def check_output_folder(
    path: str | os.PathLike,
    *,
    overwrite: bool = False,
    marker: str | None = None,
    name: str = "out",
) -> Path:
    """Validate an output folder path before any work is done; return it as a Path.

    Raises :class:`InputError` if ``path`` is a file, if it exists and ``overwrite`` is False, if
    it exists, is not empty and lacks the file ``marker`` (so ``--overwrite`` never deletes a
    folder this program did not write), or as :func:`check_output_path` for its parent.
    """
    t = Target(Path(path), folder=True, marker=marker, name=name)
    _check_names(t)
    if t.path.exists() and not t.path.is_dir():
        raise _refuse(t, "it is a file: must be a folder path")
    if t.path.is_dir():
        if not overwrite:
            raise _refuse(t, "it already exists: pass --overwrite to replace it")
        if marker is not None and any(t.path.iterdir()) and not (t.path / marker).is_file():
            raise _refuse(
                t, f"it is a folder without '{marker}', so not one this program wrote: "
                "refusing to replace it",
            )  # fmt: skip
    _check_writable(t)
    return t.path


def _as_target(t: Target | str | os.PathLike) -> Target:
    return t if isinstance(t, Target) else Target(Path(t))


def check_targets(
    targets: Sequence[Target | str | os.PathLike], *, overwrite: bool = False
) -> list[Target]:
    """Check every target (:func:`check_output_path` or :func:`check_output_folder`); plain
    paths are files named by ``--out``."""
    targets = [_as_target(t) for t in targets]
    seen: set[Path] = set()
    for t in targets:
        key = t.path.absolute()
        if key in seen:
            raise _refuse(t, "the same path is given for two outputs of this command")
        seen.add(key)
        if t.folder:
            check_output_folder(t.path, overwrite=overwrite, marker=t.marker, name=t.name)
        else:
            check_output_path(t.path, overwrite=overwrite, name=t.name)
    return list(targets)


# -- temporary names ------------------------------------------------------------------------
_TAIL_ROOM = len(".4294967295-00000000.part")  # pid (at most 10 digits), token, kind


def _suffix(path: Path) -> str:
    # Writers choose the format by suffix (xarray, matplotlib, Pillow): keep a short one.
    return path.suffix if len(os.fsencode(path.suffix)) <= 16 else ""


def _key(path: Path, limit: int) -> str:
    """The target's name, cut (and completed by a hash) to leave room for the temporary tail."""
    room = limit - 1 - _TAIL_ROOM - len(os.fsencode(_suffix(path)))
    raw = os.fsencode(path.name)
    if len(raw) <= room:
        return path.name
    digest = hashlib.sha256(raw).hexdigest()[:12]
    cut = raw[: room - 13].decode("utf-8", "ignore")  # never half a character
    return f"{cut}~{digest}"


def _temp_path(path: Path, kind: str) -> Path:
    folder = path.absolute().parent
    key = _key(path, _name_max(folder))
    return folder / f".{key}.{os.getpid()}-{secrets.token_hex(4)}.{kind}{_suffix(path)}"


def _alive(pid: int) -> bool:
    if pid == os.getpid():
        return True
    try:
        os.kill(pid, 0)
    except ProcessLookupError:
        return False
    except (PermissionError, OverflowError):
        return True
    return True


def _remove(path: Path) -> None:
    try:
        if path.is_dir() and not path.is_symlink():
            shutil.rmtree(path)
        else:
            path.unlink()
    except FileNotFoundError:
        pass


def _remove_stale(path: Path) -> None:
    """Remove temporaries of ``path`` left by runs whose process is gone."""
    folder = path.absolute().parent
    if not folder.is_dir():
        return
    key = _key(path, _name_max(folder))
    pattern = re.compile(
        re.escape(f".{key}.") + r"(\d+)-[0-9a-f]{8}\.(?:part|old)" + re.escape(_suffix(path)) + "$"
    )
    for entry in folder.iterdir():
        m = pattern.match(entry.name)
        if m and not _alive(int(m.group(1))):
            log.info("removing %s, left by an interrupted run", entry)
            try:
                _remove(entry)
            except OSError:  # not ours to fix here; the new run does not need it gone
                pass


# -- writing a set of outputs -----------------------------------------------------------------
def _umask_mode(mode: int) -> int:
    """``mode`` less the process umask."""
    mask = os.umask(0)
    os.umask(mask)
    return mode & ~mask


def _make_folders(folder: Path, made: list[Path]) -> None:
    missing = []
    probe = folder.absolute()
    while not probe.exists():
        missing.append(probe)
        probe = probe.parent
    for f in reversed(missing):
        f.mkdir()
        made.append(f)


def _new_temp(t: Target) -> Path:
    tmp = _temp_path(t.path, "part")
    if t.folder:
        tmp.mkdir(mode=0o777)
    else:
        os.close(os.open(tmp, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o666))
    return tmp


def _as_output_error(exc: OSError, targets: Sequence[Target], temps: Sequence[Path]) -> OSError:
    """``exc`` as an :class:`OutputError` naming the target it concerns; an OSError about a
    file that is none of the outputs is returned unchanged."""
    if isinstance(exc, OutputError):
        return exc
    target = targets[0].path
    name = os.fsdecode(exc.filename) if isinstance(exc.filename, (str, bytes)) else None
    if name is not None:
        hit = [
            t.path
            for t, tmp in zip(targets, temps, strict=False)
            if Path(name).absolute() in (tmp, t.path.absolute())
            or Path(name).absolute().is_relative_to(tmp)
        ]
        if not hit:
            return exc
        target = hit[0]
    return OutputError(exc.errno, f"cannot write {_quoted(target)}: {_reason(exc)}")


def record_interrupt(kind: type[BaseException] | None) -> None:
    """Record an interruption raised by a signal handler (None clears it): every later
    :func:`atomic_outputs` raises ``kind`` instead of moving its outputs into place."""
    global _interrupted
    _interrupted = kind


def _commit(targets: Sequence[Target], temps: Sequence[Path], overwrite: bool) -> None:
    """Move every temporary into place; on a failure put every old output back."""
    if _interrupted is not None:
        raise _interrupted()
    moved: list[tuple[Target, Path | None]] = []
    try:
        for t, tmp in zip(targets, temps, strict=True):
            if not t.folder:
                os.chmod(tmp, _umask_mode(0o666))
            old = None
            if t.path.exists() or t.path.is_symlink():
                if not overwrite:
                    raise _refuse(
                        t, "it was created during the run: pass --overwrite to replace it"
                    )
                old = _temp_path(t.path, "old")
                os.replace(t.path, old)
            moved.append((t, old))
            os.replace(tmp, t.path)
    except BaseException:
        for t, old in reversed(moved):
            if old is None:
                if t.path.exists():
                    _remove(t.path)
            elif old.exists():
                if t.path.exists():
                    _remove(t.path)
                os.replace(old, t.path)
        raise
    for _, old in moved:
        if old is not None:
            _remove(old)


@contextmanager
def atomic_outputs(
    targets: Sequence[Target | str | os.PathLike], *, overwrite: bool = False
) -> Iterator[list[Path]]:
    """Yield one temporary path per target; move them all into place when the block succeeds.

    Files keep the suffix of their target so writers that pick a format by suffix work
    unchanged; folder targets get an empty temporary folder. Every target is checked first
    (:func:`check_targets`). On any exception - or a failure while moving - the temporaries and
    the folders created for them are removed and every existing output is kept; an ``OSError``
    comes out as :class:`OutputError` naming the target.
    """
    items = check_targets(targets, overwrite=overwrite)
    made: list[Path] = []
    temps: list[Path] = []
    ok = False
    try:
        for t in items:
            _make_folders(t.path.parent, made)
            _remove_stale(t.path)
            temps.append(_new_temp(t))
        yield list(temps)
        _commit(items, temps, overwrite)
        ok = True
    except OSError as exc:
        raise _as_output_error(exc, items, temps) from None
    finally:
        for tmp in temps:
            if tmp.exists() or tmp.is_symlink():
                try:
                    _remove(tmp)
                except OSError:
                    log.warning("could not remove the temporary %s", tmp)
        if not ok:
            for f in reversed(made):
                try:
                    f.rmdir()
                except OSError:
                    break


@contextmanager
def atomic_output(
    path: str | os.PathLike, *, overwrite: bool = False, name: str = "out"
) -> Iterator[Path]:
    """One file written all-or-nothing: see :func:`atomic_outputs`."""
    with atomic_outputs([Target(Path(path), name=name)], overwrite=overwrite) as (tmp,):
        yield tmp


@contextmanager
def atomic_folder(
    path: str | os.PathLike,
    *,
    overwrite: bool = False,
    marker: str | None = None,
    name: str = "out",
) -> Iterator[Path]:
    """One folder (e.g. a VTK series) written all-or-nothing: see :func:`atomic_outputs` and,
    for ``marker``, :func:`check_output_folder`."""
    target = Target(Path(path), folder=True, marker=marker, name=name)
    with atomic_outputs([target], overwrite=overwrite) as (tmp,):
        yield tmp


# -- provenance -------------------------------------------------------------------------------
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
