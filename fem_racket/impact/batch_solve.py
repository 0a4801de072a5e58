"""How each solver answers a :class:`~fem_racket.impact.problem_batch.ProblemBatch`.

- :func:`engine_batch` (``exact``): the batched engine, one call per frame of the batch or, when
  the frames' modes go to it whole, one per group of frames with as many modes
  (:mod:`fem_racket.impact.engine_calls`), each case at its closing speed v_in + v_r (the
  system is linear; K_CB follows the closing speed).
- :func:`law_batch` (``general``): every case of the batch, whatever its frame, in one call of
  the general integrator (:func:`fem_racket.impact.general.integrator.solve_general`), each
  case with its own frame receptance, step and modes, so its result does not depend on the
  batch it is in.
- :func:`each_batch` (``cvode``, ``bdf``): one :class:`~fem_racket.impact.problem.ImpactProblem`
  after the other.
- a batch of rackets held in a hand (``exact``): :func:`fem_racket.impact.held.batch.held_batch`.

A swinging free racket struck at v_in is the stationary one struck at the closing speed
v_c = v_in + v_r, and the ball leaves at v_out = e_A v_in + (1 + e_A) v_r for any contact law
(derivation in :mod:`fem_racket.studies.law_cases`); the ODE solvers start from the swing's
velocity field instead. A case that fails (no separation within the time limit, a result the
solver cannot vouch for, a frame that fails its accuracy check) gets NaN, with a warning; any
other error stops the batch.
"""

from __future__ import annotations

import logging
from dataclasses import replace
from typing import Any
from weakref import WeakKeyDictionary

import numpy as np

from fem_racket.impact.closing import closing_speed
from fem_racket.impact.engine_calls import grouped, per_frame, whole_modes
from fem_racket.impact.general.batches import stack_receptances
from fem_racket.impact.general.integrator import solve_general
from fem_racket.impact.general.receptance import Receptance
from fem_racket.impact.held.batch import HELD_EXTRA
from fem_racket.impact.incidence import head_on
from fem_racket.impact.law_impact import receptance
from fem_racket.impact.oblique.solve import free_normal, oblique_on
from fem_racket.impact.problem_batch import BatchOutcome, ProblemBatch
from fem_racket.impact.settings import Settings
from fem_racket.impact.swing import ball_speed_out
from fem_racket.impact.system import NoSeparationError
from fem_racket.validation import AccuracyError

__all__ = ["each_batch", "engine_batch", "law_batch"]

log = logging.getLogger(__name__)

#: The outcome's fields, in :meth:`BatchOutcome.columns` order.
_FIELDS = ("cor", "contact_time", "ball_speed_out", "peak_force", "kcb", "racket_speed", "modes")


#: Each frame's scaled copies (EI x factor) made in this process, reused by the next batches
#: (a sweep's EI axis scales one frame many times); forgotten with the frame.
_SCALED: WeakKeyDictionary = WeakKeyDictionary()
#: Most scaled copies kept per frame.
SCALED_KEPT = 256


def scaled(model: Any, factor: float) -> Any:
    """``model`` with every EI times ``factor`` (itself for 1), its modes reused; cached."""
    if factor == 1.0:
        return model
    copies = _SCALED.setdefault(model, {})
    if factor not in copies:
        if len(copies) >= SCALED_KEPT:
            copies.clear()
        copies[factor] = model.scaled(factor)
    return copies[factor]


def _nan(n: int) -> dict[str, np.ndarray]:
    return {k: np.full(n, np.nan) for k in _FIELDS}


def _closing(batch: ProblemBatch, v_r: np.ndarray) -> np.ndarray:
    """v_in + v_r [m/s] of every case (the same sums as :func:`closing_speed`), refused in one
    line where ball and racket do not close."""
    closing = np.asarray(batch.speed, dtype=float) + v_r
    bad = np.flatnonzero(~(closing > 0.0))
    if bad.size:
        closing_speed(batch.speed[bad[0]], v_r[bad[0]])  # raises, naming the case's speeds
    return closing


def engine_batch(batch: ProblemBatch, settings: Settings) -> BatchOutcome:
    """The exact solution of every case of a batch under the paper's law (module docstring),
    to the COR ``settings.tolerance`` with at most ``settings.modes`` flexible modes."""
    out = _nan(len(batch))
    v_r = batch.racket_speed()
    closing = _closing(batch, v_r)
    calls = grouped if whole_modes(batch, settings) else per_frame
    for rows, b in calls(batch, settings, closing):
        out["cor"][rows] = b.cor
        out["contact_time"][rows] = b.contact_time
        out["ball_speed_out"][rows] = ball_speed_out(b.cor, batch.speed[rows], v_r[rows])
        if b.peak_force is not None:
            out["peak_force"][rows] = b.peak_force
        out["kcb"][rows] = b.kcb
        out["modes"][rows] = b.modes
    out["racket_speed"] = v_r
    return BatchOutcome(**out)


