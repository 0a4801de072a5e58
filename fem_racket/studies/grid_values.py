"""Sweep parameters and their values, from text or Python.

A sweepable parameter takes one value (held fixed) or several (a dimension of the sweep).
On the command line the values are a number, a comma list (``20,30,40``) or
``start:stop:num`` with an optional ``:log`` (``50:3000:60:log``: 60 values evenly spaced in
log between 50 and 3000, both ends included). The impact's parameters are :data:`PARAMETERS`,
the contact law families' :data:`LAW_PARAMETERS` (:mod:`fem_racket.studies.law_axes`).
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from fem_racket.contact.linear import LinearContact, check_ball_mass
from fem_racket.contact.registry import LAW_PARAMETERS as DECLARED
from fem_racket.contact.registry import LiveView
from fem_racket.frame.mesh import MAX_ELEMENTS
from fem_racket.strings.bed import parse_pattern
from fem_racket.studies.grid_parameters import (
    OBLIQUE_AXES,
    OPTIONAL,
    PARAMETERS,
    STRING_AXES,
    Parameter,
)
from fem_racket.studies.law_axes import check_law_value
from fem_racket.studies.limits import MAX_CASES
from fem_racket.validation import (
    InputError,
    check_elements,
    check_finite,
    check_positive,
    check_range,
    show,
)

__all__ = [
    "LAW_PARAMETERS",
    "OBLIQUE_AXES",
    "OPTIONAL",
    "PARAMETERS",
    "STRING_AXES",
    "Parameter",
    "as_values",
    "parameter",
    "parse_values",
    "pattern_code",
    "pattern_label",
    "value_count",
]


#: Sweepable parameters of the contact law families (a sweep holds those of its law's family):
#: the attribute is the run file's [contact] key with ``contact_`` before it (live, from the
#: laws' declarations: :mod:`fem_racket.contact.registry`).
LAW_PARAMETERS = LiveView(
    lambda: {
        name: Parameter("1" if p.unit == "-" else p.unit, p.help, "contact_" + p.key)
        for name, (_, p) in DECLARED.items()
    }
)


def parameter(name: str) -> Parameter:
    """The :class:`Parameter` called ``name`` (impact or law parameter)."""
    return PARAMETERS[name] if name in PARAMETERS else LAW_PARAMETERS[name]


def pattern_code(text: str) -> int:
    """``"16x19"`` -> 1619: a pattern as one number, mains*100 + crosses (both 4..40)."""
    mains, crosses = parse_pattern(text)
    return 100 * mains + crosses


def pattern_label(code: float) -> str:
    """1619 -> ``"16x19"``."""
    return f"{int(code) // 100}x{int(code) % 100}"


def _refused(name: str, value: Any, allowed: str) -> InputError:
    """``NAME = VALUE is not allowed: ALLOWED``, naming its parameter and value (a run file's
    key names them: :func:`fem_racket.io.config_named.grid_value`)."""
    return InputError(
        f"{name} = {show(value)} is not allowed: {allowed}", parameter=name, value=value
    )


def _check_value(name: str, value: object, law: bool) -> float | int:
    """One value of parameter ``name`` checked; ``law``: it is a contact law's."""
    if law:
        return check_law_value(name, value)
    unit = PARAMETERS[name].unit
    if name == "pattern":  # a code mains*100 + crosses, or the text
        return pattern_code(value if isinstance(value, str) else pattern_label(value))
    if name == "angle":
        return check_range(name, value, 0.0, 90.0, unit=unit, include_high=False)
    if name == "side_angle":  # across the face: either side, as simulate's --side-angle
        return check_range(name, value, -90.0, 90.0, unit=unit, include_low=False,
                           include_high=False)  # fmt: skip
    if name in ("spin", "side_spin"):
        return check_finite(name, value, unit)
    if name in ("friction", "compliance_ratio"):
        return check_range(name, value, 0.0, math.inf, unit="")
    if name == "ball_inertia":
        return check_range(name, value, 0.0, 2.0 / 3.0, include_low=False)
    if name in ("position", "reference"):
        return check_range(name, value, 0.0, 1.0, unit=unit)
    if name in ("racket_speed", "pivot", "offset"):  # any sign: towards/away, either side
        return check_finite(name, value, unit)
    if name in ("kcb", "zeta"):  # the paper's law's declared bounds
        return next(p for p in LinearContact.declared if p.name == name).check(value)
    if name == "elements":
        return check_elements(value, 2, MAX_ELEMENTS)  # the words of simulate's --elements
    if name == "ball_mass":
        return check_ball_mass(value, name)
    return check_positive(name, value, "" if unit == "1" else unit)


