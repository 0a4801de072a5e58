"""How a contact law declares its parameters once: :class:`LawParameter`, :class:`LawCondition`.

Each law class lists its parameters (``declared``) and the conditions they must meet together
(``conditions``); the command-line options (``--k1``), the run file's ``[contact]`` keys
(``k1_n_m_n``), the sweep axes, the JSON keys and the checks all derive from these
declarations (:mod:`fem_racket.contact.registry`). Bounds are physical: each declaration says
why (``why``) and where the range comes from; a value outside them is refused with one line
naming the parameter, its value and the allowed interval.

:func:`check_values` checks every value and every condition elementwise, so a sweep's whole grid
is checked before any work, and names the first case that fails.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np

from fem_racket.validation import InputError, check_finite, check_range, show

__all__ = ["KEY_SUFFIXES", "LawCondition", "LawFit", "LawParameter", "check_values"]

#: A parameter's unit -> the suffix of its run-file and JSON key (units in every key).
KEY_SUFFIXES = {
    "-": "",
    "N/m": "_n_m",
    "N/m^3": "_n_m3",
    "N/m^n": "_n_m_n",
    "N s/m": "_n_s_m",
    "s/m": "_s_m",
}


@dataclass(frozen=True, kw_only=True)
class LawParameter:
    """One parameter of a contact law, declared once.

    Attributes
    ----------
    name : str
        Its name on the command line (``--k1``; underscores become hyphens), as a sweep axis
        and a keyword of :func:`fem_racket.contact.presets.get_law`; unique across laws.
    field : str
        The attribute of the law's dataclass holding it; by default the name.
    unit : str
        SI unit ("-" for none).
    default : float
        The family's default value (its best fit: :mod:`fem_racket.studies.calibrate`).
    low, high : float
        Physical bounds (inclusive unless ``open_low`` / ``open_high``).
    key : str
        Its key in a run file's ``[contact]`` table and in JSON outputs, units in the key; by
        default the name and its unit's suffix (:data:`KEY_SUFFIXES`: ``k1_n_m_n``).
    help : str
        One line for ``--help`` and the sweep's variable descriptions.
    why : str
        The reasoning or source of the bounds.
    open_low, open_high : bool
        Exclude the bound itself.
    """

    name: str
    field: str | None = None
    unit: str
    default: float
    low: float
    high: float
    key: str | None = None
    help: str
    why: str
    open_low: bool = False
    open_high: bool = False

    def __post_init__(self) -> None:
        if self.field is None:
            object.__setattr__(self, "field", self.name)
        if self.key is None:
            if self.unit not in KEY_SUFFIXES:
                raise ValueError(f"unit {self.unit!r} of {self.name!r} has no key suffix: give key")
            object.__setattr__(self, "key", self.name + KEY_SUFFIXES[self.unit])

    @property
    def option(self) -> str:
        """The command-line option, ``--`` and the name with hyphens."""
        return "--" + self.name.replace("_", "-")

    @property
    def si_unit(self) -> str:
        """The unit for messages ("" for a dimensionless parameter)."""
        return "" if self.unit == "-" else self.unit

    def check(self, value: Any, label: str | None = None) -> float:
        """``value`` as a float, or a one-line :class:`InputError` naming ``label`` (the
        parameter's name by default) unless it lies within the bounds."""
        name = label or self.name
        number = check_finite(name, value, self.si_unit)
        if self.low >= 0.0 and number <= 0.0 and (self.low > 0.0 or self.open_low):
            unit = f" {self.si_unit}" if self.si_unit else ""
            raise InputError(
                f"{name} = {show(value)}{unit} is not allowed: must be a finite number > 0, "
                f"in {self.interval()}",
                parameter=name,
                value=value,
            )
        return check_range(
            name,
            number,
            self.low,
            self.high,
            unit=self.si_unit,
            include_low=not self.open_low,
            include_high=not self.open_high,
        )

    def interval(self) -> str:
        """The allowed interval as text, e.g. ``[1, 20]``."""
        lb, rb = "(" if self.open_low else "[", ")" if self.open_high else "]"
        return f"{lb}{self.low:g}, {self.high:g}{rb}"


@dataclass(frozen=True)
class LawCondition:
    """A condition several parameters of a law must meet together (e.g. k2 >= k1).

    Attributes
    ----------
    text : str
        The condition as written in messages (``"k2 >= k1"``).
    holds : callable
        ``holds(values) -> bool array``: ``values`` maps parameter names to arrays of one
        value per case (broadcast together).
    why : str
        Why it must hold (one clause, for the message and the docs).
    """

    text: str
    holds: Callable[[Mapping[str, np.ndarray]], Any]
    why: str


@dataclass(frozen=True)
class LawFit:
    """How :mod:`fem_racket.studies.calibrate` fits a law: the fitted coordinates (in log space;
    they may differ from the parameters, e.g. the hysteretic law's rigid COR instead of k2),
    their search bounds and a start per target set.

    Attributes
    ----------
    names : tuple of str
        The coordinates with their units, for reports.
    build : callable
        ``build(x) -> ContactLaw`` from the coordinates' values.
    low, high : tuple of float
        Search bounds of each coordinate.
    starts : dict
        Target-set name -> start values.
    """

    names: tuple[str, ...]
    build: Callable[[np.ndarray], Any]
    low: tuple[float, ...]
    high: tuple[float, ...]
    starts: dict[str, tuple[float, ...]]

    def __post_init__(self) -> None:
        for target, start in self.starts.items():
            inside = [lo <= x <= hi for lo, x, hi in zip(self.low, start, self.high, strict=True)]
            if not all(inside):
                raise ValueError(f"fit start {start} for {target!r} is outside its bounds")


def _case(names: tuple[str, ...], values: Mapping[str, np.ndarray], i: int) -> str:
    return ", ".join(f"{n} = {float(values[n].ravel()[i]):.6g}" for n in names)


def check_values(
    law: str,
    declared: tuple[LawParameter, ...],
    conditions: tuple[LawCondition, ...],
    values: Mapping[str, Any],
) -> dict[str, np.ndarray]:
    """Every value (numbers or arrays, broadcast against each other: one entry per case) of a
    law's parameters checked against its bounds and conditions; returns the broadcast arrays.

    Raises
    ------
    InputError
        One line naming the first parameter or the first case that fails, and the rule.
    """
    given = {p.name: np.asarray(values[p.name], dtype=float) for p in declared}
    arrays = dict(zip(given, np.broadcast_arrays(*given.values()), strict=True))
    for p in declared:  # each value once (a grid's axis, not its every case)
        a = given[p.name]
        low_ok = a > p.low if p.open_low else a >= p.low
        high_ok = a < p.high if p.open_high else a <= p.high
        bad = np.flatnonzero(~(np.isfinite(a) & low_ok & high_ok).ravel())
        if bad.size:
            p.check(a.ravel()[bad[0]])  # raises the one-line message
    names = tuple(p.name for p in declared)
    for cond in conditions:
        with np.errstate(all="ignore"):
            # on the arrays as given: a sparse grid stays sparse until the condition broadcasts
            ok = np.broadcast_to(np.asarray(cond.holds(given), dtype=bool), arrays[names[0]].shape)
        bad = np.flatnonzero(~ok.ravel())
        if bad.size:
            case = _case(names, arrays, int(bad[0]))
            where = f" (and {bad.size - 1} more cases)" if bad.size > 1 else ""
            raise InputError(
                f"law {show(law)} with {case}{where} is not allowed: must satisfy "
                f"{cond.text} ({cond.why})"
            )
    return arrays
