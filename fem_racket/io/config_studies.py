"""A run file's map and refinement study in Python: :meth:`RunConfig.map` = ``fem-racket map
--config`` and :meth:`RunConfig.refine` = ``fem-racket refine --config``.

Each command reads the core tables it has options for and its own table (``[map]``,
``[refine]``: the long options, ``--power-fraction`` -> ``power_fraction``); these functions do
the same from the same file and return what the command computes (and prints), without writing
files. The commands' defaults are :data:`MAP_DEFAULTS` and :data:`REFINE_DEFAULTS`
(``tests/io/test_config_commands.py`` checks them against the parsers). A key of the command's
table that is not one of its options is refused with a "did you mean", as the command refuses
it; ``[map]``/``[refine]`` keys that only say where the command writes or how it prints
(:data:`fem_racket.io.config_run_keys.RUN_KEYS`) are the command's, checked as it checks them.
"""

from __future__ import annotations

from typing import Any

from fem_racket.contact.linear import DEFAULT_BALL_MASS
from fem_racket.frame.model import DEFAULT_MODES
from fem_racket.impact.reduction import DEFAULT_TOLERANCE
from fem_racket.io.config_keys import PRESETS, reject_unknown
from fem_racket.io.config_named import GRIDS, grid_value, named_by_table
from fem_racket.io.config_run_keys import RUN_KEYS, run_keys
from fem_racket.studies.refine import DEFAULT_ELEMENTS, DEFAULT_GRADING, DEFAULT_POSITIONS
from fem_racket.validation import InputError, show

__all__ = ["MAP_DEFAULTS", "REFINE_DEFAULTS", "map_file", "refine_file"]

#: A :class:`fem_racket.io.config.RunConfig` (not imported: that module imports this one).
RunConfig = Any

#: Options only the command's table sets (its ``add_config_option(private=...)``): refine's
#: ``elements`` is its list of element counts, not ``frame.elements``; map's ``mesh`` its list
#: of mesh files, not ``frame.mesh``.
PRIVATE = {"refine": ("elements",), "map": ("mesh",)}
#: ``fem-racket map``'s options (argparse dests) and defaults.
MAP_DEFAULTS: dict[str, Any] = {
    "preset": None,
    "mesh": None,
    "elements": 20,
    "add_mass": None,
    "speed": 20.0,
    "positions": "0.5:1.0:200",
    "offsets": None,
    "angle": None,
    "spin": None,
    "friction": None,
    "side_angle": None,
    "side_spin": None,
    "ball_mass": DEFAULT_BALL_MASS,
    "kcb": None,
    "zeta": None,
    "separation": "displacement",
    "modes": DEFAULT_MODES,
    "tolerance": DEFAULT_TOLERANCE,
    "racket_speed": 0.0,
    "reference": None,
    "pivot": None,
    "law": "linear",
    "power_fraction": None,
}
#: ``map``'s options of the oblique ball (any of them maps the spin over the face).
OBLIQUE_KEYS = ("angle", "spin", "friction", "side_angle", "side_spin")
#: ``fem-racket refine``'s options (argparse dests) and defaults.
REFINE_DEFAULTS: dict[str, Any] = {
    "elements": list(DEFAULT_ELEMENTS),
    "family": "both",
    "grading": DEFAULT_GRADING,
    "count": 4,
    "positions": list(DEFAULT_POSITIONS),
    "speed": 20.0,
    "ball_mass": None,
    "kcb": None,
    "zeta": None,
    "separation": "displacement",
    "impact_modes": DEFAULT_MODES,
    "impact_nodes": False,
}


def _options(cfg: RunConfig, command: str, defaults: dict[str, Any]) -> dict[str, Any]:
    """The command's options from the file: its defaults, the core tables' values of its
    options, then its own table (checked against its options). A key of the impact's tables
    it takes no option for is refused, as the command refuses it."""
    from fem_racket.io.config_unused import refuse_core_only, refuse_unused
    from fem_racket.studies.grid_values import LAW_PARAMETERS

    frame = ("ei1", "ei2", "mesh", "segments") if command == "refine" else ()  # cfg.frame()
    private = PRIVATE.get(command, ())  # the command's own, not the core table's
    laws = LAW_PARAMETERS if "law" in defaults else ()
    refuse_unused(cfg, command, {*defaults, *frame, *laws} - set(private))
    core = cfg.defaults()
    out = dict(defaults)
    out.update(
        {
            k: v
            for k, v in core.items()
            if (k in defaults or k in LAW_PARAMETERS) and k not in private
        }
    )
    for key in cfg.table(command):  # as the command refuses it (cli.options.runfile)
        if key.replace("-", "_") not in private:
            refuse_core_only(f"{command}.{key}", key.replace("-", "_"))
    table = {k.replace("-", "_"): v for k, v in cfg.table(command).items()}
    reject_unknown(table, [*defaults, *LAW_PARAMETERS, *RUN_KEYS[command]], command)
    run_keys(command, table)  # where the command writes, how it prints: checked alike
    out.update({k: v for k, v in table.items() if k not in RUN_KEYS[command]})
    return out


