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

__all__ = ["SLACK", "TAIL", "first_release"]

#: The contact's tail: after the last sample pressing with at least this fraction of the peak.
TAIL = 1e-2
#: A dip of the interpolated force in the tail below zero deeper than this fraction of its peak
#: ends the window of friction (:func:`first_release`); shallower ones are round-off (1e-27 N to
#: 4e-14 N measured on pressing histories).
SLACK = 1e-9


def first_release(spline, end: float) -> float | None:
    """The first time in the contact's tail (:data:`TAIL`), before ``end``, where the force P'
    of ``spline`` falls through zero and dips below round-off (:data:`SLACK` of the peak), or
    None.

    As the force returns to zero its samples can stay positive while P' between them dips below
    zero (strings at 100 N: samples 1.44 N and 1.6e-4 N, P' -0.08 N between them for 2.7 us, 8
    us before the first negative sample): there mu F <= 0 leaves grip and slide undecided, and
    the march switched at one instant 200 times. Friction acts only while the force presses:
    the window ends at that fall. Earlier, an undershoot of P' between pressing samples (after
    a dashpot's force at t = 0: 1 275 N, then 30 N, P' -45 N between them on a 50 N bed) is
    the interpolant's, the contact presses on, and the march rides through it as before."""
    force = spline.derivative()
    knots = spline.x
    samples = force(knots)
    peak = float(np.max(samples))
    tail = knots[int(np.flatnonzero(samples >= TAIL * peak)[-1])]
    roots = force.roots(discontinuity=False, extrapolate=False)
    falls = roots[(roots > tail) & (roots < end) & (force(roots, 1) < 0.0)]
    for r in falls:
        nxt = roots[roots > r]
        dip = np.linspace(r, min(nxt[0] if nxt.size else end, end), 33)
        if float(np.min(force(dip))) < -SLACK * peak:
            return float(r)
    return None
