"""Sweet spots of a racket: centre of percussion, vibration nodes, maximum e_A and v_out.

For a frame of mass M, centre of gravity x_CG and inertia I_CG about it, pivoted at p (the hand),
a blow at the centre of percussion gives no reaction at the pivot::

    x_COP = x_CG + I_CG / (M (x_CG - p))

The nodes of the first free-free bending modes are where an impact excites no vibration of that
mode (Kawazoe & Kanda 1997, Figs 11-12; the paper's racket: mode 1 at 0.200 L and 0.769 L, mode
2 at 0.125, 0.484, 0.864 L). Along the string face the apparent COR e_A is largest toward the
throat on a stationary racket, and the ball speed off a swinging racket
v_out = e_A v_in + (1 + e_A) v_r is largest further out, moving toward the tip as the angular
speed rises (v_r grows with x) and toward the throat as the ball speed rises (Brody, Cross &
Lindsey 2002, ch. 11; DESIGN section 8). The power region is where v_out is within a fraction of
its maximum.

Maxima are located on the map's position grid and refined by bounded Brent search between the
grid neighbours of the largest value (a maximum at a grid end is left there).
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

from fem_racket.frame.modal import MassProperties, mode_nodes
from fem_racket.frame.model import FrameModel
from fem_racket.studies.views import SpotsView
from fem_racket.validation import InputError, check_finite, check_range, show

__all__ = [
    "SweetSpots",
    "centre_of_percussion",
    "curve_maximum",
    "mode_node_positions",
    "power_region",
]

#: Position tolerance of the refined maxima [x/L].
XATOL = 1e-7


def centre_of_percussion(props: MassProperties, pivot: float) -> float:
    """x_COP = x_CG + I_CG / (M (x_CG - p)) [m from the butt] for a pivot ``pivot`` [m]."""
    p = check_finite("pivot", pivot, "m")
    arm = props.cg - p
    if abs(arm) < 1e-9 * props.length:
        raise InputError(
            f"pivot = {show(pivot)} m is not allowed for a centre of percussion: it is the centre "
            f"of gravity ({props.cg:g} m)",
            parameter="pivot",
            value=pivot,
        )
    return props.cg + props.inertia / (props.mass * arm)


def mode_node_positions(model: FrameModel, modes: int = 2) -> tuple[np.ndarray, ...]:
    """Nodes (x/L) of the lowest ``modes`` free-free bending modes, one array per mode."""
    fm = model.modes(modes)
    return tuple(mode_nodes(model.fe, fm.shapes[:, k]) for k in range(min(modes, fm.omega.size)))


def curve_maximum(
    positions: np.ndarray, values: np.ndarray, evaluate: Callable[[float], float] | None = None
) -> float:
    """Position (x/L) of the largest of ``values`` on the grid ``positions``, refined by a
    bounded Brent search on ``evaluate`` between its grid neighbours when given."""
    x = np.asarray(positions, dtype=float)
    v = np.asarray(values, dtype=float)
    if not np.any(np.isfinite(v)):
        return float("nan")
    k = int(np.nanargmax(v))
    if evaluate is None or k == 0 or k == x.size - 1:
        return float(x[k])
    from scipy.optimize import minimize_scalar

    res = minimize_scalar(
        lambda s: -evaluate(s),
        bounds=(x[k - 1], x[k + 1]),
        method="bounded",
        options={"xatol": XATOL},
    )
    return float(res.x) if -res.fun >= v[k] else float(x[k])


def power_region(positions: np.ndarray, values: np.ndarray, fraction: float) -> tuple[float, float]:
    """The interval (x/L) around the maximum of ``values`` where they stay above ``fraction``
    of it, ends interpolated linearly between grid points (a grid end if never crossed)."""
    f = check_range("fraction", fraction, 0.0, 1.0, include_low=False)
    x = np.asarray(positions, dtype=float)
    v = np.asarray(values, dtype=float)
    k = int(np.nanargmax(v))
    level = f * v[k]
    lo = k
    while lo > 0 and v[lo - 1] >= level:
        lo -= 1
    hi = k
    while hi < x.size - 1 and v[hi + 1] >= level:
        hi += 1

    def cross(i: int, j: int) -> float:  # v[i] >= level > v[j]
        return float(x[i] + (x[j] - x[i]) * (v[i] - level) / (v[i] - v[j]))

    left = float(x[0]) if lo == 0 else cross(lo, lo - 1)
    right = float(x[-1]) if hi == x.size - 1 else cross(hi, hi + 1)
    return left, right


@dataclass(frozen=True, repr=False)
class SweetSpots(SpotsView):
    """A racket's sweet spots, positions as x/L from the butt (NaN when not defined).

    Attributes
    ----------
    cop : float
        Centre of percussion for the pivot (NaN without one).
    mode1_nodes, mode2_nodes : tuple of float
        Nodes of the first two free-free bending modes.
    node : float
        Mode 1's node in the string area (its node nearest the tip).
    max_apparent_cor : float
        Where e_A is largest along the map.
    max_ball_speed : float
        Where v_out is largest along the map (NaN without a swing).
    power_region : tuple of float
        Interval around ``max_ball_speed`` (with a swing) or ``max_apparent_cor`` where the
        curve stays above ``power_fraction`` of its maximum.
    power_fraction : float
    """

    cop: float
    mode1_nodes: tuple[float, ...]
    mode2_nodes: tuple[float, ...]
    node: float
    max_apparent_cor: float
    max_ball_speed: float
    power_region: tuple[float, float]
    power_fraction: float

    def summary(self) -> dict[str, object]:
        """JSON-ready, units in the keys (None for NaN)."""

        def val(v: float) -> float | None:
            return None if np.isnan(v) else float(v)

        return {
            "cop_x_over_l": val(self.cop),
            "node_x_over_l": val(self.node),
            "mode1_nodes_x_over_l": [float(v) for v in self.mode1_nodes],
            "mode2_nodes_x_over_l": [float(v) for v in self.mode2_nodes],
            "max_apparent_cor_x_over_l": val(self.max_apparent_cor),
            "max_ball_speed_x_over_l": val(self.max_ball_speed),
            "power_region_x_over_l": [float(v) for v in self.power_region],
            "power_fraction": self.power_fraction,
        }
