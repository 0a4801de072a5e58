"""A racket made from catalogue numbers, written as a mesh file with its JSON sidecar: the work of
``fem-racket fit`` (:func:`fit_files`), shared by the command and the run file's method
(:mod:`fem_racket.io.config_racket`) so that both compute and write the same files; the mesh
files of ``fem-racket customise`` too (:mod:`fem_racket.io.customise_files`).
"""

from __future__ import annotations

import json
from collections.abc import Mapping
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from fem_racket.frame.specs import DEFAULT_ELEMENTS, KG_CM2
from fem_racket.outputs import json_ready, provenance
from fem_racket.validation import InputError, show

__all__ = [
    "FIT_OUTPUT",
    "FitSpec",
    "FittedRacket",
    "fit_files",
    "fit_frame",
    "mesh_files",
    "write_mesh_files",
]

#: Where ``fem-racket fit`` writes its mesh unless told (``--out``, ``[fit] out``), replacing the
#: mesh an earlier fit wrote there.
FIT_OUTPUT = Path("output") / "racket.vtu"


def mesh_files(out: Path) -> list[Path]:
    """A racket written as a mesh file (fit, customise): the mesh ``out`` and its JSON sidecar,
    to check before the work and write as one set with :func:`write_mesh_files`; ``out`` refused
    unless a mesh format :func:`~fem_racket.io.mesh_files.read_mesh` reads back."""
    from fem_racket.io.mesh_files import check_mesh_suffix
    from fem_racket.outputs import sidecar_path

    return [check_mesh_suffix(out, "out"), sidecar_path(out)]


def write_mesh_files(mesh: Any, out: Path, sidecar: str, *, overwrite: bool = False) -> None:
    """Write ``mesh`` (a FrameMesh) to ``out`` and the text ``sidecar`` (its JSON) beside it,
    as one set: both or, on any fault, neither."""
    from fem_racket.io.mesh_files import save_mesh
    from fem_racket.outputs import atomic_outputs

    with atomic_outputs(mesh_files(out), overwrite=overwrite) as (tmp, side):
        save_mesh(mesh, tmp)
        side.write_text(sidecar, encoding="utf-8")


@dataclass(frozen=True)
class FitSpec:
    """A racket's catalogue numbers, as ``fem-racket fit`` takes them.

    Attributes
    ----------
    length, mass, balance : float
        L [m], mass [kg], balance point from the butt [m].
    swing_weight : float
        About an axis 0.10 m from the butt [kg cm^2].
    f1 : float or None
        First free-free bending frequency [Hz] (None: EI1 = 146 N m^2 kept).
    twist_weight : float or None
        Polar moment about the long axis [kg cm^2] (None: no torsion data).
    torsion_frequency : float or None
        First free-free torsion frequency [Hz], with ``twist_weight``.
    elements : int
        Cells of the mesh written.
    """

    length: float
    mass: float
    balance: float
    swing_weight: float
    f1: float | None = None
    twist_weight: float | None = None
    torsion_frequency: float | None = None
    elements: int = DEFAULT_ELEMENTS


@dataclass(frozen=True)
class FittedRacket:
    """Everything ``fem-racket fit`` reports: the frame fitted to a racket's catalogue numbers.

    Attributes
    ----------
    frame : Frame
        Three segments (:func:`fem_racket.frame.specs.fit_racket`), with torsion data given a
        twistweight.
    mesh : FrameMesh
        The frame on the cells of the fit (the mesh the command writes).
    target, fitted : dict
        The catalogue numbers asked and those of the mesh: length [m], mass [kg], balance [m],
        swing weight [kg cm^2], f1 [Hz] (and twistweight [kg cm^2], torsion f1 [Hz]).
    """

    frame: Any
    mesh: Any
    target: dict[str, Any]
    fitted: dict[str, Any]

    @property
    def segments(self) -> Any:
        """The frame's segments (as ``Frame.segments``)."""
        return self.frame.segments

    def summary(self) -> dict[str, Any]:
        """The object ``fem-racket fit --json`` prints, less the mesh's path: the targets, the
        fitted values and the segments (length [m], EI [N m^2], rhoA [kg/m])."""
        segments = [
            {"length_m": s.length, "ei_n_m2": s.EI, "rhoa_kg_m": s.rhoA} for s in self.segments
        ]
        return {"target": dict(self.target), "fitted": dict(self.fitted), "segments": segments}


def fit_frame(spec: FitSpec) -> FittedRacket:
    """The frame of ``spec`` (:func:`fem_racket.frame.specs.fit_racket`, with torsion data by
    :func:`fem_racket.frame.twist_fit.fit_torsion` given a twistweight), its mesh, the targets
    and the fitted values."""
    from fem_racket.frame.mesh import frame_mesh
    from fem_racket.frame.specs import fit_racket, racket_spec
    from fem_racket.frame.torsion import TorsionModel
    from fem_racket.frame.twist_fit import fit_torsion

    frame = fit_racket(spec.length, spec.mass, spec.balance, spec.swing_weight * KG_CM2, spec.f1,
                       elements=spec.elements)  # fmt: skip
    if spec.torsion_frequency is not None and spec.twist_weight is None:
        raise InputError(
            f"torsion_frequency = {show(spec.torsion_frequency)} Hz is not allowed without "
            "--twist-weight: the torsion profile is scaled to a twistweight"
        )
    if spec.twist_weight is not None:
        frame = fit_torsion(frame, spec.twist_weight * KG_CM2, spec.torsion_frequency)
    mesh = frame_mesh(frame, spec.elements)
    got = racket_spec(mesh).as_dict()
    target = {
        "length_m": spec.length,
        "mass_kg": spec.mass,
        "balance_m": spec.balance,
        "swing_weight_kg_cm2": spec.swing_weight,
        "f1_hz": spec.f1,
    }
    if spec.twist_weight is not None:  # the torsion of the mesh written
        tors = TorsionModel(mesh)
        target["twist_weight_kg_cm2"] = spec.twist_weight
        target["torsion_f1_hz"] = spec.torsion_frequency
        got["twist_weight_kg_cm2"] = tors.polar_moment / KG_CM2
        got["torsion_f1_hz"] = float(tors.modes(1).frequencies[0])
    return FittedRacket(frame, mesh, target, got)


def fit_files(
    spec: FitSpec, out: Path, parameters: Mapping[str, Any], *, overwrite: bool = False
) -> tuple[FittedRacket, dict[str, Any]]:
    """Fit the frame of ``spec`` (:func:`fit_frame`) and write it to ``out`` (a mesh file)
    with the sidecar ``out.json`` (``parameters`` in its provenance); the FittedRacket and the
    summary (targets, fitted values, segments, the mesh's path)."""
    fitted = fit_frame(spec)
    summary = {**fitted.summary(), "mesh": str(out)}
    meta = provenance(dict(parameters))
    text = json.dumps(json_ready({**meta, **summary}), indent=2, default=str)
    write_mesh_files(fitted.mesh, out, text + "\n", overwrite=overwrite)
    return fitted, summary
