"""Where a sampled normal force stops pressing: :func:`first_release`.

A normal history sampled at a solver's output times is a cubic Hermite spline of the impulse P
(exact at the samples, P' = F there); between two samples its force P' is a quadratic, which
can dip below zero while both samples press. Friction acts only while the force presses, so the
tangential contact's window ends at the first such fall (:class:`~fem_racket.impact.tangential.
normal.SampledNormal`); a history whose force presses up to its last positive sample keeps the
end its samples give, bit for bit.
"""

from __future__ import annotations

import numpy as np

__all__ = ["SLACK", "first_release"]

#: A dip of the interpolated force below zero deeper than this fraction of its peak ends the
#: window of friction (:func:`first_release`); shallower ones are round-off (1e-27 N to 4e-14 N
#: measured on pressing histories).
SLACK = 1e-9


def first_release(spline, end: float) -> float | None:
    """The first time in (0, ``end``), after the force's peak, where the force P' of ``spline``
    falls through zero and dips below round-off (:data:`SLACK` of the peak), or None. The
    samples of a stiff contact's tail can stay positive while P' between them (a quadratic on
    each piece) dips below zero (strings at 100 N: -0.08 N for 2.7 us, 8 us before the first
    negative sample): the force no longer presses there, and friction, which acts only while it
    presses, would switch at every instant (mu F <= 0 leaves grip and slide undecided)."""
    force = spline.derivative()
    knots = spline.x
    samples = force(knots)
    peak = float(np.max(samples))
    roots = force.roots(discontinuity=False, extrapolate=False)
    after = knots[int(np.argmax(samples))]
    falls = roots[(roots > after) & (roots < end) & (force(roots, 1) < 0.0)]
    for r in falls:
        nxt = roots[roots > r]
        dip = np.linspace(r, min(nxt[0] if nxt.size else end, end), 33)
        if float(np.min(force(dip))) < -SLACK * peak:
            return float(r)
    return None
