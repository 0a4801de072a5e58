"""Lead tape: masses added at named places on the racket (:mod:`.clock`) and what they change.

A lead ``m`` at a place (x, r) is a strip of width ``w`` (:data:`~.masses.DEFAULT_WIDTH`, 20 mm)
along the frame centred on x (kept inside [0, L], so lead "at 12" is the strip [L - w, L] and
"at the butt" [0, w]); a pair such as 3/9 puts m/2 at +r and m/2 at -r. On the 1-D frame the
strip raises rhoA by m / w (:func:`~.masses.add_masses`) and, on a frame that carries a polar
mass per length rhoIp [kg m], rhoIp by m r^2 / w. Every catalogue number is linear in the added
masses (the reason :mod:`fem_racket.studies.customise` can solve for them)::

    dM = m,  d(M B) = m x_s,  dSW = m ((x_s - a)^2 + w^2 / 12),  dTW = m r^2

with x_s the strip's centre and a = 0.10 m the swing-weight axis (across the frame, in the
string plane: a lateral offset r does not change it). :func:`lead_moments` gives these per kg.
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

import numpy as np

from fem_racket.frame.clock import Place, place_at
from fem_racket.frame.head import HeadOutline
from fem_racket.frame.masses import DEFAULT_WIDTH, AddedMass, add_masses, strip_ends
from fem_racket.frame.mesh import FrameMesh
from fem_racket.frame.specs import SWING_AXIS
from fem_racket.validation import InputError, show

__all__ = ["MAX_LEAD_G", "Lead", "add_lead", "check_grams", "lead_moments", "parse_lead"]

#: Most grams one ``LOCATION:GRAMS`` may add: players add a few grams up to about 30 g of lead,
#: and a racket weighs about 300 g; 1000 g (an order of magnitude beyond the most lead, three
#: rackets) bounds a strip that still leaves a racket with some lead on it.
MAX_LEAD_G = 1000.0


def check_grams(name: str, grams: float, shown: str | None = None) -> float:
    """The grams of one lead, refused unless in (0, :data:`MAX_LEAD_G`] (the one home of the
    bounds ``--add-mass`` and a run file's ``[[frame.lead]]`` share; 0 g would change nothing,
    an option without effect).

    Parameters
    ----------
    name : str
        What the error names (``add-mass``, ``frame.lead[0].mass_g``).
    grams : float
        Mass [g].
    shown : str, optional
        The value as the error shows it (``show(grams)`` when None).
    """
    g = float(grams)
    shown = show(grams) if shown is None else shown
    if not np.isfinite(g) or g <= 0.0:
        raise InputError(
            f"{name} = {shown} is not allowed: must be > 0 g (a lead of 0 g changes nothing)",
            parameter=name,
            value=grams,
        )
    if g > MAX_LEAD_G:
        raise InputError(
            f"{name} = {shown} is not allowed: must be at most {MAX_LEAD_G:g} g (lead tape "
            "adds a few grams; more than a racket weighs is no longer a racket)",
            parameter=name,
            value=grams,
        )
    return g


@dataclass(frozen=True)
class Lead:
    """An added mass at a place.

    Parameters
    ----------
    place : str
        A name of :data:`fem_racket.frame.clock.PLACES` or a distance from the butt [m].
    mass : float
        Mass [kg], >= 0 (the whole pair for 3/9, 2/10 and 4/8).
    """

    place: str
    mass: float

    def __post_init__(self) -> None:
        m = float(self.mass)
        if not np.isfinite(m) or m < 0.0:
            raise InputError(f"added mass = {show(self.mass)} kg is not allowed: must be >= 0")
        object.__setattr__(self, "mass", m)
        object.__setattr__(self, "place", str(self.place).strip())

    def label(self) -> str:
        """``PLACE:GRAMS`` as the command line writes it."""
        return f"{self.place}:{self.mass * 1e3:g}"


def parse_lead(text: str) -> Lead:
    """``LOCATION:GRAMS`` (e.g. ``3/9:10``, ``0.32:5``) as a :class:`Lead` (mass in kg)."""
    place, sep, grams = str(text).rpartition(":")
    try:
        g = float(grams) if sep and place.strip() else float("nan")
    except ValueError:
        g = float("nan")
    if not np.isfinite(g) or g < 0.0:
        raise InputError(
            f"add-mass = {show(text)} is not allowed: must be LOCATION:GRAMS with GRAMS > 0, "
            "e.g. 3/9:10 or 0.32:5"
        )
    return Lead(place, check_grams("add-mass", g, show(text)) * 1e-3)


def _strip(place: Place, length: float, width: float) -> tuple[float, float]:
    return strip_ends(place.x / length, width, length)


def lead_moments(
    place: str, head: HeadOutline, *, width: float = DEFAULT_WIDTH, axis: float = SWING_AXIS
) -> np.ndarray:
    """What 1 kg at ``place`` adds: [mass, first moment about the butt, swing weight, twistweight].

    Units: kg, kg m, kg m^2, kg m^2 (per kg of lead). Exact for the strip that
    :func:`add_lead` puts on the mesh (its ends moved onto a node closer than
    :data:`~.masses.MIN_GAP` x L shift these by at most ~1e-6 relative).
    """
    p = place_at(place, head)
    a, b = _strip(p, head.frame_length_m, width)
    xs = 0.5 * (a + b)
    sw = ((b - axis) ** 3 - (a - axis) ** 3) / (3.0 * (b - a))
    return np.array([1.0, xs, sw, p.r**2])


def add_lead(
    mesh: FrameMesh, leads: Sequence[Lead], head: HeadOutline, *, width: float = DEFAULT_WIDTH
) -> FrameMesh:
    """``mesh`` with every lead added as a strip (module docstring); massless leads are skipped."""
    if abs(head.frame_length_m - mesh.length) > 1e-9 * mesh.length:
        raise InputError(
            f"head frame length = {show(head.frame_length_m)} m is not allowed: must be the "
            f"frame's length {mesh.length:g} m"
        )
    places = [(lead, place_at(lead.place, head)) for lead in leads if lead.mass > 0.0]
    if not places:
        return mesh
    masses = [AddedMass(min(p.x / mesh.length, 1.0), lead.mass, width, p.r) for lead, p in places]
    return add_masses(mesh, masses)