def parse_values(name: str, text: str) -> float | np.ndarray:
    """Values of parameter ``name`` from ``text``: one number (fixed), a comma list, or
    ``start:stop:num[:log]`` (a swept dimension).

    Raises :class:`InputError` with a one-line message on malformed text or bad values.
    """
    text = str(text).strip()
    if name == "pattern":  # 16x19 or a comma list of them
        return as_values(name, [pattern_code(t) for t in text.split(",")] if "," in text else text)
    form = "a number, a comma list or start:stop:num[:log]"
    if ":" in text:
        parts = [p.strip() for p in text.split(":")]
        log = parts[-1].lower() == "log"
        if log:
            parts = parts[:-1]
        if len(parts) != 3:
            raise _refused(name, text, f"must be {form}")
        try:
            start, stop, num = float(parts[0]), float(parts[1]), float(parts[2])
        except ValueError:
            raise _refused(name, text, f"must be {form}") from None
        if not (num.is_integer() and 1 <= num <= MAX_CASES):
            raise _refused(name, text, f"num must be an integer from 1 to {MAX_CASES}")
        if not (math.isfinite(start) and math.isfinite(stop)):
            raise _refused(name, text, "start and stop must be finite")
        if num == 1 and start != stop:  # one value cannot be both ends
            raise _refused(name, text, "num 1 needs start = stop (or give one number, or num >= 2)")
        if log and (start <= 0.0 or stop <= 0.0):
            raise _refused(name, text, "log spacing needs start, stop > 0")
        values = (np.geomspace if log else np.linspace)(start, stop, int(num))
        if log:  # geomspace ends are exact in recent numpy; make sure
            values[0], values[-1] = start, stop
        return as_values(name, values)
    try:
        numbers = [float(v) for v in text.split(",")]
    except ValueError:
        raise _refused(name, text, f"must be {form}") from None
    if len(numbers) == 1:
        return as_values(name, numbers[0])
    return as_values(name, numbers)


def value_count(value: Any) -> int:
    """How many values ``value`` gives (as :func:`as_values` would), without making them: the
    ``num`` of ``start:stop:num[:log]``, the items of a comma list or a sequence; 1 otherwise.
    A malformed value, or one axis over :data:`MAX_CASES`, counts 1 (:func:`as_values` then
    says what is wrong)."""
    if isinstance(value, str):
        if ":" in value:
            parts = [p.strip() for p in value.split(":")]
            parts = parts[:-1] if parts[-1].lower() == "log" else parts
            try:
                num = float(parts[2]) if len(parts) == 3 else 1.0
            except ValueError:
                return 1
            return int(num) if 1 <= num <= MAX_CASES else 1
        return value.count(",") + 1
    return 1 if value is None or np.ndim(value) == 0 else int(np.size(value))


def as_values(name: str, value: Any) -> float | int | None | np.ndarray:
    """Normalise a Python value of parameter ``name``: None (default), a number (fixed), a
    string (see :func:`parse_values`) or a sequence (swept; a 1-D array of distinct values)."""
    if name not in PARAMETERS and name not in LAW_PARAMETERS:
        known = ", ".join([*PARAMETERS, *LAW_PARAMETERS])
        raise _refused("parameter", name, f"must be one of {known}")
    if value is None:
        return None
    if isinstance(value, str) and not (name == "pattern" and "," not in value):
        return parse_values(name, value)
    law = name in LAW_PARAMETERS  # once: the live registry is rebuilt at every look-up
    if np.ndim(value) == 0:
        return _check_value(name, value, law)
    if np.ndim(value) != 1 or len(value) == 0:
        raise _refused(name, value, "must be a number or a 1-D list")
    checked = [_check_value(name, v, law) for v in value]
    arr = np.array(checked, dtype=np.int64 if name in ("elements", "pattern") else float)
    if np.unique(arr).size != arr.size:
        raise _refused(name, arr.tolist(), "values must be distinct")
    return arr
