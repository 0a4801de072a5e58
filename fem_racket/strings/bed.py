"""The string bed's parameters: tension, pattern, head size, string; its membrane constants.

The bed is a pre-tensioned orthotropic membrane (``DESIGN.md`` section 10; Cross 2000, Goodwill &
Haake 2001): ``n_m`` mains run along the racket (x) across the head width W, ``n_c`` crosses run
across it (y) over the head length L_h, each at tension T. Per unit width the mains carry
``N_x = n_m T / W`` and the crosses ``N_y = n_c T / L_h`` [N/m], and the strings' mass per area is
``rho_s = mu (n_m / W + n_c / L_h)`` [kg/m^2] (mu: the string's linear density). The transverse
deflection w of the bed obeys (small deflection, edge on the head's ellipse)::

    rho_s w'' = N_x w_xx + N_y w_yy + p(x, y, t)

Defaults: the paper's racket was strung at 246 N (55 lb, issue 25), a 16 x 19 pattern (the most
common) with nylon; the head is the "100 in^2" (645 cm^2) ellipse 0.326 m x 0.252 m centred at 0.74
L, the head outline of the off-axis work (issue 24) with the same names (ITF rules, appendix II:
strung surface <= 39.4 cm x 29.2 cm; typical dimensions, an assumption). The ball meets the bed
over a disk of radius a (``load_radius_m``, 0.02 m: about the contact patch of a tennis ball at
impact and the probe of a stringbed-stiffness meter; an assumption): the bed's deflection "at the
impact point" is its mean over that disk.

A bed too soft to be a string bed is refused (:meth:`StringBed.check_soft`), as the contact laws
refuse a ball softer than a cushion: the bed's deflection at the head's centre under
:data:`BED_LOAD_N` must not exceed half the head's smaller axis. Its static stiffness there is the
closed form of the orthotropic membrane mapped to a circle (x = sqrt(N_x) xi, y = sqrt(N_y) eta
turn the operator into a Laplacian; ``membrane.py``)::

    k = 2 pi sqrt(N_x N_y) / (ln(R'/a') + 1/4),
    R' = (L_h/(2 sqrt(N_x)) + W/(2 sqrt(N_y))) / 2,   a' = (a/sqrt(N_x) + a/sqrt(N_y)) / 2

(the mapped head and contact disk as circles of their mean radius). Against the FE stiffness
(``tests/strings/test_soft_bed.py``) it is within 1.1 % on the default head with 16 x 19 or 18 x 20,
and up to 26 % low (soft) for a 4 x 40 pattern: stiffer for none of the beds tested, so a bed
the check passes deflects at most the bound (the centre: the bed's softest point). k is
proportional to T: the check is a least tension per bed.
"""

from __future__ import annotations

import math
import re
from dataclasses import dataclass

from fem_racket.strings.materials import StringMaterial, get_string
from fem_racket.validation import (
    InputError,
    check_choice,
    check_integer,
    check_positive,
    check_range,
    show,
)

__all__ = ["BED_LOAD_N", "EDGES", "HEAD_AXIS_RANGE", "StringBed", "parse_pattern"]

#: How the head ring follows the frame (:mod:`fem_racket.impact.strung.point`): uniformly with the
#: impact point, or each edge point with the frame at its own x (bending along the hoop).
EDGES = ("point", "hoop")

#: Most and fewest strings in either direction a pattern may have.
PATTERN_RANGE = (4, 40)
#: Shortest and longest head axis [m] (rackets: about 0.25-0.35 m long, 0.2-0.27 m wide).
HEAD_AXIS_RANGE = (0.05, 1.0)
#: The load [N] at which a bed's deflection is checked: the order of a tennis impact's peak force
#: (the contact laws' reference load; Cross 1999: 0.5-1.5 kN at 15-30 m/s for a ball on strings).
#: Under it a bed may deflect at most half its head's smaller axis: the linear membrane assumes
#: deflections small against the head (``DESIGN.md`` section 10: geometric stiffening is already
#: 5-30 % at 10-20 mm), and a bed deflecting more than its half width is not a string bed (a
#: strung racket's bed is of order 50 kN/m, 2 cm under 1 kN).
BED_LOAD_N = 1e3


def parse_pattern(text: str, name: str = "pattern") -> tuple[int, int]:
    """``"16x19"`` -> (16, 19): mains x crosses (``name``: the parameter named in errors)."""
    match = re.fullmatch(r"\s*(\d+)\s*[xX]\s*(\d+)\s*", str(text))
    if match is None:
        raise InputError(f"{name} = {show(text)} is not allowed: must be MAINSxCROSSES, e.g. 16x19")
    lo, hi = PATTERN_RANGE
    mains = check_integer(f"{name} mains", int(match.group(1)), lo, hi)
    crosses = check_integer(f"{name} crosses", int(match.group(2)), lo, hi)
    return mains, crosses


