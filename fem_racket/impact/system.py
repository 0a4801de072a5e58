"""The coupled ball + frame system as a linear second-order ODE.

With ball displacement u_B (positive towards the frame) and frame coordinates y (physical
Hermite DOFs q, or free-free modal coordinates eta with q = Phi eta)::

    M x'' + K x = -h F,        x = [u_B, y],   h = [1, -g],   delta = h . x = u_B - w(x_i)
    F = K_CB delta + C_CB delta'

The contact force F pushes the ball back and the frame forward at the impact point x_i; ``g``
holds the frame's shape functions (or mode shapes) at x_i. The initial state is at rest with the
ball at speed V_B0.

The impact ends at one of two named events, turned into terminal/direction settings only by the
integrators: ``"displacement"`` (the paper's criterion, section 2.3: the spring returns from
compression to tension, delta falls through 0) or ``"force"`` (F falls through 0).
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property
from typing import TYPE_CHECKING

import numpy as np

from fem_racket.impact.constants import SEPARATION_EVENTS
from fem_racket.validation import InputError, check_choice, show

if TYPE_CHECKING:
    import scipy.sparse as sp

__all__ = [
    "DEFAULT_INTEGRATION",
    "MAX_OUTPUT_TIMES",
    "SEPARATION_EVENTS",
    "CoupledSystem",
    "Integration",
    "NoSeparationError",
    "Trajectory",
    "modal_system",
    "no_separation",
    "check_output_count",
    "output_times",
    "physical_system",
]

#: Largest number of output times a simulation may be asked for.
MAX_OUTPUT_TIMES = 1e6


class NoSeparationError(InputError):
    """The ball did not leave the strings within the time limit."""


def no_separation(t_max: float) -> NoSeparationError:
    """The error raised when the ball has not separated by ``t_max`` [s]."""
    return NoSeparationError(
        f"t_max = {t_max:g} s is not enough: the ball did not separate within it; "
        "raise t_max (it must exceed the contact time)",
        parameter="t_max",
        value=t_max,
    )


def check_output_count(step: float | None, span: float, what: str) -> None:
    """Refuse ``step`` [s] giving more than :data:`MAX_OUTPUT_TIMES` output times over ``span``
    [s] (``what`` says what the span is), before anything that size is allocated."""
    if step is not None and span / step > MAX_OUTPUT_TIMES:
        raise InputError(
            f"output_step = {show(step)} s is not allowed: at most {MAX_OUTPUT_TIMES:.0e} output "
            f"times over {what}, so output_step >= {span / MAX_OUTPUT_TIMES:.3g} s"
        )


def output_times(step: float | None, t_end: float) -> np.ndarray:
    """Uniform times 0, step, 2 step, ... below ``t_end``, then ``t_end`` itself [s].

    With ``step`` None only the two end points are returned; more than
    :data:`MAX_OUTPUT_TIMES` are refused (:func:`check_output_count`).
    """
    if step is None:
        return np.array([0.0, t_end])
    check_output_count(step, t_end, f"the contact's {t_end:.3g} s")
    t = np.arange(0.0, t_end, step)
    if t_end - t[-1] < 1e-9 * step:
        t = t[:-1]
    return np.append(t, t_end)


@dataclass(frozen=True, eq=False)
class CoupledSystem:
    """``M x'' + K x = -h (kcb delta + ccb delta')`` with x(0) = 0, x'(0) = speed * e_0
    (plus the frame's ``frame_velocity0``).

    Attributes
    ----------
    mass, stiffness : sparse matrix, shape (n, n)
        M [kg] and K [N/m] of ball (index 0) and frame coordinates.
    h : ndarray, shape (n,)
        Contact direction: delta = h @ x.
    kcb, ccb : float
        Spring [N/m] and dashpot [N s/m] of the ball/string law.
    speed : float
        Initial ball speed V_B0 [m/s].
    basis : {"modal", "physical"}
        Meaning of the frame coordinates.
    rigid_compliance : float
        1/m_R + d^2/I_R of the free rigid frame at the impact point [1/kg].
    omega : ndarray or None
        For the modal basis: angular frequency of each frame coordinate [rad/s] (rigid = 0).
    frame_map : ndarray or None
        Matrix taking frame coordinates to physical Hermite DOFs (None: identity).
    frame_velocity0 : ndarray or None
        Initial rates of the frame coordinates (a swinging racket's rigid velocity field, see
        :mod:`fem_racket.impact.swing`); at rest when None. Taken by the BDF integrators; the
        exact solver solves the stationary impact and refuses it.
    """

    mass: sp.spmatrix
    stiffness: sp.spmatrix
    h: np.ndarray
    kcb: float
    ccb: float
    speed: float
    basis: str
    rigid_compliance: float
    omega: np.ndarray | None = None
    frame_map: np.ndarray | None = None
    frame_velocity0: np.ndarray | None = None

    @property
    def size(self) -> int:
        """Number of second-order coordinates (ball + frame)."""
        return int(self.h.size)

    @property
    def ball_mass(self) -> float:
        """m_B [kg]."""
        return float(self.mass.diagonal()[0])

    def initial_state(self) -> np.ndarray:
        """First-order state [x, x'] at t = 0."""
        y0 = np.zeros(2 * self.size)
        y0[self.size] = self.speed
        if self.frame_velocity0 is not None:
            y0[self.size + 1 :] = self.frame_velocity0
        return y0

    @cached_property
    def state_matrix(self) -> np.ndarray:
        """Dense A with y' = A y for y = [x, x'] (the law is linear)."""
        n = self.size
        minv = np.linalg.inv(self.mass.toarray())
        hh = np.outer(self.h, self.h)
        A = np.zeros((2 * n, 2 * n))
        A[:n, n:] = np.eye(n)
        A[n:, :n] = -minv @ (self.stiffness.toarray() + self.kcb * hh)
        A[n:, n:] = -minv @ (self.ccb * hh)
        return A

    def event_vector(self, separation: str) -> np.ndarray:
        """Row c with event value c @ [x, x'] (delta, or the contact force F)."""
        check_choice("separation", separation, SEPARATION_EVENTS)
        n = self.size
        c = np.zeros(2 * n)
        if separation == "displacement":
            c[:n] = self.h
        else:
            c[:n] = self.kcb * self.h
            c[n:] = self.ccb * self.h
        return c

    def contact_time_estimate(self) -> float:
        """pi sqrt(m_eff / K_CB) with the rigid-body effective mass (eq 11) [s]."""
        inv_meff = 1.0 / self.ball_mass + self.rigid_compliance
        return float(np.pi / np.sqrt(self.kcb * inv_meff))


@dataclass(frozen=True, eq=False)
class Trajectory:
    """What an integrator returns: coordinates at output times, ending at separation.

    Attributes
    ----------
    t : ndarray, shape (nt,)
        Output times [s]; the last is the separation time.
    x, v : ndarray, shape (nt, n)
        Coordinates and their rates.
    peak_force : float
        Largest contact force during contact [N], found by the integrator on its own dense
        solution (not only at the output times).
    """

    t: np.ndarray
    x: np.ndarray
    v: np.ndarray
    peak_force: float

    @property
    def contact_time(self) -> float:
        """Separation time [s]."""
        return float(self.t[-1])


@dataclass(frozen=True)
class Integration:
    """How an integrator runs a :class:`CoupledSystem` to a :class:`Trajectory` (the options
    every integrator of :data:`fem_racket.impact.ode.integrators.SOLVERS` takes).

    Attributes
    ----------
    separation : {"displacement", "force"}
        The event ending the contact (:data:`SEPARATION_EVENTS`).
    output_step : float or None
        Spacing of the output times [s]; None: only t = 0 and t_c.
    t_max : float or None
        Give up if the ball has not separated by then [s]; None: 20 x the eq 11 estimate.
    rtol, atol : float
        Tolerances of the BDF integrators (the exact path has none).
    """

    separation: str = "displacement"
    output_step: float | None = 1e-5
    t_max: float | None = None
    rtol: float = 1e-10
    atol: float = 1e-12


#: The integrators' defaults.
DEFAULT_INTEGRATION = Integration()


def modal_system(
    omega: np.ndarray,
    shapes: np.ndarray,
    g: np.ndarray,
    ball_mass: float,
    kcb: float,
    ccb: float,
    speed: float,
) -> CoupledSystem:
    """Ball + frame in mass-normalised free-free modal coordinates.

    Parameters
    ----------
    omega : ndarray, shape (m,)
        Angular frequencies of the retained modes, rigid modes as 0 [rad/s].
    shapes : ndarray, shape (ndof, m)
        Mass-normalised mode shapes.
    g : ndarray, shape (ndof,)
        Point vector at the impact point.
    """
    import scipy.sparse as sp

    a = shapes.T @ g
    m = a.size
    mass = sp.diags(np.concatenate([[ball_mass], np.ones(m)]))
    stiff = sp.diags(np.concatenate([[0.0], omega**2]))
    h = np.concatenate([[1.0], -a])
    rc = float(np.sum(a[omega == 0.0] ** 2))
    return CoupledSystem(mass, stiff, h, kcb, ccb, speed, "modal", rc, np.asarray(omega), shapes)


def physical_system(
    K: sp.spmatrix,
    M: sp.spmatrix,
    g: np.ndarray,
    ball_mass: float,
    kcb: float,
    ccb: float,
    speed: float,
    rigid_compliance: float,
) -> CoupledSystem:
    """Ball + frame in the physical Hermite DOFs (the full FE model, nothing truncated).

    ``rigid_compliance`` is 1/m_R + d^2/I_R [1/kg], used only to estimate the contact time.
    """
    import scipy.sparse as sp

    mass = sp.block_diag([sp.csr_matrix([[ball_mass]]), M]).tocsr()
    stiff = sp.block_diag([sp.csr_matrix((1, 1)), K]).tocsr()
    h = np.concatenate([[1.0], -g])
    return CoupledSystem(mass, stiff, h, kcb, ccb, speed, "physical", rigid_compliance)
