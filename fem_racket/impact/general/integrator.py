"""A fast general integrator for any contact law: the frame as an impact-point receptance.

The frame is linear, so the contact force F(t) is the only unknown: the deflection at the
contact is a Volterra integral of F over the frame's receptance
(:mod:`fem_racket.impact.general.receptance`). F is a piecewise cubic on a uniform grid
(:mod:`fem_racket.impact.general.cubic_force`, fourth order), every mode responds to it exactly,
and each node solves only the contact equation ``F_m = law(delta_m(F_m), delta'_m(F_m), z)``
(:mod:`fem_racket.impact.general.step`). Flexible modes above ``beta`` times the contact
frequency pi / t_c (t_c the law's estimate) are replaced by one residual pseudo-mode per case,
by the engine's rule (:func:`fem_racket.impact.reduction.split_modes`); separation is found
per case on the law's own end condition inside its step.

The laws of :mod:`fem_racket.contact` march compiled (:mod:`fem_racket.impact.general.kernel`,
numba): every case with its own modes and its own step h = t_c / N, so a batch may span frames
and a case's answer does not depend on the batch it is in. A lone impact that is a process's
first solve (``fem-racket simulate --law``) runs the same kernels' code interpreted instead,
which costs less than loading numba (:mod:`fem_racket.impact.general.jit`). A COR tolerance
sets N and the mode cut-off (:func:`settings`), and each answer is vouched for against it
(:mod:`fem_racket.impact.general.vouch`: step halving, state resolution, energy balance; N
doubled where it fails, refused where it still fails; where the law's estimate of t_c is far
too long, the contact time found replaces it). A law without a kernel (a
user's subclass) marches in numpy (:mod:`fem_racket.impact.general.march`; few cases: every
node at once, :mod:`fem_racket.impact.general.nodes`), grouped by contact time, each group
with one step, at the tolerance's N without vouching.

Accuracy against CVODE (:mod:`fem_racket.impact.ode.law_cvode`; ``scripts/bench_kernels.py``,
``tests/impact/general/test_vouch.py``): fourth order where the force is smooth. A force cut to
zero at separation (power laws; a kink, which the cubic would smear to second order) takes the
branch's cubic continuation on its last step in the compiled march. Exponents just above 1 are
singular at contact (F ~ t^n): second order, which the halving estimate sees.
"""

from __future__ import annotations

import logging
import math
from dataclasses import replace
from typing import Any

import numpy as np

from fem_racket.contact.law import ContactLaw
from fem_racket.impact.general.compiled import MarchCases, kernel_law, march_compiled
from fem_racket.impact.general.jit import lone_solve
from fem_racket.impact.general.march import GeneralOutcome, march
from fem_racket.impact.general.receptance import Receptance, free_motion
from fem_racket.impact.general.step import per_case
from fem_racket.impact.general.stored import laid_out
from fem_racket.impact.general.vouch import STEP_SHARE, first_steps, vouched
from fem_racket.impact.reduction import (
    DEFAULT_TOLERANCE,
    check_tolerance,
    contact_frequency,
    cutoff_factor,
)
from fem_racket.validation import (
    AccuracyError,
    check_choice,
    check_integer,
    check_positive,
)

__all__ = ["NONE_TOLERANCE", "STEP_ERROR", "GeneralOutcome", "settings", "solve_general"]

log = logging.getLogger(__name__)

#: Time steps per estimated contact time for a COR tolerance tol: (STEP_ERROR / tol)^(1/4)
#: (fourth order; the largest COR error over the laws of ``scripts/bench_laws.py`` at 8 random
#: impacts each with every mode kept was ~660 / steps^4 (Hunt-Crossley, n = 9, 64-128 steps),
#: times a safety factor of 2).
STEP_ERROR = 1300.0
#: First integration span as a multiple of the estimated contact time (doubled while some case
#: has not separated, up to t_max).
SPAN = 2.0
#: Cases whose estimated contact times differ by more than this factor run in separate groups
#: (each with its own step), so a batch never takes the shortest case's step for all.
GROUP_RATIO = 1.3
#: Default t_max as a multiple of the estimated contact time.
LIMIT = 16.0
#: The COR tolerance answers are vouched for at when the tolerance is None (every mode).
NONE_TOLERANCE = 1e-6
#: Batches up to this size (laws without an ODE state) solve all nodes at once
#: (:mod:`fem_racket.impact.general.nodes`); larger ones march, vectorised across cases.
WHOLE = 2


