"""Many impacts on hand-held rackets at once: a :class:`~fem_racket.impact.problem_batch.
ProblemBatch` with a hand, by the exact modal path (:mod:`fem_racket.impact.held.modal`).

The modes of frame + hand are computed once per frame (and EI factor) of the batch, and every
case on that frame is solved from them in one :func:`~fem_racket.impact.held.modal.
held_contacts` call (cases with one ball mass, K_CB and zeta together), each at its closing
speed v_in + v_r (a swing moves racket and hand rigidly: :mod:`fem_racket.impact.held.run`).
Besides the outcome's fields each case gets its handle-shock measures over the batch's window
(:mod:`fem_racket.impact.held.shock`): the RMS of the grip force's vibration part always, the
peak grip force (and the peak contact force) when the batch asks for peaks. A frame whose cases
cannot be solved gets NaN, with a warning, as the other batch paths do.
"""

from __future__ import annotations

import logging

import numpy as np

from fem_racket.contact.linear import LinearContact
from fem_racket.impact.batch_outcome import BatchOutcome
from fem_racket.impact.closing import closing_speed
from fem_racket.impact.held.basis import held_basis
from fem_racket.impact.held.modal import held_contacts
from fem_racket.impact.held.run import HELD_MAX_ELEMENTS, MAX_WINDOW
from fem_racket.impact.held.shock import DEFAULT_WINDOW, contact_peak, grip_peak, vibration_rms
from fem_racket.impact.problem_batch import ProblemBatch
from fem_racket.impact.swing import ball_speed_out
from fem_racket.impact.system import NoSeparationError
from fem_racket.validation import AccuracyError, InputError, check_range

__all__ = ["HELD_EXTRA", "held_batch"]

log = logging.getLogger(__name__)

#: The outcome's extra fields of a held racket.
HELD_EXTRA = ("grip_vibration_rms_n", "peak_grip_force_n")


def _window(batch: ProblemBatch) -> float:
    """The batch's shock window [s], checked as :func:`~fem_racket.impact.held.run.held_impact`
    checks it, and its frames' sizes."""
    window = DEFAULT_WINDOW if batch.shock_window is None else batch.shock_window
    for model in batch.models:
        if model.mesh.n_elements > HELD_MAX_ELEMENTS:
            raise InputError(
                f"elements = {model.mesh.n_elements} is not allowed with a hand: at most "
                f"{HELD_MAX_ELEMENTS} (dense matrices of frame + hand)",
                parameter="elements",
                value=model.mesh.n_elements,
            )
    return check_range("shock_window", window, 0.0, MAX_WINDOW, unit="s", include_low=False)


def _groups(batch: ProblemBatch) -> dict[tuple, list[int]]:
    """Case indices by (frame, EI factor, ball mass, K_CB, zeta), in order of appearance."""
    none = [None] * len(batch)
    columns = [batch.frame, batch.ei_factor, batch.ball_mass]
    columns += [none if c is None else c for c in (batch.kcb, batch.zeta)]
    groups: dict[tuple, list[int]] = {}
    for i, key in enumerate(zip(*columns, strict=True)):
        groups.setdefault(tuple(None if v is None else float(v) for v in key), []).append(i)
    return groups


def held_batch(batch: ProblemBatch, tolerance: float | None) -> BatchOutcome:
    """Every case of a held ``batch`` by the exact modal path (module docstring), the modes kept
    by the COR ``tolerance`` (None: every mode, as a single held run)."""
    window = _window(batch)
    n = len(batch)
    names = ("cor", "contact_time", "ball_speed_out", "peak_force", "kcb", "modes")
    out = {k: np.full(n, np.nan) for k in names}
    extra = {k: np.full(n, np.nan) for k in HELD_EXTRA}
    v_r = batch.racket_speed()
    closing = batch.speed + v_r
    bad = np.flatnonzero(~(closing > 0.0))
    if bad.size:
        closing_speed(batch.speed[bad[0]], v_r[bad[0]])  # raises, naming the case's speeds
    bases: dict[tuple, object] = {}
    stiffness: dict[tuple, float] = {}
    for (k, f, mb, kcb, zeta), rows in _groups(batch).items():
        if (k, f) not in bases:
            model = batch.models[int(k)]
            model = model if f == 1.0 else model.scaled(f)
            bases[(k, f)] = held_basis(model.fe, batch.hand)
        try:
            contacts = held_contacts(
                bases[(k, f)],
                batch.position[rows],
                closing[rows],
                ball_mass=mb,
                kcb=kcb,
                zeta=zeta,
                tolerance=tolerance,
            )
        except (NoSeparationError, AccuracyError, RuntimeError, np.linalg.LinAlgError) as exc:
            log.warning("%d cases failed (NaN in the results): %s", len(rows), exc)
            continue
        for i, c in zip(rows, contacts, strict=True):
            out["cor"][i], out["contact_time"][i], out["modes"][i] = c.cor, c.contact_time, c.modes
            key = (closing[i], kcb)
            if key not in stiffness:  # K_CB of each closing speed, once
                stiffness[key] = LinearContact.for_speed(closing[i], kcb=kcb, zeta=zeta).stiffness
            out["kcb"][i] = stiffness[key]
            extra["grip_vibration_rms_n"][i] = vibration_rms(c, window)
            if batch.peak_force:
                out["peak_force"][i] = contact_peak(c)
                extra["peak_grip_force_n"][i] = grip_peak(c, window)
    out["ball_speed_out"] = ball_speed_out(out["cor"], batch.speed, v_r)
    return BatchOutcome(**out, racket_speed=v_r, extra=extra)
