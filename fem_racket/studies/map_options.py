"""The options of a power map (:func:`fem_racket.studies.racket_map.racket_map`): the racket's
setting (:class:`MapSetup`), how the racket is played over the map (:class:`MapPlay`: the ball
speed, the swing and the grid; also the base of
:class:`fem_racket.studies.compare.Play`) and how each point is struck and solved
(:class:`MapImpact`).

The map functions take them as keywords, checked with a "did you mean"
(:func:`fem_racket.studies.options.take`).
"""

from __future__ import annotations

from dataclasses import dataclass, field, fields
from typing import Any

from fem_racket.contact.linear import DEFAULT_BALL_MASS
from fem_racket.frame.model import DEFAULT_MODES
from fem_racket.impact.reduction import DEFAULT_TOLERANCE
from fem_racket.impact.swing import DEFAULT_REFERENCE, Swing

__all__ = ["DEFAULT_POSITIONS", "DEFAULT_POWER_FRACTION", "MapImpact", "MapPlay", "MapSetup"]

#: Default grid: the string face from its throat end to the tip, x/L (start, stop, points).
DEFAULT_POSITIONS = (0.5, 1.0, 200)
#: Default fraction of the maximum v_out bounding the power region.
DEFAULT_POWER_FRACTION = 0.95


@dataclass(frozen=True)
class MapImpact:
    """How each point is struck and solved.

    Attributes
    ----------
    ball_mass, kcb, zeta, separation, modes, tolerance
        As for :func:`fem_racket.simulate` (``tolerance``: the batched engine's COR tolerance,
        or the general integrator's under a law).
    law : ContactLaw, str or None
        A contact law other than the paper's (the general integrator; it takes neither
        ``kcb`` nor ``zeta``).
    kcb_factor : float
        Factor on the linear law's K_CB (a stiffer or softer string bed).
    """

    ball_mass: float = DEFAULT_BALL_MASS
    kcb: float | None = None
    zeta: float | None = None
    separation: str = "displacement"
    modes: int | None = DEFAULT_MODES
    tolerance: float | None = DEFAULT_TOLERANCE
    law: Any = None
    kcb_factor: float = 1.0


@dataclass(frozen=True)
class MapPlay:
    """How the racket is played over a map: the ball speed, the swing and the grid.

    Attributes
    ----------
    speed : float
        Incoming ball speed v_in [m/s].
    racket_speed, reference, pivot
        The swing: speed [m/s] of the point ``reference`` (x/L) towards the ball, turning about
        ``pivot`` [m from the butt] or translating when None (:meth:`swing`).
    positions : array of float or None
        Impact points x/L; :data:`DEFAULT_POSITIONS` when None.
    """

    speed: float = 20.0
    racket_speed: float = 0.0
    reference: float = DEFAULT_REFERENCE
    pivot: float | None = None
    positions: Any = None

    def swing(self, length: float) -> Swing:
        """The swing of a racket of length ``length`` [m]
        (:meth:`fem_racket.impact.swing.Swing.from_speed`)."""
        return Swing.from_speed(
            self.racket_speed, length, reference=self.reference, pivot=self.pivot
        )

    def keywords(self) -> dict[str, Any]:
        """The fields of :class:`MapPlay`, by name, as the map functions take them."""
        return {f.name: getattr(self, f.name) for f in fields(MapPlay)}


@dataclass(frozen=True)
class MapSetup:
    """The racket's setting and how it is played over the map.

    Attributes
    ----------
    name : str
        The racket's label in tables and plots.
    play : MapPlay
        Ball speed, swing and grid (given as their own keywords: ``speed``, ``racket_speed``,
        ``reference``, ``pivot``, ``positions``).
    elements : int
        Cells when meshing a Frame.
    power_fraction : float
        The power region is where v_out >= power_fraction x its maximum.
    """

    name: str = "racket"
    play: MapPlay = field(default_factory=MapPlay)
    elements: int = 20
    power_fraction: float = DEFAULT_POWER_FRACTION
