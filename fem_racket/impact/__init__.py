"""One impact of the ball on the frame.

Where and how fast the ball strikes (:mod:`.setup`), the coupled ball + frame system
(:mod:`.system`), the closed forms of the paper's eqs 1-16 (:mod:`.rigid`), the coupled modes
(:mod:`.coupled`), the solvers (the closed-form eigen-solution :mod:`.closed_form`, CVODE and
scipy BDF in :mod:`.integrators`; for any contact law the fast general integrator
:mod:`.general` on the impact-point receptance :mod:`.receptance`, CVODE :mod:`.law_cvode`, and
:mod:`.law_impact` for histories and an initially moving racket) and
:func:`~fem_racket.impact.simulate.simulate` (its paths: the paper's linear law in
:mod:`.simulate_linear`, any law or a moving racket in :mod:`.simulate_law`) returning an
:class:`~fem_racket.impact.simulate.ImpactResult`.

Layer: above :mod:`fem_racket.frame` and :mod:`fem_racket.contact`; may import those two and the
base modules (:mod:`fem_racket.validation`, :mod:`fem_racket.outputs`, :mod:`fem_racket.version`).
"""
