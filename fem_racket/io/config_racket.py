"""A run file's racket commands in Python: :meth:`RunConfig.fit` = ``fem-racket fit --config``,
:meth:`RunConfig.customise` = ``customise`` and :meth:`RunConfig.closest` = ``closest``
(``modes``: :mod:`fem_racket.io.config_modes`).

Each takes from the core tables what its command has options for (``customise`` the frame with
its lead, the ball's speed and the swing of its maps, ``fit`` and ``customise``
``output.overwrite``) and skips the other keys, as the command does; its own table (``[fit]``,
...) is read as the command reads it
(:func:`fem_racket.io.config_tables.table_options`). Files are written only where the method is
given ``out`` or the table names one (``[fit] out``, ``[customise] out``): the same files the
command writes there, checked before the work as the command checks them.
"""

from __future__ import annotations

from pathlib import Path
from typing import Any

from fem_racket.frame.clock import PLACES
from fem_racket.frame.specs import DEFAULT_ELEMENTS
from fem_racket.io.config_defaults import FRAME_ELEMENTS, PLAY_DEFAULTS
from fem_racket.io.config_tables import Option, flag, integer, number, table_options, text
from fem_racket.studies.target_values import RANKED, TARGETS, parse_target
from fem_racket.validation import InputError, check_integer, show, work_begins

__all__ = [
    "CLOSEST_OPTIONS",
    "CUSTOMISE_OPTIONS",
    "FIT_OPTIONS",
    "closest_file",
    "customise_file",
    "fit_file",
]

#: A :class:`fem_racket.io.config.RunConfig` (not imported: that module imports this one).
RunConfig = Any


def _target(where: str, value: Any) -> Any:
    """A target key: a value, ``"LOW:HIGH"`` or ``"keep"``, as ``--swing-weight`` takes it."""
    if isinstance(value, (bool, list, dict)):
        raise InputError(f"{where} = {show(value)} is not allowed: must be a value or LOW:HIGH")
    try:
        return parse_target(str(value))
    except ValueError as exc:
        raise InputError(f"{where} = {show(value)} is not allowed: {exc}") from None


def _targets(ranked: bool) -> dict[str, tuple[Any, Option]]:
    names = {**TARGETS, **(RANKED if ranked else {})}
    return {**dict.fromkeys(names, (None, _target)), "places": (",".join(PLACES), text)}


#: The options of each command's table: dest -> (default, conversion); the commands' defaults
#: but ``out`` (no file unless given).
_FILES = {"out": (None, text), "overwrite": (False, flag)}
_SPEC = ("length", "mass", "balance", "swing_weight", "f1", "twist_weight", "torsion_frequency")
FIT_OPTIONS = {**dict.fromkeys(_SPEC, (None, number)), "elements": (DEFAULT_ELEMENTS, integer),
               **_FILES}  # fmt: skip
CUSTOMISE_OPTIONS = {**_targets(False), **_FILES, "maps": (None, text)}
CLOSEST_OPTIONS = {**_targets(True), "count": (3, integer)}


def _overwrite(cfg: RunConfig) -> dict[str, Any]:
    d = cfg.defaults()
    return {"overwrite": d["overwrite"]} if "overwrite" in d else {}


def fit_file(cfg: RunConfig, out: Any = None) -> Any:
    """The frame ``fem-racket fit --config`` fits to ``[fit]``'s catalogue numbers, with the
    targets and fitted values it reports (a FittedRacket); with ``out`` (else ``[fit] out``)
    the mesh file and its sidecar written there, as the command writes them: both or neither,
    an existing one refused unless the file says ``overwrite``, or ``out`` is the command's
    default (``output/racket.vtu``) and holds an earlier fit (the command replaces its own
    output there)."""
    from fem_racket.io.config_rerun import rerun_overwrite
    from fem_racket.io.racket_files import FIT_OUTPUT, FitSpec, fit_files, fit_frame, mesh_files
    from fem_racket.outputs import check_output_path

    o = table_options(cfg, "fit", FIT_OPTIONS, _overwrite(cfg))
    elements = check_integer("elements", o["elements"], minimum=3)
    for name in ("length", "mass", "balance", "swing_weight"):
        if o[name] is None:
            flag_name = "--" + name.replace("_", "-")
            raise InputError(
                f"{name} is required: give {flag_name} (or {name} in the run file's [fit])"
            )
    fit = FitSpec(**{k: o[k] for k in _SPEC}, elements=elements)
    out = out or o["out"]
    if out is None:
        work_begins()
        return fit_frame(fit)
    files = mesh_files(Path(out))
    overwrite = rerun_overwrite(o["overwrite"], Path(out) == FIT_OUTPUT, files)
    for f in files:
        check_output_path(f, overwrite=overwrite)
    work_begins()
    parameters = {"config": str(cfg.source), **o, "out": str(out)}
    return fit_files(fit, Path(out), parameters, overwrite=overwrite)[0]


