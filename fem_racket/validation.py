"""Input checks shared by every user-facing entry point.

Each check raises :class:`InputError` with a one-line message that names the parameter, the value
it was given and the allowed range or form, e.g.
``speed = -3.0 m/s is not allowed: must be a finite number > 0``. Values are shown by
:func:`show`: as a user would type them (no numpy reprs such as ``np.float64(26.5)``), long ones
shortened, so every message stays one readable line.
"""

from __future__ import annotations

import contextvars
import math
import os
from collections.abc import Iterable, Iterator
from contextlib import contextmanager
from pathlib import Path

from fem_racket.display import plain

__all__ = [
    "AccuracyError",
    "ChecksPassed",
    "InputError",
    "check_choice",
    "check_elements",
    "check_file",
    "check_finite",
    "check_integer",
    "check_positive",
    "check_range",
    "checks_only",
    "show",
    "show_path",
    "work_begins",
]

#: Longest value shown in a message [characters]; longer ones are shortened with "...".
SHOW_LIMIT = 60
#: The same for file and folder paths, which are read whole more often.
PATH_LIMIT = 120


class InputError(ValueError):
    """A user-supplied value is outside its allowed range or form.

    Parameters
    ----------
    message : str
        The one line the user reads.
    parameter : str, optional
        The parameter refused, when the message opens with it (``NAME = VALUE ...``), as
        every ``check_*`` helper of this module sets it: a caller may name the value its own way
        (:meth:`named`). None when the message names no single parameter.
    value : object, optional
        The value refused (as the check got it: ``1000.0`` for ``speed = 1000.0 m/s``); None
        when unknown.
    """

    def __init__(self, message: str = "", *, parameter: str | None = None, value: object = None):
        super().__init__(message)
        self.parameter = parameter
        self.value = value

    def named(self, name: str, prefix: str = "") -> InputError:
        """The same refusal with its parameter named ``name`` (``speed = 1000.0 m/s ...`` ->
        ``impact.speed_m_s = 1000.0 m/s ...``), after ``prefix`` (``"run.toml: "``): the message
        from the value on is kept. ``self`` when the message does not open with
        :attr:`parameter`."""
        text = str(self)
        if self.parameter is None or not text.startswith(f"{self.parameter} = "):
            return self
        renamed = f"{prefix}{name}{text[len(self.parameter) :]}"
        return type(self)(renamed, parameter=None if prefix else name, value=self.value)


def show(value: object, limit: int = SHOW_LIMIT) -> str:
    """``value`` as it appears in a message: numbers and strings as Python writes them
    (``26.5``, ``'a.gif'``), numpy scalars and arrays as plain numbers and lists, and anything
    longer than ``limit`` characters shortened (``[0.5, 0.5, ... (80 values)]``,
    ``'aaaa...aaaa.json'``)."""
    value = plain(value)
    if isinstance(value, (list, tuple)):
        left, right = "()" if isinstance(value, tuple) else "[]"
        items = [show(v, limit) for v in value]
        text = left + ", ".join(items) + right
        if len(text) <= limit:
            return text
        kept: list[str] = []
        for item in items:
            if len(", ".join([*kept, item])) > limit - 20:
                break
            kept.append(item)
        return left + ", ".join([*kept, f"... ({len(items)} values)"]) + right
    text = repr(value)
    if len(text) <= limit:
        return text
    head = (limit - 3) * 2 // 3
    return text[:head] + "..." + text[head + 3 - limit :]


def show_path(path: object) -> str:
    """A file or folder path as it appears in a message: quoted, shortened beyond
    :data:`PATH_LIMIT` characters."""
    return show(str(path), PATH_LIMIT)


class AccuracyError(InputError):
    """A case the tool cannot compute to its stated accuracy (an a-posteriori check failed).

    Raised instead of returning a number that may be wrong; like :class:`InputError` it carries
    a one-line message naming what was asked and why it is refused.
    """


def _refused(name: str, value: object, unit: str, allowed: str) -> InputError:
    """``NAME = VALUE UNIT is not allowed: ALLOWED``, naming its parameter and value."""
    unit_txt = f" {unit}" if unit else ""
    return InputError(
        f"{name} = {show(value)}{unit_txt} is not allowed: {allowed}", parameter=name, value=value
    )


