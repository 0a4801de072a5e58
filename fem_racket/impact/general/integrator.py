"""A fast general integrator for any contact law: the frame as an impact-point receptance.

The frame is linear, so the contact force F(t) is the only unknown: the deflection at the
contact is a Volterra integral of F over the frame's receptance
(:mod:`fem_racket.impact.general.receptance`). F is a piecewise cubic on a uniform grid
(:mod:`fem_racket.impact.general.cubic_force`, fourth order), every mode responds to it exactly, and
each node solves only the contact equation ``F_m = law(delta_m(F_m), delta'_m(F_m), z)``
(:mod:`fem_racket.impact.general.step`; the march: :mod:`fem_racket.impact.general.march`).
Flexible modes above ``beta`` times the contact frequency pi / t_c (t_c the law's estimate) are
replaced by one residual pseudo-mode per case, by the engine's rule
(:func:`fem_racket.impact.reduction.split_modes`). Many cases (positions, speeds, law
parameters) advance together as arrays; separation is found per case on the law's own end
condition (deflection falling through its end value, or the force or the law state through
zero) inside its step.

A COR tolerance sets the step count and the mode cut-off (:func:`settings`). Single impacts
solve every node at once (:mod:`fem_racket.impact.general.nodes`), batches march node by node
vectorised across cases. Accuracy (``scripts/bench_laws.py`` and
``tests/impact/general/test_general.py``, against CVODE, :mod:`fem_racket.impact.ode.law_cvode`):
fourth
order in the step where the force is smooth (Hunt-Crossley, hysteretic n = 8.9, series). Two
things limit it: a force with a jump or kink at contact (the linear spring-dashpot's C v0, the
hysteretic law with n = 1) rings with the frame modes above 1/h, which the cubic force aliases,
and the jump in F'' at each turning point of a hysteresis loop; both are within the tolerance
for the laws measured, the hysteretic law with linear branches within twice it.
"""

from __future__ import annotations

import logging
import math
from typing import Any

import numpy as np

from fem_racket.contact.law import ContactLaw
from fem_racket.impact.general.march import GeneralOutcome, march
from fem_racket.impact.general.receptance import Receptance, free_motion
from fem_racket.impact.general.step import per_case
from fem_racket.impact.reduction import (
    DEFAULT_TOLERANCE,
    check_tolerance,
    contact_frequency,
    cutoff_factor,
)
from fem_racket.validation import check_integer, check_positive

__all__ = ["STEP_ERROR", "GeneralOutcome", "settings", "solve_general"]

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
) -> GeneralOutcome:
    """Integrate a batch of impacts until each ball separates.

    Parameters
    ----------
    law : ContactLaw
        The ball/string law (parameters float, or arrays of shape (C,) for per-case values).
    rec : Receptance
        The frame at each case's impact point.
    speed : float or ndarray, shape (C,)
        Ball speed towards the frame at t = 0 [m/s] (relative to the frame's rest state).
    frame_velocity : ndarray, shape (C, 2 + n), optional
        Initial modal velocities of the frame (rigid translation and rotation about the CG first,
        then the flexible modes of ``rec.omega``) [sqrt(kg) m/s]; at rest when None. Positive
        moves the frame along the ball's travel (away from the ball).
    tolerance : float or None
        COR tolerance [-] setting ``steps`` and ``beta`` when they are not given
        (:func:`settings`); None (or 0): every mode, 800 steps.
    steps : int, optional
        Time steps per estimated contact time (the step is shared by a group of cases).
    beta : float, optional
        Keep flexible modes below beta x pi / t_c (the rest: one pseudo-mode; inf keeps all).
    t_max : float, optional
        Give up at this time [s]; 16 x the estimated contact time by default.

    Returns
    -------
    GeneralOutcome
    """
    steps, beta = settings(tolerance, steps, beta)
    ncase = rec.a.shape[0]
    speed = np.broadcast_to(np.asarray(speed, dtype=float), (ncase,)).copy()
    closing = speed  # ball against the frame's impact point at t = 0 [m/s]
    if frame_velocity is not None:
        closing = free_motion(rec, speed, frame_velocity, np.zeros(1))[1][:, 0]
    t_case = np.broadcast_to(
        law.contact_time_estimate(1.0 / rec.compliance, np.abs(closing)), (ncase,)
    )
    groups = _groups(t_case)
    if len(groups) > 1:
        parts = [
            solve_general(
                per_case(law, ncase, idx),
                per_case(rec, ncase, idx),
                speed[idx],
                frame_velocity=None if frame_velocity is None else frame_velocity[idx],
                tolerance=tolerance,
                steps=steps,
                beta=beta,
                t_max=t_max,
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
