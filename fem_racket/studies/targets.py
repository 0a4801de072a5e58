"""The mass properties a racket can be customised to (``customise``: lead meets them) or ranked
on (``closest``), by name: plain tables importing nothing of the library's numerics, so the
command line shows them (``fem-racket COMMAND --help``) without numpy;
:mod:`fem_racket.studies.target_values` reads the values given for them.
"""

from __future__ import annotations

from fem_racket.frame.constants import KG_CM2

__all__ = ["KEEP", "RANKED", "TARGETS"]

#: Targets lead can meet: dest -> (metavar, help, factor to SI, JSON key).
TARGETS = {
    "swing_weight": (
        "KG_CM2",
        "swing weight about 0.10 m from the butt [kg cm^2]",
        KG_CM2,
        "swing_weight_kg_cm2",
    ),
    "balance": ("M", "balance point from the butt [m]", 1.0, "balance_m"),
    "twist_weight": (
        "KG_CM2",
        "twistweight, polar moment about the long axis [kg cm^2]",
        KG_CM2,
        "twist_weight_kg_cm2",
    ),
    "mass": ("KG", "mass [kg]", 1.0, "mass_kg"),
}
#: Targets only ranked on (closest).
RANKED = {
    "f1": ("HZ", "first free-free frequency [Hz]", 1.0, "f1_hz"),
    "stiffness_ra": ("RA", "stiffness [RA]", 1.0, "stiffness_ra"),
}
#: The target value meaning "as the racket is now".
KEEP = "keep"
