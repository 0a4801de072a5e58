"""The outcome of one impact: :class:`ImpactResult` (histories, COR, contact time, peak force,
the swing's ball speed, energies and momenta, what the run used).

COR = -v_B(t_c) / V_B0 on a stationary free racket (Kawazoe & Kanda 1997, section 3.2); with a
swing the apparent COR e_A = (v_out - v_r) / (v_in + v_r).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from fem_racket.contact.law import ContactLaw
from fem_racket.contact.linear import Ball, LinearContact
from fem_racket.frame.model import FrameModel
from fem_racket.impact.problem import Impact
from fem_racket.impact.swing import Swing, racket_velocity, rebound_summary, swing_summary

__all__ = ["ImpactResult"]


@dataclass(frozen=True, eq=False)
class ImpactResult:
    """Outcome and time histories of one impact.

    Attributes
    ----------
    model : FrameModel
        The frame that was struck (mesh, K, M).
    impact : Impact
        Impact point (x/L) and speed [m/s].
    ball : Ball
    contact : LinearContact or None
        K_CB [N/m] and zeta used (None when another contact law was used).
    solver, separation, basis : str
        How the impact was computed.
    n_modes : int or None
        Flexible modes kept (None for the physical basis).
    t : ndarray, shape (nt,)
        Output times [s]; the last is the contact time.
    ball_displacement, ball_velocity : ndarray, shape (nt,)
        u_B [m] and v_B [m/s], positive towards the frame.
    frame_displacement, frame_velocity : ndarray, shape (nt, ndof)
        Hermite DOFs of the frame (deflection [m] and slope [rad] per node) and their rates.
    peak_force : float
        Largest contact force during contact [N], from the integrator's dense solution (the
        closed form is maximised exactly), whatever the output times.
    law : ContactLaw or None
        The contact law when it is not the paper's linear one on its exact path.
    law_state : ndarray or None, shape (nt,)
        The law's internal state [m] at the output times.
    rtol, atol : float or None
        Tolerances of the BDF integrator that ran (None for the exact solver, which has none).
    tolerance : float or None
        COR tolerance of the batched engine when it ran (exact solver, no histories); None
        otherwise.
    """

    model: FrameModel
    impact: Impact
    ball: Ball
    contact: LinearContact
    solver: str
    separation: str
    basis: str
    n_modes: int | None
    t: np.ndarray
    ball_displacement: np.ndarray
    ball_velocity: np.ndarray
    frame_displacement: np.ndarray
    frame_velocity: np.ndarray
    peak_force: float
    law: ContactLaw | None = None
    law_state: np.ndarray | None = None
    rtol: float | None = None
    atol: float | None = None
    tolerance: float | None = None

    # -- notebook forms (fem_racket.impact.result_views) ------------------------------------
    def __repr__(self) -> str:
        from fem_racket.impact.result_views import impact_repr

        return impact_repr(self)

    def _repr_html_(self) -> str:
        from fem_racket.impact.result_views import impact_html

        return impact_html(self)

    def to_xarray(self, x: np.ndarray | None = None) -> Any:
        """Time histories as an ``xarray.Dataset`` over ``time`` [s], with the frame's
        deflection over ``x`` [m] (the mesh nodes by default) and the summary in ``attrs``."""
        from fem_racket.impact.result_views import impact_dataset

        return impact_dataset(self, x)

    swing: Swing | None = None
    #: Lateral offset of the impact point from the long axis [m]; off axis (!= 0) the twist
    #: histories on the torsion DOFs [rad], [rad/s] (:mod:`fem_racket.impact.result_twist`),
    #: None on the axis.
    offset: float = 0.0
    twist: np.ndarray | None = None
    twist_rate: np.ndarray | None = None

    # -- scalar outcomes -------------------------------------------------------------------
    @property
    def contact_time(self) -> float:
        """t_c [s]."""
        return float(self.t[-1])

    @property
    def rebound_velocity(self) -> float:
        """Ball velocity at separation [m/s] (negative: rebounding)."""
        return float(self.ball_velocity[-1])

    @property
    def cor(self) -> float:
        """Coefficient of restitution: the apparent COR :attr:`apparent_cor` (on a stationary
        racket -v_B(t_c) / V_B0)."""
        return self.apparent_cor

    @property
    def racket_speed_at_impact(self) -> float:
        """v_r: speed of the impact point towards the ball before impact [m/s] (0 at rest)."""
        return 0.0 if self.swing is None else float(self.swing.speed_at(self.x_impact))

    @property
    def ball_speed_out(self) -> float:
        """v_out = -v_B(t_c): the ball's speed away from the racket after impact [m/s]."""
        return -self.rebound_velocity

    @property
    def apparent_cor(self) -> float:
        """e_A = (v_out - v_r) / (v_in + v_r): rebound over closing speed relative to the impact
        point (the COR of the stationary racket struck at the closing speed)."""
        v_r = self.racket_speed_at_impact
        return (self.ball_speed_out - v_r) / (self.impact.speed + v_r)

    def racket_motion_after(self) -> tuple[float, float]:
        """Rigid motion of the racket at separation: centre-of-gravity speed [m/s] and angular
        speed [rad/s], both towards the ball (a racket pushed back by the ball slows down)."""
        return racket_velocity(self.model, -self.frame_velocity[-1])

    # -- derived histories -----------------------------------------------------------------
    @property
    def x_impact(self) -> float:
        """Impact point x_i [m]."""
        return self.impact.position * self.model.mesh.length

    @property
    def damping(self) -> float:
        """C_CB [N s/m]."""
        return self.contact.damping(self.ball.mass)

    @property
    def impact_point_displacement(self) -> np.ndarray:
        """Frame displacement at the impact point w(x_i, t) (+ y theta(x_i, t) off axis) [m]."""
        w = self.frame_displacement @ self.model.fe.point_vector(self.x_impact)
        return w if self.twist is None else w + self.twist @ self._twist_point

    @property
    def impact_point_velocity(self) -> np.ndarray:
        """Frame velocity at the impact point [m/s]."""
        w = self.frame_velocity @ self.model.fe.point_vector(self.x_impact)
        return w if self.twist is None else w + self.twist_rate @ self._twist_point

    @property
    def _twist_point(self) -> np.ndarray:
        """y g_t(x_i): the face point's displacement per torsion DOF [m/rad]."""
        g = self.model.torsion.point_matrix(np.array([self.x_impact]))[0]
        return self.offset * g

    @property
    def deflection(self) -> np.ndarray:
        """Spring deflection delta = u_B - w(x_i) [m] (positive: compressed)."""
        return self.ball_displacement - self.impact_point_displacement

    @property
    def deflection_rate(self) -> np.ndarray:
        """delta' [m/s]."""
        return self.ball_velocity - self.impact_point_velocity

    @property
    def force(self) -> np.ndarray:
        """Contact force F = K_CB delta + C_CB delta' [N] (or the law's F(delta, delta', z))."""
        rate = self.deflection_rate
        if self.law is not None:
            return np.asarray(self.law.force(self.deflection, rate, self.law_state))
        return self.contact.stiffness * self.deflection + self.damping * rate

    @property
    def compression_stiffness(self) -> float:
        """The normal stiffness k_n [N/m] of an oblique impact's tangential contact: K_CB for
        the paper's law (exact: its dashpot's force vanishes at the largest compression); under
        another law its force over delta where delta peaks, located between the output times
        (:func:`~fem_racket.impact.result_peak.peak_secant`). Needs histories."""
        if self.contact is not None:
            return self.contact.stiffness
        from fem_racket.impact.result_peak import peak_secant

        return peak_secant(self.t, self.deflection, self.deflection_rate, self.law, self.law_state)

    def normal_samples(self) -> ImpactResult:
        """The result whose samples drive an oblique impact's tangential contact: this one (its
        output times are the caller's ``output_step``)."""
        return self

    def frame_field(self, x: np.ndarray, order: int = 0, velocity: bool = False) -> np.ndarray:
        """Frame deflection (order 0, [m]), slope (1, [rad]) or curvature (2, [1/m]) at points
        ``x`` [m] for every output time, shape (nt, len(x)); of the velocity when asked."""
        R = self.model.fe.field_matrix(np.asarray(x, dtype=float), order)
        q = self.frame_velocity if velocity else self.frame_displacement
        return np.asarray((R @ q.T).T)

    def energies(self) -> dict[str, np.ndarray]:
        """Energy histories [J]: ball kinetic, frame kinetic, frame strain, spring, dissipated
        (off axis also torsion kinetic and torsion strain).

        ``dissipated`` is the dashpot's work int C_CB delta'^2 dt (cumulative Simpson on the
        output times, so its accuracy follows ``output_step``); their sum ``total`` stays at
        the initial kinetic energy. Under another contact law ``spring`` and ``dissipated`` are
        replaced by ``contact``, the work the law has absorbed, int F delta' dt (stored plus
        dissipated). Needs time histories (an ``output_step``).
        """
        from fem_racket.impact.result_energy import impact_energies

        return impact_energies(self)

    def momentum(self) -> tuple[np.ndarray, np.ndarray]:
        """Linear [kg m/s] and angular momentum about the grip end [kg m^2/s] of ball + frame."""
        fe = self.model.fe
        one = fe.M @ fe.rigid_motion(1.0, 0.0)
        lever = fe.M @ fe.rigid_motion(0.0, 1.0)
        mv = self.ball.mass * self.ball_velocity
        return mv + self.frame_velocity @ one, self.x_impact * mv + self.frame_velocity @ lever

    def summary(self) -> dict[str, Any]:
        """Scalar results and :meth:`settings`, JSON-ready, units in the keys."""
        return {
            **rebound_summary(self, self.racket_speed_at_impact),
            **self.settings(),
            **swing_summary(self.model, self.swing, self.racket_motion_after()),
            **self._twist_summary(),
        }

    def _twist_summary(self) -> dict[str, Any]:
        if self.twist is None:
            return {}
        from fem_racket.impact.result_twist import twist_summary

        return twist_summary(self)

    def settings(self) -> dict[str, Any]:
        """What the run used, not what was asked: the solver that ran and its tolerances, the
        flexible modes kept, K_CB and zeta (derived from the speed unless given), C_CB, and the
        racket's swing when it had one.
        JSON-ready, units in the keys; every provenance records it under ``"used"``."""
        return {
            "solver": self.solver,
            "separation": self.separation,
            "basis": self.basis,
            "modes": self.n_modes,
            "elements": self.model.mesh.n_elements,
            "position_x_over_l": self.impact.position,
            "speed_m_s": self.impact.speed,
            "ball_mass_kg": self.ball.mass,
            "rtol": self.rtol,
            "atol": self.atol,
            "tolerance": self.tolerance,
            **self.law_summary(),
            **({} if self.swing is None else {"swing": self.swing.summary()}),
        }

    def law_summary(self) -> dict[str, Any]:
        """The contact law's name and parameters, units in the keys."""
        if self.law is not None:
            return self.law.describe()
        return {
            "law": "linear",
            "kcb_n_m": self.contact.stiffness,
            "zeta": self.contact.zeta,
            "ccb_n_s_m": self.damping,
        }
