"""Input checks shared by every user-facing entry point.

Each check raises :class:`InputError` with a one-line message that names the parameter, the value
it was given and the allowed range or form, e.g.
``speed = -3.0 m/s is not allowed: must be a finite number > 0``.
"""

from __future__ import annotations

import math
from collections.abc import Iterable

__all__ = [
    "AccuracyError",
    "InputError",
    "check_choice",
    "check_finite",
    "check_integer",
    "check_positive",
    "check_range",
]


class InputError(ValueError):
    """A user-supplied value is outside its allowed range or form."""


class AccuracyError(InputError):
    """A case the tool cannot compute to its stated accuracy (an a-posteriori check failed).

    Raised instead of returning a number that may be wrong; like :class:`InputError` it carries
    a one-line message naming what was asked and why it is refused.
    """


def _fmt(name: str, value: object, unit: str) -> str:
    unit_txt = f" {unit}" if unit else ""
    return f"{name} = {value!r}{unit_txt}"


def check_finite(name: str, value: object, unit: str = "") -> float:
    """Return ``value`` as a float, or raise if it is not a finite real number."""
    try:
        number = float(value)  # type: ignore[arg-type]
    except (TypeError, ValueError):
        raise InputError(
            f"{_fmt(name, value, unit)} is not allowed: must be a finite number"
        ) from None
    if isinstance(value, bool) or not math.isfinite(number):
        raise InputError(f"{_fmt(name, value, unit)} is not allowed: must be a finite number")
    return number


def check_positive(name: str, value: object, unit: str = "") -> float:
    """Return ``value`` as a float, or raise unless it is finite and > 0."""
    number = check_finite(name, value, unit)
    if number <= 0.0:
        raise InputError(f"{_fmt(name, value, unit)} is not allowed: must be a finite number > 0")
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
        raise InputError(
            f"{_fmt(name, value, unit)} is not allowed: must lie in {lb}{low:g}, {high:g}{rb}"
        )
    return number


def check_choice(name: str, value: object, choices: Iterable[str]) -> str:
    """Return ``value`` if it is one of ``choices``, or raise listing them."""
    options = tuple(choices)
    if value not in options:
        raise InputError(f"{name} = {value!r} is not allowed: must be one of {', '.join(options)}")
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
        raise InputError(f"{name} = {value!r} is not allowed: must be {allowed}")
    return int(value)