def check_finite(name: str, value: object, unit: str = "") -> float:
    """Return ``value`` as a float, or raise if it is not a finite real number (a bool or a
    text such as ``"20"`` is refused alike: ``float`` would take them)."""
    try:
        number = float(value)  # type: ignore[arg-type]
    except (TypeError, ValueError):
        raise _refused(name, value, unit, "must be a finite number") from None
    if isinstance(value, bool | str | bytes) or not math.isfinite(number):
        raise _refused(name, value, unit, "must be a finite number")
    return number


def check_positive(name: str, value: object, unit: str = "") -> float:
    """Return ``value`` as a float, or raise unless it is finite and > 0."""
    number = check_finite(name, value, unit)
    if number <= 0.0:
        raise _refused(name, value, unit, "must be a finite number > 0")
    return number


def check_range(
    name: str,
    value: object,
    low: float,
    high: float,
    *,
    unit: str = "",
    include_low: bool = True,
    include_high: bool = True,
) -> float:
    """Return ``value`` as a float, or raise unless it lies in the interval low..high."""
    number = check_finite(name, value, unit)
    ok_low = number >= low if include_low else number > low
    ok_high = number <= high if include_high else number < high
    if not (ok_low and ok_high):
        lb = "[" if include_low else "("
        rb = "]" if include_high else ")"
        raise _refused(name, value, unit, f"must lie in {lb}{low:g}, {high:g}{rb}")
    return number


def check_file(name: str, path: str | os.PathLike, what: str) -> Path:
    """``path`` as a Path, or raise unless it is a file: a folder is named as one (``mesh =
    '/tmp' is not allowed: it is a folder, not a mesh file``), else "no such file"."""
    path = Path(path)
    if path.is_dir():
        raise InputError(
            f"{name} = {show_path(path)} is not allowed: it is a folder, not a {what}",
            parameter=name,
            value=path,
        )
    if not path.is_file():
        raise InputError(
            f"{name} = {show_path(path)} is not allowed: no such file", parameter=name, value=path
        )
    return path


def check_choice(name: str, value: object, choices: Iterable[str]) -> str:
    """Return ``value`` if it is one of ``choices``, or raise listing them."""
    options = tuple(choices)
    if value not in options:
        raise _refused(name, value, "", f"must be one of {', '.join(options)}")
    return str(value)


def check_integer(name: str, value: object, minimum: int = 1, maximum: int | None = None) -> int:
    """Return ``value`` as an int, or raise unless it is an integer >= ``minimum`` (and
    <= ``maximum`` when given)."""
    import numbers

    allowed = (
        f"an integer >= {minimum}"
        if maximum is None
        else (f"an integer from {minimum} to {maximum}")
    )
    if (
        isinstance(value, bool)
        or not isinstance(value, numbers.Integral)
        or value < minimum
        or (maximum is not None and value > maximum)
    ):
        raise _refused(name, value, "", f"must be {allowed}")
    return int(value)


def check_elements(
    value: object, minimum: int = 2, maximum: int | None = None, name: str = "elements"
) -> int:
    """Return a number of beam elements as an int, or raise unless it is an integer (a whole
    float such as 20.0 counts) from ``minimum`` to ``maximum``, in the words of
    :func:`check_integer` (every command's ``--elements``; the standard frame's two segments
    need at least 2)."""
    number = plain(value)
    whole = (
        isinstance(number, (int, float))
        and not isinstance(number, bool)
        and math.isfinite(number)
        and float(number).is_integer()
    )
    if not whole or number < minimum or (maximum is not None and number > maximum):
        shown = int(number) if whole else value  # "0", not "0.0", for a count read as a float
        return check_integer(name, shown, minimum, maximum)  # raises, in its words
    return int(number)


class ChecksPassed(Exception):
    """Raised by :func:`work_begins` inside :func:`checks_only`: every check has passed."""


_CHECKS_ONLY: contextvars.ContextVar[bool] = contextvars.ContextVar("checks_only", default=False)


@contextmanager
def checks_only() -> Iterator[None]:
    """Run a command's checks but not its work: :func:`work_begins` raises :class:`ChecksPassed`.

    ``fem-racket config --check`` runs every command this way, so it fails where the command
    would (everything short of the computation and of any file written or folder made).
    """
    token = _CHECKS_ONLY.set(True)
    try:
        yield
    finally:
        _CHECKS_ONLY.reset(token)


def work_begins() -> None:
    """Mark the point where a command's checks end and its work (computation, files) begins.

    Does nothing, unless inside :func:`checks_only`: then raises :class:`ChecksPassed`.
    """
    if _CHECKS_ONLY.get():
        raise ChecksPassed
