"""The options of a power map (:func:`fem_racket.studies.racket_map.racket_map`): the racket's
setting (:class:`MapSetup`) and how each point is struck and solved (:class:`MapImpact`).

The map functions take them as keywords, checked with a "did you mean"
(:func:`fem_racket.studies.options.take`).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

from fem_racket.contact.linear import DEFAULT_BALL_MASS
from fem_racket.frame.model import DEFAULT_MODES
from fem_racket.impact.reduction import DEFAULT_TOLERANCE
from fem_racket.impact.swing import DEFAULT_REFERENCE

__all__ = ["DEFAULT_POSITIONS", "DEFAULT_POWER_FRACTION", "MapImpact", "MapSetup"]

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
class MapSetup:
    """The racket's setting and the map's grid.

    Attributes
    ----------
    name : str
        The racket's label in tables and plots.
    speed : float
        Incoming ball speed v_in [m/s].
    racket_speed, reference, pivot
        The swing (:meth:`fem_racket.impact.swing.Swing.from_speed`).
    positions : array of float or None
        Impact points x/L; :data:`DEFAULT_POSITIONS` when None.
    elements : int
        Cells when meshing a Frame.
    power_fraction : float
        The power region is where v_out >= power_fraction x its maximum.
    """

    name: str = "racket"
    speed: float = 20.0
    racket_speed: float = 0.0
    reference: float = DEFAULT_REFERENCE
    pivot: float | None = None
    positions: Any = None
    elements: int = 20
    power_fraction: float = DEFAULT_POWER_FRACTION