def _law(o: dict[str, Any], cfg: RunConfig) -> Any:
    from fem_racket.contact.presets import check_linear_options, get_law, law_parameters

    if o["law"] != "linear":
        for key in ("kcb_n_m", "zeta", "clamped_cor"):
            if key in cfg.values.get("contact", {}):
                raise InputError(
                    f"contact.{key} = {show(cfg.values['contact'][key])} ({cfg.source}) is not "
                    f"allowed with contact law {show(o['law'])}: it sets the paper's linear "
                    "law's K_CB and zeta only"
                )
    check_linear_options(o["law"], kcb=o["kcb"], zeta=o["zeta"])
    return get_law(o["law"], **law_parameters(o))


def _listed(key: str, value: Any) -> list[str]:
    """``[map] preset`` or ``mesh``: an array of texts, as ``--preset A B`` takes them."""
    if value is None:
        return []
    if not isinstance(value, list):
        raise InputError(f"map.{key} = {show(value)} is not allowed: must be an array")
    return [str(v) for v in value]


def _rackets(o: dict[str, Any]) -> list[tuple[str, Any]]:
    """(name, FrameModel) of the ``preset`` list then the ``mesh`` files' (read as they are,
    relative to the working directory, as the command reads them; the standard racket when
    neither), each with the file's lead."""
    from pathlib import Path

    from fem_racket.frame.head import DEFAULT_HEAD
    from fem_racket.frame.lead import add_lead
    from fem_racket.frame.mesh import frame_mesh
    from fem_racket.frame.model import FrameModel
    from fem_racket.frame.segments import Frame, standard_frame
    from fem_racket.io.mesh_files import read_mesh

    names, meshes = _listed("preset", o["preset"]), _listed("mesh", o["mesh"])
    for name in names:
        if name not in PRESETS:
            allowed = ", ".join(sorted(PRESETS))
            raise InputError(f"map.preset = {show(name)} is not allowed: must be one of {allowed}")
    frames = [(name, standard_frame(PRESETS[name])) for name in names]
    frames += [(Path(path).stem, read_mesh(path)) for path in meshes]
    out = []
    for name, frame in frames or [("standard", standard_frame())]:
        if o["add_mass"]:
            mesh = frame_mesh(frame, o["elements"]) if isinstance(frame, Frame) else frame
            frame = add_lead(mesh, o["add_mass"], DEFAULT_HEAD.on_frame(mesh.length))
        out.append((name, FrameModel.build(frame, o["elements"])))
    return out


def _key(cfg: RunConfig, command: str, dest: str) -> str:
    """The file's key setting option ``dest`` of ``command``, with its value, for a message."""
    from fem_racket.io.config_keys import CORE_KEYS

    named = {
        keys[key].dest: f"{table}.{key} = {show(value)}"
        for table, keys in CORE_KEYS.items()
        for key, value in cfg.values.get(table, {}).items()
    }
    named.update(  # the command's table wins
        {k.replace("-", "_"): f"{command}.{k} = {show(v)}" for k, v in cfg.table(command).items()}
    )
    return f"{named.get(dest, dest)} ({cfg.source})"


def _refuse_spin(cfg: RunConfig, o: dict[str, Any], law: Any) -> None:
    """Refuse what the spin map would drop (a key at the command's default changes nothing)."""
    given = {k for k, v in MAP_DEFAULTS.items() if o[k] != v}
    from fem_racket.studies.spin_map import SPIN_REFUSES

    why = dict(SPIN_REFUSES)
    if law is not None:  # the law's own parameters replace the paper's law's
        why.update(dict.fromkeys(("kcb", "zeta", "separation", "modes"), f"law {law.name}'s own"))
    for dest, reason in why.items():
        if dest in given:
            raise InputError(
                f"{_key(cfg, 'map', dest)} is not allowed with an oblique ball: {reason}"
            )


