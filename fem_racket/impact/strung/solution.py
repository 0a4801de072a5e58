"""A solved strung impact, before its output times are chosen: :func:`strung_solution` gives the
contact time and a :data:`States` (picklable), the states at any times in the contact.

The paths (:func:`fem_racket.impact.strung.impact.strung_impact`): the exact solution in closed
form (:class:`~fem_racket.impact.strung.exact.ExactStates`), the general integrator's
piecewise-cubic force driving every coordinate exactly
(:func:`~fem_racket.impact.general.histories.law_histories`), CVODE's outputs (every
t_est / 400 s) interpolated linearly, as is the stretching bed's CVODE. The impact's histories
(:data:`~fem_racket.impact.strung.impact.SAMPLES`) and the oblique impact's normal history
(:data:`~fem_racket.impact.strung.impact.OBLIQUE_SAMPLES`) are two samplings of one solution.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from fem_racket.contact.law import ContactLaw
from fem_racket.impact.general.histories import law_histories, ode_state_at
from fem_racket.impact.general.integrator import GeneralOutcome, solve_general
from fem_racket.impact.general.receptance import Receptance
from fem_racket.impact.ode.law_cvode import solve_law_cvode
from fem_racket.impact.strung.exact import ExactStates, strung_exact
from fem_racket.impact.strung.point import StrungPoint
from fem_racket.impact.strung.stretch import solve_stretch

__all__ = ["States", "strung_solution"]

#: States at times t [s] (a callable): the states [u_B, eta] (T, 1 + n), their rates and the
#: law's ODE state (T,) [m] (None without one).
States = Any


@dataclass(frozen=True, eq=False)
class _Exact:
    """The exact solution's states (no law state)."""

    exact: ExactStates

    def __call__(self, t: np.ndarray) -> tuple[np.ndarray, np.ndarray, None]:
        return (*self.exact(t), None)


@dataclass(frozen=True, eq=False)
class _Interpolated:
    """CVODE's outputs ``y`` (T, 2 n [+ 1]) at ``t_raw``, interpolated linearly; the last
    column the law's ODE state when ``ode``."""

    t_raw: np.ndarray
    y: np.ndarray
    n: int
    ode: bool

    def __call__(self, t: np.ndarray) -> tuple[np.ndarray, np.ndarray, Any]:
        y = np.column_stack([np.interp(t, self.t_raw, col) for col in self.y.T])
        n = self.n
        return y[:, :n], y[:, n : 2 * n], y[:, -1] if self.ode else None


@dataclass(frozen=True, eq=False)
class _General:
    """The general integrator's outcome ``out`` on the structure (``omega``, shapes ``a``)."""

    out: GeneralOutcome
    law: ContactLaw
    omega: np.ndarray
    a: np.ndarray
    ball_mass: float
    speed: float

    def __call__(self, t: np.ndarray) -> tuple[np.ndarray, np.ndarray, Any]:
        x, v = law_histories(self.out, self.omega, self.a, self.ball_mass, self.speed, None, t)
        z = ode_state_at(self.law, self.out, t) if self.law.state == "ode" else None
        return x, v, z


def strung_solution(
    point: StrungPoint, law: ContactLaw, ball_mass: float, speed: float, solver: str, how: dict
) -> tuple[float, States]:
    """The contact time [s] and the :data:`States` of the ball (``ball_mass`` [kg], ``speed``
    [m/s]) under ``law`` on ``point`` by ``solver`` (``how``: its ``tolerance``, ``rtol``,
    ``atol``; a stretching bed by CVODE, the caller has checked the solver)."""
    w, a = point.omega, point.a
    if point.strings.stretch:
        t_raw, y = solve_stretch(point, law, ball_mass, speed, rtol=how["rtol"], atol=how["atol"])
        return float(t_raw[-1]), _Interpolated(t_raw, y, w.size + 1, False)
    if solver == "exact":
        tc, exact = strung_exact(point, law, ball_mass, speed)
        return tc, _Exact(exact)
    if solver == "cvode":
        tr = solve_law_cvode(law, w, a, ball_mass, speed, rtol=how["rtol"], atol=how["atol"])
        return tr.contact_time, _Interpolated(tr.t, tr.y, tr.n, law.state == "ode")
    rc = point.rigid_count
    rec = Receptance(w[rc:], a[None, rc:], a[None, :rc], np.array([ball_mass]))
    out = solve_general(law, rec, speed, tolerance=how["tolerance"])
    return float(out.contact_time[0]), _General(out, law, w, a, ball_mass, speed)
