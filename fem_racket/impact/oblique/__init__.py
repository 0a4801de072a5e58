"""The oblique, spinning ball: its normal impact solved as a head-on one (by the problem's
solver, on the hand-held racket or on a clamped head), then the tangential contact
(:mod:`fem_racket.impact.tangential`) over its force history (:mod:`.solve`); and a stroke's
geometry, a tilted face swung along an inclined path (:mod:`.stroke`).

Room of impact/ above ``held/`` and ``tangential/``: the solvers call it for a problem with an
incidence; the entry points that build the problem and its solver stay at the root
(:mod:`fem_racket.impact.simulate_oblique`, :mod:`fem_racket.impact.simulate_stroke`).
"""
