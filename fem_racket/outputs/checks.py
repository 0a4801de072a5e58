"""Output destinations checked before the work: :class:`Target`, :func:`check_targets`.

A destination is refused (:class:`~fem_racket.validation.InputError`, one line naming the option,
the path and the reason) when it exists and ``overwrite`` is not given, when a name is longer
than the file system allows, when its folder cannot be created, or when the folder does not take
a new file - found by creating and deleting a probe file, since the permission bits do not tell
(root may "write" ``/proc``; a read-only mount). :class:`OutputError` is a fault found later,
while writing.
"""

from __future__ import annotations

import contextlib
import os
import secrets
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

from fem_racket.validation import InputError, show, show_path

__all__ = [
    "OutputError",
    "Target",
    "check_output_folder",
    "check_output_path",
    "check_targets",
    "name_max",
    "as_target",
    "quoted",
    "reason",
    "refuse",
]


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


def reason(exc: OSError) -> str:
    """The system's words for ``exc`` (``No space left on device``)."""
    return exc.strerror or str(exc) or type(exc).__name__


def name_max(folder: Path) -> int:
    """The longest file name [bytes] the file system of ``folder`` takes (255 if unknown)."""
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


def quoted(path: Path) -> str:
    """``path`` quoted for a message (shortened when very long)."""
    return show_path(path)


def refuse(t: Target, why: str) -> InputError:
    """The one-line refusal of target ``t``: ``out = 'x.nc' is not allowed: <why>``."""
    return InputError(f"{t.name} = {quoted(t.path)} is not allowed: {why}")


def _check_names(t: Target) -> Path:
    """Raise unless every missing part of ``t.path`` fits the file system's name length;
    return the nearest existing folder."""
    base = _existing_ancestor(t.path)
    limit = name_max(base if base.is_dir() else base.parent)
    for part in t.path.relative_to(base).parts:
        size = len(os.fsencode(part))
        if size > limit:
            raise refuse(t, f"the name {show(part)} is {size} bytes long: at most {limit} here")
    return base


def _check_writable(t: Target) -> None:
    """Raise unless every missing folder of ``t.path`` can be created and the folder takes a new
    file; creates and deletes a probe file in the nearest existing folder."""
    base = _existing_ancestor(t.path.parent)
    if not base.is_dir():
        raise refuse(t, f"its folder cannot be created: {quoted(base)} is a file")
    probe = base / f".fem_racket-probe-{os.getpid()}-{secrets.token_hex(4)}"
    try:  # named first, removed in finally: an interruption at any point leaves no probe
        try:
            os.close(os.open(probe, os.O_WRONLY | os.O_CREAT | os.O_EXCL, 0o600))
        except OSError as exc:
            raise refuse(t, f"cannot create a file in {quoted(base)} ({reason(exc)})") from None
    finally:
        with contextlib.suppress(OSError):
            os.unlink(probe)


def _check_link(t: Target, overwrite: bool) -> None:
    """Refuse a dangling symbolic link at ``t.path`` unless ``overwrite`` (which replaces the link
    itself): nothing exists there, yet a new file cannot be put in its place without it."""
    if t.path.is_symlink() and not t.path.exists() and not overwrite:
        try:
            to = os.readlink(t.path)
        except OSError:
            to = "?"
        raise refuse(
            t, f"it is a symbolic link to {show(to)}, which does not exist: remove the link, or "
            "pass --overwrite to replace it",
        )  # fmt: skip


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
        raise refuse(t, "it is a folder: must be a file path")
    if t.path.exists() and not overwrite:
        raise refuse(t, "it already exists: pass --overwrite to replace it")
    _check_link(t, overwrite)
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
        raise refuse(t, "it is a file: must be a folder path")
    if t.path.is_dir():
        if not overwrite:
            raise refuse(t, "it already exists: pass --overwrite to replace it")
        if marker is not None and any(t.path.iterdir()) and not (t.path / marker).is_file():
            raise refuse(
                t, f"it is a folder without '{marker}', so not one this program wrote: "
                "refusing to replace it",
            )  # fmt: skip
    _check_link(t, overwrite)
    _check_writable(t)
    return t.path


def as_target(t: Target | str | os.PathLike) -> Target:
    """``t`` as a :class:`Target` (a plain path is a file named by ``--out``)."""
    return t if isinstance(t, Target) else Target(Path(t))


def check_targets(
    targets: Sequence[Target | str | os.PathLike], *, overwrite: bool = False
) -> list[Target]:
    """Check every target (:func:`check_output_path` or :func:`check_output_folder`); plain
    paths are files named by ``--out``."""
    targets = [as_target(t) for t in targets]
    seen: set[Path] = set()
    for t in targets:
        key = t.path.absolute()
        if key in seen:
            raise refuse(t, "the same path is given for two outputs of this command")
        seen.add(key)
        if t.folder:
            check_output_folder(t.path, overwrite=overwrite, marker=t.marker, name=t.name)
        else:
            check_output_path(t.path, overwrite=overwrite, name=t.name)
    return list(targets)
