"""A fast general integrator for any contact law: the frame as an impact-point receptance.

The frame is linear, so with the contact force F(t) the only unknown, the deflection at the
contact is a Volterra integral of F (free-free modal superposition)::

    delta(t)  = delta_free(t)  - int_0^t K(t - s) F(s) ds
    K(tau)    = (1/m_B + sum_rigid a_r^2) tau + sum_j a_j^2 sin(omega_j tau) / omega_j

(a_j: mass-normalised mode shapes at the impact point; delta_free: the ball's and the frame's
motion without contact, e.g. a swinging racket). With F piecewise linear on a uniform grid of step
h (first-order hold) every mode's response is exact, and the kernel weights of a unit hat function
are closed forms (:mod:`fem_racket.impact.receptance`), so each step solves only the scalar
contact equation ``F_m = law(delta_m(F_m), delta'_m(F_m), z)``
(delta_m affine in F_m; Newton on one unknown, or two with an ODE state advanced by the
trapezoidal rule). Flexible modes above ``beta`` times the contact frequency pi / t_c are replaced
by one residual pseudo-mode per case with their static flexibility sum a^2/omega^2 and their
mobility sum a^2 (DESIGN section 9: 10-100x smaller error than plain truncation). The scheme is
second order in h, so by default a run with 2x the steps is Richardson-extrapolated with it
(the turning point of a hysteresis loop is located inside its step by the cubic Hermite
interpolant of delta, which keeps the error expansion smooth). Errors are measured against
CVODE (:mod:`fem_racket.impact.law_cvode`) by ``scripts/bench_laws.py`` and the tests. Many
cases (positions, speeds, law parameters) advance together as arrays; separation is found per
case on the law's own end condition (deflection falling through its end value: cubic Hermite
root in the last step; or the force or the law state through zero).
"""

from __future__ import annotations

import logging
from dataclasses import dataclass, replace
from typing import Any

import numpy as np

from fem_racket.contact.law import ContactLaw
from fem_racket.impact.receptance import Receptance, free_motion, kernels
from fem_racket.validation import check_integer, check_positive

__all__ = ["DEFAULT_BETA", "DEFAULT_STEPS", "GeneralOutcome", "solve_general"]

log = logging.getLogger(__name__)

#: Time steps per estimated contact time of the coarse run (the fine run takes twice as many);
#: with extrapolation |dCOR| ~ 1e-6 on the paper's racket (scripts/bench_laws.py).
DEFAULT_STEPS = 100
#: Flexible modes above beta x the contact frequency become one residual pseudo-mode.
DEFAULT_BETA = 50.0
#: First integration span as a multiple of the estimated contact time (doubled while some case
#: has not separated, up to t_max).
SPAN = 3.0
#: Cases whose estimated contact times differ by more than this factor run in separate groups
#: (each with its own step), so a batch never takes the shortest case's step for all.
GROUP_RATIO = 1.3
#: Default t_max as a multiple of the estimated contact time.
LIMIT = 16.0
_NEWTON_ITER = 40


@dataclass(frozen=True, eq=False)
class GeneralOutcome:
    """Per-case results of :func:`solve_general` (arrays of shape (C,), histories (C, N)).

    Attributes
    ----------
    contact_time : ndarray
        t_c [s].
    ball_velocity : ndarray
        Ball velocity at separation [m/s] (negative: rebounding).
    impulse : ndarray
        int F dt over the contact [N s].
    peak_force : ndarray
        Largest contact force [N].
    step : ndarray
        Time step h of each case [s] (cases with similar contact times share one).
    force, deflection, rate, state : ndarray, shape (C, N)
        F [N], delta [m], delta' [m/s] and the law's state [m] at t = m h (valid up to each
        case's separation step ``last``).
    last : ndarray of int
        Index of the step in which each case separated.
    fraction : ndarray
        Where in that step it separated (0-1].
    coarse : GeneralOutcome or None
        The run with half the steps, when the scalars were extrapolated.
    """

    contact_time: np.ndarray
    ball_velocity: np.ndarray
    impulse: np.ndarray
    peak_force: np.ndarray
    step: np.ndarray
    force: np.ndarray
    deflection: np.ndarray
    rate: np.ndarray
    state: np.ndarray
    last: np.ndarray
    fraction: np.ndarray
    coarse: GeneralOutcome | None = None


