"""The spin map's grid unless given, and the map options it refuses. Plain values importing
nothing, so ``fem-racket map --help`` shows them without numpy; :mod:`fem_racket.studies.spin_map`
imports them (and keeps them among its own names).
"""

from __future__ import annotations

__all__ = ["SPIN_OFFSETS", "SPIN_POSITIONS", "SPIN_REFUSES"]

#: The spin map's grid unless given: x/L along the head and y [m] across it (each point is one
#: oblique impact).
SPIN_POSITIONS = "0.52:0.96:12"
SPIN_OFFSETS = "-0.12:0.12:9"
#: Options of a map that the spin map does not use, refused by ``map --angle`` and a run file's
#: spin map alike (a swing is a stroke: simulate's face and path angles).
SPIN_REFUSES = {
    "power_fraction": "the spin map has no power area",
    "racket_speed": "the spin map strikes the racket at rest (simulate --path-angle strokes)",
    "pivot": "the spin map strikes the racket at rest",
    "reference": "the spin map strikes the racket at rest",
}
