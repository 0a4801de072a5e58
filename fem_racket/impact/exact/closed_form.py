"""Closed-form (exact) solution of the linear ball + frame impact in modal coordinates.

The rigid-body modes are eliminated through the spring deflection delta, leaving a reduced state
``z = [delta, eta_f, delta', eta_f']`` with ``z' = A z`` and no zero eigenvalue::

    delta'' = -mu F + sum_f a_f omega_f^2 eta_f,   mu = 1/m_B + sum_k a_k^2
    eta_f'' = -omega_f^2 eta_f + a_f F,            F = K_CB delta + C_CB delta'

so every coordinate is a sum of exponentials, ``z(t) = Re sum_j Z_j exp(lambda_j t)`` over the
eigenvalues of A (amplitudes from the eigenvectors, ``Z = V diag(V^-1 z0)``), and
``F(t) = sum_j f_j exp(lambda_j t)``. The impulse J = int F and its integral P = int J are
summed in closed form, giving the ball (u_B = V_B0 t - P/m_B) and rigid modes (eta_r = a_r P).
The separation time is the first sign change of the event function on a fine grid, refined by
Brent's method on the closed form. Without histories (:mod:`fem_racket.impact.exact.outcome`)
only delta's amplitudes are needed, which follow from the eigenvalues as residues of the
Laplace transform delta(s) = V_B0 / P(s), with no eigenvectors.
"""

from __future__ import annotations

from collections.abc import Callable

import numpy as np

from fem_racket.impact.system import (
    DEFAULT_INTEGRATION,
    SEPARATION_EVENTS,
    CoupledSystem,
    Integration,
    Trajectory,
    no_separation,
    output_times,
)
from fem_racket.validation import AccuracyError, InputError, check_choice, show

__all__ = [
    "ModalClosedForm",
    "peak_force",
    "reduced_matrix",
    "separation_time",
    "solve_exact",
]


def _re_matmul(a: np.ndarray, b: np.ndarray) -> np.ndarray:
    """Re(a @ b) from real products only.

    OpenBLAS's threaded complex kernels stall for ~10 ms on these small sizes when the other
    cores are busy (measured here: 8 ms against 0.03 ms for the real products).
    """
    return a.real @ b.real - a.imag @ b.imag


#: In the residue path, flexible modes with |a_f| below this fraction of max |a| are decoupled
#: from the ball (an impact on a vibration node) and left out: their effect on delta is O(a_f^2).
DECOUPLED = 1e-7
#: Relative tolerance of the initial-condition sum rules checking the residues.
SUM_RULE_TOL = 1e-9


def reduced_matrix(af: np.ndarray, wf2: np.ndarray, mu: float, k: float, c: float) -> np.ndarray:
    """State matrix A of z = [delta, eta_f, delta', eta_f'] (module docstring), z' = A z.

    Parameters
    ----------
    af : ndarray
        Flexible mode shapes at the impact point [1/sqrt(kg)].
    wf2 : ndarray
        Their squared angular frequencies [rad^2/s^2].
    mu : float
        1/m_B plus the rigid modes' inverse effective mass at the impact point [1/kg].
    k, c : float
        Contact stiffness [N/m] and damping [N s/m].
    """
    n = af.size + 1
    A = np.zeros((2 * n, 2 * n))
    A[:n, n:] = np.eye(n)
    A[n, 0], A[n, n] = -mu * k, -mu * c
    A[n, 1:n] = af * wf2
    A[n + 1 :, 0], A[n + 1 :, n] = af * k, af * c
    A[n + 1 :, 1:n] = -np.diag(wf2)
    return A


def _deflection_residues(
    lam: np.ndarray, af: np.ndarray, wf2: np.ndarray, mu: float, k: float, c: float, v0: float
) -> np.ndarray | None:
    """Amplitudes r_j with delta(t) = Re sum_j r_j exp(lambda_j t), from the eigenvalues alone.

    Laplace transform of the reduced system: delta(s) = v0 / P(s) with
    P(s) = s^2 + (k + c s) (mu - sum_f a_f^2 omega_f^2 / (s^2 + omega_f^2)), whose zeros are the
    eigenvalues lambda_j; so r_j = v0 / P'(lambda_j). Returns None unless the initial state's
    sum rules (sum_j r_j = 0, sum_j lambda_j r_j = v0) hold to SUM_RULE_TOL. About half the cost
    of eigenvectors, and as accurate for delta and F (~1e-11 on the standard racket); the frame
    modes' own amplitudes would lose digits near their poles, so histories use eigenvectors.
    """
    with np.errstate(all="ignore"):
        d = (lam * lam)[:, None] + wf2
        bw = (af * af * wf2) / d
        q = mu - bw.sum(axis=1)
        dP = 2.0 * lam + c * q + (k + c * lam) * (bw * (2.0 * lam[:, None] / d)).sum(axis=1)
        r = v0 / dP
        ok = abs(r.sum()) <= SUM_RULE_TOL * np.abs(r).sum()
        ok = ok and abs((lam * r).sum() - v0) <= SUM_RULE_TOL * np.abs(lam * r).sum()
    return r if ok and np.all(np.isfinite(r)) else None


