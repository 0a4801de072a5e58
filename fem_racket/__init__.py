"""fem_racket: finite-element simulation of a tennis ball striking a racket frame.

Reproduces and extends Kawazoe & Kanda (1997), "Analysis of impact phenomena in a tennis
ball-racket system", JSME Int. J. C 40(1).
"""

from importlib.metadata import PackageNotFoundError, version

from .animate import render_animation
from .config import RunConfig, example_config, load_config, parse_config
from .coupled import CoupledModes, coupled_modes
from .exact import free_free_frequencies
from .forms import FrameFE, assemble
from .hermite import assemble_closed_form
from .impact import ImpactResult, simulate
from .integrators import SOLVERS, NoSeparationError
from .mesh import FrameMesh, frame_from_mesh, frame_mesh, graded_mesh
from .mesh_io import read_mesh, write_mesh
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
from .refine import RefinementStudy, refinement_study
from .rigid import ClampedImpact, RigidImpact, clamped_impact, rigid_impact, rigid_impact_at
from .sweep import sweep
from .validation import InputError
from .vtk import ImpactSeries, impact_series, write_vtk_series

try:
    __version__ = version("fem_racket")
except PackageNotFoundError:  # running from a source tree without installation
    __version__ = "0.0.0"

__all__ = [
    "SOLVERS",
    "Ball",
    "ClampedImpact",
    "CoupledModes",
    "Frame",
    "FrameFE",
    "FrameMesh",
    "FrameModel",
    "FreeModes",
    "Impact",
    "ImpactResult",
    "ImpactSeries",
    "InputError",
    "LinearContact",
    "MassProperties",
    "NoSeparationError",
    "RefinementStudy",
    "RigidImpact",
    "RunConfig",
    "Segment",
    "__version__",
    "assemble",
    "assemble_closed_form",
    "clamped_impact",
    "cor_from_zeta",
    "frame_from_mesh",
    "coupled_modes",
    "example_config",
    "frame_mesh",
    "free_free_frequencies",
    "free_modes",
    "impact_series",
    "kcb_from_speed",
    "graded_mesh",
    "load_config",
    "mass_properties",
    "mode_nodes",
    "parse_config",
    "read_mesh",
    "refinement_study",
    "render_animation",
    "rigid_frame",
    "rigid_impact",
    "rigid_impact_at",
    "simulate",
    "standard_frame",
    "sweep",
    "write_mesh",
    "write_vtk_series",
    "zeta_from_cor",
]
