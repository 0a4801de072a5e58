"""The ball and the racket along the face before an oblique impact: :class:`BallMotion` (with
the racket's tangential compliance at the impact point) and :class:`RacketYaw` (the free
racket's rotation about the face normal); :mod:`fem_racket.impact.tangential.oblique` marches
the contact from them.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

__all__ = ["BallMotion", "RacketYaw"]


@dataclass(frozen=True)
class RacketYaw:
    """The free racket's rotation about the face normal through its centre of gravity.

    Parameters
    ----------
    inertia : float
        I_n [kg m^2], the moment of inertia about the face normal through the centre of gravity
        (a flat racket: I_cg + I_p, the perpendicular-axis theorem).
    arm : float
        b [m], the impact point from the centre of gravity along the long axis.
    offset : float
        y [m], the impact point from the long axis across the face.
    """

    inertia: float
    arm: float = 0.0
    offset: float = 0.0


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
    lateral_speed : float
        v_y [m/s], the ball across the face.
    racket_lateral_speed : float
        V_y [m/s], the strings' surface across the face before impact.
    yaw : RacketYaw, optional
        The free racket's yaw; None: it only translates (or it is clamped).
    """

    mass: float
    tangential_speed: float
    normal_speed_out: float
    racket_mass: float = math.inf
    racket_speed: float = 0.0
    lateral_speed: float = 0.0
    racket_lateral_speed: float = 0.0
    yaw: RacketYaw | None = None

    def racket_compliance(self) -> np.ndarray:
        """C_r [1/kg]: the impact point's velocity change per tangential impulse on the
        racket, (along, across) (zero for a clamped head)."""
        if math.isinf(self.racket_mass):
            return np.zeros((2, 2))
        y = b = 0.0
        inertia = math.inf
        if self.yaw is not None:
            y, b, inertia = self.yaw.offset, self.yaw.arm, self.yaw.inertia
        inv = 1.0 / self.racket_mass
        return np.array(
            [[inv + y * y / inertia, -b * y / inertia], [-b * y / inertia, inv + b * b / inertia]]
        )
