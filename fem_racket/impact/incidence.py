"""An oblique, spinning ball and its frictional contact with the strings: :class:`Incidence`.

Geometry: the plane of the racket's long axis x and the face normal n. The ball arrives at speed
V at ``angle`` from the face normal (in that plane): normal speed V cos(angle) towards the
strings, tangential speed V sin(angle) >= 0 along the unit vector t of the face (the direction of
its tangential velocity; at angle 0 the tip direction +x by convention).

Spin, about the axis normal to that plane, is signed relative to the strings like a ball on the
ground: positive (topspin) when the ball's surface on the strings' side moves backward (-t)
relative to its centre, the sense of rolling along the strings; negative (backspin) when it
moves forward (+t), so the contact point slips faster. The contact point's velocity is
``v_t - R omega``: a ball rolling along the strings has ``omega = v_t / R``.

Across the face: the lateral axis y of the face (positive toward the side of a positive
``offset``, :mod:`fem_racket.impact.offaxis`). ``side_angle`` is the angle between the ball's
path and the plane of the long axis and the face normal (positive: moving toward +y), so the
ball arrives at normal speed V cos(side) cos(angle), along the face V cos(side) sin(angle) and
across it V sin(side); ``angle`` is then the angle of the path's projection on that plane from
the normal. ``side_spin``, about the long axis's direction, is signed like ``spin`` along y:
positive when the ball's surface on the strings' side moves toward -y relative to its centre
(the sense of rolling toward +y); the contact point's lateral velocity is ``v_y - R omega_s``.
With both zero the impact is the one in the plane of the long axis, unchanged.

The ball is a rigid sphere of radius R and moment of inertia I = k m R^2 about its centre. A
tennis ball is a thick rubber shell under felt: a uniform shell of outer radius 33 mm and wall
3.3 mm gives k = (2/5)(1 - 0.9^5)/(1 - 0.9^3) = 0.605; the literature's range is 0.55-0.67
(DESIGN.md section 10; Cross 2005, Am. J. Phys. 73). The contact carries Coulomb friction mu
(ball on strings about 0.4, Cross 2003, Sports Eng. 6, measured sliding friction) through a
tangential spring (Stronge's compliant contact, Stronge 2000, *Impact Mechanics*, ch. 5):
``eta^2 = k_n / k_t``, the normal-to-tangential stiffness ratio. Its default 0.14 is fitted
to one measurement: a ball at 25.0 m/s (56 mph), 40 deg from the normal, with 3820 rpm of
backspin on a head-clamped racket leaves at 1591 rpm, the mean of 14 strings (1207-1803 rpm;
Lindsey, "String movement and spin", Tennis Warehouse University, 2011, data taken with
R. Cross). The paper's K_CB (k_n) is mostly the string bed's deflection, which gives no
tangential compliance, so eta^2 is far below Mindlin's (2 - nu) / (2 (1 - nu)) = 1.5 of a solid
elastic sphere (Johnson 1985, *Contact Mechanics*, section 7.2; the previous default, which
gives 2946 rpm there). With 0.14 the clamped ball slides, grips with the friction reversing,
and slides backward at release, as Cross (2003, Sports Eng. 6) describes; the measured spread
spans eta^2 = 0.10-0.18 (README "Oblique impacts and spin": sensitivity).
``eta^2 = 0`` is the rigid (Routh) tangential contact: the ball slides until it rolls, then
rolls.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, replace
from typing import Any

from fem_racket.validation import InputError, check_range, show

__all__ = [
    "DEFAULT_BALL_INERTIA",
    "DEFAULT_BALL_RADIUS",
    "DEFAULT_COMPLIANCE_RATIO",
    "DEFAULT_FRICTION",
    "Incidence",
    "RPM",
    "check_incidence",
    "check_kcb_normal",
    "head_on",
]

#: I / (m R^2) of a tennis ball (uniform shell, R = 33 mm, wall 3.3 mm: 0.605; range 0.55-0.67).
DEFAULT_BALL_INERTIA = 0.6
#: Ball radius R [m] (ITF: 32.7-34.3 mm).
DEFAULT_BALL_RADIUS = 0.033
#: Sliding friction ball on strings (Cross 2003, Sports Eng. 6: about 0.4).
DEFAULT_FRICTION = 0.4
#: eta^2 = k_n / k_t, fitted to a clamped-head spin measurement (module docstring).
DEFAULT_COMPLIANCE_RATIO = 0.14
#: rad/s per rpm.
RPM = 2.0 * math.pi / 60.0

# Upper bounds where the model's assumptions end, each about an order of magnitude beyond real
# play so that no real ball is refused:
#: |spin| and |side spin| [rpm]: spins in play are a few thousand rpm (the module docstring's
#: clamped-head measurement: 3820 rpm; about 5000 rpm for the heaviest topspin, an assumption);
#: far beyond, the ball's surface speed (R omega = 170 m/s at 50000 rpm) dwarfs the impact
#: speed and a rigid spinning sphere with one point of contact no longer describes it.
MAX_SPIN_RPM = 50_000.0
#: Coulomb friction mu: about 0.4 ball on strings (Cross 2003), rubber on dry surfaces rarely
#: above 1.5; beyond 5 a coefficient is no longer a Coulomb friction of felt on strings.
MAX_FRICTION = 5.0
#: Ball radius R [m]: 33 mm (ITF 32.7-34.3 mm); at 0.1 m the ball spans most of the head's
#: 0.252 m width, and the point contact of the frame's model ends.
MAX_BALL_RADIUS = 0.1
#: eta^2 = k_n / k_t: fitted 0.14 (0.10-0.18), Mindlin's solid sphere 1.5; ten times that bounds
#: a tangential compliance that still belongs to a ball.
MAX_COMPLIANCE_RATIO = 15.0


@dataclass(frozen=True)
class Incidence:
    """The ball's incidence and spin, and the tangential contact's parameters.

    Parameters
    ----------
    angle : float
        Angle between the ball's path (its projection on the plane of the long axis and the
        face normal) and the face normal [deg], in [0, 90).
    spin : float
        Incoming spin [rpm], positive = topspin (see the module docstring); |spin| <=
        :data:`MAX_SPIN_RPM`.
    friction : float
        Coulomb friction coefficient mu in [0, :data:`MAX_FRICTION`] (0: frictionless, the
        head-on normal problem).
    ball_inertia : float
        I / (m R^2) of the ball, in (0, 2/3] (2/3: a thin shell).
    radius : float
        Ball radius R [m], in (0, :data:`MAX_BALL_RADIUS`].
    compliance_ratio : float
        eta^2 = k_n / k_t in [0, :data:`MAX_COMPLIANCE_RATIO`] (0: rigid tangential contact).
    side_angle : float
        Angle between the ball's path and the plane of the long axis and the face normal [deg],
        in (-90, 90), positive toward +y (module docstring).
    side_spin : float
        Incoming side spin [rpm], positive = rolling toward +y (module docstring); |side_spin|
        <= :data:`MAX_SPIN_RPM`.
    """

    angle: float = 0.0
    spin: float = 0.0
    friction: float = DEFAULT_FRICTION
    ball_inertia: float = DEFAULT_BALL_INERTIA
    radius: float = DEFAULT_BALL_RADIUS
    compliance_ratio: float = DEFAULT_COMPLIANCE_RATIO
    side_angle: float = 0.0
    side_spin: float = 0.0

    def __post_init__(self) -> None:
        checks = {
            "angle": check_range("angle", self.angle, 0.0, 90.0, unit="deg", include_high=False),
            "spin": check_range("spin", self.spin, -MAX_SPIN_RPM, MAX_SPIN_RPM, unit="rpm"),
            "friction": check_range("friction", self.friction, 0.0, MAX_FRICTION),
            "ball_inertia": check_range(
                "ball_inertia", self.ball_inertia, 0.0, 2.0 / 3.0, include_low=False
            ),
            "radius": check_range(
                "radius", self.radius, 0.0, MAX_BALL_RADIUS, unit="m", include_low=False
            ),
            "compliance_ratio": check_range(
                "compliance_ratio", self.compliance_ratio, 0.0, MAX_COMPLIANCE_RATIO
            ),
            "side_angle": check_range(
                "side_angle",
                self.side_angle,
                -90.0,
                90.0,
                unit="deg",
                include_low=False,
                include_high=False,
            ),
            "side_spin": check_range(
                "side_spin", self.side_spin, -MAX_SPIN_RPM, MAX_SPIN_RPM, unit="rpm"
            ),
        }
        for name, value in checks.items():
            object.__setattr__(self, name, value)

    @property
    def spin_rad_s(self) -> float:
        """Incoming spin omega [rad/s], positive = topspin."""
        return self.spin * RPM

    @property
    def beta_t(self) -> float:
        """beta_t = 1 + m R^2 / I: the ball's contact point accelerates at beta_t F_t / m."""
        return 1.0 + 1.0 / self.ball_inertia

    @property
    def side_spin_rad_s(self) -> float:
        """Incoming side spin omega_s [rad/s], positive = rolling toward +y."""
        return self.side_spin * RPM

    @property
    def lateral(self) -> bool:
        """True when the ball arrives with a component across the face or side spin."""
        return self.side_angle != 0.0 or self.side_spin != 0.0

    def components(self, speed: float) -> tuple[float, float]:
        """(normal, along the face) ball speed [m/s] for an incident ``speed`` [m/s]."""
        a, b = math.radians(self.angle), math.radians(self.side_angle)
        v = speed * math.cos(b)  # cos(0) = 1 exactly: the plane's numbers bit for bit
        return v * math.cos(a), v * math.sin(a)

    def lateral_speed(self, speed: float) -> float:
        """The ball's speed across the face v_y [m/s] for an incident ``speed`` [m/s]."""
        return speed * math.sin(math.radians(self.side_angle))

    def summary(self) -> dict[str, float]:
        """The incidence and contact parameters, units in the keys."""
        return {
            "angle_deg": self.angle,
            "spin_rpm": self.spin,
            "friction": self.friction,
            "ball_inertia_i_over_mr2": self.ball_inertia,
            "ball_radius_m": self.radius,
            "compliance_ratio_eta2": self.compliance_ratio,
            "side_angle_deg": self.side_angle,
            "side_spin_rpm": self.side_spin,
        }


