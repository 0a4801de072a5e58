"""A racket's catalogue numbers from its mesh: mass, balance, swing weight, twistweight, f1.

Mass, balance and swing weight are moments of rhoA (:mod:`.specs`); the twistweight is the
polar moment about the long axis, TW = sum over cells of rhoIp h, on a frame that carries a polar
mass per length rhoIp [kg m] (None on one that does not: this module does not guess one). f1 is
the first free-free bending frequency of the FE model on the mesh as it is, and on a frame with
torsion data the first free-free torsion frequency (:mod:`fem_racket.frame.torsion`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from fem_racket.frame.mesh import FrameMesh
from fem_racket.frame.model import FrameModel
from fem_racket.frame.specs import KG_CM2, balance_point, swing_weight

__all__ = ["Catalogue", "catalogue", "twist_weight"]


def twist_weight(mesh: FrameMesh) -> float | None:
    """Polar moment about the long axis [kg m^2]: sum of rhoIp h; None without torsion data."""
    if not mesh.has_torsion:
        return None
    return float(np.sum(np.asarray(mesh.rhoIp) * np.diff(mesh.points)))


@dataclass(frozen=True)
class Catalogue:
    """Catalogue numbers, SI (swing and twist weight in kg m^2, 1e-4 x the kg cm^2 quoted).

    ``twist_weight`` and ``torsion_f1`` are None for a frame without torsion data; ``f1`` and
    ``torsion_f1`` [Hz] None when not computed.
    """

    length: float
    mass: float
    balance: float
    swing_weight: float
    twist_weight: float | None = None
    f1: float | None = None
    torsion_f1: float | None = None

    def as_dict(self) -> dict[str, float | None]:
        """JSON-ready, units in the keys, swing and twist weight in kg cm^2 as quoted."""
        tw = self.twist_weight
        return {
            "length_m": self.length,
            "mass_kg": self.mass,
            "balance_m": self.balance,
            "swing_weight_kg_cm2": self.swing_weight / KG_CM2,
            "twist_weight_kg_cm2": None if tw is None else tw / KG_CM2,
            "f1_hz": self.f1,
            "torsion_f1_hz": self.torsion_f1,
        }


def catalogue(frame: FrameMesh | FrameModel, *, f1: bool = True) -> Catalogue:
    """The catalogue numbers of a mesh (the frequencies from its FE models when ``f1``)."""
    model = frame if isinstance(frame, FrameModel) else None
    mesh = model.mesh if model is not None else frame
    mass = float(np.sum(np.asarray(mesh.rhoA) * np.diff(mesh.points)))
    freq = torsion = None
    if f1:
        model = model or FrameModel.build(mesh)
        freq = float(model.modes(1).frequencies[0])
        if mesh.has_torsion:
            torsion = float(model.torsion.modes(1).frequencies[0])
    tw = twist_weight(mesh)
    return Catalogue(mesh.length, mass, balance_point(mesh), swing_weight(mesh), tw, freq, torsion)
