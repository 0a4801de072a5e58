"""A face map's defaults: its grid along the face and the fraction bounding its power region.
Plain numbers importing nothing, so ``fem-racket map --help`` shows them without numpy;
:mod:`fem_racket.studies.map_options` imports them (and keeps them among its own names as
``DEFAULT_POSITIONS`` and ``DEFAULT_POWER_FRACTION``).
"""

from __future__ import annotations

__all__ = ["MAP_POSITIONS", "MAP_POWER_FRACTION"]

#: A map's default grid: the string face from its throat end to the tip, x/L (start, stop,
#: points) (:data:`fem_racket.studies.map_options.DEFAULT_POSITIONS`).
MAP_POSITIONS = (0.5, 1.0, 200)
#: Default fraction of the maximum v_out bounding the power region
#: (:data:`fem_racket.studies.map_options.DEFAULT_POWER_FRACTION`).
MAP_POWER_FRACTION = 0.95
