"""One impact's named values that the command line shows before any work: the solvers' and
events' names and the default tolerances, swing and shock window, importing nothing of the
library's numerics (``fem-racket COMMAND --help`` reads them without numpy).

Each value has this one home; the modules that use it import it from here (and keep it among
their own names): :mod:`fem_racket.impact.solvers` (whose registry must hold exactly the
solvers named here), :mod:`fem_racket.impact.settings`, :mod:`fem_racket.impact.reduction`,
:mod:`fem_racket.impact.system`, :mod:`fem_racket.impact.swing`,
:mod:`fem_racket.impact.held.shock`. The separation events are the linear law's
(:data:`fem_racket.contact.constants.SEPARATION_EVENTS`), kept here among the impact's names.
"""

from __future__ import annotations

from fem_racket.contact.constants import KCB_SPEED_RANGE, SEPARATION_EVENTS

__all__ = [
    "BASES",
    "DEFAULT_REFERENCE",
    "DEFAULT_TOLERANCE",
    "DEFAULT_WINDOW",
    "MAX_RACKET_SPEED",
    "SEPARATION_EVENTS",
    "SOLVER_NAMES",
]

#: Every name :func:`fem_racket.impact.solvers.make_solver` takes: ``auto``, then the solvers
#: of :data:`fem_racket.impact.solvers.SOLVERS` in its order.
SOLVER_NAMES = ("auto", "exact", "general", "cvode", "bdf")
#: Frame coordinates of the ODE solvers: free-free modes or every FE DOF.
BASES = ("modal", "physical")
#: COR tolerance used when none is given (at or below the 20-element model's own
#: discretisation error, ~4e-7 in COR).
DEFAULT_TOLERANCE = 1e-6
#: Largest |racket speed| [m/s] the tool takes: racket heads move at up to about 40-50 m/s in the
#: fastest serves (an assumption of this bound), and 100 m/s is the top of the speeds the paper's
#: K_CB law is given for (:data:`fem_racket.contact.constants.KCB_SPEED_RANGE`).
MAX_RACKET_SPEED = KCB_SPEED_RANGE[1]
#: Reference point of the racket speed, x/L (the string centre).
DEFAULT_REFERENCE = 0.75
#: Window of the shock measures from the start of contact [s] (assumption,
#: :mod:`fem_racket.impact.held.shock`).
DEFAULT_WINDOW = 0.05
