"""Integrators of the coupled system, all behind one signature.

``solver(system, run: Integration) -> Trajectory``

- ``exact``: the closed-form eigen-solution of the linear system in modal coordinates
  (:mod:`fem_racket.impact.exact.closed_form`), the default.
- ``cvode``: SUNDIALS CVODE (BDF, scikit-sundae) with a dense Jacobian and a root-finding event.
- ``bdf``: scipy ``solve_ivp`` BDF with a terminal event, the fallback of ``cvode``.

Both root-find the contact force's maxima on their dense solution (the peak force), and the
extrema of any other linear outputs a caller watches (:class:`Watched`, :data:`INTEGRATORS`:
the hand-held racket's grip force).

The BDF paths accept either basis (``modal`` or the full ``physical`` FE system) and carry the
general first-order form ``y' = A y``; the separation events are named parts of the model
(:data:`fem_racket.impact.system.SEPARATION_EVENTS`) turned into terminal/direction settings here.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np

from fem_racket.impact.exact.closed_form import solve_exact
from fem_racket.impact.system import (
    DEFAULT_INTEGRATION,
    SEPARATION_EVENTS,
    CoupledSystem,
    Integration,
    NoSeparationError,
    Trajectory,
    no_separation,
)
from fem_racket.validation import AccuracyError, InputError, check_choice, check_range

__all__ = [
    "ATOL_RANGE",
    "GRID_STEPS",
    "INTEGRATORS",
    "PHYSICAL_MAX_ELEMENTS",
    "RTOL_RANGE",
    "SOLVERS",
    "NoSeparationError",
    "check_solver_settings",
    "cvode_bdf",
    "get_solver",
    "Integrated",
    "integrate_bdf",
    "integrate_cvode",
    "peak_rates",
    "solve_bdf",
    "solve_cvode",
    "solve_exact",
    "Watched",
]

Solver = Callable[[CoupledSystem, Integration], Trajectory]

#: Relative tolerances of the BDF paths that meet the stated accuracy (COR 1e-8, t_c 1e-7):
#: measured on the standard racket against the exact path, COR/t_c errors 2e-10/3e-9 (cvode)
#: and 5e-9/4e-9 (bdf) at rtol 1e-6 with atol 1e-8; at 1e-4 they reach 9e-8, at 1e-2 5e-4 and
#: at 1 the COR is -0.98. Below 1e-12 the BDF paths take minutes or stop (step size underflow).
RTOL_RANGE = (1e-12, 1e-6)
#: Absolute tolerances [m, m/s and modal units] that meet it with any allowed rtol (atol 1e-6
#: gives COR errors of 4e-8 to 9e-8; 1e-20 stops scipy's BDF).
ATOL_RANGE = (1e-16, 1e-8)
#: Most elements for the physical basis (every FE DOF in the BDF system): its undamped high
#: modes make CVODE take 3 s at 20 elements, 23 s at 40 and minutes at 80.
PHYSICAL_MAX_ELEMENTS = 40
#: Output grid of the BDF paths per estimated contact time when no output times are asked (the
#: summary's peak force is taken on it).
GRID_STEPS = 200


def check_solver_settings(solver: str, basis: str, elements: int, rtol: float, atol: float) -> None:
    """Refuse tolerances and bases that cannot meet the stated accuracy in reasonable time.

    The tolerances apply to the BDF solvers only (the exact path has none).
    """
    if solver != "exact":
        check_range("rtol", rtol, *RTOL_RANGE)
        check_range("atol", atol, *ATOL_RANGE)
    if basis == "physical" and elements > PHYSICAL_MAX_ELEMENTS:
        raise InputError(
            f"basis = 'physical' is not allowed with {elements} elements: at most "
            f"{PHYSICAL_MAX_ELEMENTS} (BDF on every FE DOF takes minutes beyond; use basis 'modal')"
        )


def _one_line(message: object) -> str:
    return " ".join(str(message).split())


def _bdf_setup(
    system: CoupledSystem, run: Integration
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    check_choice("separation", run.separation, SEPARATION_EVENTS)
    A = system.state_matrix
    c = system.event_vector(run.separation)
    t_est = system.contact_time_estimate()
    t_max = 20.0 * t_est if run.t_max is None else run.t_max
    step = t_est / GRID_STEPS if run.output_step is None else run.output_step
    tspan = np.arange(0.0, t_max + 0.5 * step, step)
    return A, c, tspan, system.initial_state()


def peak_rates(A: Any, rows: np.ndarray) -> np.ndarray:
    """Rows r_i with d(c_i @ y)/dt = r_i @ y for the linear outputs c_i @ y (``rows``, shape
    (k, 2 n); y' = A y): the roots of r_i @ y are the outputs' extrema (falling through 0 a
    maximum, rising a minimum), found by the integrator's root finding on its dense solution (so
    they do not depend on the output times)."""
    return np.array([np.asarray(A.T @ c).ravel() for c in rows])


@dataclass(frozen=True, eq=False)
class Watched:
    """Linear outputs c_i @ y whose extrema an integrator root-finds (:func:`peak_rates`).

    Attributes
    ----------
    rows : ndarray, shape (k, 2 n)
        The rows c_i.
    directions : tuple of int
        Per output: -1 its maxima, 1 its minima, 0 both.
    """

    rows: np.ndarray
    directions: tuple[int, ...]


@dataclass(frozen=True, eq=False)
class Integrated:
    """An integrator's states ``y`` [x, x'] at the times ``t`` (the output grid, or t_est /
    :data:`GRID_STEPS` steps without one), ending at separation, and the states at each watched
    output's extrema between them (``extrema[i]``, shape (m_i, 2 n))."""

    t: np.ndarray
    y: np.ndarray
    extrema: list[np.ndarray]


