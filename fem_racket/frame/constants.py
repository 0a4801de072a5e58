"""The frame's named values that the command line shows before any work: plain numbers and
names, importing nothing (``fem-racket COMMAND --help`` reads them without numpy).

Each value has this one home; the modules that use it import it from here (and keep it among
their own names): :mod:`fem_racket.frame.segments`, :mod:`fem_racket.frame.model`,
:mod:`fem_racket.frame.clock`, :mod:`fem_racket.frame.specs`.
"""

from __future__ import annotations

__all__ = [
    "CLOCK_PLACES",
    "DEFAULT_MODES",
    "FIT_ELEMENTS",
    "KG_CM2",
    "PAPER_EI1",
    "PLACES",
    "RIGID_EI1",
]

#: EI1 of the paper's standard racket [N m^2] (section 2.2).
PAPER_EI1 = 146.0
#: EI1 of the paper's "rigid" racket [N m^2] (section 3.1).
RIGID_EI1 = 9999.0
#: Flexible modes kept by default (COR within ~1e-7 of the untruncated FE model).
DEFAULT_MODES = 80
#: Cells of the mesh used to compute f1 and written by ``fem-racket fit``
#: (:data:`fem_racket.frame.specs.DEFAULT_ELEMENTS`).
FIT_ELEMENTS = 40
#: kg m^2 per kg cm^2.
KG_CM2 = 1e-4
#: Clock places -> the hour whose angle from the tip they sit at.
CLOCK_PLACES = {"12": 0, "2/10": 2, "3/9": 3, "4/8": 4}
#: Every named place, tip first.
PLACES = (*CLOCK_PLACES, "throat", "handle", "butt")
