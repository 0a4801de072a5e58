"""A racket made from catalogue numbers, written as a mesh file with its JSON sidecar: the work of
``fem-racket fit`` (:func:`fit_files`) and ``fem-racket customise`` (:func:`customise_files`),
shared by the commands and the run file's methods (:mod:`fem_racket.io.config_racket`) so that
both compute and write the same files.
"""

from __future__ import annotations

import json
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from fem_racket.frame.specs import DEFAULT_ELEMENTS, KG_CM2
from fem_racket.outputs import json_ready, provenance
from fem_racket.validation import InputError, show

__all__ = [
    "FIT_OUTPUT",
    "CustomisedRacket",
    "FitSpec",
    "FittedRacket",
    "customise_files",
    "customise_racket",
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


@dataclass(frozen=True)
class CustomisedRacket:
    """Everything ``fem-racket customise`` reports: the least lead and the racket's maps.

    Attributes
    ----------
    customisation : Customisation
        Of :func:`fem_racket.studies.customise.customise`: the lead per place [kg], the
        customised mesh, the catalogue numbers before and after.
    maps : tuple of RacketMap
        The frame ``before`` and ``customised``: apparent COR and ball speed along it, with
        their sweet spots [x/L] (:func:`fem_racket.studies.racket_map.racket_map`).
    targets : mapping
        Spec name -> Target (SI) the lead meets.
    """

    customisation: Any
    maps: tuple[Any, Any]
    targets: Mapping[str, Any]

    @property
    def mesh(self) -> Any:
        """The customised frame (a FrameMesh)."""
        return self.customisation.mesh

    @property
    def added(self) -> dict[str, float]:
        """Place -> added mass [kg]."""
        return self.customisation.added

    @property
    def before(self) -> Any:
        """Catalogue numbers before (SI)."""
        return self.customisation.before

    @property
    def after(self) -> Any:
        """Catalogue numbers after (SI)."""
        return self.customisation.after

    @property
    def total(self) -> float:
        """Total added mass [kg]."""
        return self.customisation.total

    def summary(self) -> dict[str, Any]:
        """The object ``fem-racket customise --json`` prints, less the paths it wrote: the
        placement [g], the catalogue numbers before and after, the targets and each map's
        summary (sweet spots [x/L], no curves)."""
        from fem_racket.studies.target_values import target_summary

        summary = self.customisation.summary()
        summary["targets"] = target_summary(self.targets)
        summary["maps"] = {m.name: m.summary(curves=False) for m in self.maps}
        return summary


def customise_racket(
    mesh: Any, targets: Mapping[str, Any], places: Sequence[str], play: Mapping[str, Any]
) -> CustomisedRacket:
    """Solve the least lead (:func:`fem_racket.studies.customise.customise`) bringing ``mesh``
    (a FrameMesh) to ``targets`` (spec name -> Target, SI) with lead at ``places``, and map the
    racket before and after (``play``: the maps' ``speed`` [m/s], ``racket_speed`` [m/s],
    ``reference`` [x/L] and ``pivot`` [m])."""
    from fem_racket.studies.customise import customise
    from fem_racket.studies.racket_map import racket_map

    result = customise(mesh, targets, places)
    maps = tuple(
        racket_map(m, name=name, **play)
        for name, m in (("before", mesh), ("customised", result.mesh))
    )
    return CustomisedRacket(result, maps, dict(targets))


def customise_files(
    mesh: Any,
    targets: Mapping[str, Any],
    places: Sequence[str],
    play: Mapping[str, Any],
    files: tuple[Path, Path],
    parameters: Mapping[str, Any],
    overwrite: bool = False,
) -> tuple[CustomisedRacket, dict[str, Any]]:
    """Customise and map the racket (:func:`customise_racket`), write the customised mesh with
    its sidecar to ``files[0]`` and the maps to ``files[1]`` (``parameters`` in their
    provenance); the CustomisedRacket and the summary (placement, specs, targets, maps, the
    paths written)."""
    from fem_racket.io.map_files import write_maps

    out, maps_path = files
    report = customise_racket(mesh, targets, places, play)
    summary = report.summary()
    summary["mesh"], summary["maps_file"] = str(out), str(maps_path)
    meta = provenance(dict(parameters))
    text = json.dumps({**meta, **summary}, indent=2, default=str)
    write_mesh_files(report.mesh, out, text + "\n", overwrite=overwrite)
    write_maps(list(report.maps), [maps_path], overwrite=overwrite, parameters=parameters)
    return report, summary