def customise_file(cfg: RunConfig, out: Any = None) -> Any:
    """The least lead ``fem-racket customise --config`` finds for the file's frame and the
    maps of the racket before and after it, everything the command reports (a
    :class:`~fem_racket.io.customise_files.CustomisedRacket`); with ``out`` (else
    ``[customise] out``) the customised racket's mesh file, its sidecar and the maps before and
    after (``[customise] maps``, else beside the mesh as the command puts them) written as one
    set, as the command writes them: an existing one refused unless the file says
    ``overwrite``, or ``out`` is the command's default (``output/customised.vtu``, the maps
    beside it) and they are an earlier customise's; ``[customise] maps`` without ``out`` is
    refused (the command writes no maps alone)."""
    from fem_racket.frame.catalogue import catalogue
    from fem_racket.frame.mesh import FrameMesh, frame_mesh
    from fem_racket.io.config_rerun import rerun_overwrite
    from fem_racket.io.config_run import file_frame
    from fem_racket.io.customise_files import (
        CUSTOMISE_OUTPUT,
        customise_files,
        customise_racket,
        customise_targets,
    )
    from fem_racket.outputs import check_targets
    from fem_racket.studies.map_options import MapPlay
    from fem_racket.studies.swing_points import check_swing_points
    from fem_racket.studies.target_values import place_list, targets_from

    d = cfg.defaults()
    core = {**PLAY_DEFAULTS, **{k: d[k] for k in PLAY_DEFAULTS if k in d}, **_overwrite(cfg)}
    o = table_options(cfg, "customise", CUSTOMISE_OPTIONS, core)
    places, out = place_list(o["places"]), out or o["out"]
    if out is None and "maps" in cfg.table("customise"):  # the command maps beside its mesh
        raise InputError(
            f"customise.maps = {show(o['maps'])} is not allowed without out: the maps are "
            "written with the customised racket's mesh file (give out)"
        )
    files = None if out is None else customise_targets(out, o["maps"])
    if files is not None:
        default = Path(out) == CUSTOMISE_OUTPUT and o["maps"] is None
        overwrite = rerun_overwrite(o["overwrite"], default, [t.path for t in files])
        check_targets(files, overwrite=overwrite)
    frame = file_frame(cfg)
    elements = d.get("elements", FRAME_ELEMENTS)
    mesh = frame if isinstance(frame, FrameMesh) else frame_mesh(frame, elements)
    targets = targets_from(o, catalogue(mesh, f1=False))
    play = {k: o[k] for k in PLAY_DEFAULTS}
    # a swing's point without a swing, its closing speed at the maps' points: before any work
    check_swing_points(mesh, MapPlay(**play))
    work_begins()
    if files is None:
        return customise_racket(mesh, targets, places, play)
    parameters = {"config": str(cfg.source), **o, "out": str(out)}
    return customise_files(mesh, targets, places, play, files, parameters, overwrite)[0]


def closest_file(cfg: RunConfig, rackets: Any) -> list[Any]:
    """The rackets of the CSV list ``rackets`` nearest ``[closest]``'s targets, each with its
    least lead, as ``fem-racket closest RACKETS --config`` ranks them: the Matches of
    :func:`fem_racket.studies.closest.closest`, nearest first."""
    from fem_racket.io.racket_table import read_rackets
    from fem_racket.studies.closest import closest
    from fem_racket.studies.target_values import place_list, targets_from

    o = table_options(cfg, "closest", CLOSEST_OPTIONS)
    if rackets is None:
        raise InputError("rackets = none is not allowed: give the racket list, a CSV file")
    targets = targets_from(o)
    listed = read_rackets(rackets)
    work_begins()
    return closest(listed, targets, place_list(o["places"]), o["count"])
