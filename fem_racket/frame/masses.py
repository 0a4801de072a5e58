"""Masses added to a frame (lead tape, weights) as short strips of extra mass per length.

A racket is tuned by sticking lead tape or clamping weights on the frame (Cross 2001, Sports
Eng. 4: 30 g at the tip raises the ball speed of a swung racket and moves its maximum tipward).
Here an added mass ``m`` centred at ``x`` is a strip of width ``w`` (default 20 mm, a typical
piece of tape) over which the frame's mass per length rises by ``m / w``::

    rhoA(s) -> rhoA(s) + m / w    for  a <= s <= b,  b - a = w,  centred on x, kept inside [0, L]

Nodes are inserted at the strip's ends, so the result is an ordinary :class:`FrameMesh`: mass
properties, modes, impacts and mesh files need nothing new, and a mesh file written from it
reloads the same racket. A strip end closer than :data:`MIN_GAP` x L (0.7 um on a 0.68 m frame)
to an existing node is moved onto it (the strip keeps its mass), so a mass whose position varies
continuously (a design variable) never makes a cell of vanishing length, whose stiffness
~EI/h^3 would swamp the others (scikit-fem's Hermite basis is singular below ~1e-9 L; the
engine's static solves lose digits below ~1e-5 L). As ``w`` -> 0 the strip tends to a point mass
(its own moment of inertia m w^2 / 12 is 3e-6 kg m^2 for 30 g over 20 mm: 0.02 % of the paper
racket's I_CG).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass, replace

import numpy as np

from fem_racket.frame.mesh import FrameMesh, insert_nodes
from fem_racket.validation import InputError, check_positive, check_range, show

__all__ = ["DEFAULT_WIDTH", "MIN_GAP", "AddedMass", "add_masses", "strip_ends"]

#: Width of an added mass's strip [m] (a piece of lead tape).
DEFAULT_WIDTH = 0.02
#: Strip ends this close to a node (as a fraction of L) are moved onto it.
MIN_GAP = 1e-6


@dataclass(frozen=True)
class AddedMass:
    """A mass added to the frame.

    Parameters
    ----------
    position : float
        Centre of the strip as x/L from the grip end, in [0, 1] (moved inward so the whole strip
        lies on the frame).
    mass : float
        Added mass [kg], >= 0.
    width : float
        Strip width [m], > 0.
    radius : float
        Distance [m] of the mass (or of each half of a pair on both sides) from the long axis:
        on a frame with torsion data the strip's polar mass per length rhoIp rises by
        m radius^2 / width (0: on the axis).
    """

    position: float
    mass: float
    width: float = DEFAULT_WIDTH
    radius: float = 0.0

    def __post_init__(self) -> None:
        object.__setattr__(
            self, "position", check_range("mass position", self.position, 0.0, 1.0, unit="x/L")
        )
        m = float(self.mass)
        if not np.isfinite(m) or m < 0.0:
            raise InputError(f"added mass = {show(self.mass)} kg is not allowed: must be >= 0")
        object.__setattr__(self, "mass", m)
        object.__setattr__(self, "width", check_positive("mass width", self.width, "m"))
        r = float(self.radius)
        if not np.isfinite(r) or r < 0.0:
            raise InputError(f"mass radius = {show(self.radius)} m is not allowed: must be >= 0")
        object.__setattr__(self, "radius", r)


def strip_ends(position: float, width: float, length: float) -> tuple[float, float]:
    """Ends (a, b) [m] of a strip of ``width`` centred at ``position`` x/L, kept inside [0, L]."""
    if width >= length:
        raise InputError(f"mass width = {show(width)} m is not allowed: must be < L = {length:g} m")
    a = min(max(position * length - width / 2.0, 0.0), length - width)
    return a, a + width


def add_masses(mesh: FrameMesh, masses: Sequence[AddedMass]) -> FrameMesh:
    """``mesh`` with each added mass spread over its strip (nodes inserted at the strip ends).

    The total mass rises by exactly the sum of the added masses; on a frame with torsion data
    (rhoIp) its polar moment by the sum of m radius^2. Other cell data are kept.
    """
    length = mesh.length
    nodes = mesh.points

    def snap(e: float) -> float:
        near = nodes[int(np.argmin(np.abs(nodes - e)))]
        return float(near) if abs(near - e) <= MIN_GAP * length else e

    ends = []
    for m in masses:
        a, b = strip_ends(m.position, m.width, length)
        a, b = snap(a), snap(b)
        ends.append((a, b))
        nodes = np.union1d(nodes, [a, b])
    out = insert_nodes(mesh, [e / length for ab in ends for e in ab])
    rho = out.rhoA.copy()
    polar = np.array(out.rhoIp, dtype=float) if out.has_torsion else None
    mid = 0.5 * (out.points[:-1] + out.points[1:])
    for m, (a, b) in zip(masses, ends, strict=True):
        cells = (mid > a) & (mid < b)
        rho[cells] += m.mass / (b - a)
        if polar is not None:
            polar[cells] += m.mass * m.radius**2 / (b - a)
    if polar is None:
        return replace(out, rhoA=rho)
    return replace(out, rhoA=rho, rhoIp=polar)