def map_file(cfg: RunConfig) -> list[Any]:
    """The maps ``fem-racket map --config`` computes from ``cfg``: a RacketMap per racket,
    a FaceMap with ``offsets``, a SpinMap with an oblique ball (:data:`OBLIQUE_KEYS`; the grids of
    :mod:`fem_racket.cli.options.faces` unless given)."""
    o = _options(cfg, "map", MAP_DEFAULTS)
    for key in GRIDS:  # the file's grids read as the command reads them (its convert)
        if key in cfg.table("map"):
            try:
                grid_value(f"map.{key}", o[key])
            except InputError as exc:
                raise InputError(f"{cfg.source}: {exc}", value=exc.value) from None
    try:
        return _maps(cfg, o)
    except InputError as exc:  # a [map] value the library refused: named by its key, as
        keys = {k.replace("-", "_"): f"map.{k}" for k in cfg.table("map")}  # the command's
        named = named_by_table(exc, keys, o, cfg.source)
        if named is exc:
            raise
        raise named from None


def _maps(cfg: RunConfig, o: dict[str, Any]) -> list[Any]:
    """The maps of :func:`map_file` from the command's options ``o``."""
    from fem_racket.impact.incidence import Incidence
    from fem_racket.studies.grid_values import as_values
    from fem_racket.studies.map_options import MapPlay
    from fem_racket.studies.racket_map import DEFAULT_POWER_FRACTION, racket_map

    law = _law(o, cfg)
    impact = {k: o[k] for k in ("ball_mass", "kcb", "zeta", "separation", "modes", "tolerance")}
    impact = {k: v for k, v in impact.items() if v != MAP_DEFAULTS[k]}  # given: as the CLI
    oblique = {k: o[k] for k in OBLIQUE_KEYS if o[k] is not None}
    if oblique:
        from fem_racket.studies.spin_map import SPIN_OFFSETS, SPIN_POSITIONS, spin_map

        _refuse_spin(cfg, o, law)

        table = cfg.table("map")
        positions = o["positions"] if "positions" in table else SPIN_POSITIONS
        grid = {
            "positions": as_values("position", positions),
            "offsets": as_values("offset", o["offsets"] or SPIN_OFFSETS),
        }
        if law is not None:
            impact = {k: impact[k] for k in ("ball_mass", "tolerance")}
        inc = Incidence(**oblique)
        return [
            spin_map(model, **grid, incidence=inc, speed=o["speed"], name=name,
                     options={**impact, "law": law})
            for name, model in _rackets(o)
        ]  # fmt: skip
    positions = as_values("position", o["positions"])
    play = MapPlay(o["speed"], o["racket_speed"], o["reference"], o["pivot"], positions)
    if o["offsets"] is not None:
        from fem_racket.studies.face_map import DEFAULT_AREA_FRACTION, face_map

        fraction = o["power_fraction"] or DEFAULT_AREA_FRACTION
        return [
            face_map(model, **play.keywords(), offsets=as_values("offset", o["offsets"]),
                     name=name, options={**impact, "power_fraction": fraction})
            for name, model in _rackets(o)
        ]  # fmt: skip
    fraction = o["power_fraction"] or DEFAULT_POWER_FRACTION
    return [
        racket_map(model, name=name, **play.keywords(), **impact, power_fraction=fraction,
                   law=law)
        for name, model in _rackets(o)
    ]  # fmt: skip


def refine_file(cfg: RunConfig) -> dict[str, Any]:
    """The refinement studies ``fem-racket refine --config`` computes from ``cfg``: family ->
    :class:`~fem_racket.studies.refine.RefinementStudy` (both families by default)."""
    from fem_racket.studies.options import field_names
    from fem_racket.studies.refine import FAMILIES, RefineOptions, graded, refinement_study

    o = _options(cfg, "refine", REFINE_DEFAULTS)
    families = FAMILIES if o["family"] == "both" else (o["family"],)
    # the table's values of RefineOptions' fields (the family is each study's own)
    study = {k: o[k] for k in field_names(RefineOptions) if k in o and k != "family"}
    study |= {"n_modes": o["count"], "progress": False}
    if study.get("grading") == DEFAULT_GRADING:  # a key at its default: not given, as the CLI
        del study["grading"]
    return {
        fam: refinement_study(cfg.frame(), o["elements"], **graded(study, fam, o["family"]))
        for fam in families
    }
