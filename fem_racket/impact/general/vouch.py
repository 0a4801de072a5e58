"""The general integrator answers only what it can vouch for: step halving and energy balance.

Each case runs compiled (:mod:`fem_racket.impact.general.compiled`) at its own step
h = t_c / N (t_c the law's estimated contact time) and at 2 h. The difference of the two CORs
estimates the error of the finer one: for the fourth-order scheme in its asymptotic range it
overstates it ~15 times, and where the convergence is irregular (the kinks of exponent n = 1
laws, which the frame's ringing repeats; a stiff state) it is of the error's own size. A case
is accepted when

- the estimate is within the step's share of the COR tolerance (:data:`STEP_SHARE`; the rest
  is the mode cut-off's, calibrated by :func:`fem_racket.impact.reduction.cutoff_factor`),
- an ODE state is resolved: h |dz'/dz| <= :data:`STIFF_LIMIT` (Adams-Moulton 4 is stable on
  (-3, 0) of the real axis),
- the energy balance holds: the contact work int F delta' dt (fourth-order quadrature of the
  nodal F delta') equals the energy the ball and the frame lost (the impulse's rigid motion and
  the exact modal energies of the piecewise-cubic force's response) to the COR tolerance
  relative to the impact energy (the frame at rest before impact; a moving frame is checked by
  halving alone).

A case that fails runs again with N doubled (its last run becomes the coarse one), up to
:data:`MAX_DOUBLINGS` times; a case still not accepted is NaN, never a number, and the caller
refuses it.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from fem_racket.impact.general.compiled import KernelLaw, march_compiled
from fem_racket.impact.general.cubic_force import BACKWARD, ORDER, step_stencil
from fem_racket.impact.general.march import GeneralOutcome
from fem_racket.impact.general.receptance import Receptance, stencil_quadrature
from fem_racket.impact.general.step import per_case
from fem_racket.validation import show

__all__ = ["MAX_DOUBLINGS", "STEP_SHARE", "STIFF_LIMIT", "Run", "energy_residual", "vouched"]

#: Share of the COR tolerance given to the step (the rest: the mode cut-off's).
STEP_SHARE = 0.5
#: Largest h |dz'/dz| of an ODE state accepted.
STIFF_LIMIT = 2.0
#: Times the step count of a case may be doubled.
MAX_DOUBLINGS = 6


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
        if not np.isfinite(self.estimate[i]):
            why = "its contact-law iteration did not converge"
        elif self.stiffness[i] > 1.0:
            why = f"its state needs a {show(float(self.stiffness[i]))} times finer step"
        else:
            why = (
                f"the COR error estimate is {show(float(self.estimate[i]))} and the energy "
                f"residual {show(float(self.residual[i]))}"
            )
        return (
            f"tolerance = {show(tol)} could not be met for {what} by the general integrator "
            f"({why} at {2**MAX_DOUBLINGS} times its first step count): loosen the tolerance "
            "or use solver cvode"
        )


def _step_integrals(X: np.ndarray, h: np.ndarray) -> np.ndarray:
    """int over each step of the cubic through the nodal values X (C, N): (C, N - 1)."""
    ncase, n = X.shape
    out = np.zeros((ncase, n - 1))
    for k in (0, 1):
        off = step_stencil(k)
        out[:, k] = h * (X[:, [k + o for o in off]] @ stencil_quadrature(off))
    qb = stencil_quadrature(BACKWARD)
    out[:, 2:] = h[:, None] * sum(qb[r] * X[:, r : n - 3 + r] for r in range(ORDER))
    return out


def energy_residual(out: GeneralOutcome, flexible: np.ndarray, rec: Receptance, speed):
    """(contact work - energy lost by ball and frame) / impact energy up to the separation
    node (frame at rest before impact; ``flexible``: the modes' energy there [J])."""
    pad = max(ORDER + 1 - out.force.shape[1], 0)  # a contact ended within the first steps
    F, V = (np.pad(x, ((0, 0), (0, pad))) for x in (out.force, out.rate))
    upto = np.arange(F.shape[1] - 1)[None, :] < out.last[:, None]
    work = np.sum(np.where(upto, _step_integrals(F * V, out.step), 0.0), 1)
    impulse = np.sum(np.where(upto, _step_integrals(F, out.step), 0.0), 1)
    m = rec.ball_mass
    energy = 0.5 * m * speed**2
    ball = 0.5 * m * (speed - impulse / m) ** 2
    rigid = 0.5 * (rec.compliance - 1.0 / m) * impulse**2
    return (work - (energy - ball - rigid - flexible)) / energy


def _judge(fine, coarse, rec, speed, tol, moving):
    """Accepted cases, their estimates and energy residuals."""
    out, chk, status = fine
    cor = -out.ball_velocity / speed
    est = np.abs(cor + coarse[0].ball_velocity / speed)
    est = np.where((status == 0) & (coarse[2] == 0), est, np.inf)
    res = np.zeros(speed.size) if moving else energy_residual(out, chk.flexible_energy, rec, speed)
    ok = (est <= STEP_SHARE * tol) & (chk.stiffness <= STIFF_LIMIT) & (np.abs(res) <= tol)
    return ok & np.isfinite(cor), est, res, status == 1


def vouched(
    law: KernelLaw,
    rec: Receptance,
    speed: np.ndarray,
    frame_velocity: np.ndarray | None,
    omega_c: np.ndarray,
    beta: float,
    t_case: np.ndarray,
    steps: int,
    tol: float,
    limits: tuple[np.ndarray, np.ndarray],
) -> tuple[list[GeneralOutcome], list[np.ndarray], Run]:
    """Every case at ``steps`` per contact time ``t_case`` [s], doubled until accepted.

    ``limits``: the first span and t_max per case [s]. Returns the outcomes and the case
    indices they hold (every case once; NaN where refused) and the :class:`Run`.
    """
    ncase = speed.size
    span, t_max = limits
    n_case = np.full(ncase, int(steps))
    est, res, stiff = np.full(ncase, np.inf), np.full(ncase, np.inf), np.zeros(ncase)
    stuck = np.zeros(ncase, dtype=bool)
    todo = np.arange(ncase)

    def run(idx, h):
        sub = per_case(rec, ncase, idx)
        fv = None if frame_velocity is None else frame_velocity[idx]
        return march_compiled(law, sub, speed[idx], fv, omega_c[idx], beta, h, span[idx],
                              t_max[idx])  # fmt: skip

    coarse = run(todo, 2.0 * t_case / steps)
    fine = run(todo, t_case / steps)
    parts, where = [], []
    for doubling in range(MAX_DOUBLINGS + 1):
        sub = per_case(rec, ncase, todo)
        ok, e, r, open_ = _judge(fine, coarse, sub, speed[todo], tol, frame_velocity is not None)
        est[todo], res[todo], stiff[todo] = e, r, fine[1].stiffness / STIFF_LIMIT
        stuck[todo] = open_
        done = ok | open_ | (doubling == MAX_DOUBLINGS)
        out = fine[0]
        if not np.all(ok[done]):
            out = _refuse(out, ~ok)
        parts.append(per_case(out, todo.size, np.flatnonzero(done)))
        where.append(todo[done])
        n_case[todo[~done]] *= 2
        n_case[todo[done & ~ok]] = 0
        if np.all(done):
            break
        keep = np.flatnonzero(~done)
        coarse = (per_case(fine[0], todo.size, keep), per_case(fine[1], todo.size, keep),
                  fine[2][keep])  # fmt: skip
        todo = todo[keep]
        fine = run(todo, t_case[todo] / n_case[todo])
    return parts, where, Run(n_case, est, res, stiff, stuck)


def _refuse(out: GeneralOutcome, bad: np.ndarray) -> GeneralOutcome:
    """The outcome with NaN answers for the cases ``bad``."""
    from dataclasses import replace

    nan = {
        k: np.where(bad, np.nan, getattr(out, k))
        for k in ("contact_time", "ball_velocity", "impulse", "peak_force")
    }
    return replace(out, **nan)
