"""The general integrator answers only what it can vouch for: step halving and energy balance.

Each case runs compiled (:mod:`fem_racket.impact.general.compiled`) at its own step
h = t_c / N (t_c the law's estimated contact time), and at 2 h and 4 h. N starts at the
tolerance's count times n^(1/8), n the law's exponent (:func:`first_steps`): a power law's
pulse is sharper by sqrt(n) near its peak, and the COR error at a given N grows with n
(measured at 1e-6, 400 impacts each: from N = 190, 73 % of the Hunt-Crossley default's
cases (n = 14.9) and 38 % of kawazoe-1997-nonlinear's (n = 8.9) were doubled; from 266 and
250, almost none). Where N starts changes only the cost and the last digits: every answer passes
the same rule. The last two CORs' difference d over 2^p - 1, p the order the three show (within
1-4), is the Richardson estimate of the finest one's error; twice it is the estimate used.
Irregular convergence (a stiff state, or kinks the frame's ringing repeats) shows a low order and
keeps the estimate near d itself. Since p >= 1, 2 d bounds the estimate: where 2 d is already
within the step's share the run at 4 h could not change the decision and is not made (the decision,
so the answer, is the full rule's, whatever the order). A case is accepted when

- the estimate is within the step's share of the COR tolerance (:data:`STEP_SHARE`; the rest
  is the mode cut-off's, calibrated by :func:`fem_racket.impact.reduction.cutoff_factor`),
- an ODE state is resolved: h |dz'/dz| <= :data:`STIFF_LIMIT` (Adams-Moulton 4 is stable on
  (-3, 0) of the real axis),
- the energy balance holds: the contact work int F delta' dt (fourth-order quadrature of the
  nodal F delta') equals the energy the ball and the frame lost (the impulse's rigid motion and
  the exact modal energies of the piecewise-cubic force's response) to the COR tolerance
  relative to the impact energy (the frame at rest before impact; a moving frame is checked by
  halving alone).

A case that fails runs again with N doubled (its runs at N and N/2 becoming the coarse ones), up
to :data:`MAX_DOUBLINGS` times and :data:`MAX_NODES` nodes; a case still not accepted is NaN,
never a number, and the caller refuses it.
"""

from __future__ import annotations

from dataclasses import dataclass, replace

import numpy as np

from fem_racket.impact.general.compiled import Checks, MarchCases, MarchOptions, march_compiled
from fem_racket.impact.general.march import GeneralOutcome
from fem_racket.impact.general.receptance import Receptance
from fem_racket.impact.general.step import per_case
from fem_racket.impact.general.stored import Stored
from fem_racket.validation import show

__all__ = [
    "MAX_DOUBLINGS",
    "STEP_SHARE",
    "STIFF_LIMIT",
    "Run",
    "energy_residual",
    "first_steps",
    "vouched",
]

#: Share of the COR tolerance given to the step (the rest: the mode cut-off's, whose
#: calibration integrator.settings asks for the remaining share).
STEP_SHARE = 0.75
#: Largest h |dz'/dz| of an ODE state accepted.
STIFF_LIMIT = 2.0
#: Times the step count of a case may be doubled.
MAX_DOUBLINGS = 6
#: Times a case may start again on a shorter contact-time estimate (an eighth each time the
#: contact equation cannot be solved), and the most nodes of one run.
MAX_RESTARTS = 2
MAX_NODES = 2**18


