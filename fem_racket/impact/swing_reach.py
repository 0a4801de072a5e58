"""How fast a swing may move the racket: the bound on any point's speed, and the pivots a racket
speed allows (:meth:`fem_racket.impact.swing.Swing.from_speed` refuses the others).

A racket swung at V [m/s] at its reference point r [m] about a pivot P moves its point x at
V (x - P)/(r - P): a pivot near r turns it ever faster (``--pivot 0.5099999`` with r = 0.51 m
and V = 10 m/s: 1e8 rad/s). The speed is linear along the racket, so its largest |value| is
the butt's (x = 0) or the tip's (x = L); both are held within :data:`MAX_RACKET_SPEED`, the
bound the racket speed itself is held to.
"""

from __future__ import annotations

import math

from fem_racket.impact.constants import MAX_RACKET_SPEED

__all__ = ["allowed_pivots", "pivot_reach"]


def pivot_reach(racket_speed: float, reference_m: float, length: float) -> tuple[float, float]:
    """The pivots P [m] refused at ``racket_speed`` V [m/s] for a racket of ``length`` L [m]
    with its reference point at ``reference_m`` r: the open interval (lo, hi) around r where the
    butt or the tip would move faster than V_max = :data:`MAX_RACKET_SPEED`.

    The point x moves at V (x - P)/(r - P); it stays within V_max where u |x - P| <= |r - P|,
    u = |V|/V_max, i.e. outside the interval between (r - u x)/(1 - u) and (r + u x)/(1 + u)
    (around r; for u = 1 the first is at infinity on the side away from x). The refused pivots
    are the union of the butt's (x = 0) and the tip's (x = L) intervals, one interval around r.
    """
    u = min(abs(float(racket_speed)) / MAX_RACKET_SPEED, 1.0)
    ends = []
    for x in (0.0, float(length)):
        if u < 1.0:
            ends += [(reference_m - u * x) / (1.0 - u), (reference_m + u * x) / (1.0 + u)]
        else:
            far = reference_m if reference_m == x else math.copysign(math.inf, reference_m - x)
            ends += [far, 0.5 * (reference_m + x)]
    return min(ends), max(ends)


def allowed_pivots(racket_speed: float, reference_m: float, length: float) -> str:
    """The pivots allowed at ``racket_speed`` (:func:`pivot_reach`) in words (``"must be ..."``),
    rounded inward to 0.1 mm (every value printed is allowed)."""
    lo, hi = pivot_reach(racket_speed, reference_m, length)
    parts = [f"<= {math.floor(lo * 1e4) / 1e4:.4f} m"] if math.isfinite(lo) else []
    parts += [f">= {math.ceil(hi * 1e4) / 1e4:.4f} m"] if math.isfinite(hi) else []
    if not parts:
        return "no pivot is allowed at that racket speed (give none: the racket translates)"
    return f"must be {' or '.join(parts)} at that racket speed (reference {reference_m:.4g} m)"
