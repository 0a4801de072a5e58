"""The ball/string law's named values that the command line shows before any work: plain
numbers, importing nothing (``fem-racket COMMAND --help`` reads them without numpy).

Each value has this one home; :mod:`fem_racket.contact.linear` imports them from here (and keeps
them among its own names).
"""

from __future__ import annotations

__all__ = ["DEFAULT_BALL_MASS", "KCB_SPEED_RANGE", "SEPARATION_EVENTS"]

#: Ball mass [kg]. The paper does not print it; the rules allow 56.0-59.4 g.
DEFAULT_BALL_MASS = 0.057
#: Impact speeds [m/s] over which :func:`fem_racket.contact.linear.kcb_from_speed` extrapolates
#: the paper's K_CB law.
KCB_SPEED_RANGE = (1.0, 100.0)
#: The events that end the linear law's contact: the spring's deflection back to 0 (the
#: paper's) or its force back to 0.
SEPARATION_EVENTS = ("displacement", "force")