def check_incidence(incidence: object, *, strung: bool) -> None:
    """Refuse an ``incidence`` that is not an :class:`Incidence` (or None: head-on), or one
    crossing the face on a strung racket (the bed's oblique impact runs over its normal history
    in the plane of the long axis; the strings' lateral motion and the yaw on the bed are not
    modelled). A hand-held racket takes one in the plane of its long axis
    (:func:`fem_racket.impact.oblique.solve.oblique_on`)."""
    if incidence is None:
        return
    if not isinstance(incidence, Incidence):
        raise InputError(f"incidence = {incidence!r} is not allowed: must be an Incidence or None")
    if strung and incidence.lateral:
        raise InputError(
            "side_angle and side_spin are not allowed with a string bed: the oblique impact on "
            "the bed is modelled in the plane of the long axis only"
        )


def check_kcb_normal(incidence: Incidence, speed: float) -> None:
    """Refuse an ``incidence`` leaving the normal speed of a ball at ``speed`` [m/s] below the
    speeds the paper gives K_CB for, where K_CB follows from it (the caller's condition: the
    paper's law without kcb, no string bed, the racket at rest): named as the steeper of the
    angle and the side angle, not as the normal speed it derives."""
    from fem_racket.contact.linear import KCB_SPEED_RANGE

    low, normal = KCB_SPEED_RANGE[0], incidence.components(speed)[0]
    if normal >= low:
        return
    dest = "angle" if abs(incidence.angle) >= abs(incidence.side_angle) else "side_angle"
    raise InputError(
        f"{dest} = {show(getattr(incidence, dest))} deg is not allowed with speed = "
        f"{show(speed)} m/s: the ball's normal speed {normal:.3g} m/s is below the {low:g} m/s "
        "where the paper's K_CB holds (give kcb)",
        parameter=dest,
        value=getattr(incidence, dest),
    )


def head_on(problem: Any) -> Any:
    """The normal impact of an oblique :class:`~fem_racket.impact.problem.ImpactProblem`: the
    ball at V cos(angle), without incidence (``problem`` itself when it is head-on)."""
    if problem.incidence is None:
        return problem
    v_n = problem.incidence.components(problem.impact.speed)[0]
    return replace(problem, impact=replace(problem.impact, speed=v_n), incidence=None)
