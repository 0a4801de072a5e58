"""One impact of the ball on the racket.

Stating it: :mod:`fem_racket.impact.problem` (:class:`ImpactProblem`: the structure, free or
held in a hand, the impact point, the ball and its speed, the contact law, the racket's motion).
Solving it: :mod:`fem_racket.impact.solvers` (one protocol and one registry: ``exact``,
``general``, ``cvode``, ``bdf``, ``auto``; options bound when a solver is made,
:mod:`fem_racket.impact.settings`); :func:`fem_racket.impact.simulate.simulate` is the one-call
shim over both, returning an :class:`~fem_racket.impact.result.ImpactResult`.

The rooms, lowest first (``tests/test_layering.py`` keeps them in order):

- the root's base modules: the problem and its checks, the solver options
  (:mod:`fem_racket.impact.settings`), the coupled ball + frame ODE
  (:mod:`fem_racket.impact.system`), the mode reduction (:mod:`fem_racket.impact.reduction`),
  modal data at impact points, on and off the long axis (:mod:`fem_racket.impact.point`,
  :mod:`fem_racket.impact.offaxis`), the swing (:mod:`fem_racket.impact.swing`), the incidence
  of an oblique ball (:mod:`fem_racket.impact.incidence`), the result (``result*``);
- ``analytic/``: the paper's closed forms, eqs 1-16;
- ``exact/``: the exact solution of the linear law (eigen-solution, batched engine);
- ``general/``: the general integrator for any contact law;
- ``ode/``: CVODE and scipy BDF on the coupled ODE;
- ``tangential/``: the tangential contact of an oblique ball over a normal force history;
- ``held/``: the hand-held racket; ``strung/``: the strung racket (frame and string bed);
- ``oblique/``: the oblique, spinning ball (its normal impact, then the tangential contact);
- the root's dispatch: the solvers (:mod:`fem_racket.impact.solvers`, one batch,
  :mod:`fem_racket.impact.batch_solve`), ``simulate`` and its two paths
  (:mod:`fem_racket.impact.simulate_linear`, :mod:`fem_racket.impact.simulate_law`), the law
  path's histories (:mod:`fem_racket.impact.law_impact`) and the oblique entry points
  (:mod:`fem_racket.impact.simulate_oblique`, :mod:`fem_racket.impact.simulate_stroke`).

Layer: above :mod:`fem_racket.frame` and :mod:`fem_racket.contact`; may import those two and the
base modules (:mod:`fem_racket.validation`, :mod:`fem_racket.outputs`, :mod:`fem_racket.version`).
"""
