"""A design study's search methods, by name: plain tuples importing nothing, so ``fem-racket
optimize --help`` shows them without numpy or scipy; :mod:`fem_racket.studies.design.solvers`
runs scipy.optimize's local and global ones, :mod:`fem_racket.studies.design.pareto` pymoo's
NSGA-II, and :mod:`fem_racket.studies.design.unused` checks the options each one takes.
"""

from __future__ import annotations

__all__ = ["GLOBAL_METHODS", "LOCAL_METHODS", "METHODS"]

#: scipy.optimize's local and global methods (:mod:`fem_racket.studies.design.solvers`).
LOCAL_METHODS = ("SLSQP", "trust-constr")
GLOBAL_METHODS = ("differential-evolution",)
#: Every method: scipy's and pymoo's NSGA-II.
METHODS = (*LOCAL_METHODS, *GLOBAL_METHODS, "nsga2")
