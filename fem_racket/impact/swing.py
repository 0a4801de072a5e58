"""The racket's motion before impact: a swing, and the ball speed it gives.

A swinging racket moves as a rigid body before the impact: the point at x [m] from the butt
moves towards the ball at ``s(x) = v + omega x`` (``v`` the butt's speed, ``omega`` the angular
speed; positive towards the ball). Players give it as a racket speed V at a reference point
x_ref (the string centre, 0.75 L by default) and a pivot P (the hand, 0.07-0.10 m from the butt,
or the shoulder beyond the butt at P < 0): the racket turns about P, so
``s(x) = V (x - P) / (x_ref - P)``; without a pivot it translates, ``s(x) = V``.

The ball arrives at v_in; the impact point x_i moves at ``v_r = s(x_i)``. In the linear model the
rigid swing, with the ball moving along with the contact point, is a free solution (rigid modes
carry no strain and the spring stays at delta = 0), so the impact superposes on the stationary
one at the closing speed v_in + v_r (Brody, Cross & Lindsey, *The Physics and Technology of
Tennis*, 2002, ch. 11)::

    v_out = e_A v_in + (1 + e_A) v_r

with e_A the apparent coefficient of restitution: the COR of the stationary free racket struck
at the closing speed (the COR every other command computes). The ball/string stiffness K_CB
follows the closing speed (the speed at which ball and strings meet) unless given. The identity
is exact for the linear law; the tests check it against a direct BDF/CVODE integration started
from the swing's velocity field.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, replace
from typing import Any, Protocol

import numpy as np

from fem_racket.frame.model import FrameModel
from fem_racket.impact.closing import closing_speed
from fem_racket.impact.constants import DEFAULT_REFERENCE, MAX_RACKET_SPEED
from fem_racket.impact.swing_reach import allowed_pivots
from fem_racket.impact.system import CoupledSystem, Trajectory
from fem_racket.validation import InputError, check_finite, check_range, show

__all__ = [
    "MAX_RACKET_SPEED",
    "Rebound",
    "Swing",
    "add_swing",
    "ball_speed_out",
    "check_racket_speed",
    "check_swing_speeds",
    "racket_velocity",
    "rebound_summary",
    "swing_setup",
    "swing_summary",
]


@dataclass(frozen=True)
class Swing:
    """Rigid racket motion before impact: the point x [m] moves at v + omega x towards the ball.

    Parameters
    ----------
    velocity : float
        Speed of the butt (x = 0) towards the ball [m/s].
    omega : float
        Angular speed [rad/s], positive when the tip moves faster towards the ball.
    """

    velocity: float = 0.0
    omega: float = 0.0

    def __post_init__(self) -> None:
        object.__setattr__(self, "velocity", check_finite("velocity", self.velocity, "m/s"))
        object.__setattr__(self, "omega", check_finite("omega", self.omega, "rad/s"))

    @classmethod
    def from_speed(
        cls,
        racket_speed: float,
        length: float,
        *,
        reference: float | None = None,
        pivot: float | None = None,
    ) -> Swing:
        """A swing given as a racket speed at a reference point, about an optional pivot.

        Parameters
        ----------
        racket_speed : float
            Speed of the reference point towards the ball [m/s].
        length : float
            Racket length L [m].
        reference : float, optional
            Reference point, x/L in [0, 1]; when None (not given), 0.75 (the string centre).
        pivot : float, optional
            Pivot from the butt [m] (negative: beyond the butt, e.g. a shoulder); the racket
            translates when None. Refused where it would move the butt or the tip faster than
            :data:`MAX_RACKET_SPEED` (:func:`~fem_racket.impact.swing_reach.pivot_reach`).
        """
        v = check_racket_speed(racket_speed)
        reference = DEFAULT_REFERENCE if reference is None else reference
        ref = check_range("reference", reference, 0.0, 1.0, unit="x/L") * length
        if pivot is None:
            return cls(v, 0.0)
        p = check_finite("pivot", pivot, "m")
        if abs(ref - p) < 1e-9 * length:
            raise InputError(
                f"pivot = {show(pivot)} m is not allowed: it is the reference point "
                f"({ref:g} m), whose speed it would fix at zero",
                parameter="pivot",
                value=pivot,
            )
        omega = v / (ref - p)
        swing = cls(-omega * p, omega)
        try:
            check_swing_speeds(swing, length)
        except InputError:  # named as the pivot given, with the pivots allowed
            raise InputError(
                f"pivot = {show(pivot)} m is not allowed with racket_speed = {show(v)} m/s: the "
                f"racket would turn at {abs(omega):.4g} rad/s, its butt or tip faster than "
                f"{MAX_RACKET_SPEED:g} m/s: {allowed_pivots(v, ref, length)}",
                parameter="pivot",
                value=pivot,
            ) from None
        return swing

    def fastest(self, length: float) -> float:
        """The largest |speed| [m/s] of a point of a racket of ``length`` [m]: its butt's or
        its tip's (the speed is linear along it)."""
        return float(np.max(np.abs(self.speed_at(np.array([0.0, length])))))

    def speed_at(self, x: float | np.ndarray) -> float | np.ndarray:
        """Speed of the point(s) ``x`` [m] towards the ball [m/s]."""
        out = self.velocity + self.omega * np.asarray(x, dtype=float)
        return float(out) if out.ndim == 0 else out

    def cg_motion(self, cg: float) -> tuple[float, float]:
        """(v, omega) of the centre of gravity at ``cg`` [m] along the ball's travel: the
        speed [m/s] and angular speed [rad/s] with the signs of the frame coordinates (a racket
        swung towards the ball has both negative); the ``frame_velocity`` form of the general
        integrator's moving racket."""
        return -float(self.speed_at(cg)), -self.omega

    @property
    def pivot(self) -> float | None:
        """The point of zero speed [m from the butt]; None for a translation."""
        return None if self.omega == 0.0 else -self.velocity / self.omega

    def summary(self) -> dict[str, Any]:
        """JSON-ready, units in the keys."""
        return {
            "racket_butt_speed_m_s": self.velocity,
            "racket_angular_speed_rad_s": self.omega,
            "pivot_m": self.pivot,
        }


