"""The sweepable parameters of an impact: name, unit, description and attribute, in dimension
order (:data:`PARAMETERS`), and the axes that add physics. Plain tables, importing nothing of the
library's numerics, so ``fem-racket sweep --help`` and a run file's keys read them before any
work; :mod:`fem_racket.studies.grid_values` (their values) imports them from here.
"""

from __future__ import annotations

from dataclasses import dataclass

__all__ = ["OBLIQUE_AXES", "OPTIONAL", "PARAMETERS", "STRING_AXES", "Parameter"]


@dataclass(frozen=True)
class Parameter:
    """A sweepable parameter: unit, description and attribute name (with its unit)."""

    unit: str
    description: str
    attribute: str


#: Sweepable parameters in dimension order.
PARAMETERS: dict[str, Parameter] = {
    "position": Parameter("x/L", "impact point from the grip end", "position_x_over_l"),
    "offset": Parameter("m", "impact point's lateral offset from the long axis", "offset_m"),
    "speed": Parameter("m/s", "incident ball speed", "speed_m_s"),
    "racket_speed": Parameter(
        "m/s", "racket speed towards the ball at the reference point", "racket_speed_m_s"
    ),
    "reference": Parameter("x/L", "point whose speed racket_speed gives", "reference_x_over_l"),
    "pivot": Parameter("m", "pivot of the swing from the butt (none: translation)", "pivot_m"),
    "ei1": Parameter("N m^2", "grip-side bending rigidity EI1 (EI2 = 0.88 EI1)", "ei1_n_m2"),
    "ei_factor": Parameter("1", "factor on every segment's EI", "ei_factor"),
    "ball_mass": Parameter("kg", "ball mass m_B", "ball_mass_kg"),
    "zeta": Parameter("1", "ball/string damping ratio", "zeta"),
    "kcb": Parameter("N/m", "ball/string stiffness K_CB", "kcb_n_m"),
    "elements": Parameter("1", "number of beam elements", "elements"),
    # the string bed (issue 25): with either, the bed replaces the lumped K_CB
    "string_tension": Parameter("N", "tension per string", "string_tension_n"),
    "pattern": Parameter(
        "1", "string pattern as mains*100 + crosses (1619: 16 mains x 19 crosses)", "pattern"
    ),
    # the oblique, spinning ball (issue 26)
    "angle": Parameter("deg", "incidence angle from the face normal", "angle_deg"),
    "spin": Parameter("rpm", "incoming spin, positive = topspin", "spin_rpm"),
    "side_angle": Parameter(
        "deg", "angle of the ball's path from the plane of the long axis", "side_angle_deg"
    ),
    "side_spin": Parameter("rpm", "incoming side spin, positive = rolling to +y", "side_spin_rpm"),
    "friction": Parameter("1", "Coulomb friction coefficient ball/strings", "friction"),
    "ball_inertia": Parameter("1", "ball's moment of inertia I/(m R^2)", "ball_inertia_i_over_mr2"),
    "ball_radius": Parameter("m", "ball radius R", "ball_radius_m"),
    "compliance_ratio": Parameter(
        "1", "normal over tangential contact stiffness eta^2", "compliance_ratio_eta2"
    ),
}
#: The axes that put a string bed on every case.
STRING_AXES = ("string_tension", "pattern")
#: The axes that make the ball oblique (an incidence).
OBLIQUE_AXES = (
    "angle",
    "spin",
    "side_angle",
    "side_spin",
    "friction",
    "ball_inertia",
    "ball_radius",
    "compliance_ratio",
)
#: The parameters that are None unless given: they add physics (a string bed, an incidence).
OPTIONAL = (*STRING_AXES, *OBLIQUE_AXES)