@dataclass(frozen=True, eq=False)
class Run:
    """What :func:`vouched` settled per case: steps per contact time (0: refused), the COR
    error estimate [-] and the energy residual [-] of the answer, h |dz'/dz| / STIFF_LIMIT
    (> 1: an unresolved state) and whether the ball was still in contact at t_max."""

    steps: np.ndarray
    estimate: np.ndarray
    residual: np.ndarray
    stiffness: np.ndarray
    no_separation: np.ndarray

    def refusal(self, i: int, tol: float, what: str) -> str:
        """One line: why case ``i`` (described by ``what``) was refused at ``tol``."""
        advice = "loosen the tolerance or use solver cvode"
        if not np.isfinite(self.estimate[i]):
            why = "its contact-law iteration did not converge"
            advice = "use solver cvode"
        elif self.stiffness[i] > 1.0:
            why = f"its state needs a {float(self.stiffness[i]):.3g} times finer step"
            advice = "use solver cvode"
        else:
            why = (
                f"the COR error estimate is {show(float(self.estimate[i]))} and the energy "
                f"residual {show(float(self.residual[i]))}"
            )
        return (
            f"tolerance = {show(tol)} could not be met for {what} by the general integrator "
            f"({why} at its finest step): {advice}"
        )


def energy_residual(chk: Checks, rec: Receptance, speed: np.ndarray) -> np.ndarray:
    """(contact work - energy lost by ball and frame) / impact energy up to the separation
    node (frame at rest before impact; the work, impulse and the modes' energy there from the
    march's :class:`~fem_racket.impact.general.compiled.Checks`)."""
    impulse = chk.node_impulse
    m = rec.ball_mass
    energy = 0.5 * m * speed**2
    ball = 0.5 * m * (speed - impulse / m) ** 2
    rigid = 0.5 * (rec.compliance - 1.0 / m) * impulse**2
    return (chk.work - (energy - ball - rigid - chk.flexible_energy)) / energy


def first_steps(steps: int, exponent: np.ndarray | float, ncase: int) -> np.ndarray:
    """Steps per contact time each case starts from: ``steps`` times n^(1/8) (n the law's
    exponent per case, at least 1; see the module docstring)."""
    n = np.broadcast_to(np.asarray(exponent, dtype=float), (ncase,))
    return np.ceil(steps * np.maximum(n, 1.0) ** 0.125).astype(int)


def _estimate(cors: np.ndarray) -> np.ndarray:
    """COR error estimate of the finest of three runs (C, 3) at N/4, N/2, N steps: twice the
    Richardson estimate d / (2^p - 1) for the last difference d, p the observed order (from
    the ratio of the two differences) within [1, 4]."""
    d1 = np.abs(cors[:, 2] - cors[:, 1])
    d2 = np.abs(cors[:, 1] - cors[:, 0])
    with np.errstate(divide="ignore", invalid="ignore"):
        p = np.clip(np.log2(d2 / d1), 1.0, 4.0)
    p = np.where(np.isfinite(p), p, np.where(d1 == 0.0, 4.0, 1.0))
    return np.where(np.all(np.isfinite(cors), 1), 2.0 * d1 / (2.0**p - 1.0), np.inf)


