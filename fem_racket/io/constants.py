"""The run files' named values that the command line shows before any work: plain tables,
importing nothing of the library's numerics (``fem-racket COMMAND --help`` reads them without
numpy). Each has this one home; :mod:`fem_racket.io.config_design` imports it from here.
"""

from __future__ import annotations

__all__ = ["CONSTRAINTS"]

#: Constraint options (argparse dests, table keys) -> (quantity, help).
CONSTRAINTS = {
    "mass_range": ("mass_kg", "total mass [kg]"),
    "balance_range": ("balance_m", "balance point from the butt [m]"),
    "swing_weight_range": ("swing_weight_kg_cm2", "swing weight about 0.10 m [kg cm^2]"),
    "f1_range": ("f1_hz", "first free-free frequency [Hz]"),
}