def _force_watch(system: CoupledSystem) -> Watched:
    """The contact force's maxima: the free racket's peak force."""
    return Watched(system.event_vector("force")[None, :], (-1,))


def _trajectory(system: CoupledSystem, run: Integration, out: Integrated) -> Trajectory:
    """Split the states into coordinates and rates; the peak force over every computed time and
    the force's maxima ``out.extrema[0]`` found between them."""
    n = system.size
    t, y = out.t, out.y
    peak = float(np.max(np.vstack([y, out.extrema[0]]) @ system.event_vector("force")))
    if run.output_step is None:
        t, y = t[[0, -1]], y[[0, -1]]
    return Trajectory(np.asarray(t), y[:, :n].copy(), y[:, n:].copy(), peak)


def cvode_bdf(
    rhs: Callable[..., None],
    jac: Callable[..., None],
    events: Callable[..., None],
    num_events: int,
    *,
    rtol: float,
    atol: float,
    max_num_steps: int,
) -> Any:
    """A scikit-sundae CVODE solver: BDF, the dense Jacobian ``jac``, root-found ``events``.

    The callbacks take CVODE's in-place forms (``rhs(t, y, yp)``, ``jac(t, y, yp, JJ)``,
    ``events(t, y, ev)``); ``events.terminal`` and ``events.direction`` are read by CVODE.
    """
    from sksundae.cvode import CVODE

    return CVODE(
        rhs,
        method="BDF",
        rtol=rtol,
        atol=atol,
        jacfn=jac,
        eventsfn=events,
        num_events=num_events,
        max_num_steps=max_num_steps,
    )


