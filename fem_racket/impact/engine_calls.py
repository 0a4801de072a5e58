"""Which cases of a :class:`~fem_racket.impact.problem_batch.ProblemBatch` go in one call of the
batched engine (the exact solver's :func:`fem_racket.impact.batch_solve.engine_batch`).

- :func:`per_frame`: one :func:`fem_racket.impact.exact.engine.impacts` call per frame, which
  computes the frame's modes up to each case's cut-off and the static totals of the others,
  and twists the frame off the axis;
- :func:`grouped`: when every frame's modes go to the engine whole (a mode limit ``modes``, or
  no COR tolerance: no static totals) and every case is on the axis, the frames' mode values
  are gathered and the frames with as many modes share one
  :func:`~fem_racket.impact.exact.engine.modal_impacts` call (a batch of designs: one call for
  all of them, not one per design). Each case gets the numbers :func:`per_frame` gives it, to
  the bit: the same mode values, its frequencies times sqrt(EI factor) as the engine scales
  them, and each case solved on its own.

A frame that cannot be solved (its accuracy check, an eigenproblem) gives no part: its cases
stay NaN, with a warning.
"""

from __future__ import annotations

import logging
import math
from collections.abc import Iterator

import numpy as np

from fem_racket.impact.exact.engine import impacts, modal_impacts
from fem_racket.impact.exact.impact_batch import ImpactBatch
from fem_racket.impact.exact.inputs import EngineOptions, check_array
from fem_racket.impact.point import frame_modal_data
from fem_racket.impact.problem_batch import ProblemBatch
from fem_racket.impact.reduction import cutoff_factor
from fem_racket.impact.settings import Settings
from fem_racket.validation import AccuracyError, InputError

__all__ = ["grouped", "per_frame", "whole_modes"]

log = logging.getLogger(__name__)

#: Errors of a frame that cannot be solved (its cases get NaN).
FAILURES = (AccuracyError, np.linalg.LinAlgError)


def _options(batch: ProblemBatch, settings: Settings, modes: int | None) -> EngineOptions:
    separation = batch.separation or "displacement"
    return EngineOptions(separation, settings.tolerance, batch.peak_force, modes)


def _laws(batch: ProblemBatch, rows: np.ndarray) -> dict:
    """The paper's law's per-case arguments of the engine for ``rows``."""
    return {
        "kcb": None if batch.kcb is None else batch.kcb[rows],
        "zeta": None if batch.zeta is None else batch.zeta[rows],
        "ball_mass": batch.ball_mass[rows],
    }


def whole_modes(batch: ProblemBatch, settings: Settings) -> bool:
    """True when every frame's modes go to the engine whole and every case is on the axis
    (module docstring): :func:`grouped` applies."""
    beta = cutoff_factor(settings.tolerance, batch.separation or "displacement")
    return not np.any(batch.offset != 0.0) and (settings.modes is not None or math.isinf(beta))


def per_frame(
    batch: ProblemBatch, settings: Settings, closing: np.ndarray, frames: np.ndarray | None = None
) -> Iterator[tuple[np.ndarray, ImpactBatch]]:
    """(rows, their engine outcome) per frame (of ``frames``, all when None), each case at its
    ``closing`` speed [m/s]."""
    for k in np.unique(batch.frame) if frames is None else frames:
        rows = np.flatnonzero(batch.frame == k)
        try:
            b = impacts(
                batch.models[k],
                position=batch.position[rows],
                offset=batch.offset[rows],
                speed=closing[rows],
                ei_factor=batch.ei_factor[rows],
                options=_options(batch, settings, settings.modes),
                **_laws(batch, rows),
            )
        except FAILURES as exc:  # the frame cannot be solved
            log.warning("%d cases failed (NaN in the results): %s", rows.size, exc)
            continue
        yield rows, b


def grouped(
    batch: ProblemBatch, settings: Settings, closing: np.ndarray
) -> Iterator[tuple[np.ndarray, ImpactBatch]]:
    """(rows, their engine outcome) per group of frames with as many modes (module docstring)."""
    check_array("position", batch.position, "x/L", 0.0, 1.0)
    check_array("ei_factor", batch.ei_factor, "", 0.0, math.inf)
    groups: dict[int, list] = {}
    for k in np.unique(batch.frame):
        rows = np.flatnonzero(batch.frame == k)
        uniq, index = np.unique(batch.position[rows], return_inverse=True)
        try:
            data = frame_modal_data(batch.models[k], uniq, None, limit=settings.modes)
        except FAILURES as exc:
            log.warning("%d cases failed (NaN in the results): %s", rows.size, exc)
            continue
        omega = data.omega[None, :] * np.sqrt(batch.ei_factor[rows])[:, None]
        part = (k, rows, omega, data.values[index], data.rigid[index])
        groups.setdefault(data.omega.size, []).append(part)
    for parts in groups.values():
        rows = np.concatenate([p[1] for p in parts])
        try:
            b = modal_impacts(
                *(np.concatenate([p[j] for p in parts]) for j in (2, 3, 4)),
                speed=closing[rows],
                options=_options(batch, settings, None),
                **_laws(batch, rows),
            )
        except InputError:  # e.g. two equal frequencies, which modal_impacts refuses
            yield from per_frame(batch, settings, closing, np.array([p[0] for p in parts]))
            continue
        yield rows, b
