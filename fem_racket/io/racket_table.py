"""Racket lists: a CSV of the numbers retailers publish, one racket per row.

Columns (header row, any order; units in the names, as the JSON outputs write them)::

    name, length_m, mass_kg, balance_m, swing_weight_kg_cm2      required
    twist_weight_kg_cm2, stiffness_ra, f1_hz                     optional (a column or a cell
                                                                 may be left out or empty)

Every problem is one line naming the file, the row (as a spreadsheet counts it, header = 1)
and the column.
"""

from __future__ import annotations

import csv
import math
import os

from fem_racket.frame.catalogue import Catalogue
from fem_racket.frame.specs import KG_CM2
from fem_racket.studies.closest import Listed
from fem_racket.validation import InputError, check_file, show

__all__ = ["OPTIONAL", "REQUIRED", "read_rackets"]

#: Required columns -> unit factor to SI.
REQUIRED = {
    "name": None,
    "length_m": 1.0,
    "mass_kg": 1.0,
    "balance_m": 1.0,
    "swing_weight_kg_cm2": KG_CM2,
}
#: Optional columns -> unit factor to SI.
OPTIONAL = {"twist_weight_kg_cm2": KG_CM2, "stiffness_ra": 1.0, "f1_hz": 1.0}


def _number(where: str, text: str, factor: float) -> float:
    try:
        value = float(text)
    except ValueError:
        value = math.nan
    if not (math.isfinite(value) and value > 0.0):
        raise InputError(f"{where} = {show(text)} is not allowed: must be a number > 0")
    return value * factor


def read_rackets(path: str | os.PathLike) -> list[Listed]:
    """The rackets of a CSV list (module docstring)."""
    path = check_file("rackets", path, "racket list (CSV)")
    with path.open(newline="", encoding="utf-8") as f:
        reader = csv.DictReader(f)
        header = [h.strip() for h in reader.fieldnames or []]
        missing = [c for c in REQUIRED if c not in header]
        if missing:
            raise InputError(
                f"rackets = '{path}' is not allowed: column {missing[0]} is missing (need "
                f"{', '.join(REQUIRED)}; optional {', '.join(OPTIONAL)})"
            )
        unknown = [c for c in header if c not in REQUIRED and c not in OPTIONAL]
        if unknown:
            raise InputError(
                f"rackets = '{path}' is not allowed: unknown column {unknown[0]} (allowed: "
                f"{', '.join([*REQUIRED, *OPTIONAL])})"
            )
        out = []
        for row_number, raw in enumerate(reader, start=2):
            row = {k.strip(): (v or "").strip() for k, v in raw.items() if k is not None}
            where = f"{path} row {row_number}"
            if not row["name"]:
                raise InputError(f"{where} name = '' is not allowed: every racket needs a name")
            req = {k: _number(f"{where} {k}", row[k], f) for k, f in REQUIRED.items() if f}
            opt = {
                k: _number(f"{where} {k}", row[k], f) if row.get(k) else None
                for k, f in OPTIONAL.items()
            }
            if not 0.0 < req["balance_m"] < req["length_m"]:
                raise InputError(
                    f"{where} balance_m = {show(row['balance_m'])} is not allowed: must lie "
                    f"within the length (0, {req['length_m']:g}) m"
                )
            specs = Catalogue(
                req["length_m"],
                req["mass_kg"],
                req["balance_m"],
                req["swing_weight_kg_cm2"],
                opt["twist_weight_kg_cm2"],
                opt["f1_hz"],
            )
            out.append(Listed(row["name"], specs, opt["stiffness_ra"]))
    if not out:
        raise InputError(f"rackets = '{path}' is not allowed: it lists no racket")
    return out