class ModalClosedForm:
    """Closed-form evaluation of the linear modal system at arbitrary times.

    ``Z`` holds the amplitudes of [delta, eta_f] on the eigenvalues ``lam``: from the
    eigenvectors, or, when ``histories`` is False, only delta's from the residue formula of
    :func:`_deflection_residues` (eigenvectors again if its sum rules fail).
    """

    def __init__(self, system: CoupledSystem, histories: bool = True) -> None:
        if system.basis != "modal":
            raise InputError(
                f"basis = {show(system.basis)} is not allowed with solver 'exact': must be 'modal'"
            )
        if system.frame_velocity0 is not None:
            raise InputError(
                "frame_velocity0 is not allowed with solver 'exact': it solves the stationary "
                "impact (a swing is superposed on it, fem_racket.impact.swing)"
            )
        om = system.omega
        self.mb = system.ball_mass
        self.v0 = system.speed
        self.a = -system.h[1:]
        self.rigid = om == 0.0
        af, wf2 = self.a[~self.rigid], om[~self.rigid] ** 2
        k, c = system.kcb, system.ccb
        mu = 1.0 / self.mb + float(np.sum(self.a**2))
        r = None
        if not histories:
            coupled = np.abs(af) > DECOUPLED * float(np.max(np.abs(self.a)))
            A = reduced_matrix(af[coupled], wf2[coupled], mu, k, c)
            lam = np.linalg.eigvals(A)
            r = _deflection_residues(lam, af[coupled], wf2[coupled], mu, k, c, self.v0)
            Z = None if r is None else r[None, :]
        if r is None:
            n = af.size + 1
            A = reduced_matrix(af, wf2, mu, k, c)
            lam, V = np.linalg.eig(A)
            z0 = np.zeros(2 * n)
            z0[n] = self.v0
            Z = V[:n] * np.linalg.solve(V, z0)
        self.lam, self.Z = lam, Z
        self.fvec = (k + c * lam) * Z[0]
        self.k, self.c = k, c

    def weights(self, separation: str) -> np.ndarray:
        """Coefficients w with event value Re sum_j w_j exp(lambda_j t) (delta, or F)."""
        if separation == "displacement":
            return self.Z[0]
        return self.fvec

    def event(self, separation: str) -> Callable[[np.ndarray], np.ndarray]:
        """Vectorised event function of time (delta, or F)."""
        w = self.weights(separation)
        lam = self.lam
        return lambda t: _re_matmul(np.exp(np.multiply.outer(t, lam)), w)

    def on_grid(
        self, w: np.ndarray, t0: float, t1: float, num: int
    ) -> tuple[np.ndarray, np.ndarray]:
        """Re sum_j w_j exp(lambda_j t) on ``num`` uniform times from t0 to t1.

        exp(lambda t_k) = exp(lambda t0) exp(lambda dt)^k, the powers by repeated doubling
        (rows k + m = rows k times exp(lambda dt)^m): a few vectorised products instead of one
        complex exponential per grid point (relative round-off ~ log2(num) eps).
        """
        grid = np.linspace(t0, t1, num)
        E = np.empty((num, self.lam.size), dtype=complex)
        E[0] = np.exp(self.lam * t0)
        power = np.exp(self.lam * (grid[1] - grid[0]))
        filled = 1
        while filled < num:
            m = min(filled, num - filled)
            np.multiply(E[:m], power, out=E[filled : filled + m])
            filled += m
            power = power * power
        return grid, _re_matmul(E, w)

    def force(self, t: float) -> float:
        """Contact force F(t) [N]."""
        return float(_re_matmul(np.exp(self.lam * t), self.fvec))

    def force_rate(self, t: float) -> float:
        """dF/dt [N/s]."""
        return float(_re_matmul(np.exp(self.lam * t), self.lam * self.fvec))

    def impulse(self, t: float) -> float:
        """J(t) = int_0^t F dt [N s]."""
        lt = self.lam * t
        return float(_re_matmul(np.expm1(lt) / self.lam, self.fvec))

    def states(self, t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
        """Coordinates [u_B, eta] and their rates at times ``t`` (needs ``histories``)."""
        lt = np.multiply.outer(t, self.lam)
        E = np.exp(lt)
        z = _re_matmul(E, self.Z.T)
        zr = _re_matmul(E * self.lam, self.Z.T)
        with np.errstate(invalid="ignore", divide="ignore"):
            em1 = np.expm1(lt)
        J = _re_matmul(em1 / self.lam, self.fvec)
        P = _re_matmul((em1 - lt) / self.lam**2, self.fvec)
        nt, m = t.size, self.a.size
        x, v = np.empty((nt, m + 1)), np.empty((nt, m + 1))
        x[:, 0] = self.v0 * t - P / self.mb
        v[:, 0] = self.v0 - J / self.mb
        x[:, 1:][:, self.rigid] = np.outer(P, self.a[self.rigid])
        v[:, 1:][:, self.rigid] = np.outer(J, self.a[self.rigid])
        x[:, 1:][:, ~self.rigid] = z[:, 1:]
        v[:, 1:][:, ~self.rigid] = zr[:, 1:]
        # Self-check: u_B - w(x_i) must equal the reduced state's delta.
        delta = x[:, 0] - x[:, 1:] @ self.a
        scale = max(float(np.max(np.abs(x[:, 0]))), 1e-300)
        if np.max(np.abs(delta - z[:, 0])) > 1e-7 * scale:
            raise AccuracyError(
                "solver = 'exact' cannot solve this case to the stated accuracy: its "
                "eigen-solution is ill-conditioned (self-check failed); use solver 'cvode'"
            )
        return x, v


def separation_time(
    cf: ModalClosedForm, separation: str, t_est: float, t_max: float | None
) -> float:
    """First time the event function falls through 0 [s]: a sign change on a grid of 513
    points per 2 t_est window, refined by Brent's method on the closed form."""
    from scipy.optimize import brentq

    w = cf.weights(separation)
    g = cf.event(separation)
    t_max = 20.0 * t_est if t_max is None else t_max
    t0 = 0.0
    while t0 < t_max:
        grid, vals = cf.on_grid(w, t0, min(t0 + 2.0 * t_est, t_max), 513)
        start = 1 if t0 == 0.0 else 0
        falls = np.flatnonzero((vals[start:-1] > 0.0) & (vals[start + 1 :] <= 0.0))
        if falls.size:
            i = falls[0] + start
            if vals[i + 1] == 0.0:
                return float(grid[i + 1])
            return float(
                brentq(
                    lambda s: float(g(np.array([s]))[0]),
                    grid[i],
                    grid[i + 1],
                    xtol=1e-15,
                    rtol=4 * np.finfo(float).eps,
                )
            )
        t0 = grid[-1]
    raise no_separation(t_max)


def solve_exact(system: CoupledSystem, run: Integration = DEFAULT_INTEGRATION) -> Trajectory:
    """Closed-form (eigen-solution) path; see the module docstring. Tolerances are unused."""
    check_choice("separation", run.separation, SEPARATION_EVENTS)
    cf = ModalClosedForm(system)
    tc = separation_time(cf, run.separation, system.contact_time_estimate(), run.t_max)
    t = output_times(run.output_step, tc)
    x, v = cf.states(t)
    return Trajectory(t, x, v, peak_force(cf, tc)[0])


def peak_force(cf: ModalClosedForm, tc: float) -> tuple[float, float]:
    """Maximum of F on [0, t_c] and its time.

    The largest of 257 values on [0, t_c], then of 257 values on the four grid steps around it
    (steps of t_c / 65536, finer than the ripple of the highest FE modes), then dF/dt = 0 by
    Brent's method between the neighbours of that one.
    """
    from scipy.optimize import brentq

    grid, F = cf.on_grid(cf.fvec, 0.0, tc, 257)
    i = int(np.argmax(F))
    grid, F = cf.on_grid(cf.fvec, grid[max(i - 2, 0)], grid[min(i + 2, grid.size - 1)], 257)
    i = int(np.argmax(F))
    best_t, best = float(grid[i]), float(F[i])
    if 0 < i < grid.size - 1:
        a, b = grid[i - 1], grid[i + 1]
        if cf.force_rate(a) > 0.0 > cf.force_rate(b):
            t = brentq(cf.force_rate, a, b, xtol=1e-15, rtol=4 * np.finfo(float).eps)
            f = cf.force(t)
            if f > best:
                best_t, best = float(t), f
    return best, best_t
