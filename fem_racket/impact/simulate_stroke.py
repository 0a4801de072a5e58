"""A stroke: the ball met by a tilted face swung along an inclined path, :func:`simulate_stroke`.

The stroke's geometry (:mod:`fem_racket.impact.oblique.stroke`) resolves the horizontal ball and the
racket's path on the face: the normal impact is the swinging racket's
(:func:`fem_racket.impact.simulate_oblique.normal_impact`) at ball speed V sin F with the swing
scaled to its normal part S sin(F - P), and the tangential contact starts from the ball's and
the strings' speeds along the face (the strings moving with the swing's part S cos(F - P)).
"""

from __future__ import annotations

import math
from typing import Any

from fem_racket.impact.incidence import Incidence
from fem_racket.impact.model_cache import frame_model
from fem_racket.impact.oblique.solve import ObliqueResult
from fem_racket.impact.oblique.stroke import Stroke
from fem_racket.impact.simulate_oblique import normal_impact
from fem_racket.impact.swing import Swing
from fem_racket.impact.tangential.oblique import BallMotion, tangential_impact
from fem_racket.validation import InputError, check_positive, show

__all__ = ["simulate_stroke"]


def simulate_stroke(
    frame: Any = None,
    *,
    incidence: Incidence,
    stroke: Stroke,
    speed: float = 20.0,
    swing: Swing | None = None,
    **kwargs: Any,
) -> ObliqueResult:
    """An oblique impact set by a stroke's face and path angles.

    Parameters
    ----------
    frame : optional
        The racket (as :func:`fem_racket.impact.simulate.simulate`); None with ``clamped``.
    incidence : Incidence
        Spin (and side spin), friction, ball inertia and radius, eta^2; its ``angle`` and
        ``side_angle`` must be 0 (the stroke sets the incidence).
    stroke : Stroke
        Face and path angles.
    speed : float
        The ball's horizontal speed V [m/s].
    swing : Swing, optional
        The racket's motion along the path (its speed at the impact point is S); at rest when
        None (then the path angle does not matter).
    **kwargs
        The normal impact's other arguments (``clamped``, ``position``, ``elements``, ...).
    """
    for name in ("angle", "side_angle"):
        if getattr(incidence, name) != 0.0:
            raise InputError(
                f"{name} = {show(getattr(incidence, name))} deg is not allowed with a stroke: the "
                "face and path angles set the incidence",
                parameter=name,
                value=getattr(incidence, name),
            )
    v = check_positive("speed", speed, "m/s")
    s = 0.0
    if swing is not None:
        if kwargs.get("clamped"):
            raise InputError("swing is not allowed with a clamped head: it does not move")
        model = frame_model(frame, kwargs.pop("elements", 20))
        frame = model
        s = float(swing.speed_at(kwargs.get("position", 0.75) * model.mesh.length))
    c = stroke.components(v, s)
    if c.ball_normal + c.racket_normal <= 0.0:
        raise InputError(
            f"face_angle = {show(stroke.face_angle)} deg and "
            f"path_angle = {show(stroke.path_angle)} deg "
            "are not allowed here: ball and strings do not close along the face normal",
            parameter="face_angle",
            value=stroke.face_angle,
        )
    k = math.sin(math.radians(stroke.face_angle - stroke.path_angle))
    extra = {} if swing is None else {"swing": Swing(swing.velocity * k, swing.omega * k)}
    normal = normal_impact(frame, c.ball_normal, **extra, **kwargs)
    yaw = normal.racket_yaw() if incidence.lateral or normal.offset != 0.0 else None
    motion = BallMotion(
        normal.ball_mass, c.ball_tangential, normal.rebound_speed, normal.racket_mass,
        c.racket_tangential, yaw=yaw,
    )  # fmt: skip
    out = tangential_impact(incidence, normal.history, motion)
    slip = c.ball_tangential - c.racket_tangential
    info = {
        "face_angle_deg": stroke.face_angle,
        "path_angle_deg": stroke.path_angle,
        "racket_path_speed_m_s": s,
        "normal_speed_m_s": c.ball_normal,
        "angle_deg": math.degrees(math.atan2(slip, c.ball_normal + c.racket_normal)),
        "launch_angle_deg": stroke.launch_angle(
            normal.rebound_speed, out.tangential_speed_out, c.sign
        ),
    }
    return ObliqueResult(normal.result, out, v, normal.contact, info)
