"""A player's swing for any racket: slower for a heavier swing (Cross & Bower 2006).

The racket turns about a pivot on the handle (the hand, ``p`` from the butt), so a point x moves
towards the ball at ``v_r = V (x - p) / (x_ref - p)`` for a racket speed V at the reference point
x_ref (:meth:`fem_racket.impact.swing.Swing.from_speed`). A player swings a racket of larger
moment of inertia about the pivot, ``I_p = I_CG + M (x_CG - p)^2``, more slowly: Cross & Bower
(2006, J. Sports Sci. 24) measured swing speed ~ I^-0.27, so here::

    V = V_0 (I_p / I_0)^-0.27

with V_0 the racket speed with a reference racket of inertia I_0 (a design study's starting
racket). The ball leaves at v_out = e_A v_in + (1 + e_A) v_r
(:func:`fem_racket.impact.swing.ball_speed_out`, Brody, Cross & Lindsey 2002, ch. 11), e_A being
the apparent COR at the closing speed v_in + v_r. Swing weight is I_p about the standard axis
0.10 m from the butt, quoted in kg cm^2 (:func:`fem_racket.frame.specs.swing_weight`).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from fem_racket.frame.mesh import FrameMesh
from fem_racket.frame.specs import SWING_AXIS, balance_point, swing_weight
from fem_racket.impact.swing import Swing
from fem_racket.validation import check_finite, check_positive, check_range

__all__ = ["SWING_EXPONENT", "SWING_WEIGHT_AXIS", "SwingModel", "mass_quantities"]

#: Exponent of swing speed against moment of inertia (Cross & Bower 2006).
SWING_EXPONENT = -0.27
#: Axis of the swing weight, from the butt [m].
SWING_WEIGHT_AXIS = SWING_AXIS


def mass_quantities(mesh: FrameMesh, pivot: float = SWING_WEIGHT_AXIS) -> dict[str, float]:
    """Mass [kg], CG [m], I_CG and I about ``pivot`` [kg m^2], swing weight [kg cm^2] (exact)."""
    m = float(np.sum(mesh.rhoA * np.diff(mesh.points)))
    cg = balance_point(mesh)
    return {
        "mass": m,
        "cg": cg,
        "inertia_cg": swing_weight(mesh, cg),
        "inertia_pivot": swing_weight(mesh, pivot),
        "swing_weight_kg_cm2": swing_weight(mesh) * 1e4,
    }


@dataclass(frozen=True)
class SwingModel:
    """A player swinging rackets about a pivot, slower for larger moments of inertia.

    Parameters
    ----------
    head_speed : float
        Speed V_0 of the reference point towards the ball with the reference racket [m/s].
    reference : float
        Reference point x/L (0.75: near the string centre).
    pivot : float
        Pivot (hand) distance from the butt [m]; 0.10 m, the swing-weight axis, by default.
    exponent : float
        Swing speed ~ I_p^exponent; -0.27 (Cross & Bower 2006); 0 keeps the swing speed fixed.
    reference_inertia : float, optional
        I_0 about the pivot [kg m^2]; the design problem sets it to its starting racket's.
    """

    head_speed: float
    reference: float = 0.75
    pivot: float = SWING_WEIGHT_AXIS
    exponent: float = SWING_EXPONENT
    reference_inertia: float | None = None

    def __post_init__(self) -> None:
        v = check_finite("racket speed", self.head_speed, "m/s")
        check_range("racket speed", v, 0.0, 100.0, unit="m/s")
        check_range("swing reference", self.reference, 0.0, 1.0, unit="x/L")
        check_range("pivot", self.pivot, 0.0, 1.0, unit="m")
        check_range("swing exponent", self.exponent, -2.0, 0.0)
        if self.reference_inertia is not None:
            check_positive("reference inertia", self.reference_inertia, "kg m^2")

    def racket_speed(self, inertia: float) -> float:
        """V [m/s] at the reference point for a racket of ``inertia`` about the pivot [kg m^2]."""
        i0 = inertia if self.reference_inertia is None else self.reference_inertia
        return float(self.head_speed * (inertia / i0) ** self.exponent)

    def swing(self, inertia: float, length: float) -> Swing:
        """The rigid swing of a racket of ``inertia`` about the pivot and ``length`` [m]."""
        return Swing.from_speed(
            self.racket_speed(inertia), length, reference=self.reference, pivot=self.pivot
        )

    def impact_speed(self, x_over_l: np.ndarray, inertia: float, length: float) -> np.ndarray:
        """v_r [m/s] of the points ``x_over_l`` of a racket of ``inertia`` and ``length``."""
        return np.asarray(self.swing(inertia, length).speed_at(np.asarray(x_over_l) * length))