def check_racket_speed(racket_speed: object) -> float:
    """The racket speed V [m/s] as a float, or refused beyond +-:data:`MAX_RACKET_SPEED` (one
    line naming ``racket_speed``): a swing's, ``--racket-speed``'s, a run file's, a sweep's."""
    v_max = MAX_RACKET_SPEED
    return check_range("racket_speed", racket_speed, -v_max, v_max, unit="m/s")


def check_swing_speeds(swing: Swing, length: float) -> None:
    """Refuse a swing moving a point of a racket of ``length`` [m] (its butt or its tip)
    faster than :data:`MAX_RACKET_SPEED` (one line, naming the swing)."""
    if swing.fastest(length) > MAX_RACKET_SPEED:
        butt, tip = swing.speed_at(0.0), swing.speed_at(length)
        raise InputError(
            f"swing = {swing!r} is not allowed: its butt moves at {butt:.4g} m/s and its tip "
            f"at {tip:.4g} m/s, faster than the {MAX_RACKET_SPEED:g} m/s a racket may move"
        )


def ball_speed_out(apparent_cor: Any, speed: Any, racket_speed: Any) -> Any:
    """v_out = e_A v_in + (1 + e_A) v_r [m/s] (Brody, Cross & Lindsey 2002, ch. 11).

    Elementwise on arrays: apparent COR e_A, ball speed v_in and impact-point speed v_r [m/s].
    """
    e = np.asarray(apparent_cor)
    return e * np.asarray(speed) + (1.0 + e) * np.asarray(racket_speed)


class Rebound(Protocol):
    """An impact's outcome on a racket at rest or swinging (a free or a held racket's)."""

    @property
    def apparent_cor(self) -> float:
        """Apparent COR e_A = (v_out - v_r) / (v_in + v_r) [-]: that of the racket at rest
        struck at the closing speed."""

    @property
    def ball_speed_out(self) -> float:
        """The ball's speed after impact v_out [m/s], away from the racket."""

    @property
    def contact_time(self) -> float:
        """Contact time t_c [s]."""

    @property
    def peak_force(self) -> float:
        """Peak contact force [N]."""


