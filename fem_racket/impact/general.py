"""A fast general integrator for any contact law: the frame as an impact-point receptance.

The frame is linear, so the contact force F(t) is the only unknown: the deflection at the
contact is a Volterra integral of F over the frame's receptance
(:mod:`fem_racket.impact.receptance`). F is a piecewise cubic on a uniform grid
(:mod:`fem_racket.impact.cubic_force`, fourth order), every mode responds to it exactly, and
each node solves only the contact equation ``F_m = law(delta_m(F_m), delta'_m(F_m), z)``
(:mod:`fem_racket.impact.general_step`; the march: :mod:`fem_racket.impact.general_march`).
Flexible modes above ``beta`` times the contact frequency pi / t_c (t_c the law's estimate) are
replaced by one residual pseudo-mode per case, by the engine's rule
(:func:`fem_racket.impact.reduction.split_modes`). Many cases (positions, speeds, law
parameters) advance together as arrays; separation is found per case on the law's own end
condition (deflection falling through its end value, or the force or the law state through
zero) inside its step.

Accuracy (``scripts/bench_laws.py`` and ``tests/impact/test_general.py``, against CVODE with
:mod:`fem_racket.impact.law_cvode`): fourth order in the step wherever the force is smooth; the
hysteresis turning point (a jump in F'' located inside its step) and the first step of a law
whose force jumps at contact keep it at that order in practice (measured).
"""

from __future__ import annotations

import logging
from dataclasses import fields, replace
from typing import Any

import numpy as np

from fem_racket.contact.law import ContactLaw
from fem_racket.impact.general_march import GeneralOutcome, march
from fem_racket.impact.receptance import Receptance
from fem_racket.impact.reduction import contact_frequency
from fem_racket.validation import check_integer, check_positive

__all__ = ["DEFAULT_BETA", "DEFAULT_STEPS", "GeneralOutcome", "solve_general"]

log = logging.getLogger(__name__)

#: Time steps per estimated contact time.
DEFAULT_STEPS = 50
#: Flexible modes above beta x the contact frequency become one residual pseudo-mode.
DEFAULT_BETA = 50.0
#: First integration span as a multiple of the estimated contact time (doubled while some case
#: has not separated, up to t_max).
SPAN = 2.0
#: Cases whose estimated contact times differ by more than this factor run in separate groups
#: (each with its own step), so a batch never takes the shortest case's step for all.
GROUP_RATIO = 1.3
#: Default t_max as a multiple of the estimated contact time.
LIMIT = 16.0


def solve_general(
    law: ContactLaw,
    rec: Receptance,
    speed: Any,
    *,
    frame_velocity: np.ndarray | None = None,
    steps: int = DEFAULT_STEPS,
    beta: float | None = DEFAULT_BETA,
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
    steps : int
        Time steps per estimated contact time (the step is shared by a group of cases).
    beta : float or None
        Keep flexible modes below beta x pi / t_c (the rest: one pseudo-mode); None keeps all.
    t_max : float, optional
        Give up at this time [s]; 16 x the estimated contact time by default.

    Returns
    -------
    GeneralOutcome
    """
    check_integer("steps", steps, 10)
    beta = np.inf if beta is None else check_positive("beta", beta)
    ncase = rec.a.shape[0]
    speed = np.broadcast_to(np.asarray(speed, dtype=float), (ncase,)).copy()
    t_case = np.broadcast_to(
        law.contact_time_estimate(1.0 / rec.compliance, np.abs(speed)), (ncase,)
    )
    groups = _groups(t_case)
    if len(groups) > 1:
        parts = [
            solve_general(
                _subset(law, idx, ncase),
                _subset(rec, idx, ncase),
                speed[idx],
                frame_velocity=None if frame_velocity is None else frame_velocity[idx],
                steps=steps,
                beta=beta,
                t_max=t_max,
            )
            for idx in groups
        ]
        return _merge(parts, groups, ncase)
    t_est = float(np.min(t_case))
    t_max = LIMIT * t_est if t_max is None else check_positive("t_max", t_max, "s")
    omega_c = contact_frequency(t_case)
    h = t_est / steps
    span = min(SPAN * t_est, t_max)
    while True:
        out = march(law, rec, speed, frame_velocity, omega_c, beta, span, h)
        if out is not None:
            return out
        if span >= t_max:
            from fem_racket.impact.system import no_separation

            raise no_separation(t_max)
        span = min(2.0 * span, t_max)


def _groups(t_case: np.ndarray) -> list[np.ndarray]:
    """Case indices grouped by estimated contact time (within :data:`GROUP_RATIO`)."""
    order = np.argsort(t_case, kind="stable")
    groups, start = [], 0
    for k in range(1, order.size + 1):
        if k == order.size or t_case[order[k]] > GROUP_RATIO * t_case[order[start]]:
            groups.append(np.sort(order[start:k]))
            start = k
    return groups


def _subset(obj: Any, idx: np.ndarray, ncase: int) -> Any:
    """A law or receptance with its per-case array fields cut to the cases ``idx``."""
    cut = {}
    for f in fields(obj):
        value = getattr(obj, f.name)
        if np.ndim(value) > 0 and np.shape(value)[0] == ncase and f.name != "omega":
            cut[f.name] = np.asarray(value)[idx]
    return replace(obj, **cut)


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