def vouched(
    cases: MarchCases,
    t_case: np.ndarray,
    steps: np.ndarray,
    tol: float,
    limits: tuple[np.ndarray, np.ndarray],
) -> tuple[list[GeneralOutcome], list[np.ndarray], Run, list[tuple[np.ndarray, Stored]]]:
    """Every case of ``cases`` at its ``steps`` per contact time ``t_case`` [s] (and a quarter
    and half of them), doubled until accepted.

    ``limits``: the first span and t_max per case [s]. Where the contact ends in less than a
    quarter of ``t_case`` (or the contact equation cannot be solved) the estimate is replaced
    by the contact time found (or an eighth of it) and the case starts again: the steps are
    set per contact time, so a law whose estimate is far too long (a ball much softer than its
    string bed) would otherwise be stepped too coarsely to resolve. Returns the outcomes and
    the case indices they hold (every case once; NaN where refused), the :class:`Run`, and the
    histories of the answers as stored (case indices,
    :class:`~fem_racket.impact.general.stored.Stored`).
    """
    speed = cases.speed
    ncase = speed.size
    span, t_max = limits[0].copy(), limits[1]
    cases = replace(cases, omega_c=cases.omega_c.copy())  # a restart rescales its omega_c
    t_case, omega_c = t_case.copy(), cases.omega_c
    n_case = np.broadcast_to(np.asarray(steps, dtype=int), (ncase,)).copy()
    est, res, stiff = np.full(ncase, np.inf), np.full(ncase, np.inf), np.zeros(ncase)
    stuck = np.zeros(ncase, dtype=bool)
    restarts = np.zeros(ncase, dtype=int)
    cors = np.full((ncase, 3), np.nan)
    moving = cases.frame_velocity is not None

    def run(idx, scale):
        sub = cases.take(idx)
        h = t_case[idx] / (n_case[idx] * scale)
        options = MarchOptions(histories=scale == 1.0)  # a coarse run: its COR alone
        return sub.rec, march_compiled(sub, h, span[idx], t_max[idx], options)

    quarter = np.zeros(ncase, dtype=bool)  # cors[:, 0] holds the run at a quarter of the steps

    def level(idx, k):  # the run at a quarter (k = 0) or half (k = 1) of the steps
        cors[idx, k] = -run(idx, 0.25 * (k + 1))[1][0].ball_velocity / speed[idx]
        quarter[idx] = k == 0

    todo = np.arange(ncase)
    level(todo, 1)
    parts, where, histories = [], [], []
    for doubling in range(MAX_DOUBLINGS + 1):
        sub, (out, chk, status, stored) = run(todo, 1.0)
        cors[todo, 2] = -out.ball_velocity / speed[todo]
        short = ((status == 0) & (out.contact_time < 0.25 * t_case[todo])) | (status == 2)
        # twice the last difference bounds the estimate at any order p >= 1: where it passes,
        # the run at a quarter of the steps would change nothing and is not made
        bound = 2.0 * np.abs(cors[todo, 2] - cors[todo, 1])
        lacking = todo[(status == 0) & ~quarter[todo] & ~(bound <= STEP_SHARE * tol)]
        if lacking.size:
            level(lacking, 0)
        e = np.where(quarter[todo], _estimate(cors[todo]), bound)
        e = np.where(status == 0, e, np.inf)
        r = np.zeros(todo.size) if moving else energy_residual(chk, sub, speed[todo])
        est[todo], res[todo], stiff[todo] = e, r, chk.stiffness / STIFF_LIMIT
        ok = (e <= STEP_SHARE * tol) & (chk.stiffness <= STIFF_LIMIT) & (np.abs(r) <= tol)
        ok &= ~short & np.isfinite(cors[todo, 2])
        stuck[todo] = status == 1
        over = restarts[todo] + short > MAX_RESTARTS  # the contact time keeps shrinking
        over |= span[todo] * n_case[todo] / t_case[todo] > MAX_NODES / 2  # no finer step
        done = ok | (status == 1) | over | (doubling == MAX_DOUBLINGS)
        if not np.all(ok[done]):
            out = _refuse(out, ~ok)
        parts.append(per_case(out, todo.size, np.flatnonzero(done)))
        where.append(todo[done])
        histories.append((todo[done], stored.take(np.flatnonzero(done))))
        n_case[todo[done & ~ok]] = 0
        if np.all(done):
            break
        again = todo[~done & short]  # the contact-time estimate was far too long
        restarts[again] += 1
        found = np.where(status == 2, t_case[todo] / 8.0, out.contact_time)[~done & short]
        omega_c[again] *= t_case[again] / found
        span[again] = np.minimum(span[again] * found / t_case[again], t_max[again])
        t_case[again] = found
        finer = todo[~done & ~short]
        n_case[finer] *= 2
        cors[finer, :2] = cors[finer, 1:]
        quarter[finer] = True
        if again.size:
            level(again, 1)
        todo = todo[~done]
    return parts, where, Run(n_case, est, res, stiff, stuck), histories


def _refuse(out: GeneralOutcome, bad: np.ndarray) -> GeneralOutcome:
    """The outcome with NaN answers for the cases ``bad``."""
    from dataclasses import replace

    nan = {
        k: np.where(bad, np.nan, getattr(out, k))
        for k in ("contact_time", "ball_velocity", "impulse", "peak_force")
    }
    return replace(out, **nan)
