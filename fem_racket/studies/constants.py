"""The studies' named values that the command line shows before any work: the executors, the
spin map's grid, the design study's zones and objectives, the catalogue's targets. Plain names,
numbers and tables, importing nothing of the library's numerics (``fem-racket COMMAND --help``
reads them without numpy).

Each value has this one home; the modules that use it import it from here (and keep it among
their own names): :mod:`fem_racket.studies.executors`, :mod:`fem_racket.studies.map_options`,
:mod:`fem_racket.studies.spin_map`, :mod:`fem_racket.studies.design.zone`,
:mod:`fem_racket.studies.design.variables`, :mod:`fem_racket.studies.design.solvers`,
:mod:`fem_racket.studies.design.unused`, :mod:`fem_racket.studies.target_values`.
"""

from __future__ import annotations

from fem_racket.frame.constants import KG_CM2

__all__ = [
    "BACKENDS",
    "GLOBAL_METHODS",
    "KEEP",
    "LOCAL_METHODS",
    "MAP_POSITIONS",
    "MAP_POWER_FRACTION",
    "METHODS",
    "MINIMISED",
    "OBJECTIVES",
    "RANKED",
    "SPIN_OFFSETS",
    "SPIN_POSITIONS",
    "SPIN_REFUSES",
    "TARGETS",
    "ZONES",
]

#: Where sweep chunks run (:mod:`fem_racket.studies.executors`).
BACKENDS = ("serial", "processes", "dask")

#: A map's default grid: the string face from its throat end to the tip, x/L (start, stop,
#: points) (:data:`fem_racket.studies.map_options.DEFAULT_POSITIONS`).
MAP_POSITIONS = (0.5, 1.0, 200)
#: Default fraction of the maximum v_out bounding the power region
#: (:data:`fem_racket.studies.map_options.DEFAULT_POWER_FRACTION`).
MAP_POWER_FRACTION = 0.95

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

#: A design study's search methods: scipy.optimize's local and global ones
#: (:mod:`fem_racket.studies.design.solvers`), and all, with pymoo's NSGA-II
#: (:mod:`fem_racket.studies.design.unused`).
LOCAL_METHODS = ("SLSQP", "trust-constr")
GLOBAL_METHODS = ("differential-evolution",)
METHODS = (*LOCAL_METHODS, *GLOBAL_METHODS, "nsga2")
#: The zones a design study names: uniform over a range, or a Gaussian about mode 1's node.
ZONES = ("uniform", "node")
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
