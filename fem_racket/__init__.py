"""fem_racket: finite-element simulation of a tennis ball striking a racket frame.

Reproduces and extends Kawazoe & Kanda (1997), "Analysis of impact phenomena in a tennis
ball-racket system", JSME Int. J. C 40(1).

The public names below are imported on first use (PEP 562 module ``__getattr__``):
``import fem_racket`` costs a few milliseconds, and ``fem_racket.simulate`` imports only what
an impact needs, not the plotting, file and study modules (the command line starts fast).
"""

from __future__ import annotations

import importlib
from typing import Any

#: Public names by the module that defines them (relative to ``fem_racket``).
_PUBLIC: dict[str, tuple[str, ...]] = {
    "contact.hunt_crossley": ("HuntCrossley",),
    "contact.hysteretic": ("Hysteretic",),
    "contact.law": ("ContactLaw",),
    "contact.linear": ("Ball", "LinearContact", "cor_from_zeta", "kcb_from_speed", "zeta_from_cor"),
    "contact.parameters": ("LawCondition", "LawFit", "LawParameter"),
    "contact.presets": ("get_law",),
    "contact.series": ("SeriesBallString",),
    "frame.catalogue": ("Catalogue", "catalogue"),
    "frame.continuous": ("free_free_frequencies",),
    "frame.fe": ("FrameFE",),
    "frame.forms": ("assemble",),
    "frame.hand": ("Hand",),
    "frame.head": ("HeadOutline",),
    "frame.hermite": ("assemble_closed_form",),
    "frame.lead": ("Lead", "add_lead"),
    "frame.mesh": ("FrameMesh", "frame_from_mesh", "frame_mesh", "graded_mesh"),
    "frame.modal": ("FreeModes", "MassProperties", "free_modes", "mass_properties", "mode_nodes"),
    "frame.model": ("FrameModel",),
    "frame.segments": ("Frame", "Segment", "TorsionSegment", "rigid_frame", "standard_frame"),
    "frame.specs": ("RacketSpec", "balance_point", "fit_racket", "racket_spec", "swing_weight"),
    "frame.torsion": ("TorsionModel", "TorsionModes"),
    "frame.twist_fit": ("fit_torsion",),
    "impact.analytic.coupled": ("CoupledModes", "coupled_modes"),
    "impact.exact.engine": ("EngineOptions", "ImpactBatch", "impacts", "modal_impacts"),
    "impact.held.grip": ("simulate_held",),
    "impact.held.modal": ("HeldContact", "held_contact"),
    "impact.held.run": ("HeldRun", "held_impact"),
    "impact.held.shock": ("grip_peak", "vibration_rms"),
    "impact.ode.integrators": ("NoSeparationError",),
    "impact.result": ("ImpactResult",),
    "impact.analytic.rigid": (
        "ClampedImpact",
        "RigidImpact",
        "clamped_impact",
        "rigid_impact",
        "rigid_impact_at",
    ),
    "impact.clamped": ("ClampedHead", "ClampedImpact"),
    "impact.incidence": ("Incidence",),
    "impact.oblique.solve": ("ObliqueResult", "solve_oblique"),
    "impact.simulate_oblique": ("simulate_oblique",),
    "impact.problem": ("HeldRacket", "Impact", "ImpactProblem"),
    "impact.settings": ("SolverOptions",),
    "impact.simulate": ("simulate",),
    "impact.solvers": ("SOLVERS", "SOLVER_NAMES", "Solver", "make_solver"),
    "impact.strung.point": ("StrungPoint", "strung_point"),
    "impact.strung.impact": ("StrungImpact", "simulate_strung"),
    "impact.swing": ("Swing", "ball_speed_out"),
    "io.animate": ("AnimationOptions", "render_animation"),
    "io.config": ("RunConfig", "example_config", "load_config", "parse_config"),
    "io.figure_files": ("save_figure",),
    "io.map_files": ("map_figure",),
    "io.mesh_files": ("read_mesh", "write_mesh"),
    "io.plotting": ("plot_impact", "plot_refinement", "plot_sweep"),
    "io.vtk": ("write_vtk_series",),
    "io.strung_vtk": ("write_strung_vtk",),
    "io.vtk_series": ("ImpactSeries", "impact_series"),
    "studies.closest": ("closest",),
    "studies.compare": ("Play", "Setup", "compare"),
    "studies.customise": ("Target", "customise"),
    "studies.face_map": ("FaceMap", "face_map"),
    "strings.bed": ("StringBed",),
    "strings.materials": ("STRINGS", "StringMaterial"),
    "strings.point": ("bed_point_data",),
    "strings.stiffening": ("stiffening",),
    "studies.oblique_sweep": ("ObliqueSweep", "oblique_map", "oblique_sweep"),
    "studies.racket_map": ("RacketMap", "racket_map"),
    "studies.strings_sweep": ("tension_sweep",),
    "studies.refine": ("RefinementStudy", "refinement_study"),
    "studies.sweep": ("sweep",),
    "studies.sweetspots": ("SweetSpots", "centre_of_percussion"),
    "validation": ("InputError",),
    "version": ("__version__",),
}
_HOME = {name: module for module, names in _PUBLIC.items() for name in names}

__all__ = list(_HOME)


def __getattr__(name: str) -> Any:
    """Import a public name from its module on first use (then it is a plain attribute)."""
    module = _HOME.get(name)
    if module is None:
        raise AttributeError(f"module 'fem_racket' has no attribute {name!r}")
    value = getattr(importlib.import_module(f"fem_racket.{module}"), name)
    globals()[name] = value
    return value


def __dir__() -> list[str]:
    """The public names and the module's dunders, not its helpers (``importlib``, ``Any``)."""
    return sorted({*__all__, *(n for n in globals() if n.startswith("__") and n.endswith("__"))})
