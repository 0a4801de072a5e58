"""CVODE (BDF, scikit-sundae) for any contact law: the reference path of the general integrator.

Ball + frame in mass-normalised free-free modal coordinates x = [u_B, eta] (rigid modes first),
with the law's force F(delta, delta', z)::

    m_B u_B'' = -F,   eta_j'' + omega_j^2 eta_j = a_j F,   z' = g(delta, delta', z) (ODE state)
    delta = u_B - a . eta,   delta' = u_B' - a . eta'

The Jacobian is analytic: the frame part is constant, the law adds the rank-one terms
dF/d delta h^T, dF/d delta' h^T (h = [1, -a]) and dF/dz. A memory state (hysteresis) is handled by
phases: loading with z = delta until delta' falls through 0, then unloading with z fixed until
the contact ends or delta climbs back to z (then loading again). The contact ends on the law's
own condition (:attr:`ContactLaw.end`) found by CVODE's root finding.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from fem_racket.contact.law import ContactLaw

__all__ = ["GRID_STEPS", "LawTrajectory", "solve_law_cvode"]

#: Stored times per estimated contact time when no output step is given.
GRID_STEPS = 400


@dataclass(frozen=True, eq=False)
class LawTrajectory:
    """CVODE's answer: times and states [u_B, eta, u_B', eta', (z)] up to separation, and
    the contact force at its maxima between them (root-found: dF/dt falling through 0) [N]."""

    t: np.ndarray
    y: np.ndarray
    n: int
    peaks: np.ndarray

    @property
    def contact_time(self) -> float:
        """t_c [s]."""
        return float(self.t[-1])

    @property
    def ball_velocity(self) -> float:
        """Ball velocity at separation [m/s]."""
        return float(self.y[-1, self.n])


def solve_law_cvode(
    law: ContactLaw,
    omega: np.ndarray,
    a: np.ndarray,
    ball_mass: float,
    speed: float,
    *,
    frame_velocity: np.ndarray | None = None,
    rtol: float = 1e-10,
    atol: float = 1e-13,
    t_max: float | None = None,
    output_step: float | None = None,
) -> LawTrajectory:
    """Integrate one impact with CVODE until the law's end condition.

    Parameters
    ----------
    law : ContactLaw
        Scalar parameters.
    omega : ndarray, shape (n,)
        Angular frequencies of the frame coordinates, rigid modes as 0 [rad/s].
    a : ndarray, shape (n,)
        Mass-normalised mode shapes at the impact point [1/sqrt(kg)].
    ball_mass, speed : float
        m_B [kg] and the ball's initial speed towards the frame [m/s].
    frame_velocity : ndarray, shape (n,), optional
        Initial modal velocities of the frame [sqrt(kg) m/s].
    rtol, atol : float
        CVODE tolerances.
    t_max : float, optional
        Give up at this time [s]; 4 x the law's estimate by default.
    output_step : float, optional
        Spacing of stored times [s]; by default :data:`GRID_STEPS` per estimated contact time.
    """
    from fem_racket.impact.ode.integrators import cvode_bdf
    from fem_racket.impact.system import no_separation

    n = omega.size + 1
    h = np.concatenate([[1.0], -a])
    minv = np.concatenate([[1.0 / ball_mass], np.ones(n - 1)])
    w2 = np.concatenate([[0.0], omega**2])
    ode = law.state == "ode"
    size = 2 * n + (1 if ode else 0)
    meff = 1.0 / (1.0 / ball_mass + np.sum(a[omega == 0] ** 2))
    t_est = float(law.contact_time_estimate(meff, speed))
    t_max = 4.0 * t_est if t_max is None else t_max
    step = t_est / GRID_STEPS if output_step is None else output_step
    base = np.zeros((size, size))
    base[:n, n : 2 * n] = np.eye(n)
    base[n : 2 * n, :n] = -np.diag(w2)
    y0 = np.zeros(size)
    y0[n] = speed
    if frame_velocity is not None:
        y0[n + 1 : 2 * n] = frame_velocity
    z_fixed = [0.0]
    loading = [law.state == "memory"]

    def parts(y: np.ndarray) -> tuple[float, float, float]:
        d, v = h @ y[:n], h @ y[n : 2 * n]
        if ode:
            z = y[-1]
        elif loading[0]:
            z = d
        else:
            z = z_fixed[0]
        return d, v, z

    def rhs(t: float, y: np.ndarray, yp: np.ndarray) -> None:
        d, v, z = parts(y)
        F = law.force(d, v, z)
        yp[:n] = y[n : 2 * n]
        yp[n : 2 * n] = -w2 * y[:n] - minv * h * F
        if ode:
            yp[-1] = law.rate(d, v, z)

    def jac(t: float, y: np.ndarray, yp: np.ndarray, JJ: np.ndarray) -> None:
        d, v, z = parts(y)
        fd, fv, fz = (float(x) for x in law.partials(d, v, z))
        JJ[:, :] = base
        mh = minv * h
        JJ[n : 2 * n, :n] -= np.outer(mh, h) * fd
        JJ[n : 2 * n, n : 2 * n] -= np.outer(mh, h) * fv
        if ode:
            JJ[n : 2 * n, -1] -= mh * fz
            gd, gv, gz = (float(x) for x in law.rate_partials(d, v, z))
            JJ[-1, :n] = gd * h
            JJ[-1, n : 2 * n] = gv * h
            JJ[-1, -1] = gz

    def force_rate(y: np.ndarray, d: float, v: float, z: float) -> float:
        """dF/dt [N/s] = F_d delta' + F_v delta'' + F_z z' (z = delta while loading)."""
        yp = np.empty(size)
        rhs(0.0, y, yp)
        fd, fv, fz = (float(x) for x in law.partials(d, v, z))
        zp = yp[-1] if ode else (v if loading[0] else 0.0)
        return fd * v + fv * float(h @ yp[n : 2 * n]) + fz * zp

    def events(t: float, y: np.ndarray, ev: np.ndarray) -> None:
        d, v, z = parts(y)
        ev[2] = force_rate(y, d, v, z)
        if law.end == "force":
            ev[0] = law.force(d, v, z)
        elif law.end == "state":
            ev[0] = z
        else:
            ev[0] = d - float(law.end_deflection(z)) if not loading[0] else d
        # re-loading needs delta to climb back past the turning point (by a round-off margin)
        ev[1] = v if loading[0] else d - z_fixed[0] * (1.0 + 1e-9)

    events.terminal = [True, law.state == "memory", False]  # a force maximum: recorded
    events.direction = [-1, -1, -1]
    ts, ys, peaks = [np.array([0.0])], [y0[None, :]], [np.zeros(0)]
    t0 = 0.0
    while True:
        if law.state == "memory":
            events.direction = [-1, -1 if loading[0] else 1, -1]
        span = np.arange(t0, t_max + 0.5 * step, step)
        if span.size < 2:
            raise no_separation(t_max)
        solver = cvode_bdf(rhs, jac, events, 3, rtol=rtol, atol=atol, max_num_steps=200000)
        sol = solver.solve(span, y0)
        if not sol.success:
            raise RuntimeError(f"CVODE failed: {sol.message}")
        ts.append(sol.t[1:])
        ys.append(sol.y[1:])
        hits = np.zeros((0, 3)) if sol.i_events is None else np.asarray(sol.i_events)
        at_peaks = np.asarray(sol.y_events)[hits[:, 2] != 0] if hits.size else []
        peaks.append(np.array([law.force(*parts(y)) for y in at_peaks], dtype=float))
        ends = hits[np.any(hits[:, :2], axis=1), :2]  # the end and branch events
        if ends.size == 0:
            raise no_separation(t_max)
        which = np.flatnonzero(ends[-1])
        if 0 in which and (law.state != "memory" or not loading[0]):
            break
        # a memory law changes branch: loading <-> unloading
        t0, y0 = float(sol.t[-1]), sol.y[-1].copy()
        if loading[0]:
            z_fixed[0] = float(h @ y0[:n])
        loading[0] = not loading[0]
    return LawTrajectory(np.concatenate(ts), np.vstack(ys), n, np.concatenate(peaks))
