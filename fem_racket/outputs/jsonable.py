"""Numbers as JSON holds them: what every JSON a command prints or writes goes through.

Numpy scalars and arrays become the Python numbers, bools and lists they hold
(:func:`fem_racket.display.plain`; ``json`` would write ``np.int64`` and ``np.bool_`` as strings
or refuse them); NaN and infinities, which JSON cannot hold, become ``null``; a float within a
few units in the last place of a short decimal is written as that decimal, an input after
arithmetic (``27400.0``, not ``27399.999999999993``; ``0.68``, not ``0.6799999999999999``),
while a computed value keeps every digit, bit for bit the library's.
"""

from __future__ import annotations

import math
from typing import Any

from fem_racket.display import plain

__all__ = ["JSON_DIGITS", "JSON_ULPS", "json_ready"]

#: A "short decimal": at most this many significant digits (an input such as 0.68 or 2.74e4).
JSON_DIGITS = 12
#: How far from a short decimal a float may be and still be that decimal, in units in the last
#: place: the rounding of a few operations (27399.999999999993 is 27400 less 1 ulp).
JSON_ULPS = 4


def _meant(v: float) -> float:
    """``v``, or the short decimal it is within :data:`JSON_ULPS` units in the last place of."""
    short = float(f"{v:.{JSON_DIGITS}g}")
    return short if abs(short - v) <= JSON_ULPS * math.ulp(v) else v


def json_ready(v: Any) -> Any:
    """``v`` with numpy scalars and arrays as Python numbers and lists, and every non-finite
    float (at any depth of dicts, lists, tuples) replaced by None and every float that is a
    short decimal plus rounding noise by that decimal."""
    return _ready(plain(v))


def _ready(v: Any) -> Any:
    if isinstance(v, float):
        return _meant(v) if math.isfinite(v) else None
    if isinstance(v, dict):
        return {k: _ready(x) for k, x in v.items()}
    if isinstance(v, (list, tuple)):
        return [_ready(x) for x in v]
    return v
