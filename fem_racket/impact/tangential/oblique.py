"""The oblique impact's outcome: the ball's speed, angle and spin out, and the contact regime.

The ball (mass m, radius R, I = k m R^2) arrives at normal speed v_n, tangential speed v_t along
the face (x, the long axis) and v_y across it, with spin omega (positive = topspin) and side
spin omega_s (positive = rolling toward +y, :mod:`fem_racket.impact.incidence`); the strings'
surface moves along the face at (V, V_y) (a swinging racket; 0 at rest). The contact point
slips at s_0 = (v_t - R omega - V, v_y - R omega_s - V_y). With J = (J_x, J_y) the tangential
impulse on the ball (:mod:`fem_racket.impact.tangential.plane`)::

    v_t' = v_t + J_x / m,   omega' = omega - R J_x / I,   v_y' = v_y + J_y / m,
    omega_s' = omega_s - R J_y / I

so the ball's angular momentum about the contact point (I omega + m R v_t, and across) is
conserved. The racket (:class:`BallMotion`, :class:`RacketYaw`) moves rigidly in the face's
plane: its centre of gravity by -J / M and its yaw (rotation about the face normal) by
-(b J_y - y J_x) / I_n, the impact point at (b, y) from the centre of gravity. The ball leaves
at speed |(v_n', v_t', v_y')|, angle atan(v_t' / v_n') from the face normal in the plane of the
long axis (positive: on the side it arrived from) and side angle atan(v_y' / |(v_n', v_t')|)
from that plane, with v_n' the normal impact's rebound speed. The tangential COR is
e_T = -s_end . s_0 / |s_0|^2 (Cross 2005, Am. J. Phys. 73: e_x = -(v_x2 - R omega_2) / v_x1
for a ball without spin on a fixed surface).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from fem_racket.impact.incidence import RPM, Incidence
from fem_racket.impact.tangential.motion import BallMotion, RacketYaw
from fem_racket.impact.tangential.normal import NormalHistory
from fem_racket.impact.tangential.plane import LineSolution, PlaneContact, march_plane

__all__ = ["BallMotion", "ObliqueOutcome", "RacketYaw", "tangential_impact"]


@dataclass(frozen=True, eq=False)
class ObliqueOutcome:
    """Outcome of the tangential contact of one oblique impact."""

    incidence: Incidence
    ball: BallMotion
    plane: Any

    @property
    def solution(self) -> Any:
        """The marched contact: the 1-D
        :class:`~fem_racket.impact.tangential.march.TangentialSolution` when it stays on the
        long axis's line (as in the plane of the long axis), else the vector solution of
        :mod:`fem_racket.impact.tangential.plane` (``LineSolution`` or ``PlaneSolution``)."""
        p = self.plane
        if isinstance(p, LineSolution) and p.direction[1] == 0.0:
            return p.line
        return p

    @property
    def inertia(self) -> float:
        """I [kg m^2]."""
        return self.incidence.ball_inertia * self.ball.mass * self.incidence.radius**2

    @property
    def impulse(self) -> float:
        """J_x [N s], tangential impulse on the ball along the face."""
        return float(self.plane.impulse[0])

    @property
    def lateral_impulse(self) -> float:
        """J_y [N s], tangential impulse on the ball across the face."""
        return float(self.plane.impulse[1]) + 0.0  # no -0.0

    @property
    def lateral(self) -> bool:
        """True when anything crosses the face (incidence, racket or impulse)."""
        b = self.ball
        return (
            self.incidence.lateral
            or b.lateral_speed != 0.0
            or b.racket_lateral_speed != 0.0
            or self.lateral_impulse != 0.0
        )

    @property
    def tangential_speed_out(self) -> float:
        return self.ball.tangential_speed + self.impulse / self.ball.mass

    @property
    def lateral_speed_out(self) -> float:
        return self.ball.lateral_speed + self.lateral_impulse / self.ball.mass

    @property
    def spin_out(self) -> float:
        """omega' [rad/s], positive = topspin."""
        return self.incidence.spin_rad_s - self.incidence.radius * self.impulse / self.inertia

    @property
    def side_spin_out(self) -> float:
        """omega_s' [rad/s], positive = rolling toward +y."""
        r, j = self.incidence.radius, self.lateral_impulse
        return self.incidence.side_spin_rad_s - r * j / self.inertia

    def _racket_out(self) -> tuple[np.ndarray, float]:
        """The racket's centre-of-gravity velocity along the face (x, y) [m/s] and yaw rate
        [rad/s] after impact (it translated at the strings' speed before; clamped: unmoved)."""
        b = self.ball
        v = np.array([b.racket_speed, b.racket_lateral_speed])
        if math.isinf(b.racket_mass):
            return v, 0.0
        j = (self.impulse, self.lateral_impulse)
        v = np.array([v[0] - j[0] / b.racket_mass, v[1] - j[1] / b.racket_mass])
        if b.yaw is None:
            return v, 0.0
        return v, -(b.yaw.arm * j[1] - b.yaw.offset * j[0]) / b.yaw.inertia

    @property
    def racket_speed_out(self) -> float:
        """V' [m/s] of the strings' surface at the impact point along the face."""
        v, w = self._racket_out()
        return float(v[0] + w * -(0.0 if self.ball.yaw is None else self.ball.yaw.offset))

    @property
    def racket_lateral_speed_out(self) -> float:
        """V_y' [m/s] of the strings' surface at the impact point across the face."""
        v, w = self._racket_out()
        return float(v[1] + w * (0.0 if self.ball.yaw is None else self.ball.yaw.arm))

    @property
    def yaw_rate_out(self) -> float:
        """The racket's yaw rate after impact [rad/s] (about the face normal)."""
        return self._racket_out()[1]

    @property
    def slip_in(self) -> np.ndarray:
        """s_0 [m/s], (along, across)."""
        return self.plane.slip_in

    @property
    def tangential_cor(self) -> float:
        """e_T = -s_end . s_0 / |s_0|^2 (NaN when the ball arrives without slip)."""
        s0, s1 = self.slip_in, self.plane.final_slip
        if s0[1] == 0.0 and s1[1] == 0.0:
            return float(-s1[0] / s0[0]) if s0[0] != 0.0 else math.nan
        return float(-(s1 @ s0) / (s0 @ s0))

    @property
    def ball_speed_out(self) -> float:
        vn, vt, vy = self.ball.normal_speed_out, self.tangential_speed_out, self.lateral_speed_out
        return math.hypot(vn, vt) if vy == 0.0 else math.hypot(vn, vt, vy)

    @property
    def angle_out(self) -> float:
        """Angle of the outgoing path (projected on the plane of the long axis) from the outward
        face normal [deg], in (-180, 180]: over 90 in size where the ball keeps moving forward
        (a negative normal rebound, COR < 0: 180 head-on), as simulate's rebound speed says."""
        return math.degrees(math.atan2(self.tangential_speed_out, self.ball.normal_speed_out))

    @property
    def side_angle_out(self) -> float:
        """Angle of the outgoing path from the plane of the long axis [deg], positive toward
        +y."""
        in_plane = math.hypot(self.ball.normal_speed_out, self.tangential_speed_out)
        return math.degrees(math.atan2(self.lateral_speed_out, in_plane))

    def tangential_energy(self) -> tuple[float, float]:
        """Kinetic energy in the face's plane of ball (with spin and side spin) and racket
        (translation and yaw), before and after [J]; for a clamped head in the frame moving
        with it."""
        b, m, inertia = self.ball, self.ball.mass, self.inertia
        clamped = math.isinf(b.racket_mass)
        inc = self.incidence
        racket_in = np.array([b.racket_speed, b.racket_lateral_speed])
        racket_out, yaw = self._racket_out()
        i_n = 0.0 if b.yaw is None else b.yaw.inertia

        def energy(v, w, big_v, yaw_rate) -> float:
            if clamped:
                return 0.5 * (m * float(np.sum((v - big_v) ** 2)) + inertia * float(w @ w))
            racket = b.racket_mass * float(big_v @ big_v) + i_n * yaw_rate**2
            return 0.5 * (m * float(v @ v) + inertia * float(w @ w) + racket)

        before = energy(
            np.array([b.tangential_speed, b.lateral_speed]),
            np.array([inc.spin_rad_s, inc.side_spin_rad_s]),
            racket_in,
            0.0,
        )
        after = energy(
            np.array([self.tangential_speed_out, self.lateral_speed_out]),
            np.array([self.spin_out, self.side_spin_out]),
            racket_out,
            yaw,
        )
        return before, after

    def histories(self, t: np.ndarray) -> dict[str, np.ndarray]:
        """Slip velocity and tangential force on the ball at times ``t`` [s] (along the face;
        across it too when anything crosses)."""
        s, f = self.plane.at(t)
        out = {"slip velocity [m/s]": s[:, 0], "tangential force [N]": f[:, 0]}
        if self.lateral:
            out["lateral slip velocity [m/s]"] = s[:, 1]
            out["lateral tangential force [N]"] = f[:, 1]
        return out

    def summary(self) -> dict[str, Any]:
        """Outgoing speed, angle and spin, the regime and its times, units in the keys."""
        sol = self.plane
        return {
            "ball_speed_out_m_s": self.ball_speed_out,
            "angle_out_deg": self.angle_out,
            # in rpm from the rpm given, so that no impulse leaves the number as it was
            "spin_out_rpm": self.incidence.spin
            - self.incidence.radius * self.impulse / self.inertia / RPM,
            "side_spin_out_rpm": self.incidence.side_spin
            - self.incidence.radius * self.lateral_impulse / self.inertia / RPM,
            "side_angle_out_deg": self.side_angle_out,
            "contact_regime": sol.regime,
            "grip_times_s": [list(g) for g in sol.grip_intervals],
            "friction_reversal_times_s": sol.reversal_times,
            "tangential_cor": self.tangential_cor,
            "tangential_impulse_n_s": self.impulse,
            "lateral_tangential_impulse_n_s": self.lateral_impulse,
            "racket_yaw_rate_rad_s": self.yaw_rate_out,
            "tangential_stiffness_n_m": self.plane.contact.stiffness,
            **self.incidence.summary(),
        }


def tangential_impact(
    incidence: Incidence, normal: NormalHistory, ball: BallMotion
) -> ObliqueOutcome:
    """The tangential contact of an oblique impact over a computed normal impact.

    Parameters
    ----------
    incidence : Incidence
        Angle, spin, friction, ball inertia and radius, eta^2.
    normal : NormalHistory
        The normal impact's force history.
    ball : BallMotion
        Ball mass, speeds and the racket's tangential response and speed.
    """
    m = ball.mass
    a = ball.racket_compliance()
    a[0, 0] = incidence.beta_t / m + a[0, 0]
    a[1, 1] = incidence.beta_t / m + a[1, 1]
    eta2 = incidence.compliance_ratio
    k_t = math.inf if eta2 == 0.0 else normal.stiffness / eta2
    contact = PlaneContact(incidence.friction, k_t, a)
    r = incidence.radius
    slip = np.array(
        [
            ball.tangential_speed - r * incidence.spin_rad_s - ball.racket_speed,
            ball.lateral_speed - r * incidence.side_spin_rad_s - ball.racket_lateral_speed,
        ]
    )
    return ObliqueOutcome(incidence, ball, march_plane(contact, normal, slip))
