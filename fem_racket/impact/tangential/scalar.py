"""A normal history's smooth force and its slope at one time, as Python floats:
:func:`scalar_force`, what the vector contact's ODE right-hand side calls at every stage."""

from __future__ import annotations

from fem_racket.impact.tangential.normal import NormalHistory

__all__ = ["scalar_force"]


def scalar_force(normal: NormalHistory):
    """(F(t), F'(t)) of the history's smooth force for one time t [s], as floats: a sampled
    history's spline evaluated piece by piece in Python (a scipy call per step costs ~15x)."""
    spline = getattr(normal, "force_spline", None)
    if spline is None:
        return (lambda t: float(normal.smooth_force(t))), (lambda t: float(normal.slope(t)))
    from bisect import bisect_right

    x = spline.x.tolist()
    c3, c2, c1, c0 = (row.tolist() for row in spline.c)
    last = len(x) - 2

    def piece(t):
        i = min(max(bisect_right(x, t) - 1, 0), last)
        return i, t - x[i]

    def force(t):
        i, h = piece(t)
        return ((c3[i] * h + c2[i]) * h + c1[i]) * h + c0[i]

    def slope(t):
        i, h = piece(t)
        return (3.0 * c3[i] * h + 2.0 * c2[i]) * h + c1[i]

    return force, slope
