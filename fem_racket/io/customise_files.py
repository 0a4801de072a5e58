"""The work of ``fem-racket customise``, shared by the command and the run file's method
(:meth:`fem_racket.io.config.RunConfig.customise`) so that both compute and write the same files:
the least lead (:func:`customise_racket`), and the customised racket's mesh file, its JSON
sidecar and the maps before and after written as one set (:func:`customise_files`).

The maps go beside the mesh unless named (``--maps``, ``[customise] maps``): the mesh's name less
its suffix, then ``_map.png`` (:func:`customise_maps`: ``output/customised.vtu`` ->
``output/customised_map.png``). A path derived so is named in a refusal by the option that gave
it, ``out``, as the sidecar ``out.json`` is.
"""

from __future__ import annotations

import json
from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from fem_racket.outputs import Target, provenance

__all__ = [
    "CUSTOMISE_OUTPUT",
    "CustomisedRacket",
    "customise_files",
    "customise_maps",
    "customise_racket",
    "customise_targets",
]

#: Where ``fem-racket customise`` writes its mesh unless told (``--out``, ``[customise] out``),
#: replacing the files an earlier customise wrote there (its maps beside it included).
CUSTOMISE_OUTPUT = Path("output") / "customised.vtu"


def customise_maps(out: str | Path) -> Path:
    """The maps' file beside the mesh file ``out`` [a path]: its name less the suffix, then
    ``_map.png`` (``a/x.vtu`` -> ``a/x_map.png``)."""
    out = Path(out)
    return out.with_name(f"{out.stem}_map.png")


def customise_targets(out: str | Path, maps: str | Path | None = None) -> list[Target]:
    """Every file customise writes: the mesh ``out`` and its sidecar (:func:`mesh_files`), the
    maps ``maps`` (.png, .nc, .csv with its sidecar), beside ``out`` when None
    (:func:`customise_maps`); suffixes checked, each named by the option that gave it."""
    from fem_racket.io.map_files import map_targets
    from fem_racket.io.racket_files import mesh_files

    mesh = [Target(p) for p in mesh_files(Path(out))]
    if maps is None:
        return [*mesh, *map_targets([customise_maps(out)])]
    return [*mesh, *map_targets([Path(maps)], name="maps")]


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
    files: Sequence[Target],
    parameters: Mapping[str, Any],
    overwrite: bool = False,
) -> tuple[CustomisedRacket, dict[str, Any]]:
    """Customise and map the racket (:func:`customise_racket`) and write ``files``
    (:func:`customise_targets`: the customised mesh, its sidecar, the maps; ``parameters`` in
    their provenance) as one set: all of them or, on any fault, none. The CustomisedRacket and
    the summary (placement, specs, targets, maps, the paths written)."""
    from fem_racket.io.map_files import fill_maps
    from fem_racket.io.mesh_files import save_mesh
    from fem_racket.outputs import atomic_outputs

    out, side, *maps = files
    report = customise_racket(mesh, targets, places, play)
    summary = report.summary()
    summary["mesh"], summary["maps_file"] = str(out.path), str(maps[0].path)
    meta = provenance(dict(parameters))
    text = json.dumps({**meta, **summary}, indent=2, default=str)
    with atomic_outputs(files, overwrite=overwrite) as (tmp, side_tmp, *map_temps):
        save_mesh(report.mesh, tmp)
        side_tmp.write_text(text + "\n", encoding="utf-8")
        fill_maps(list(report.maps), maps, map_temps, parameters)
    return report, summary