def solve_general(
    law: ContactLaw,
    rec: Receptance,
    speed: Any,
    *,
    frame_velocity: np.ndarray | None = None,
    tolerance: float | None = DEFAULT_TOLERANCE,
    steps: int | None = None,
    beta: float | None = None,
    t_max: float | None = None,
    refused: str = "raise",
) -> GeneralOutcome:
    """Integrate a batch of impacts until each ball separates.

    Parameters
    ----------
    law : ContactLaw
        The ball/string law (parameters float, or arrays of shape (C,) for per-case values).
    rec : Receptance
        The frame at each case's impact point (``omega`` shared, or one row per case: a batch
        may span frames).
    speed : float or ndarray, shape (C,)
        Ball speed towards the frame at t = 0 [m/s] (relative to the frame's rest state).
    frame_velocity : ndarray, shape (C, 2 + n), optional
        Initial modal velocities of the frame (rigid translation and rotation about the CG first,
        then the flexible modes of ``rec.omega``) [sqrt(kg) m/s]; at rest when None. Positive
        moves the frame along the ball's travel (away from the ball).
    tolerance : float or None
        COR tolerance [-]: sets ``beta`` and the first step count (:func:`settings`), and each
        answer is vouched for against it (:mod:`fem_racket.impact.general.vouch`: step halving,
        energy balance); None (or 0): every mode, from 800 steps, vouched for at
        :data:`NONE_TOLERANCE`.
    steps : int, optional
        Time steps per estimated contact time, as given (no halving: an expert's setting).
    beta : float, optional
        Keep flexible modes below beta x pi / t_c (the rest: one pseudo-mode; inf keeps all).
    t_max : float, optional
        Give up at this time [s]; 16 x the estimated contact time by default.
    refused : {"raise", "nan"}
        A case the integrator cannot vouch for: :class:`~fem_racket.validation.AccuracyError`
        (an InputError, one line), or NaN in its results.

    Returns
    -------
    GeneralOutcome
    """
    given, beta_given = steps is not None, beta
    check_choice("refused", refused, ("raise", "nan"))
    tol = check_tolerance(tolerance)
    steps, beta = settings(tolerance, steps, beta)
    ncase = rec.a.shape[0]
    speed = np.broadcast_to(np.asarray(speed, dtype=float), (ncase,)).copy()
    closing = speed  # ball against the frame's impact point at t = 0 [m/s]
    if frame_velocity is not None:
        closing = free_motion(rec, speed, frame_velocity, np.zeros(1))[1][:, 0]
    t_case = np.broadcast_to(
        law.contact_time_estimate(1.0 / rec.compliance, np.abs(closing)), (ncase,)
    ).astype(float)
    kernel = kernel_law(law, ncase)
    if kernel is None:
        log.info("law %s has no compiled kernel: the numpy march runs", type(law).__name__)
        if np.ndim(rec.omega) == 1:
            return _solve_numpy(law, rec, speed, frame_velocity, t_case, steps, beta, t_max)
        # a batch spanning frames: the numpy march takes one frame at a time
        frames = np.unique(rec.omega, axis=0, return_inverse=True)[1].ravel()
        groups = [np.flatnonzero(frames == f) for f in range(frames.max() + 1)]
        parts = []
        for idx in groups:
            sub = per_case(rec, ncase, idx)
            n = int(np.sum(np.isfinite(sub.omega[0])))
            sub = replace(sub, omega=sub.omega[0, :n], a=sub.a[:, :n])
            fv = None if frame_velocity is None else frame_velocity[idx]
            one = per_case(law, ncase, idx)
            parts.append(_solve_numpy(one, sub, speed[idx], fv, t_case[idx], steps, beta, t_max))
        return _merge(parts, groups, ncase)
    exponent = getattr(law, "exponent", 1.0)
    limit = LIMIT * t_case if t_max is None else np.full(ncase, check_positive("t_max", t_max, "s"))
    omega_c = contact_frequency(t_case, exponent) + 0.0 * t_case
    limits = (np.minimum(SPAN * t_case, limit), limit)
    if given:
        with lone_solve(ncase):
            cases = MarchCases(kernel, rec, speed, frame_velocity, omega_c, beta)
            out, _, status, stored = march_compiled(cases, t_case / steps, *limits)
        _check_status(status, limit)
        return replace(out, **laid_out([(np.arange(ncase), stored)], ncase))
    target = NONE_TOLERANCE if tol is None else tol
    if beta_given is None and tol is not None:  # the cut-off's share of the tolerance
        beta = cutoff_factor(tol * (1.0 - STEP_SHARE))
    with lone_solve(ncase):
        first = first_steps(steps, exponent, ncase)
        cases = MarchCases(kernel, rec, speed, frame_velocity, omega_c, beta)
        parts, where, run, stored = vouched(cases, t_case, first, target, limits)
    out = replace(_merge(parts, where, ncase), **laid_out(stored, ncase))
    if refused == "raise":
        _check_status(np.where(run.no_separation, 1, 0), limit)
        bad = np.flatnonzero(run.steps == 0)
        if bad.size:
            i = int(bad[0])
            one = per_case(law, ncase, np.array([i]))
            what = f"law {one.label()} at {float(speed[i]):g} m/s"
            what += f" (case {i} of {ncase})" if ncase > 1 else ""
            raise AccuracyError(run.refusal(i, tol or NONE_TOLERANCE, what))
    return out


