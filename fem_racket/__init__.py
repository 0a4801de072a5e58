"""fem_racket: finite-element simulation of a tennis ball striking a racket frame.

Reproduces and extends Kawazoe & Kanda (1997), "Analysis of impact phenomena in a tennis
ball-racket system", JSME Int. J. C 40(1).
"""

from importlib.metadata import PackageNotFoundError, version

from .config import RunConfig, example_config, load_config, parse_config
from .forms import FrameFE, assemble
from .impact import ImpactResult, simulate
from .integrators import SOLVERS, NoSeparationError
from .mesh import FrameMesh, frame_mesh, read_mesh, write_mesh
from .modal import FreeModes, MassProperties, free_modes, mass_properties, mode_nodes
from .model import FrameModel
from .params import (
    Ball,
    Frame,
    Impact,
    LinearContact,
    Segment,
    cor_from_zeta,
    kcb_from_speed,
    rigid_frame,
    standard_frame,
    zeta_from_cor,
)
from .rigid import ClampedImpact, RigidImpact, clamped_impact, rigid_impact
from .validation import InputError

try:
    __version__ = version("fem_racket")
except PackageNotFoundError:  # running from a source tree without installation
    __version__ = "0.0.0"

__all__ = [
    "SOLVERS",
    "Ball",
    "ClampedImpact",
    "Frame",
    "FrameFE",
    "FrameMesh",
    "FrameModel",
    "FreeModes",
    "Impact",
    "ImpactResult",
    "InputError",
    "LinearContact",
    "MassProperties",
    "NoSeparationError",
    "RigidImpact",
    "RunConfig",
    "Segment",
    "__version__",
    "assemble",
    "clamped_impact",
    "cor_from_zeta",
    "example_config",
    "frame_mesh",
    "free_modes",
    "kcb_from_speed",
    "load_config",
    "mass_properties",
    "mode_nodes",
    "parse_config",
    "read_mesh",
    "rigid_frame",
    "rigid_impact",
    "simulate",
    "standard_frame",
    "write_mesh",
    "zeta_from_cor",
]
