"""How a variable of a dataset is labelled: one table, :data:`LABELS`, for every output.

The rule (CF style: a short name and a separate unit):

- ``long_name`` is short, what a plot's axis shows: a few words and the symbol
  (``"apparent COR e_A"``), so that xarray's own ``.plot()`` (which prints
  ``long_name [units]`` and wraps it at 30 characters) and :func:`fem_racket.plot_sweep` show it
  on one line. A longer explanation (definition, formula, source) goes to ``description``.
- ``units`` is the SI unit alone; a dimensionless quantity says ``"-"`` (the label reads
  ``[-]``, as every label and option help of the package); an impact point's ``"x/L"``.

Sweeps (:class:`fem_racket.studies.sweep_result.SweepResult`: the swept parameters and the result
variables) and power maps (:func:`fem_racket.io.map_files.map_dataset`) take their attributes from
here. A variable added to a sweep gets its line in :data:`LABELS`; a name missing from it (a
contact law registered later) is labelled by its own name, its declared unit and help
(:func:`label`).
"""

from __future__ import annotations

from dataclasses import dataclass

__all__ = ["LABELS", "MAX_LABEL", "Label", "label"]

#: Longest ``long_name [units]`` (xarray's plots wrap labels longer than 30 characters).
MAX_LABEL = 30


@dataclass(frozen=True)
class Label:
    """A variable's attributes: short name, unit and (optional) longer description."""

    long_name: str
    units: str
    description: str = ""

    @property
    def text(self) -> str:
        """The axis label, ``long_name [units]``."""
        return f"{self.long_name} [{self.units}]"

    def attrs(self) -> dict[str, str]:
        """The netCDF/xarray attributes: ``long_name``, ``units`` and ``description`` if any."""
        out = {"long_name": self.long_name, "units": self.units}
        if self.description:
            out["description"] = self.description
        return out


