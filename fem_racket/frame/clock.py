"""Places on a racket named as a stringer names them: clock positions on the head, throat, handle.

Lead tape is placed "at 12" (the tip), "at 3 and 9" (both sides of the head at its widest
point), "at 2 and 10", "at 4 and 8", in the throat, along the handle or under the butt cap. On
the 1-D frame a place is a distance x from the butt [m] and a lateral distance r from the long
axis [m] (in the string plane); a pair such as 3/9 is two equal halves at +r and -r, so it
adds to the mass and to the moments about axes across the frame as one mass at x does, and
m r^2 to the polar moment about the long axis (the twistweight).

Head geometry (an assumption, not a measured frame): the frame's centre line around the head is
an ellipse of length ``length_m`` and width ``width_m`` whose far end is the tip (x = L). The
default is a "midplus" head of about 100 in^2 = 645 cm^2 (string bed about 33 x 25 cm:
pi/4 x 0.33 x 0.25 = 0.0648 m^2), giving r = 0.125 m at 3/9 (DESIGN.md section 10: r is about
0.11-0.13 m on rackets). Clock hour h sits at the angle theta = 30 deg x h from the tip::

    x = x_c + a cos(theta),   r = b |sin(theta)|      (a, b: half the length and width)

so 12 is the tip (x = L, r = 0), 3/9 the widest point (x = x_c, r = b) and 2/10, 4/8 lie at
x_c +- a/2, r = b sqrt(3)/2. The throat is the head's butt end (6 o'clock: x = x_c - a, r = 0);
the handle is the middle of the grip, :data:`HANDLE_X` = 0.10 m from the butt (the swing-weight
axis, so lead there changes the swing weight only by its own tiny strip inertia); the butt is
x = 0.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from fem_racket.validation import InputError, check_positive, show

__all__ = [
    "CLOCK_PLACES",
    "DEFAULT_HEAD_LENGTH",
    "DEFAULT_HEAD_WIDTH",
    "HANDLE_X",
    "PLACES",
    "HeadEllipse",
    "Place",
    "place_at",
]

#: Length and width of the default head's centre line [m] (about 645 cm^2, a 100 in^2 head).
DEFAULT_HEAD_LENGTH, DEFAULT_HEAD_WIDTH = 0.33, 0.25
#: The "handle" place: middle of the grip, from the butt [m].
HANDLE_X = 0.10
#: Clock places -> the hour whose angle from the tip they sit at.
CLOCK_PLACES = {"12": 0, "2/10": 2, "3/9": 3, "4/8": 4}
#: Every named place, tip first.
PLACES = (*CLOCK_PLACES, "throat", "handle", "butt")


@dataclass(frozen=True)
class HeadEllipse:
    """The head's centre line: an ellipse ending at the tip of a racket of length ``racket_m``.

    Parameters
    ----------
    racket_m : float
        Racket length L [m].
    length_m, width_m : float
        Head length (along the axis) and width [m]; the head must fit on the racket.
    """

    racket_m: float
    length_m: float = DEFAULT_HEAD_LENGTH
    width_m: float = DEFAULT_HEAD_WIDTH

    def __post_init__(self) -> None:
        check_positive("racket length", self.racket_m, "m")
        check_positive("head length", self.length_m, "m")
        check_positive("head width", self.width_m, "m")
        if self.length_m >= self.racket_m:
            raise InputError(
                f"head length = {show(self.length_m)} m is not allowed: must be shorter than "
                f"the racket ({self.racket_m:g} m)"
            )

    @property
    def centre_m(self) -> float:
        """x of the head's centre (the widest point) from the butt [m]."""
        return self.racket_m - self.length_m / 2.0

    @property
    def area_m2(self) -> float:
        """Area inside the centre line [m^2]."""
        return math.pi * self.length_m * self.width_m / 4.0


@dataclass(frozen=True)
class Place:
    """Where an added mass sits.

    Attributes
    ----------
    name : str
        The place as given (``"3/9"``, ``"0.32"``).
    x : float
        Distance from the butt [m].
    r : float
        Lateral distance from the long axis [m] (each half of a pair).
    """

    name: str
    x: float
    r: float


def place_at(name: str, head: HeadEllipse) -> Place:
    """The place ``name``: one of :data:`PLACES` or a distance from the butt in metres.

    Raises
    ------
    InputError
        For an unknown name or a distance off the racket.
    """
    key = str(name).strip()
    if key in CLOCK_PLACES:
        theta = math.radians(30.0 * CLOCK_PLACES[key])
        a, b = head.length_m / 2.0, head.width_m / 2.0
        x = head.centre_m + a * math.cos(theta)
        return Place(key, head.racket_m if key == "12" else x, b * abs(math.sin(theta)))
    if key == "throat":
        return Place(key, head.racket_m - head.length_m, 0.0)
    if key == "handle":
        return Place(key, HANDLE_X, 0.0)
    if key == "butt":
        return Place(key, 0.0, 0.0)
    try:
        x = float(key)
    except ValueError:
        x = math.nan
    if not 0.0 <= x <= head.racket_m:  # also NaN
        raise InputError(
            f"place = {show(name)} is not allowed: must be one of {', '.join(PLACES)} or a "
            f"distance from the butt in m within [0, {head.racket_m:g}]"
        )
    return Place(key, x, 0.0)
