"""A player's swing: the impact point's speed before impact for any racket, and v_out.

The racket turns about a pivot on the handle (the hand, ``p`` from the butt) at angular speed
omega, so the impact point at x moves towards the ball at ``v_r = omega (x - p)``. The player's
swing slows as the racket's moment of inertia about the pivot ``I_p = I_CG + M (x_CG - p)^2``
grows: Cross & Bower (2006, J. Sports Sci. 24) measured swing speed ~ I^-0.27, so::

    omega = omega_0 (I_p / I_0)^-0.27,   omega_0 = V_head / (x_ref - p)

with V_head the head speed at the reference point x_ref when swinging a reference racket of
inertia I_0 (the design study's starting racket). The ball arriving at v_in leaves at
(Brody, Cross & Lindsey 2002, ch. 11; exact for a linear ball/string law)::

    v_out = e_A v_in + (1 + e_A) v_r

with e_A the apparent COR of the stationary free racket at the relative speed v_in + v_r. Swing
weight is I_p about the standard axis 0.10 m from the butt, quoted in kg cm^2.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from fem_racket.frame.mesh import FrameMesh
from fem_racket.validation import check_finite, check_positive, check_range

__all__ = [
    "SWING_EXPONENT",
    "SWING_WEIGHT_AXIS",
    "SwingModel",
    "ball_speed_out",
    "inertia_about",
    "mass_quantities",
]

#: Exponent of swing speed against moment of inertia (Cross & Bower 2006).
SWING_EXPONENT = -0.27
#: Axis of the swing weight, from the butt [m].
SWING_WEIGHT_AXIS = 0.10


def inertia_about(mass: np.ndarray, cg: np.ndarray, inertia_cg: np.ndarray, pivot: float):
    """Moment of inertia about an axis at ``pivot`` [m] from the butt [kg m^2] (parallel axes)."""
    return inertia_cg + mass * (cg - pivot) ** 2


def ball_speed_out(cor: np.ndarray, v_in: np.ndarray, v_r: np.ndarray) -> np.ndarray:
    """v_out = e_A v_in + (1 + e_A) v_r [m/s]."""
    return cor * v_in + (1.0 + cor) * v_r


@dataclass(frozen=True)
class SwingModel:
    """A player swinging a racket about a pivot.

    Parameters
    ----------
    head_speed : float
        Speed of the reference point towards the ball with the reference racket [m/s], >= 0.
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
        v = check_finite("head speed", self.head_speed)
        check_range("head speed", v, 0.0, 100.0, unit="m/s")
        check_range("swing reference", self.reference, 0.0, 1.0, unit="x/L")
        check_range("pivot", self.pivot, 0.0, 1.0, unit="m")
        check_range("swing exponent", self.exponent, -2.0, 0.0)
        if self.reference_inertia is not None:
            check_positive("reference inertia", self.reference_inertia, "kg m^2")

    def angular_speed(self, inertia: np.ndarray, length: float) -> np.ndarray:
        """omega [rad/s] for rackets of moment of inertia ``inertia`` about the pivot [kg m^2]."""
        arm = self.reference * length - self.pivot
        check_positive("reference point minus pivot", arm, "m")
        i0 = np.asarray(inertia) if self.reference_inertia is None else self.reference_inertia
        return self.head_speed / arm * (np.asarray(inertia) / i0) ** self.exponent

    def impact_speed(self, x_over_l: np.ndarray, inertia: np.ndarray, length: float) -> np.ndarray:
        """v_r [m/s] of the points ``x_over_l`` (last axis) for each racket's ``inertia``."""
        omega = np.asarray(self.angular_speed(inertia, length))
        return omega[..., None] * (np.asarray(x_over_l) * length - self.pivot)


def mass_quantities(mesh: FrameMesh, pivot: float = SWING_WEIGHT_AXIS) -> dict[str, float]:
    """Mass [kg], CG [m], I_CG and I about ``pivot`` [kg m^2], swing weight [kg cm^2] (exact)."""
    a, b, ra = mesh.points[:-1], mesh.points[1:], mesh.rhoA
    m = float(np.sum(ra * (b - a)))
    cg = float(np.sum(ra * (b**2 - a**2) / 2.0)) / m
    i_cg = float(np.sum(ra * (b**3 - a**3) / 3.0)) - m * cg**2
    return {
        "mass": m,
        "cg": cg,
        "inertia_cg": i_cg,
        "inertia_pivot": float(inertia_about(m, cg, i_cg, pivot)),
        "swing_weight_kg_cm2": float(inertia_about(m, cg, i_cg, SWING_WEIGHT_AXIS)) * 1e4,
    }