def _turn_max(d0, v0, d1, v1, h) -> np.ndarray:
    """Largest delta on the step (cubic Hermite through the ends' delta and delta')."""
    turn = (v0 > 0) & (v1 <= 0)
    if not turn.any():
        return np.maximum(d0, d1)
    m0, m1, dd = h * v0, h * v1, d0 - d1
    qa = 6.0 * dd + 3.0 * m0 + 3.0 * m1
    qb = -6.0 * dd - 4.0 * m0 - 2.0 * m1
    disc = np.sqrt(np.maximum(qb * qb - 4.0 * qa * m0, 0.0))
    # the root of p'(s) = qa s^2 + qb s + m0 where p' falls from m0 > 0 (stable form)
    den = -qb + disc
    s = np.clip(2.0 * m0 / np.where(den > 0, den, 1.0), 0.0, 1.0)
    s2, s3 = s * s, s * s * s
    p = (2 * s3 - 3 * s2 + 1) * d0 + (s3 - 2 * s2 + s) * m0 + (-2 * s3 + 3 * s2) * d1
    p += (s3 - s2) * m1
    return np.where(turn, np.maximum(p, np.maximum(d0, d1)), np.maximum(d0, d1))


def _solve_step(
    law: ContactLaw,
    A: np.ndarray,
    B: np.ndarray,
    kd0: np.ndarray,
    kv0: np.ndarray,
    guess: np.ndarray,
    z_prev: np.ndarray,
    g_prev: np.ndarray,
    h: float,
    scale: np.ndarray,
    start: tuple[np.ndarray, np.ndarray],
) -> tuple[np.ndarray, np.ndarray]:
    """Newton on F (and an ODE state z by the trapezoidal rule) for one step of every case.

    A memory state is the largest deflection up to the step's end, including a turning point
    inside the step (``start`` = delta, delta' at the step's start); it is refreshed every
    iteration (a fixed point: it moves the turn's branch point by O(h^4) only).
    """
    F = guess.copy()
    ode = law.state == "ode"
    memory = law.state == "memory"
    z = z_prev
    for _ in range(_NEWTON_ITER):
        d = A - kd0 * F
        v = B - kv0 * F
        if memory:
            z = np.maximum(z_prev, _turn_max(start[0], start[1], d, v, h))
        r1 = F - law.force(d, v, z)
        tol = 1e-12 * (np.abs(F) + scale)
        if ode:
            r2 = z - z_prev - 0.5 * h * (g_prev + law.rate(d, v, z))
            if np.all(np.abs(r1) <= tol) and np.all(np.abs(r2) <= 1e-12 * (np.abs(z) + 1e-9)):
                break
            fd, fv, fz = law.partials(d, v, z)
            gd, gv, gz = law.rate_partials(d, v, z)
            j11 = 1.0 + fd * kd0 + fv * kv0
            j21 = 0.5 * h * (gd * kd0 + gv * kv0)
            j22 = 1.0 - 0.5 * h * gz
            det = j11 * j22 + fz * j21
            dF = -(r1 * j22 + fz * r2) / det
            z = z - (j11 * r2 - j21 * r1) / det
        else:
            if np.all(np.abs(r1) <= tol):
                break
            fd, fv, _ = law.partials(d, v, z)
            dF = -r1 / (1.0 + fd * kd0 + fv * kv0)
        # damped update: a step at most doubles the force scale (hardening laws overshoot)
        cap = 2.0 * (np.abs(F) + scale)
        F = F + np.maximum(np.minimum(dF, cap), -cap)
    else:
        raise RuntimeError("contact-law Newton iteration did not converge")
    return F, z


