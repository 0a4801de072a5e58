"""Maps over the racket face (position x/L by lateral offset): the one grid several maps must
share, and their CSV written cell by cell with a JSON sidecar (face and spin maps alike)."""

from __future__ import annotations

import csv
import json
from collections.abc import Callable, Mapping, Sequence
from pathlib import Path
from typing import Any

import numpy as np

from fem_racket.outputs import atomic_outputs, provenance, sidecar_path
from fem_racket.validation import InputError


def shared_grid(maps: Sequence[Any]) -> tuple[np.ndarray, np.ndarray]:
    """The positions [x/L] and offsets [m] every map of ``maps`` shares; refuses other grids."""
    x, y = maps[0].positions, maps[0].offsets
    for m in maps[1:]:
        if not (np.array_equal(m.positions, x) and np.array_equal(m.offsets, y)):
            raise InputError("maps = several face grids is not allowed: must share one grid")
    return x, y


def write_cells_csv(
    maps: Sequence[Any],
    path: Path,
    columns: Sequence[str],
    row: Callable[[Any, int, int], list[Any] | None],
    *,
    summary_key: str,
    parameters: Mapping[str, Any] | None,
    overwrite: bool,
) -> None:
    """Write one CSV row per cell of each map (``row(map, j, i)`` for offset j and position i;
    None skips the cell) and the sidecar ``<file>.json``: the provenance of ``parameters`` and,
    under ``summary_key``, each map's ``summary()`` by name; both atomically."""
    meta = provenance(parameters)
    meta[summary_key] = {m.name: m.summary() for m in maps}
    with atomic_outputs([path, sidecar_path(path)], overwrite=overwrite) as (tmp, side):
        with open(tmp, "w", newline="", encoding="utf-8") as f:
            w = csv.writer(f)
            w.writerow(columns)
            for m in maps:
                for j in range(len(m.offsets)):
                    for i in range(len(m.positions)):
                        if (r := row(m, j, i)) is not None:
                            w.writerow(r)
        side.write_text(json.dumps(meta, indent=2, default=str) + "\n", encoding="utf-8")
