"""Sweep cases under a contact law, batched per frame through the general integrator.

The cases of a chunk that share a frame (mesh, EI scaling) run as one batch of
:func:`fem_racket.impact.general.solve_general` (positions, speeds and ball masses as arrays),
which is what makes the general integrator cheap per impact (``scripts/bench_laws.py``).
"""

from __future__ import annotations

import logging
from collections.abc import Callable
from typing import Any

import numpy as np

from fem_racket.impact.general import solve_general
from fem_racket.impact.law_impact import receptance
from fem_racket.impact.system import NoSeparationError
from fem_racket.studies.grid import SweepSpec

__all__ = ["law_chunk"]

log = logging.getLogger(__name__)


def law_chunk(spec: SweepSpec, chunk: np.ndarray, model_of: Callable[..., tuple]) -> np.ndarray:
    """Results (cor, t_c, rebound speed, peak force, NaN for K_CB) of the cases ``chunk``.

    ``model_of(spec, elements, ei1, ei_factor) -> (key, FrameModel)`` gives each case's frame
    (cached by the caller). A batch that fails (no separation within its time limit, or a
    diverging Newton iteration) gives NaN for its cases, with a warning.
    """
    cases = [spec.case(int(i)) for i in chunk]
    groups: dict[tuple, list[int]] = {}
    models: dict[tuple, Any] = {}
    for row, p in enumerate(cases):
        key, model = model_of(spec, p["elements"], p["ei1"], p["ei_factor"])
        groups.setdefault(key, []).append(row)
        models[key] = model
    out = np.full((len(cases), 6), np.nan)
    for key, rows in groups.items():
        pos = np.array([cases[r]["position"] for r in rows])
        speed = np.array([cases[r]["speed"] for r in rows])
        mass = np.array([cases[r]["ball_mass"] for r in rows])
        try:
            o = solve_general(spec.law, receptance(models[key], pos, mass), speed)
        except (NoSeparationError, RuntimeError) as exc:
            log.warning("%d cases failed (NaN in the results): %s", len(rows), exc)
            continue
        out[rows, 0] = -o.ball_velocity / speed
        out[rows, 1] = o.contact_time
        out[rows, 2] = -o.ball_velocity
        out[rows, 3] = o.peak_force
        out[rows, 5] = 0.0  # the racket at rest (a swing is refused with a law)
    return out
