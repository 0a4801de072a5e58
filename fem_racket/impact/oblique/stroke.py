"""A stroke's geometry: a horizontal ball met by a tilted face swung along an inclined path.

In the vertical plane of the stroke (taken as the plane of the racket's long axis and the face
normal, the plane of the model's oblique impact), X horizontal along the ball's travel and Z up:
the ball arrives horizontally at V; the string plane makes the face angle F with the horizontal
(90 deg: vertical; less: a closed face, its hitting side turned down; Kwon et al. 2017, JSSM 16:
about 80 deg in a forehand); the racket's impact point moves at S along a path P above the
horizontal, against the ball (about 19 deg up at about 15 m/s in a forehand, ibid.). With
n = (sin F, cos F) the face normal into the strings and t = (-cos F, sin F) up along the face::

    ball:    normal v_n = V sin F,         along the face  -V cos F
    racket:  normal towards the ball  S sin(F - P),  along the face  S cos(F - P)

so the normal impact is the swinging racket's at ball speed V sin F and impact-point speed
S sin(F - P), and the ball slips along the face relative to the strings at
-V cos F - S cos(F - P) (down the face in a forehand) before spin. The tangential axis of the
oblique impact points along that relative slip, so the signs of spin follow
:mod:`fem_racket.impact.incidence`; when it points down the face (sign -1 below) a positive
outgoing spin is topspin on the ball's flight back over the net.

Assumed: the swing's rigid motion is along the path (its normal part is the model's swing, about
its pivot in the bending plane; its part along the face a rigid translation of the head along
the face); the ball arrives horizontally.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from fem_racket.validation import check_range

__all__ = ["Stroke", "StrokeComponents"]


@dataclass(frozen=True)
class StrokeComponents:
    """Velocities of one stroke resolved on the face [m/s] (along the oblique impact's
    tangential axis, which is ``sign`` times the up-the-face direction)."""

    ball_normal: float
    racket_normal: float
    ball_tangential: float
    racket_tangential: float
    sign: int


@dataclass(frozen=True)
class Stroke:
    """Face and path angles of a stroke [deg].

    Parameters
    ----------
    face_angle : float
        String plane to the horizontal [deg], in (0, 180) (90: vertical).
    path_angle : float
        The impact point's path above the horizontal [deg], in (-90, 90).
    """

    face_angle: float = 90.0
    path_angle: float = 0.0

    def __post_init__(self) -> None:
        f = check_range(
            "face_angle", self.face_angle, 0.0, 180.0, unit="deg", include_low=False,
            include_high=False,
        )  # fmt: skip
        p = check_range(
            "path_angle", self.path_angle, -90.0, 90.0, unit="deg", include_low=False,
            include_high=False,
        )  # fmt: skip
        object.__setattr__(self, "face_angle", f)
        object.__setattr__(self, "path_angle", p)

    def components(self, ball_speed: float, racket_speed: float) -> StrokeComponents:
        """Resolve a ball at ``ball_speed`` and a racket point at ``racket_speed`` along its
        path [m/s] on the face."""
        f, d = math.radians(self.face_angle), math.radians(self.face_angle - self.path_angle)
        up_ball, up_racket = -ball_speed * math.cos(f), racket_speed * math.cos(d)
        sign = 1 if up_ball - up_racket > 0.0 else -1
        return StrokeComponents(
            ball_speed * math.sin(f),
            racket_speed * math.sin(d),
            sign * up_ball,
            sign * up_racket,
            sign,
        )

    def launch_angle(self, normal_out: float, tangential_out: float, sign: int) -> float:
        """Angle of the ball's flight after impact above the horizontal [deg], from its speed
        away from the strings and along the tangential axis [m/s]."""
        f = math.radians(self.face_angle)
        x = -normal_out * math.sin(f) - sign * tangential_out * math.cos(f)
        z = -normal_out * math.cos(f) + sign * tangential_out * math.sin(f)
        return math.degrees(math.atan2(z, -x))