@dataclass(frozen=True)
class StringBed:
    """A strung head (see the module docstring).

    Parameters
    ----------
    tension_n : float
        Tension T per string [N].
    mains, crosses : int
        Strings along the racket and across it.
    head_length_m, head_width_m : float
        The head ellipse's axes along and across the racket [m].
    string : str
        String preset (:data:`fem_racket.strings.materials.STRINGS`).
    load_radius_m : float
        Radius a of the ball's contact disk [m].
    head_centre : float
        The head's centre on the frame, x/L (0.74: a typical head on the paper's frame, as the
        off-axis work's head outline; an assumption).
    edge : {"point", "hoop"}
        How the head ring follows the frame (:data:`EDGES`).
    stretch : bool
        The strings stretch as the bed deflects, their tension rising in the dynamics
        (:mod:`fem_racket.impact.strung.stretch`; integrated by CVODE); False: the linear bed.
    """

    tension_n: float = 246.0
    mains: int = 16
    crosses: int = 19
    head_length_m: float = 0.326
    head_width_m: float = 0.252
    string: str = "nylon"
    load_radius_m: float = 0.02
    head_centre: float = 0.74
    edge: str = "point"
    stretch: bool = False

    def __post_init__(self) -> None:
        check_range("string tension", self.tension_n, 1.0, 1e16, unit="N")
        lo, hi = PATTERN_RANGE
        check_integer("pattern mains", self.mains, lo, hi)
        check_integer("pattern crosses", self.crosses, lo, hi)
        check_range("head length", self.head_length_m, *HEAD_AXIS_RANGE, unit="m")
        check_range("head width", self.head_width_m, *HEAD_AXIS_RANGE, unit="m")
        get_string(self.string)
        check_positive("load radius", self.load_radius_m, "m")
        check_range("head centre", self.head_centre, 0.0, 1.0, unit="x/L")
        check_choice("edge", self.edge, EDGES)
        if not isinstance(self.stretch, bool):
            raise InputError(
                f"stretch = {show(self.stretch)} is not allowed: must be True or False"
            )
        half = 0.5 * min(self.head_length_m, self.head_width_m)
        if self.load_radius_m >= 0.5 * half:
            raise InputError(
                f"load radius = {show(self.load_radius_m)} m is not allowed: must be < "
                f"{0.5 * half:.4g} m (a quarter of the head's smaller axis)"
            )
        self.check_soft("string tension", self.tension_n)

    @property
    def centre_stiffness_n_m(self) -> float:
        """The closed-form static stiffness at the head's centre [N/m] (module docstring)."""
        sx, sy = math.sqrt(self.n_x), math.sqrt(self.n_y)
        radius = 0.25 * (self.head_length_m / sx + self.head_width_m / sy)
        disk = 0.5 * self.load_radius_m * (1.0 / sx + 1.0 / sy)
        return 2.0 * math.pi * sx * sy / (math.log(radius / disk) + 0.25)

    @property
    def least_tension_n(self) -> float:
        """The least tension per string [N] at which this bed (its pattern, head, string and
        load radius at any tension) deflects at most half its head's smaller axis under
        :data:`BED_LOAD_N` at its centre (module docstring; k is proportional to T)."""
        most = 0.5 * min(self.head_length_m, self.head_width_m)
        return self.tension_n * BED_LOAD_N / (most * self.centre_stiffness_n_m)

    def check_soft(self, name: str, tension: object) -> float:
        """``tension`` [N] as a float, or refused naming ``name`` when this bed strung at it
        would be softer than a string bed (:attr:`least_tension_n`)."""
        value = check_range(name, tension, 1.0, 1e16, unit="N")
        least = self.least_tension_n
        if value < least:
            most = 0.5 * min(self.head_length_m, self.head_width_m)
            k = self.centre_stiffness_n_m * value / self.tension_n
            raise InputError(
                f"{name} = {show(tension)} N is not allowed: must be at least {least:.4g} N for a "
                f"{self.pattern} bed on a {self.head_length_m:g} m x {self.head_width_m:g} m head "
                f"(at {show(tension)} N it deflects {BED_LOAD_N / k:.3g} m under "
                f"{BED_LOAD_N:g} N at its centre, more than {most:.4g} m, half the head's "
                "smaller axis)",
                parameter=name,
                value=tension,
            )
        return value

    @property
    def material(self) -> StringMaterial:
        return get_string(self.string)

    @property
    def pattern(self) -> str:
        """``"16x19"``."""
        return f"{self.mains}x{self.crosses}"

    @property
    def area_m2(self) -> float:
        """Area of the head ellipse [m^2]."""
        return math.pi / 4.0 * self.head_length_m * self.head_width_m

    @property
    def n_x(self) -> float:
        """N_x = n_m T / W, the mains' tension per unit width [N/m]."""
        return self.mains * self.tension_n / self.head_width_m

    @property
    def n_y(self) -> float:
        """N_y = n_c T / L_h, the crosses' tension per unit length [N/m]."""
        return self.crosses * self.tension_n / self.head_length_m

    @property
    def rho_s(self) -> float:
        """Mass per area of the strings [kg/m^2]."""
        mu = self.material.linear_density_kg_m
        return mu * (self.mains / self.head_width_m + self.crosses / self.head_length_m)

    def describe(self) -> dict[str, float | str]:
        """Parameters and membrane constants for JSON outputs, units in the keys."""
        return {
            "string_tension_n": float(self.tension_n),
            "pattern": self.pattern,
            "head_length_m": self.head_length_m,
            "head_width_m": self.head_width_m,
            "head_area_cm2": self.area_m2 * 1e4,
            "string": self.string,
            "load_radius_m": self.load_radius_m,
            "head_centre_x_over_l": self.head_centre,
            "stringbed_edge": self.edge,
            "string_stretch": self.stretch,
            "tension_per_width_x_n_m": self.n_x,
            "tension_per_width_y_n_m": self.n_y,
            "mass_per_area_kg_m2": self.rho_s,
        }
