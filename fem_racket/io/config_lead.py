"""A run file's lead tape: ``[[frame.lead]]`` tables of ``place`` and ``mass_g``, as
``--add-mass PLACE:GRAMS`` gives (:mod:`fem_racket.frame.lead`)."""

from __future__ import annotations

import difflib
from typing import Any

from fem_racket.frame.lead import Lead, check_grams
from fem_racket.io.config_arrays import table_array
from fem_racket.validation import InputError, check_finite, show

__all__ = ["lead_tables"]

_LEAD_KEYS = {"place": "", "mass_g": "g"}


def _unknown(item: dict[str, Any], where: str) -> None:
    for key in item:
        if key not in _LEAD_KEYS:
            near = difflib.get_close_matches(key, list(_LEAD_KEYS), n=1, cutoff=0.6)
            hint = f"did you mean '{near[0]}'? " if near else ""
            raise InputError(f"{where}.{key} is not a known key: {hint}allowed: place, mass_g")


def lead_tables(name: str, value: Any) -> list[Lead]:
    """``[[frame.lead]]`` tables (place, mass_g) as leads, as --add-mass PLACE:GRAMS gives."""
    out = []
    for where, item in table_array(name, value, list(_LEAD_KEYS), _unknown, "each lead needs both"):
        place = item["place"]
        if isinstance(place, bool) or not isinstance(place, (str, int, float)):
            raise InputError(
                f"{where}.place = {show(place)} is not allowed: must be a clock place such as "
                '"3/9" or a distance from the butt in m'
            )
        grams = item["mass_g"]
        if isinstance(grams, bool) or not isinstance(grams, (int, float)):
            raise InputError(f"{where}.mass_g = {show(grams)} is not allowed: must be a number [g]")
        grams = check_grams(f"{where}.mass_g", check_finite(f"{where}.mass_g", grams, "g"))
        out.append(Lead(str(place), grams * 1e-3))
    return out