#: Labels by variable name: sweep coordinates and variables, power-map variables.
LABELS: dict[str, Label] = {
    # swept parameters (fem_racket.studies.grid_values.PARAMETERS)
    "position": Label("impact point", "x/L", "impact point from the grip end"),
    "offset": Label("lateral offset", "m", "impact point's lateral offset from the long axis"),
    "speed": Label("ball speed v_in", "m/s", "incident ball speed"),
    "racket_speed": Label(
        "racket speed", "m/s", "racket speed towards the ball at the reference point"
    ),
    "reference": Label("swing reference", "x/L", "point whose speed racket_speed gives"),
    "pivot": Label("swing pivot", "m", "pivot of the swing from the butt (none: translation)"),
    "ei1": Label("grip-side EI1", "N m^2", "grip-side bending rigidity EI1 (EI2 = 0.88 EI1)"),
    "ei_factor": Label("EI factor", "-", "factor on every segment's EI"),
    "ball_mass": Label("ball mass m_B", "kg"),
    "zeta": Label("damping ratio zeta", "-", "ball/string damping ratio"),
    "kcb": Label("stiffness K_CB", "N/m", "ball/string stiffness K_CB"),
    "elements": Label("elements", "-", "number of beam elements"),
    # the string-bed and oblique-ball axes (fem_racket.studies.sweep_physics)
    "string_tension": Label("string tension T", "N", "tension per string"),
    "pattern": Label("string pattern", "-", "mains*100 + crosses (1619: 16 mains x 19 crosses)"),
    "angle": Label("incidence angle", "deg", "ball's path from the face normal"),
    "spin": Label("spin in", "rpm", "incoming spin, positive = topspin"),
    "side_angle": Label("side angle", "deg", "ball's path from the plane of the long axis"),
    "side_spin": Label("side spin in", "rpm", "incoming side spin, positive = rolling to +y"),
    "friction": Label("friction mu", "-", "Coulomb friction coefficient ball/strings"),
    "ball_inertia": Label("ball I/(m R^2)", "-", "ball's moment of inertia I/(m R^2)"),
    "ball_radius": Label("ball radius R", "m"),
    "compliance_ratio": Label(
        "compliance ratio eta^2", "-", "normal over tangential contact stiffness eta^2"
    ),
    # contact-law parameters (fem_racket.contact.registry.LAW_PARAMETERS)
    "hc_stiffness": Label(
        "HC stiffness k", "N/m^n", "Hunt-Crossley stiffness k of F = k delta^n (1 + alpha delta')"
    ),
    "hc_exponent": Label("HC exponent n", "-", "Hunt-Crossley exponent n"),
    "hc_alpha": Label("HC damping alpha", "s/m", "Hunt-Crossley damping alpha = lambda / k"),
    "k1": Label("loading k1", "N/m^n", "hysteretic loading stiffness k1 (F = k1 delta^n)"),
    "k2": Label("unloading k2", "N/m^n", "hysteretic unloading stiffness k2"),
    "hyst_exponent": Label("exponent n", "-", "hysteretic exponent n"),
    "ball_stiffness": Label("ball stiffness K_b", "N/m", "series law: ball stiffness K_b"),
    "ball_damping": Label("ball damping C_b", "N s/m", "series law: ball damping C_b"),
    "string_stiffness": Label("string bed k_s", "N/m", "series law: string-bed stiffness k_s"),
    "string_cubic": Label("string bed k_3", "N/m^3", "series law: string-bed cubic stiffness k_3"),
    # sweep results (fem_racket.studies.cases.VARIABLES)
    "cor": Label(
        "apparent COR e_A",
        "-",
        "apparent coefficient of restitution (v_out - v_r)/(v_in + v_r) of the free racket",
    ),
    "contact_time_s": Label("contact time t_c", "s"),
    "rebound_speed_m_s": Label(
        "normal rebound v_out,n",
        "m/s",
        "ball's speed along the face normal after impact -v_B(t_c): v_out head-on (with a swing "
        "too), its normal component in an oblique impact",
    ),
    "peak_force_n": Label("peak force F_max", "N", "largest contact force"),
    "kcb_n_m": Label("stiffness K_CB", "N/m", "ball/string stiffness K_CB used"),
    "racket_speed_at_impact_m_s": Label(
        "racket speed v_r", "m/s", "impact point's speed towards the ball before impact"
    ),
    # with a string bed or an oblique ball (fem_racket.studies.cases.AXIS_VARIABLES)
    "stringbed_stiffness_n_m": Label(
        "bed stiffness k_bed", "N/m", "string bed's static stiffness at the impact point"
    ),
    "stringbed_frequency_hz": Label("bed frequency f_1", "Hz", "string bed's first frequency"),
    "angle_out_deg": Label("angle out", "deg", "ball's outgoing angle from the face normal"),
    "spin_out_rpm": Label("spin out", "rpm", "ball's outgoing spin, positive = topspin"),
    "tangential_cor": Label("tangential COR", "-", "tangential coefficient of restitution"),
    "side_angle_out_deg": Label(
        "side angle out", "deg", "ball's outgoing angle from the plane of the long axis"
    ),
    "side_spin_out_rpm": Label(
        "side spin out", "rpm", "ball's outgoing side spin, positive = rolling to +y"
    ),
    "racket_yaw_rate_rad_s": Label(
        "racket yaw rate", "rad/s", "racket's yaw rate after impact, about the face normal"
    ),
    "contact_regime": Label(
        "contact regime", "-", "phases of the contact, negative when the first grips"
    ),
    # power maps (fem_racket.io.map_files)
    "apparent_cor": Label(
        "apparent COR e_A", "-", "apparent COR e_A of the free racket at the closing speed"
    ),
    "ball_speed_out_m_s": Label(
        "ball speed out v_out", "m/s", "ball speed after impact v_out (normal and tangential)"
    ),
}


def label(name: str, units: str = "-", description: str = "") -> Label:
    """The :class:`Label` of variable ``name``; a name missing from :data:`LABELS` is labelled
    by itself, with ``units`` (``"1"`` or ``""`` read as ``"-"``) and ``description``."""
    if name in LABELS:
        return LABELS[name]
    return Label(name, "-" if units in ("1", "") else units, description)