def _same_rigid(parts: list) -> list:
    """Receptances with as many rigid modes each: on-axis cases get the roll as a zero column
    when off-axis ones (translation, rotation, roll) share their batch (it adds exactly 0)."""
    n = max(p.rigid.shape[1] for p in parts)
    return [
        replace(p, rigid=np.pad(p.rigid, ((0, 0), (0, n - p.rigid.shape[1]))))
        if p.rigid.shape[1] < n
        else p
        for p in parts
    ]


def _receptances(batch: ProblemBatch, groups: dict[tuple, list[int]]) -> list[Receptance]:
    """The receptance of each group of cases (frame, EI factor, offset). On the axis a frame's
    mode shapes at its cases' points are computed once for every EI factor (a scaled frame
    keeps its shapes; only the frequencies scale), each point's values as if asked alone."""
    parts = []
    shapes: dict[float, tuple[np.ndarray, Receptance]] = {}  # frame -> its on-axis cases
    for (k, f, y), rows in groups.items():
        base = batch.models[int(k)]
        base.modes(None)  # once per frame: its scalings reuse them
        model = scaled(base, f)
        if y != 0.0:
            parts.append(receptance(model, batch.position[rows], batch.ball_mass[rows], None, y))
            continue
        if k not in shapes:
            on = np.flatnonzero((batch.frame == k) & (batch.offset == 0.0))
            shapes[k] = on, receptance(base, batch.position[on], batch.ball_mass[on])
        on, whole = shapes[k]
        at = np.searchsorted(on, rows)
        omega = model.modes(None).omega
        parts.append(Receptance(omega, whole.a[at], whole.rigid[at], whole.ball_mass[at]))
    return parts


def _in_order(law: Any, order: np.ndarray) -> Any:
    """``law`` with its per-case parameters taken in ``order``."""
    per_case = {
        p.field: np.asarray(getattr(law, p.field))[order]
        for p in law.declared
        if np.ndim(getattr(law, p.field)) == 1
    }
    return replace(law, **per_case) if per_case else law


def law_batch(batch: ProblemBatch, settings: Settings) -> BatchOutcome:
    """Every case of a batch under its contact law by one general-integrator call, to the COR
    ``settings.tolerance``; the modes are every mode of each case's frame (the integrator
    keeps those it needs)."""
    n = len(batch)
    out = _nan(n)
    groups: dict[tuple, list[int]] = {}  # one receptance per frame, EI factor and offset
    for i, key in enumerate(zip(batch.frame, batch.ei_factor, batch.offset, strict=True)):
        groups.setdefault(tuple(float(v) for v in key), []).append(i)
    parts = _receptances(batch, groups)
    order = np.array([r for rows in groups.values() for r in rows], dtype=np.int64)
    v_r = batch.racket_speed()
    closing = _closing(batch, v_r)[order]
    try:
        o = solve_general(
            _in_order(batch.law, order),
            stack_receptances(_same_rigid(parts)),
            closing,
            tolerance=settings.tolerance,
            refused="nan",
        )
    except (NoSeparationError, RuntimeError) as exc:
        log.warning("%d cases failed (NaN in the results): %s", n, exc)
        return BatchOutcome(**out)
    bad = int(np.sum(~np.isfinite(o.ball_velocity)))
    if bad:
        log.warning(
            "%d cases could not be computed within tolerance %s or did not separate (NaN in "
            "the results)",
            bad,
            settings.tolerance,
        )
    e_a = -o.ball_velocity / closing
    out["cor"][order] = e_a
    out["contact_time"][order] = o.contact_time
    out["ball_speed_out"][order] = ball_speed_out(e_a, batch.speed[order], v_r[order])
    out["peak_force"][order] = o.peak_force
    out["racket_speed"] = v_r
    out["modes"][order] = [p.a.shape[1] for p in parts for _ in range(p.a.shape[0])]
    return BatchOutcome(**out)


#: The outcome's extra fields of a string bed and of an oblique impact.
STRUNG_EXTRA = ("stringbed_stiffness_n_m", "stringbed_frequency_hz")
OBLIQUE_EXTRA = ("ball_speed_out_m_s", "angle_out_deg", "spin_out_rpm", "tangential_cor")
#: Across the face (0 for a ball in the plane of the long axis without side spin).
LATERAL_EXTRA = ("side_angle_out_deg", "side_spin_out_rpm", "racket_yaw_rate_rad_s")