def rebound_summary(result: Rebound, racket_speed: float) -> dict[str, float]:
    """The outcome's keys of a result's summary, JSON-ready, units in the keys: the COR (the
    apparent COR e_A, that of the racket at rest at the closing speed), v_out [m/s], the impact
    point's ``racket_speed`` v_r [m/s], t_c [s], the rebound speed (v_out) [m/s] and the peak
    contact force [N]."""
    return {
        "cor": result.apparent_cor,
        "apparent_cor": result.apparent_cor,
        "ball_speed_out_m_s": result.ball_speed_out,
        "racket_speed_at_impact_m_s": racket_speed,
        "contact_time_s": result.contact_time,
        "rebound_speed_m_s": result.ball_speed_out,
        "peak_force_n": result.peak_force,
    }


def racket_velocity(model: FrameModel, qd: np.ndarray) -> tuple[float, float]:
    """Rigid part of a frame velocity ``qd`` (Hermite DOF rates): the centre of gravity's speed
    [m/s] and the angular speed [rad/s], from the frame's linear and angular momentum
    (1^T M qd / M and (x - x_CG)^T M qd / I_CG), in the sign of ``qd``."""
    fe, props = model.fe, model.props
    v_cg = fe.rigid_motion(1.0, 0.0) @ fe.mass_product(qd) / props.mass
    omega = fe.rigid_motion(0.0, 1.0, about=props.cg) @ fe.mass_product(qd) / props.inertia
    return float(v_cg), float(omega)


def swing_summary(
    model: FrameModel, swing: Swing | None, after: tuple[float, float]
) -> dict[str, Any]:
    """The swing before and the racket's rigid motion ``after`` the impact, JSON-ready."""
    before = (swing or Swing()).summary()
    props = model.props
    before["racket_cg_speed_before_m_s"] = float((swing or Swing()).speed_at(props.cg))
    before["racket_cg_speed_after_m_s"] = after[0]
    before["racket_angular_speed_after_rad_s"] = after[1]
    return before


def _frame_velocity(frame_map: np.ndarray | None, model: FrameModel, swing: Swing) -> np.ndarray:
    """The swing's rigid velocity field in the frame coordinates of ``frame_map`` (positive
    along the ball's travel, i.e. minus the speed towards the ball)."""
    fe = model.fe
    qd = fe.rigid_motion(-swing.velocity, -swing.omega)
    if frame_map is None:
        return qd
    # Mass-normalised modes: eta' = Phi^T M q' (the rigid field lies in the rigid modes; off
    # axis the torsion DOFs follow the Hermite ones and the swing does not twist).
    return frame_map[: fe.ndof].T @ fe.mass_product(qd)


def add_swing(
    traj: Trajectory, frame_map: np.ndarray | None, model: FrameModel, swing: Swing, v_r: float
) -> Trajectory:
    """The stationary impact's trajectory (struck at the closing speed) plus the free rigid
    swing: the ball moving with the impact point at -v_r, the frame with the swing's field."""
    free = np.concatenate([[-v_r], _frame_velocity(frame_map, model, swing)])
    return replace(traj, x=traj.x + np.multiply.outer(traj.t, free), v=traj.v + free)


def swing_setup(
    system: CoupledSystem, model: FrameModel, swing: Swing, x_impact: float, *, direct: bool
) -> tuple[CoupledSystem, Callable[[Trajectory], Trajectory]]:
    """The system to integrate for a swing, and the map from its trajectory to the lab's.

    ``direct``: the racket starts with the swing's velocity field and the ball at its own
    speed (every integrator that takes an initial state: BDF, CVODE). Otherwise the stationary
    system at the closing speed, with the rigid swing added afterwards (superposition; the
    exact closed form, which solves the stationary impact).
    """
    v_r = float(swing.speed_at(x_impact))
    if direct:
        w = _frame_velocity(system.frame_map, model, swing)
        return replace(system, frame_velocity0=w), lambda traj: traj
    moving = replace(system, speed=closing_speed(system.speed, v_r))
    return moving, lambda traj: add_swing(traj, system.frame_map, model, swing, v_r)
