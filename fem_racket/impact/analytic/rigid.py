"""Closed-form impacts of Kawazoe & Kanda (1997): clamped frame (eqs 1-4), rigid frame (eqs 5-12).

Clamped frame, ball of mass m_B on a spring K_CB and dashpot C_CB (eqs 1-3)::

    Omega = sqrt(K_CB / m_B),  zeta = C_CB / (2 sqrt(m_B K_CB)),  omega_d = Omega sqrt(1 - zeta^2)
    T_c = pi / omega_d                                          (1)
    V_B = -V_B0 exp(-Omega zeta T_c)                            (2)

Free rigid frame (mass m_R, inertia I_R about its centre of gravity, impact at distance d from
it), no damping (eqs 5-12)::

    alpha = d^2 / (I_R / m_R)                                   (6)
    omega = sqrt(((1 + alpha) m_B + m_R) K_CB / (m_B m_R))      (5)
    V_T = V_B0 m_B / (m_B + m_R)                                (8)
    V_R = V_B0 alpha m_B m_R / ((m_B + m_R)((1 + alpha) m_B + m_R))   (9)
    V_I = V_B0 m_R / ((1 + alpha) m_B + m_R)                    (10)
    T_c = pi / omega                                            (11)
    V_B = V_T + V_R - V_I                                       (12)

Velocities are positive in the direction of the incoming ball, so a rebound has V_B < 0 and the
coefficient of restitution is COR = -V_B / V_B0.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import TYPE_CHECKING

from fem_racket.contact.linear import DEFAULT_BALL_MASS, kcb_from_speed
from fem_racket.validation import check_finite, check_positive, check_range

if TYPE_CHECKING:
    from fem_racket.frame.modal import MassProperties

__all__ = ["ClampedImpact", "RigidImpact", "clamped_impact", "rigid_impact", "rigid_impact_at"]


@dataclass(frozen=True)
class ClampedImpact:
    """Eqs 1-3 for a clamped frame.

    Attributes
    ----------
    omega_n : float
        Undamped angular frequency Omega [rad/s].
    omega_d : float
        Damped angular frequency [rad/s].
    contact_time : float
        T_c [s], eq 1.
    rebound_velocity : float
        V_B [m/s], eq 2 (negative: away from the strings).
    cor : float
        -V_B / V_B0.
    """

    omega_n: float
    omega_d: float
    contact_time: float
    rebound_velocity: float
    cor: float


def clamped_impact(ball_mass: float, kcb: float, zeta: float, speed: float) -> ClampedImpact:
    """Ball on strings in a clamped frame: eqs 1-3.

    Parameters
    ----------
    ball_mass : float
        m_B [kg].
    kcb : float
        K_CB [N/m].
    zeta : float
        Damping ratio, in [0, 1).
    speed : float
        V_B0 [m/s].
    """
    m = check_positive("ball mass", ball_mass, "kg")
    k = check_positive("kcb", kcb, "N/m")
    z = check_range("zeta", zeta, 0.0, 1.0, include_high=False)
    v0 = check_positive("speed", speed, "m/s")
    omega_n = math.sqrt(k / m)
    omega_d = omega_n * math.sqrt(1.0 - z * z)
    tc = math.pi / omega_d
    vb = -v0 * math.exp(-omega_n * z * tc)
    return ClampedImpact(omega_n, omega_d, tc, vb, -vb / v0)


@dataclass(frozen=True)
class RigidImpact:
    """Eqs 5-12 for a free rigid frame without damping.

    Attributes
    ----------
    alpha : float
        d^2 m_R / I_R, eq 6.
    omega : float
        Angular frequency of the ball relative to the frame [rad/s], eq 5.
    v_translation, v_rotation, v_vibration : float
        V_T, V_R, V_I [m/s], eqs 8-10.
    contact_time : float
        T_c [s], eq 11.
    rebound_velocity : float
        V_B [m/s], eq 12.
    cor : float
        -V_B / V_B0.
    """

    alpha: float
    omega: float
    v_translation: float
    v_rotation: float
    v_vibration: float
    contact_time: float
    rebound_velocity: float
    cor: float


def rigid_impact(
    ball_mass: float,
    frame_mass: float,
    frame_inertia: float,
    distance: float,
    kcb: float,
    speed: float,
) -> RigidImpact:
    """Ball on strings of a free rigid frame, no damping: eqs 5-12.

    Parameters
    ----------
    ball_mass : float
        m_B [kg].
    frame_mass : float
        m_R [kg].
    frame_inertia : float
        I_R about the centre of gravity [kg m^2].
    distance : float
        d, impact point to centre of gravity [m] (either sign).
    kcb : float
        K_CB [N/m].
    speed : float
        V_B0 [m/s].
    """
    mb = check_positive("ball mass", ball_mass, "kg")
    mr = check_positive("frame mass", frame_mass, "kg")
    ir = check_positive("frame inertia", frame_inertia, "kg m^2")
    d = check_finite("distance", distance, "m")
    k = check_positive("kcb", kcb, "N/m")
    v0 = check_positive("speed", speed, "m/s")
    alpha = d * d / (ir / mr)
    meff = (1.0 + alpha) * mb + mr
    omega = math.sqrt(meff * k / (mb * mr))
    vt = v0 * mb / (mb + mr)
    vr = v0 * alpha * mb * mr / ((mb + mr) * meff)
    vi = v0 * mr / meff
    vb = vt + vr - vi
    return RigidImpact(alpha, omega, vt, vr, vi, math.pi / omega, vb, -vb / v0)


def rigid_impact_at(
    props: MassProperties,
    position: float,
    speed: float,
    *,
    ball_mass: float = DEFAULT_BALL_MASS,
    kcb: float | None = None,
) -> RigidImpact:
    """Eqs 5-12 for a frame of given mass properties struck at ``position``.

    Parameters
    ----------
    props : MassProperties
        Mass, centre of gravity and inertia of the frame (``FrameModel.props``).
    position : float
        Impact point x/L from the grip end.
    speed : float
        V_B0 [m/s].
    ball_mass : float
        m_B [kg].
    kcb : float, optional
        K_CB [N/m]; from the speed (:func:`fem_racket.contact.linear.kcb_from_speed`) when None.
    """
    pos = check_range("position", position, 0.0, 1.0, unit="x/L")
    k = kcb_from_speed(speed) if kcb is None else kcb
    d = pos * props.length - props.cg
    return rigid_impact(ball_mass, props.mass, props.inertia, d, k, speed)