def _normal_key(batch: ProblemBatch, i: int, frame: tuple) -> tuple:
    """What case ``i``'s normal impact depends on: all but its spins, friction and the ball's
    tangential parameters (its string bed, and its normal speed through both angles)."""
    law = batch.law
    params = () if law is None else tuple(
        float(np.asarray(getattr(law, p.field))[i]) if np.ndim(getattr(law, p.field)) == 1
        else getattr(law, p.field)
        for p in law.declared
    )  # fmt: skip
    columns = (batch.position, batch.offset, batch.speed, batch.ball_mass, batch.kcb, batch.zeta)
    numbers = tuple(None if c is None else float(c[i]) for c in columns)
    swing = None if batch.swing is None else tuple(batch.swing[i])
    bed = None if batch.strings is None else batch.strings[i]
    inc = batch.incidence[i]
    return (frame, numbers, swing, params, bed, inc.angle, inc.side_angle)


def _solve_case(solver: Any, batch: ProblemBatch, i: int, model: Any, normals: dict) -> tuple:
    """(problem, result, its normal impact's result) of case ``i``; an oblique case over the
    normal impact it shares with the batch's other spins and frictions at its angle."""
    problem = batch.problem(i, model)
    solver.check(problem)
    if problem.incidence is None:
        r = solver._outcome(problem)
        return problem, r, r
    key = _normal_key(batch, i, (int(batch.frame[i]), float(batch.ei_factor[i])))
    if key not in normals:
        normals[key] = free_normal(solver._outcome(head_on(problem)))
    r = oblique_on(normals[key], problem.incidence, problem.impact.speed)
    return problem, r, r.normal


def each_batch(solver: Any, batch: ProblemBatch) -> BatchOutcome:
    """Every case of a batch as its own problem by ``solver`` (checked; the ODE solvers, and
    every solver on a string bed or an oblique ball), the peak force the largest over the
    solver's output times; oblique cases at one angle share their normal impact. A held
    racket's modes kept are NaN (its integrators keep every DOF)."""
    n = len(batch)
    out = _nan(n)
    names = (
        (STRUNG_EXTRA if batch.strings is not None else ())
        + (OBLIQUE_EXTRA + LATERAL_EXTRA if batch.incidence is not None else ())
        + (HELD_EXTRA if batch.held else ())
    )
    extra = {k: np.full(n, np.nan) for k in names}
    if batch.incidence is not None:
        extra["contact_regime"] = np.full(n, "", dtype=object)
    modes = solver.options.settings().modes
    models: dict[tuple, Any] = {}
    normals: dict[tuple, Any] = {}
    for i in range(n):
        key = (int(batch.frame[i]), float(batch.ei_factor[i]))
        if key not in models:
            base = batch.models[key[0]]
            base.modes(modes)  # once per frame: its scalings reuse them
            models[key] = scaled(base, key[1])
        try:
            problem, r, normal = _solve_case(solver, batch, i, models[key], normals)
        except (NoSeparationError, AccuracyError, RuntimeError, np.linalg.LinAlgError) as exc:
            log.warning("case %d of the batch failed (NaN in the results): %s", i, exc)
            continue
        out["racket_speed"][i] = problem.racket_speed
        if problem.strings is not None:  # the bed's normal impact (oblique: at V cos(angle))
            row = (normal.cor, normal.contact_time, normal.cor * normal.speed)
            row += (normal.peak_force, np.nan, np.nan)
            extra["stringbed_stiffness_n_m"][i] = normal.point.bed_stiffness
            extra["stringbed_frequency_hz"][i] = normal.point.bed_frequencies_hz[0]
        elif problem.held:  # a HeldRun
            row = (r.apparent_cor, r.contact_time, r.ball_speed_out, r.peak_force)
            row += (problem.contact().stiffness, np.nan)
            extra["grip_vibration_rms_n"][i] = r.grip_vibration_rms
            extra["peak_grip_force_n"][i] = r.peak_grip_force
        else:
            # K_CB of the normal impact solved (oblique: at V cos(side) cos(angle), as simulate)
            kcb = head_on(problem).contact().stiffness if problem.linear else np.nan
            kept = np.nan if normal.n_modes is None else normal.n_modes  # None: physical basis
            row = (normal.cor, normal.contact_time, normal.ball_speed_out, normal.peak_force)
            row += (kcb, kept)
        for name, value in zip((*_FIELDS[:5], "modes"), row, strict=True):
            out[name][i] = value
        if problem.incidence is not None:
            summary = r.summary()
            for name in (*OBLIQUE_EXTRA, *LATERAL_EXTRA, "contact_regime"):
                extra[name][i] = summary[name]
    return BatchOutcome(**out, extra=extra)
