"""A fault while writing outputs, named as what it is: :func:`as_output_error`.

The writers of :mod:`.atomic` write to temporaries; a fault there is reported naming the output
the user gave (never the temporary) with the system's reason - a full disk named as such even
when a library reports it otherwise (netCDF/HDF5's "HDF error" or "Permission denied"), found by
the free space left on the temporaries' file systems.
"""

from __future__ import annotations

import errno
import os
from collections.abc import Sequence
from pathlib import Path

from fem_racket.outputs.checks import OutputError, Target, quoted, reason

__all__ = ["FULL_BELOW", "as_output_error"]


#: Free space below which a write fault on a folder's file system is taken for a full disk
#: [bytes]: libraries such as netCDF/HDF5 report one as "HDF error" or "Permission denied".
FULL_BELOW = 1 << 20


def _disk_full(temps: Sequence[Path]) -> bool:
    """True when a file system holding one of ``temps`` has (almost) no space left."""
    for folder in {t.parent for t in temps}:
        try:
            st = os.statvfs(folder)
        except (OSError, AttributeError):
            continue
        if st.f_bavail * st.f_frsize < FULL_BELOW:
            return True
    return False


def _latest(targets: Sequence[Target], temps: Sequence[Path]) -> Path:
    """The target whose temporary was written last (the one a fault hit)."""
    times = []
    for t, tmp in zip(targets, temps, strict=False):
        try:
            times.append((tmp.stat().st_mtime_ns, t.path))
        except OSError:
            continue
    return max(times)[1] if times else targets[0].path


def _fault_target(
    name: str | None, targets: Sequence[Target], temps: Sequence[Path]
) -> Path | None:
    """The target whose temporary (or path) ``name`` is or lies in; None if none."""
    if name is None:
        return None
    p = Path(name).absolute()
    for t, tmp in zip(targets, temps, strict=False):
        if p in (tmp, t.path.absolute()) or p.is_relative_to(tmp):
            return t.path
        # a temporary's own temporary (a writer that writes atomically too)
        if p.parent == tmp.parent and p.name.startswith(f".{tmp.name}."):
            return t.path
    return None


def as_output_error(
    exc: BaseException, targets: Sequence[Target], temps: Sequence[Path]
) -> BaseException:
    """``exc`` as an :class:`OutputError` naming the target it concerns, with the reason the
    system gives - a full disk named as such even when a library reports it otherwise (netCDF's
    "HDF error", "Permission denied"). Anything else is returned unchanged."""
    if not isinstance(exc, (OSError, RuntimeError)):
        return exc
    name = getattr(exc, "filename", None) or getattr(exc, "path", None)
    name = os.fsdecode(name) if isinstance(name, (str, bytes, os.PathLike)) else None
    target = _fault_target(name, targets, temps)
    if isinstance(exc, OutputError) and target is None:
        return exc
    if name is not None and target is None and isinstance(exc, OSError):
        return exc  # a file that is none of the outputs (an input, say)
    if getattr(exc, "errno", None) != errno.ENOSPC and _disk_full(temps):
        target = target or _latest(targets, temps)
        why = os.strerror(errno.ENOSPC)
        return _output_error(errno.ENOSPC, target, why)
    if not isinstance(exc, OSError):
        return exc
    if isinstance(exc, OutputError):  # raised for a temporary of ours: name its target
        why = exc.strerror.split(": ")[-1] if exc.strerror else reason(exc)
        return _output_error(exc.errno, target, why)
    return _output_error(exc.errno, target or targets[0].path, reason(exc))


def _output_error(code: int | None, target: Path, why: str) -> OutputError:
    """``cannot write 'target': why``, the target kept as the error's ``path``."""
    err = OutputError(code, f"cannot write {quoted(target)}: {why}")
    err.path = str(target)
    return err