def integrate_cvode(system: CoupledSystem, run: Integration, watch: Watched) -> Integrated:
    """CVODE on ``system`` until separation, root-finding the extrema of ``watch``'s outputs."""
    A, c, tspan, y0 = _bdf_setup(system, run)

    def rhs(t: float, y: np.ndarray, yp: np.ndarray) -> None:
        yp[:] = A @ y

    def jac(t: float, y: np.ndarray, yp: np.ndarray, JJ: np.ndarray) -> None:
        JJ[:, :] = A

    rates = peak_rates(A, watch.rows)

    def events(t: float, y: np.ndarray, ev: np.ndarray) -> None:
        ev[0] = c @ y
        for i, rate in enumerate(rates):
            ev[1 + i] = rate @ y

    k = len(rates)
    events.terminal = [True] + [False] * k  # separation ends the run; an extremum is recorded
    events.direction = [-1, *watch.directions]
    solver = cvode_bdf(rhs, jac, events, 1 + k, rtol=run.rtol, atol=run.atol, max_num_steps=100000)
    sol = solver.solve(tspan, y0)
    if not sol.success:
        raise AccuracyError(f"solver = 'cvode' failed: {_one_line(sol.message)}")
    hits = np.zeros((0, 1 + k)) if sol.i_events is None else np.asarray(sol.i_events)
    if not np.any(hits[:, 0]):
        raise no_separation(float(tspan[-1]))
    at = np.asarray(sol.y_events)
    return Integrated(sol.t, sol.y, [at[hits[:, 1 + i] != 0] for i in range(k)])


def integrate_bdf(system: CoupledSystem, run: Integration, watch: Watched) -> Integrated:
    """scipy ``solve_ivp`` BDF on ``system`` until separation (a terminal event),
    root-finding the extrema of ``watch``'s outputs."""
    from scipy.integrate import solve_ivp

    A, c, tspan, y0 = _bdf_setup(system, run)

    def event(t: float, y: np.ndarray) -> float:
        return float(c @ y)

    event.terminal = True
    event.direction = -1
    rates = peak_rates(A, watch.rows)
    extrema = [_rate_event(r, d) for r, d in zip(rates, watch.directions, strict=True)]
    sol = solve_ivp(
        lambda t, y: A @ y,
        (0.0, float(tspan[-1])),
        y0,
        method="BDF",
        t_eval=tspan,
        events=[event, *extrema],
        jac=lambda t, y: A,
        rtol=run.rtol,
        atol=run.atol,
    )
    if sol.status == -1:
        raise AccuracyError(f"solver = 'bdf' failed: {_one_line(sol.message)}")
    if sol.t_events[0].size == 0:
        raise no_separation(float(tspan[-1]))
    t = np.append(sol.t, sol.t_events[0][0])
    y = np.vstack([sol.y.T, sol.y_events[0][0]])
    if t.size > 1 and t[-1] - t[-2] < 1e-12:
        t, y = np.delete(t, -2), np.delete(y, -2, axis=0)
    n2 = y.shape[1]
    return Integrated(t, y, [np.asarray(e).reshape(-1, n2) for e in sol.y_events[1:]])


def _rate_event(rate: np.ndarray, direction: int) -> Callable[[float, np.ndarray], float]:
    """scipy's event for an output's extremum (recorded, not terminal)."""

    def peak(t: float, y: np.ndarray) -> float:
        return float(rate @ y)

    peak.direction = direction
    return peak


def solve_cvode(system: CoupledSystem, run: Integration = DEFAULT_INTEGRATION) -> Trajectory:
    """SUNDIALS CVODE (BDF) through scikit-sundae, dense constant Jacobian, root-found event."""
    return _trajectory(system, run, integrate_cvode(system, run, _force_watch(system)))


def solve_bdf(system: CoupledSystem, run: Integration = DEFAULT_INTEGRATION) -> Trajectory:
    """scipy ``solve_ivp`` BDF with a constant Jacobian and a terminal event."""
    return _trajectory(system, run, integrate_bdf(system, run, _force_watch(system)))


#: Integrator name -> function taking the outputs to watch (:class:`Watched`).
INTEGRATORS = {"cvode": integrate_cvode, "bdf": integrate_bdf}


#: Solver name -> function, all with the signature of :func:`solve_exact`.
SOLVERS: dict[str, Solver] = {"exact": solve_exact, "cvode": solve_cvode, "bdf": solve_bdf}


def get_solver(name: str) -> Solver:
    """The integrator called ``name`` (one of :data:`SOLVERS`)."""
    return SOLVERS[check_choice("solver", name, SOLVERS)]
