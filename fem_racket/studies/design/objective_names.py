"""A design study's objectives by name, with their labels and which are minimised: plain values
importing nothing, so the command line shows them (``fem-racket COMMAND --help``) without
numpy; :mod:`fem_racket.studies.design.variables` imports them (and keeps them among its own
names), :mod:`fem_racket.studies.design.objectives` evaluates them.
"""

from __future__ import annotations

__all__ = ["MINIMISED", "OBJECTIVES"]

#: Objectives (maximised): name -> label with units.
OBJECTIVES: dict[str, str] = {
    "cor": "mean apparent COR e_A [-]",
    "ball_speed": "mean ball speed v_out [m/s]",
    "power_region": "power region length [m]",
    "handle_shock": "mean handle shock, RMS grip vibration force [N]",
    "peak_grip_force": "mean peak grip force [N]",
}
#: Objectives minimised (the others are maximised).
MINIMISED = frozenset({"handle_shock", "peak_grip_force"})
