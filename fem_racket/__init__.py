"""fem_racket: finite-element simulation of a tennis ball striking a racket frame.

Reproduces and extends Kawazoe & Kanda (1997), "Analysis of impact phenomena in a tennis
ball-racket system", JSME Int. J. C 40(1).
"""

from fem_racket.contact.hunt_crossley import HuntCrossley
from fem_racket.contact.hysteretic import Hysteretic
from fem_racket.contact.law import ContactLaw
from fem_racket.contact.linear import (
    Ball,
    LinearContact,
    cor_from_zeta,
    kcb_from_speed,
    zeta_from_cor,
)
from fem_racket.contact.presets import get_law
from fem_racket.contact.series import SeriesBallString
from fem_racket.contact.spring_dashpot import SpringDashpot
from fem_racket.frame.continuous import free_free_frequencies
from fem_racket.frame.forms import FrameFE, assemble
from fem_racket.frame.hand import Hand
from fem_racket.frame.hermite import assemble_closed_form
from fem_racket.frame.mesh import FrameMesh, frame_from_mesh, frame_mesh, graded_mesh
from fem_racket.frame.modal import (
    FreeModes,
    MassProperties,
    free_modes,
    mass_properties,
    mode_nodes,
)
from fem_racket.frame.model import FrameModel
from fem_racket.frame.segments import Frame, Segment, rigid_frame, standard_frame
from fem_racket.frame.specs import RacketSpec, balance_point, fit_racket, racket_spec, swing_weight
from fem_racket.impact.coupled import CoupledModes, coupled_modes
from fem_racket.impact.engine import ImpactBatch, impacts, modal_impacts
from fem_racket.impact.held import simulate_held
from fem_racket.impact.integrators import SOLVERS, NoSeparationError
from fem_racket.impact.result import ImpactResult
from fem_racket.impact.rigid import (
    ClampedImpact,
    RigidImpact,
    clamped_impact,
    rigid_impact,
    rigid_impact_at,
)
from fem_racket.impact.setup import Impact
from fem_racket.impact.simulate import simulate
from fem_racket.impact.swing import Swing, ball_speed_out
from fem_racket.io.animate import render_animation
from fem_racket.io.config import RunConfig, example_config, load_config, parse_config
from fem_racket.io.figure_files import save_figure
from fem_racket.io.mesh_files import read_mesh, write_mesh
from fem_racket.io.plotting import plot_impact, plot_refinement, plot_sweep
from fem_racket.io.vtk import write_vtk_series
from fem_racket.io.vtk_series import ImpactSeries, impact_series
from fem_racket.studies.racket_map import RacketMap, racket_map
from fem_racket.studies.refine import RefinementStudy, refinement_study
from fem_racket.studies.sweep import sweep
from fem_racket.studies.sweetspots import SweetSpots, centre_of_percussion
from fem_racket.validation import InputError
from fem_racket.version import __version__

__all__ = [
    "SOLVERS",
    "Ball",
    "ClampedImpact",
    "ContactLaw",
    "CoupledModes",
    "Frame",
    "FrameFE",
    "FrameMesh",
    "FrameModel",
    "FreeModes",
    "HuntCrossley",
    "Hysteretic",
    "Impact",
    "ImpactBatch",
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
    "SeriesBallString",
    "SpringDashpot",
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
    "get_law",
    "impact_series",
    "impacts",
    "kcb_from_speed",
    "graded_mesh",
    "load_config",
    "mass_properties",
    "modal_impacts",
    "mode_nodes",
    "parse_config",
    "plot_impact",
    "plot_refinement",
    "plot_sweep",
    "read_mesh",
    "refinement_study",
    "render_animation",
    "rigid_frame",
    "rigid_impact",
    "rigid_impact_at",
    "save_figure",
    "simulate",
    "standard_frame",
    "sweep",
    "write_mesh",
    "write_vtk_series",
    "zeta_from_cor",
    # racket motion, sweet spots and power maps, racket from its specification (issue 14)
    "RacketMap",
    "RacketSpec",
    "SweetSpots",
    "Swing",
    "balance_point",
    "ball_speed_out",
    "centre_of_percussion",
    "fit_racket",
    "racket_map",
    "racket_spec",
    "swing_weight",
    "Hand",
    "simulate_held",
]
