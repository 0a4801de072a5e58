"""The strung racket: the frame and the string bed in series at the impact point.

The structure seen from the ball (:mod:`.point`: the frame's modes at the point, :mod:`.frame`,
and the bed's, one modal structure), one impact on it by the exact solution (:mod:`.exact`), the
general integrator or CVODE, a stretching bed by CVODE (:mod:`.stretch`), with histories and the
energy bookkeeping (:mod:`.impact`, :mod:`.result`), and the solvers' hook (:mod:`.solve`).

Room of impact/ beside ``held/``: it takes the methods (``exact/``, ``general/``, ``ode/``) and
the root's base modules; the problem checks a bed without it
(:func:`fem_racket.impact.problem_checks.check_strings`), and only the solvers import it.
"""
