"""The oblique impact's outcome: the ball's speed, angle and spin out, and the contact regime.

The ball (mass m, radius R, I = k m R^2) arrives at normal speed v_n and tangential speed v_t
along the face with spin omega (positive = topspin, :mod:`fem_racket.impact.incidence`); the
strings' surface moves along the face at V (a swinging racket; 0 at rest). The contact point
slips at s_0 = v_t - R omega - V. With J the tangential impulse on the ball
(:mod:`fem_racket.impact.tangential.march`)::

    v_t' = v_t + J / m,   omega' = omega - R J / I,   V' = V - J / M_t

so the ball's angular momentum about the contact point, I omega + m R v_t, and the tangential
momentum m v_t + M_t V are conserved. The ball leaves at speed sqrt(v_n'^2 + v_t'^2) and angle
atan(v_t' / v_n') from the face normal (positive: on the side it arrived from), with v_n' the
normal impact's rebound speed. The tangential COR is e_T = -s_end / s_0 (Cross 2005, Am. J.
Phys. 73: e_x = -(v_x2 - R omega_2) / v_x1 for a ball without spin on a fixed surface).
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from fem_racket.impact.incidence import RPM, Incidence
from fem_racket.impact.tangential.march import TangentialContact, TangentialSolution, march
from fem_racket.impact.tangential.normal import NormalHistory

__all__ = ["BallMotion", "ObliqueOutcome", "tangential_impact"]


@dataclass(frozen=True)
class BallMotion:
    """The ball and the strings' surface along the face.

    Parameters
    ----------
    mass : float
        m [kg].
    tangential_speed : float
        v_t [m/s] along the face.
    normal_speed_out : float
        The normal impact's rebound speed v_n' [m/s] (away from the strings).
    racket_mass : float
        M_t [kg], the racket's tangential effective mass (``math.inf``: clamped head).
    racket_speed : float
        V [m/s], the strings' surface along the face before impact.
    """

    mass: float
    tangential_speed: float
    normal_speed_out: float
    racket_mass: float = math.inf
    racket_speed: float = 0.0


@dataclass(frozen=True, eq=False)
class ObliqueOutcome:
    """Outcome of the tangential contact of one oblique impact."""

    incidence: Incidence
    ball: BallMotion
    solution: TangentialSolution

    @property
    def inertia(self) -> float:
        """I [kg m^2]."""
        return self.incidence.ball_inertia * self.ball.mass * self.incidence.radius**2

    @property
    def impulse(self) -> float:
        """J [N s], tangential impulse on the ball."""
        return self.solution.impulse

    @property
    def tangential_speed_out(self) -> float:
        return self.ball.tangential_speed + self.impulse / self.ball.mass

    @property
    def spin_out(self) -> float:
        """omega' [rad/s], positive = topspin."""
        return self.incidence.spin_rad_s - self.incidence.radius * self.impulse / self.inertia

    @property
    def racket_speed_out(self) -> float:
        """V' [m/s] of the strings' surface along the face (0 for a clamped head)."""
        if math.isinf(self.ball.racket_mass):
            return self.ball.racket_speed
        return self.ball.racket_speed - self.impulse / self.ball.racket_mass

    @property
    def slip_in(self) -> float:
        return self.solution.phases[0].slip

    @property
    def tangential_cor(self) -> float:
        """e_T = -s_end / s_0 (NaN when the ball arrives without slip)."""
        s0 = self.slip_in
        return -self.solution.final_slip / s0 if s0 != 0.0 else math.nan

    @property
    def ball_speed_out(self) -> float:
        return math.hypot(self.ball.normal_speed_out, self.tangential_speed_out)

    @property
    def angle_out(self) -> float:
        """Angle of the outgoing path from the face normal [deg]."""
        return math.degrees(math.atan2(self.tangential_speed_out, self.ball.normal_speed_out))

    def tangential_energy(self) -> tuple[float, float]:
        """Kinetic energy along the face of ball (with spin) and racket, before and after [J];
        for a clamped head (infinite M_t) in the frame moving with it."""
        m, inertia, big_m = self.ball.mass, self.inertia, self.ball.racket_mass
        clamped = math.isinf(big_m)

        def energy(v: float, w: float, big_v: float) -> float:
            if clamped:
                return 0.5 * (m * (v - big_v) ** 2 + inertia * w * w)
            return 0.5 * (m * v * v + inertia * w * w + big_m * big_v**2)

        before = energy(
            self.ball.tangential_speed, self.incidence.spin_rad_s, self.ball.racket_speed
        )
        after = energy(self.tangential_speed_out, self.spin_out, self.racket_speed_out)
        return before, after

    def histories(self, t: np.ndarray) -> dict[str, np.ndarray]:
        """Slip velocity and tangential force on the ball at times ``t`` [s]."""
        s, f = self.solution.at(t)
        return {"slip velocity [m/s]": s, "tangential force [N]": f}

    def summary(self) -> dict[str, Any]:
        """Outgoing speed, angle and spin, the regime and its times, units in the keys."""
        sol = self.solution
        return {
            "ball_speed_out_m_s": self.ball_speed_out,
            "angle_out_deg": self.angle_out,
            # in rpm from the rpm given, so that no impulse leaves the number as it was
            "spin_out_rpm": self.incidence.spin
            - self.incidence.radius * self.impulse / self.inertia / RPM,
            "contact_regime": sol.regime,
            "grip_times_s": [list(g) for g in sol.grip_intervals],
            "friction_reversal_times_s": sol.reversal_times,
            "tangential_cor": self.tangential_cor,
            "tangential_impulse_n_s": self.impulse,
            "tangential_stiffness_n_m": self.solution.contact.stiffness,
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
        Ball mass, speeds and the racket's tangential mass and speed.
    """
    m = ball.mass
    inv = incidence.beta_t / m + (0.0 if math.isinf(ball.racket_mass) else 1.0 / ball.racket_mass)
    eta2 = incidence.compliance_ratio
    k_t = math.inf if eta2 == 0.0 else normal.stiffness / eta2
    contact = TangentialContact(incidence.friction, k_t, 1.0 / inv)
    slip = ball.tangential_speed - incidence.radius * incidence.spin_rad_s - ball.racket_speed
    return ObliqueOutcome(incidence, ball, march(contact, normal, slip))
