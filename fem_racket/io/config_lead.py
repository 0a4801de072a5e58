"""A run file's lead tape: ``[[frame.lead]]`` tables of ``place`` and ``mass_g``, as
``--add-mass PLACE:GRAMS`` gives (:mod:`fem_racket.frame.lead`)."""

from __future__ import annotations

import difflib
from typing import Any

from fem_racket.frame.lead import Lead
from fem_racket.validation import InputError, check_finite, show

__all__ = ["lead_tables"]

_LEAD_KEYS = {"place": "", "mass_g": "g"}


def lead_tables(name: str, value: Any) -> list[Lead]:
    """``[[frame.lead]]`` tables (place, mass_g) as leads, as --add-mass PLACE:GRAMS gives."""
    if not isinstance(value, list) or not value:
        raise InputError(
            f"{name} is not allowed: must be a non-empty array of tables with place and mass_g"
        )
    out = []
    for i, item in enumerate(value):
        where = f"{name}[{i}]"
        if not isinstance(item, dict):
            raise InputError(
                f"{where} = {show(item)} is not allowed: must be a table with place and mass_g"
            )
        for key in item:
            if key not in _LEAD_KEYS:
                near = difflib.get_close_matches(key, list(_LEAD_KEYS), n=1, cutoff=0.6)
                hint = f"did you mean '{near[0]}'? " if near else ""
                raise InputError(f"{where}.{key} is not a known key: {hint}allowed: place, mass_g")
        missing = [k for k in _LEAD_KEYS if k not in item]
        if missing:
            raise InputError(f"{where} is missing {', '.join(missing)} (each lead needs both)")
        place = item["place"]
        if isinstance(place, bool) or not isinstance(place, (str, int, float)):
            raise InputError(
                f"{where}.place = {show(place)} is not allowed: must be a clock place such as "
                '"3/9" or a distance from the butt in m'
            )
        grams = item["mass_g"]
        if isinstance(grams, bool) or not isinstance(grams, (int, float)):
            raise InputError(f"{where}.mass_g = {show(grams)} is not allowed: must be a number [g]")
        grams = check_finite(f"{where}.mass_g", grams, "g")
        if grams < 0.0:
            raise InputError(f"{where}.mass_g = {show(grams)} is not allowed: must be >= 0 g")
        out.append(Lead(str(place), grams * 1e-3))
    return out
