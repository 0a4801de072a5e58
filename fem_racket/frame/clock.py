"""Places on a racket named as a stringer names them: clock positions on the head, throat, handle.

Lead tape is placed "at 12" (the tip), "at 3 and 9" (both sides of the head at its widest
point), "at 2 and 10", "at 4 and 8", in the throat, along the handle or under the butt cap. On
the 1-D frame a place is a distance x from the butt [m] and a lateral distance r from the long
axis [m] (in the string plane); a pair such as 3/9 is two equal halves at +r and -r, so it
adds to the mass and to the moments about axes across the frame as one mass at x does, and
m r^2 to the polar moment about the long axis (the twistweight).

Head geometry (an assumption, not a measured frame): the string bed is an ellipse of length
``length_m`` and width ``width_m`` centred on the long axis at ``centre`` x/L; the lead sits on
the frame around it (:class:`fem_racket.frame.head.HeadOutline`). The default is the 100 in^2
(645 cm^2) head ``DEFAULT_HEAD`` (0.326 m x 0.252 m centred at 0.74 L), so r at
3/9 is 0.126 m (DESIGN.md section 10: r is about 0.11-0.13 m on rackets). Clock hour h sits at
the angle theta = 30 deg x h from the tip::

    x = x_c + a cos(theta),   r = b |sin(theta)|      (a, b: half the length and width)

so 3/9 is the widest point (x = x_c, r = b) and 2/10, 4/8 lie at x_c +- a/2, r = b sqrt(3)/2;
12 is the tip of the frame (x = L, r = 0; the frame closes the head beyond the bed). The throat
is the bed's butt end (6 o'clock: x = x_c - a, r = 0); the handle is the middle of the grip,
:data:`HANDLE_X` = 0.10 m from the butt (the swing-weight axis, so lead there changes the swing
weight only by its own tiny strip inertia); the butt is x = 0.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

from fem_racket.frame.constants import CLOCK_PLACES, PLACES
from fem_racket.frame.head import HeadOutline
from fem_racket.validation import InputError, show

__all__ = [
    "CLOCK_PLACES",
    "HANDLE_X",
    "PLACES",
    "Place",
    "place_at",
]

#: The "handle" place: middle of the grip, from the butt [m].
HANDLE_X = 0.10
#: A distance beyond the frame's length by at most this fraction of it is the tip (the place
#: "12"): the length is the sum of the cells' lengths, 0.68 m coming out as 0.6799999999999999.
TIP_TOL = 1e-9


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


def place_at(name: str, head: HeadOutline) -> Place:
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
        return Place(key, head.frame_length_m if key == "12" else x, b * abs(math.sin(theta)))
    if key == "throat":
        return Place(key, head.centre_m - head.length_m / 2.0, 0.0)
    if key == "handle":
        return Place(key, HANDLE_X, 0.0)
    if key == "butt":
        return Place(key, 0.0, 0.0)
    try:
        x = float(key)
    except ValueError:
        x = math.nan
    if not 0.0 <= x <= head.frame_length_m * (1.0 + TIP_TOL):  # also NaN
        raise InputError(
            f"place = {show(name)} is not allowed: must be one of {', '.join(PLACES)} or a "
            f"distance from the butt in m within [0, {head.frame_length_m:g}]"
        )
    return Place(key, min(x, head.frame_length_m), 0.0)
