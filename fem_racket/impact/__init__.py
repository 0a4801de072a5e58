"""One impact of the ball on the frame.

Where and how fast the ball strikes (:mod:`fem_racket.impact.problem`), the coupled ball + frame
system
(:mod:`fem_racket.impact.system`), the closed forms of the paper's eqs 1-16
(:mod:`fem_racket.impact.analytic.rigid`), the coupled modes
(:mod:`fem_racket.impact.analytic.coupled`), the solvers (the closed-form eigen-solution
:mod:`fem_racket.impact.exact.closed_form`, CVODE and
scipy BDF in :mod:`fem_racket.impact.ode.integrators`; for any contact law the fast general
integrator
:mod:`fem_racket.impact.general.integrator` on the impact-point receptance
:mod:`fem_racket.impact.general.receptance`, CVODE :mod:`fem_racket.impact.ode.law_cvode`, and
:mod:`fem_racket.impact.law_impact` for histories and an initially moving racket) and
:func:`~fem_racket.impact.simulate.simulate` (its paths: the paper's linear law in
:mod:`fem_racket.impact.simulate_linear`, any law or a moving racket in
:mod:`fem_racket.impact.simulate_law`) returning an
:class:`~fem_racket.impact.simulate.ImpactResult`.

Layer: above :mod:`fem_racket.frame` and :mod:`fem_racket.contact`; may import those two and the
base modules (:mod:`fem_racket.validation`, :mod:`fem_racket.outputs`, :mod:`fem_racket.version`).
"""