def _check_status(status: np.ndarray, limit: np.ndarray) -> None:
    """Raise for a case still in contact at t_max or whose Newton iteration failed."""
    if np.any(status == 1):
        from fem_racket.impact.system import no_separation

        raise no_separation(float(limit[np.argmax(status == 1)]))
    if np.any(status == 2):
        raise RuntimeError("contact-law Newton iteration did not converge")


def _solve_numpy(law, rec, speed, frame_velocity, t_case, steps, beta, t_max) -> GeneralOutcome:
    """The numpy march for a law without a kernel: cases grouped by contact time, each group
    with one step."""
    ncase = speed.size
    groups = _groups(t_case)
    if len(groups) > 1:
        parts = [
            _solve_numpy(
                per_case(law, ncase, idx),
                per_case(rec, ncase, idx),
                speed[idx],
                None if frame_velocity is None else frame_velocity[idx],
                t_case[idx],
                steps,
                beta,
                t_max,
            )
            for idx in groups
        ]
        return _merge(parts, groups, ncase)
    t_est = float(np.min(t_case))
    t_max = LIMIT * t_est if t_max is None else check_positive("t_max", t_max, "s")
    omega_c = contact_frequency(t_case, getattr(law, "exponent", 1.0))
    h = t_est / steps
    span = min(SPAN * t_est, t_max)
    while True:
        out = march(law, rec, speed, frame_velocity, omega_c, beta, span, h, ncase <= WHOLE)
        if out is not None:
            return out
        if span >= t_max:
            from fem_racket.impact.system import no_separation

            raise no_separation(t_max)
        span = min(2.0 * span, t_max)


def settings(
    tolerance: float | None, steps: int | None = None, beta: float | None = None
) -> tuple[int, float]:
    """Steps per contact time and cut-off factor for a COR ``tolerance``.

    The modes follow the engine's rule (:func:`fem_racket.impact.reduction.cutoff_factor`, its
    "displacement" calibration, with the law's contact frequency pi / t_c); the step count is
    (:data:`STEP_ERROR` / tolerance)^(1/4). Given ``steps`` or ``beta`` take precedence.
    """
    tol = check_tolerance(tolerance)
    if steps is None:
        steps = 800 if tol is None else int(np.ceil((STEP_ERROR / tol) ** 0.25))
    check_integer("steps", steps, 10)
    if beta is None:
        beta = cutoff_factor(tol)
    elif beta != math.inf:
        beta = check_positive("beta", beta)
    return int(steps), float(beta)


def _groups(t_case: np.ndarray) -> list[np.ndarray]:
    """Case indices grouped by estimated contact time (within :data:`GROUP_RATIO`)."""
    order = np.argsort(t_case, kind="stable")
    groups, start = [], 0
    for k in range(1, order.size + 1):
        if k == order.size or t_case[order[k]] > GROUP_RATIO * t_case[order[start]]:
            groups.append(np.sort(order[start:k]))
            start = k
    return groups


def _merge(parts: list[GeneralOutcome], groups: list[np.ndarray], ncase: int) -> GeneralOutcome:
    """One outcome from the groups' (histories padded with NaN to the longest)."""
    width = max(p.force.shape[1] for p in parts)
    out: dict[str, Any] = {}
    for name in ("contact_time", "ball_velocity", "impulse", "peak_force", "step", "fraction"):
        arr = np.empty(ncase)
        for p, idx in zip(parts, groups, strict=True):
            arr[idx] = getattr(p, name)
        out[name] = arr
    for name in ("last", "kept"):
        arr = np.empty(ncase, dtype=int)
        for p, idx in zip(parts, groups, strict=True):
            arr[idx] = getattr(p, name)
        out[name] = arr
    for name in ("force", "deflection", "rate", "state"):
        arr = np.full((ncase, width), np.nan)
        for p, idx in zip(parts, groups, strict=True):
            h = getattr(p, name)
            arr[idx, : h.shape[1]] = h
        out[name] = arr
    return GeneralOutcome(**out)