def _hermite_root(d0, v0, d1, v1, end, h) -> np.ndarray:
    """Fraction s in (0, 1] where the cubic Hermite interpolant of delta reaches ``end``."""
    p0, p1, m0, m1 = d0 - end, d1 - end, h * v0, h * v1
    s = np.clip(p0 / np.where(p0 - p1 > 0, p0 - p1, 1.0), 0.0, 1.0)
    for _ in range(8):
        s2, s3 = s * s, s * s * s
        f = (2 * s3 - 3 * s2 + 1) * p0 + (s3 - 2 * s2 + s) * m0 + (-2 * s3 + 3 * s2) * p1
        f += (s3 - s2) * m1
        df = (6 * s2 - 6 * s) * (p0 - p1) + (3 * s2 - 4 * s + 1) * m0 + (3 * s2 - 2 * s) * m1
        s = np.clip(s - f / np.where(df != 0, df, -1.0), 0.0, 1.0)
    return np.where(p1 >= 0, 1.0, s)


def solve_general(
    law: ContactLaw,
    rec: Receptance,
    speed: Any,
    *,
    frame_velocity: np.ndarray | None = None,
    steps: int = DEFAULT_STEPS,
    beta: float | None = DEFAULT_BETA,
    extrapolate: bool = True,
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
        Time steps per estimated contact time (the step is shared by the batch).
    beta : float or None
        Keep flexible modes below beta x pi / t_c (the rest: one pseudo-mode); None keeps all.
    extrapolate : bool
        Also run with 2 x ``steps`` and Richardson-extrapolate the scalar outcomes
        ((4 fine - coarse) / 3: the scheme is second order); histories are the fine run's.
    t_max : float, optional
        Give up at this time [s]; 16 x the estimated contact time by default.

    Returns
    -------
    GeneralOutcome
    """
    check_integer("steps", steps, 10)
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
                extrapolate=extrapolate,
                t_max=t_max,
            )
            for idx in groups
        ]
        return _merge(parts, groups, ncase)
    t_est = float(np.min(t_case))
    t_max = LIMIT * t_est if t_max is None else check_positive("t_max", t_max, "s")
    keep = np.ones(rec.omega.size, bool)
    if beta is not None:
        keep = rec.omega < check_positive("beta", beta) * np.pi / t_est

    def run(h: float) -> GeneralOutcome:
        span = min(SPAN * t_est, t_max)
        while True:
            out = _integrate(law, rec, speed, frame_velocity, keep, span, h)
            if out is not None:
                return out
            if span >= t_max:
                from fem_racket.impact.system import no_separation

                raise no_separation(t_max)
            span = min(2.0 * span, t_max)

    if not extrapolate:
        return run(t_est / steps)
    coarse = run(t_est / steps)
    fine = run(t_est / (2 * steps))

    def rich(name: str) -> np.ndarray:
        return (4.0 * getattr(fine, name) - getattr(coarse, name)) / 3.0

    return replace(
        fine,
        contact_time=rich("contact_time"),
        ball_velocity=rich("ball_velocity"),
        impulse=rich("impulse"),
        peak_force=rich("peak_force"),
        coarse=coarse,
    )


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
    from dataclasses import fields

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
    last = np.empty(ncase, dtype=int)
    for p, idx in zip(parts, groups, strict=True):
        last[idx] = p.last
    for name in ("force", "deflection", "rate", "state"):
        arr = np.full((ncase, width), np.nan)
        for p, idx in zip(parts, groups, strict=True):
            h = getattr(p, name)
            arr[idx, : h.shape[1]] = h
        out[name] = arr
    return GeneralOutcome(last=last, **out)


def _integrate(
    law: ContactLaw,
    rec: Receptance,
    speed: np.ndarray,
    frame_velocity: np.ndarray | None,
    keep: np.ndarray,
    span: float,
    h: float,
) -> GeneralOutcome | None:
    """One run of the scheme with step ``h`` [s] up to ``span`` [s] (None: some case is still in
    contact at ``span``)."""
    ncase = rec.a.shape[0]
    meff = 1.0 / rec.compliance
    nsteps = int(np.ceil(span / h)) + 1
    Kd, Kv, Hd, Hv = kernels(rec, keep, h, nsteps)
    t = np.arange(nsteps) * h
    dfree, vfree = free_motion(rec, speed, frame_velocity, t)

    F = np.zeros((ncase, nsteps))
    D = np.zeros((ncase, nsteps))
    V = np.zeros((ncase, nsteps))
    Z = np.zeros((ncase, nsteps))
    D[:, 0], V[:, 0] = dfree[:, 0], vfree[:, 0]
    z = np.zeros(ncase)
    F[:, 0] = law.force(D[:, 0], V[:, 0], z)
    g = law.rate(D[:, 0], V[:, 0], z) if law.state == "ode" else z
    scale = meff * np.abs(speed) / span
    end_kind = law.end
    last = np.full(ncase, -1)
    frac = np.ones(ncase)
    kd0, kv0 = Kd[:, 0], Kv[:, 0]
    for m in range(1, nsteps):
        hist_d = Hd[:, m] * F[:, 0] + np.einsum("ij,ij->i", Kd[:, m - 1 : 0 : -1], F[:, 1:m])
        hist_v = Hv[:, m] * F[:, 0] + np.einsum("ij,ij->i", Kv[:, m - 1 : 0 : -1], F[:, 1:m])
        A = dfree[:, m] - hist_d
        B = vfree[:, m] - hist_v
        guess = 2.0 * F[:, m - 1] - F[:, m - 2] if m > 1 else F[:, 0]
        Fm, zm = _solve_step(law, A, B, kd0, kv0, guess, z, g, h, scale, (D[:, m - 1], V[:, m - 1]))
        d, v = A - kd0 * Fm, B - kv0 * Fm
        if law.state == "memory":
            zm = np.maximum(z, _turn_max(D[:, m - 1], V[:, m - 1], d, v, h))
        elif law.state == "ode":
            g = law.rate(d, v, zm)
        F[:, m], D[:, m], V[:, m], Z[:, m], z = Fm, d, v, zm, zm
        open_ = last < 0
        if end_kind in ("force", "state"):
            e0, e1 = (F[:, m - 1], Fm) if end_kind == "force" else (Z[:, m - 1], zm)
            ended = open_ & (e0 > 0) & (e1 <= 0)
            s = e0 / np.where(ended, e0 - e1, 1.0)
        else:
            end = law.end_deflection(zm)
            ended = open_ & (D[:, m - 1] - end > 0) & (d - end <= 0)
            s = frac.copy()
            if ended.any():
                k = np.flatnonzero(ended)
                end_k = np.broadcast_to(end, d.shape)[k]
                s[k] = _hermite_root(D[k, m - 1], V[k, m - 1], d[k], v[k], end_k, h)
        last = np.where(ended, m, last)
        frac = np.where(ended, s, frac)
        if np.all(last >= 0):
            break
    else:
        return None
    idx = np.arange(ncase)
    f_prev = F[idx, last - 1]
    f_end = f_prev + frac * (F[idx, last] - f_prev)
    mask = np.arange(nsteps)[None, :] < last[:, None]
    trap = h * (np.sum(np.where(mask, F, 0.0), axis=1) - 0.5 * F[:, 0] - 0.5 * f_prev)
    impulse = trap + 0.5 * frac * h * (f_prev + f_end)
    peak = np.max(np.where(np.arange(nsteps)[None, :] <= last[:, None], F, -np.inf), axis=1)
    return GeneralOutcome(
        contact_time=(last - 1 + frac) * h,
        ball_velocity=speed - impulse / rec.ball_mass,
        impulse=impulse,
        peak_force=peak,
        step=np.full(ncase, h),
        force=F[:, : last.max() + 1],
        deflection=D[:, : last.max() + 1],
        rate=V[:, : last.max() + 1],
        state=Z[:, : last.max() + 1],
        last=last,
        fraction=frac,
    )
