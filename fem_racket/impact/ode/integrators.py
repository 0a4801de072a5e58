"""Integrators of the coupled system, all behind one signature.

``solver(system, run: Integration) -> Trajectory``

- ``exact``: the closed-form eigen-solution of the linear system in modal coordinates
  (:mod:`fem_racket.impact.exact.closed_form`), the default.
- ``cvode``: SUNDIALS CVODE (BDF, scikit-sundae) with a dense Jacobian and a root-finding event.
- ``bdf``: scipy ``solve_ivp`` BDF with a terminal event, the fallback of ``cvode``.

The BDF paths accept either basis (``modal`` or the full ``physical`` FE system) and carry the
general first-order form ``y' = A y``; the separation events are named parts of the model
(:data:`fem_racket.impact.system.SEPARATION_EVENTS`) turned into terminal/direction settings here.
"""

from __future__ import annotations

from collections.abc import Callable
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
    "PHYSICAL_MAX_ELEMENTS",
    "RTOL_RANGE",
    "SOLVERS",
    "NoSeparationError",
    "check_solver_settings",
    "cvode_bdf",
    "get_solver",
    "solve_bdf",
    "solve_cvode",
    "solve_exact",
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


def _peak_rate(system: CoupledSystem, A: Any) -> np.ndarray:
    """Row r with dF/dt = r @ y (F = c @ y the contact force, y' = A y): its roots falling
    through 0 are the force's maxima, found by the integrator's root finding on its dense
    solution (so the peak force does not depend on the output times)."""
    return np.asarray(A.T @ system.event_vector("force")).ravel()


def _trajectory(
    system: CoupledSystem, t: np.ndarray, y: np.ndarray, keep_all: bool, peaks: np.ndarray
) -> Trajectory:
    """Split the states into coordinates and rates; the peak force over every computed time
    (the output grid, or t_est / :data:`GRID_STEPS` steps when only the ends are kept) and the
    force's maxima ``peaks`` (states, shape (k, 2 n)) found between them."""
    n = system.size
    peak = float(np.max(np.vstack([y, peaks]) @ system.event_vector("force")))
    if not keep_all:
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


def solve_cvode(system: CoupledSystem, run: Integration = DEFAULT_INTEGRATION) -> Trajectory:
    """SUNDIALS CVODE (BDF) through scikit-sundae, dense constant Jacobian, root-found event."""
    A, c, tspan, y0 = _bdf_setup(system, run)

    def rhs(t: float, y: np.ndarray, yp: np.ndarray) -> None:
        yp[:] = A @ y

    def jac(t: float, y: np.ndarray, yp: np.ndarray, JJ: np.ndarray) -> None:
        JJ[:, :] = A

    rate = _peak_rate(system, A)

    def events(t: float, y: np.ndarray, ev: np.ndarray) -> None:
        ev[0] = c @ y
        ev[1] = rate @ y

    events.terminal = [True, False]  # separation ends the run; a force maximum is recorded
    events.direction = [-1, -1]
    solver = cvode_bdf(rhs, jac, events, 2, rtol=run.rtol, atol=run.atol, max_num_steps=100000)
    sol = solver.solve(tspan, y0)
    if not sol.success:
        raise AccuracyError(f"solver = 'cvode' failed: {_one_line(sol.message)}")
    hits = np.zeros((0, 2)) if sol.i_events is None else np.asarray(sol.i_events)
    if not np.any(hits[:, 0]):
        raise no_separation(float(tspan[-1]))
    peaks = np.asarray(sol.y_events)[hits[:, 1] != 0]
    return _trajectory(system, sol.t, sol.y, run.output_step is not None, peaks)


def solve_bdf(system: CoupledSystem, run: Integration = DEFAULT_INTEGRATION) -> Trajectory:
    """scipy ``solve_ivp`` BDF with a constant Jacobian and a terminal event."""
    from scipy.integrate import solve_ivp

    A, c, tspan, y0 = _bdf_setup(system, run)

    def event(t: float, y: np.ndarray) -> float:
        return float(c @ y)

    rate = _peak_rate(system, A)

    def peak(t: float, y: np.ndarray) -> float:
        return float(rate @ y)

    event.terminal = True
    event.direction = -1
    peak.direction = -1  # a force maximum, recorded (not terminal)
    sol = solve_ivp(
        lambda t, y: A @ y,
        (0.0, float(tspan[-1])),
        y0,
        method="BDF",
        t_eval=tspan,
        events=[event, peak],
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
    peaks = np.asarray(sol.y_events[1]).reshape(-1, y.shape[1])
    return _trajectory(system, t, y, run.output_step is not None, peaks)


#: Solver name -> function, all with the signature of :func:`solve_exact`.
SOLVERS: dict[str, Solver] = {"exact": solve_exact, "cvode": solve_cvode, "bdf": solve_bdf}


def get_solver(name: str) -> Solver:
    """The integrator called ``name`` (one of :data:`SOLVERS`)."""
    return SOLVERS[check_choice("solver", name, SOLVERS)]
