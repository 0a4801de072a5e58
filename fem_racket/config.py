"""TOML run configuration: a whole run (frame, ball, ball/string law, impact, solver, output).

A run file has fixed *core* tables, each key with its unit in its name::

    [frame]    preset | ei1_n_m2, ei2_n_m2 | [[frame.segments]] | mesh ; elements
    [ball]     mass_kg
    [contact]  kcb_n_m, zeta | clamped_cor      (the compound ball/string law, eqs 1-4)
    [impact]   position_x_over_l, speed_m_s
    [solver]   name, separation, basis, modes, rtol, atol, t_max_s
    [output]   out, overwrite

and optional *command* tables (``[simulate]``, ``[modes]``, ``[sweep]``, ``[refine]``, ``[vtk]``
for ``export-vtk``, ``[animate]``, ``[reproduce]``) whose keys are the long options of that
command (``--ei1-values`` -> ``ei1_values``); the command checks them when it reads the file (see
:func:`fem_racket.cli.common.apply_config`). Every key is optional: a missing key keeps the
built-in default. Unknown tables and keys are errors with a "did you mean"; a wrong type or an
out-of-range value is a one-line :class:`~fem_racket.validation.InputError` naming the dotted key,
e.g. ``run.toml: impact.speed_m_s = -3 m/s is not allowed: must be a finite number > 0``.

Relative paths in the file (``frame.mesh``) are relative to the file's folder; ``output.out`` is
relative to the working directory, like the command line's ``--out``.
"""

from __future__ import annotations

import difflib
import math
import os
import tomllib
from collections.abc import Callable, Mapping
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from .config_example import example_config
from .impact import BASES
from .integrators import SOLVERS
from .params import PAPER_EI1, RIGID_EI1, Segment, zeta_from_cor
from .system import SEPARATION_EVENTS
from .validation import InputError, check_choice, check_positive, check_range

__all__ = [
    "COMMAND_TABLES",
    "CORE_KEYS",
    "RunConfig",
    "example_config",
    "load_config",
    "parse_config",
]

#: Sub-command -> the table of the run file holding its own options. A command missing here
#: reads the table named after it.
COMMAND_TABLES = {
    "simulate": "simulate",
    "modes": "modes",
    "sweep": "sweep",
    "refine": "refine",
    "export-vtk": "vtk",
    "animate": "animate",
    "reproduce": "reproduce",
}

#: Frame presets: name -> EI1 [N m^2] (EI2 = 0.88 EI1 unless ei2_n_m2 is given).
PRESETS = {"standard": PAPER_EI1, "rigid": RIGID_EI1}


# -- value checks: (dotted name, raw TOML value) -> clean value --------------------------------
def _number(unit: str, check: Callable[..., float]) -> Callable[[str, Any], float]:
    def conv(name: str, value: Any) -> float:
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise InputError(f"{name} = {value!r} is not allowed: must be a number [{unit}]")
        return float(check(name, value, unit))

    return conv


def _positive(unit: str = "") -> Callable[[str, Any], float]:
    return _number(unit, check_positive)


def _interval(low: float, high: float, **kw: bool) -> Callable[[str, Any], float]:
    def check(name: str, value: float, unit: str) -> float:
        return check_range(name, value, low, high, unit=unit, **kw)

    return _number("", check)


def _integer(low: int) -> Callable[[str, Any], int]:
    def conv(name: str, value: Any) -> int:
        if isinstance(value, bool) or not isinstance(value, int) or value < low:
            raise InputError(f"{name} = {value!r} is not allowed: must be an integer >= {low}")
        return value

    return conv


def _choice(options: tuple[str, ...]) -> Callable[[str, Any], str]:
    def conv(name: str, value: Any) -> str:
        return check_choice(name, value, options)

    return conv


def _string(name: str, value: Any) -> str:
    if not isinstance(value, str) or not value.strip():
        raise InputError(f"{name} = {value!r} is not allowed: must be a non-empty path string")
    return value


def _boolean(name: str, value: Any) -> bool:
    if not isinstance(value, bool):
        raise InputError(f"{name} = {value!r} is not allowed: must be true or false")
    return value


_SEGMENT_KEYS = {"length_m": "m", "ei_n_m2": "N m^2", "rhoa_kg_m": "kg/m"}


def _segments(name: str, value: Any) -> tuple[Segment, ...]:
    if not isinstance(value, list) or not value:
        raise InputError(
            f"{name} is not allowed: must be a non-empty array of tables "
            "with length_m, ei_n_m2 and rhoa_kg_m"
        )
    out = []
    for i, item in enumerate(value):
        where = f"{name}[{i}]"
        if not isinstance(item, dict):
            raise InputError(
                f"{where} = {item!r} is not allowed: must be a table "
                "with length_m, ei_n_m2 and rhoa_kg_m"
            )
        _reject_unknown(item, _SEGMENT_KEYS, where)
        missing = [k for k in _SEGMENT_KEYS if k not in item]
        if missing:
            raise InputError(f"{where} is missing {', '.join(missing)} (each segment needs all 3)")
        vals = [_positive(u)(f"{where}.{k}", item[k]) for k, u in _SEGMENT_KEYS.items()]
        out.append(Segment(*vals))
    return tuple(out)


@dataclass(frozen=True)
class Key:
    """One key of a core table: how to check it and which CLI option (argparse dest) it sets."""

    check: Callable[[str, Any], Any]
    dest: str | None
    help: str


#: The core tables: table -> key -> :class:`Key`.
CORE_KEYS: dict[str, dict[str, Key]] = {
    "frame": {
        "preset": Key(_choice(tuple(PRESETS)), "ei1", "standard (EI1 146 N m^2) or rigid (9999)"),
        "ei1_n_m2": Key(_positive("N m^2"), "ei1", "grip-side bending rigidity EI1"),
        "ei2_n_m2": Key(_positive("N m^2"), "ei2", "top-side bending rigidity EI2"),
        "segments": Key(_segments, "segments", "uniform segments from the grip end"),
        "mesh": Key(_string, "mesh", "mesh file with cell data EI and rhoA"),
        "elements": Key(_integer(1), "elements", "number of beam elements"),
    },
    "ball": {"mass_kg": Key(_positive("kg"), "ball_mass", "ball mass m_B")},
    "contact": {
        "kcb_n_m": Key(_positive("N/m"), "kcb", "ball/string stiffness K_CB"),
        "zeta": Key(_interval(0.0, 1.0, include_high=False), "zeta", "damping ratio"),
        "clamped_cor": Key(
            _interval(0.0, 1.0, include_low=False), "zeta", "clamped-frame COR fixing zeta"
        ),
    },
    "impact": {
        "position_x_over_l": Key(_interval(0.0, 1.0), "position", "impact point x/L"),
        "speed_m_s": Key(_positive("m/s"), "speed", "incident ball speed V_B0"),
    },
    "solver": {
        "name": Key(_choice(tuple(sorted(SOLVERS))), "solver", "integrator"),
        "separation": Key(_choice(SEPARATION_EVENTS), "separation", "end of contact"),
        "basis": Key(_choice(BASES), "basis", "frame coordinates for the BDF solvers"),
        "modes": Key(_integer(1), "modes", "flexible modes kept"),
        "rtol": Key(_positive(), "rtol", "relative tolerance of the BDF solvers"),
        "atol": Key(_positive(), "atol", "absolute tolerance of the BDF solvers"),
        "t_max_s": Key(_positive("s"), "t_max", "give up if no separation by then"),
    },
    "output": {
        "out": Key(_string, "out", "simulate's output file (other commands: their own table)"),
        "overwrite": Key(_boolean, "overwrite", "replace an existing output file"),
    },
}

#: The argparse dests the core tables own; a command table may not set them.
CORE_DESTS = frozenset(k.dest for t in CORE_KEYS.values() for k in t.values() if k.dest)


def _all_keys() -> list[str]:
    return [f"{t}.{k}" for t, keys in CORE_KEYS.items() for k in keys]


def _reject_unknown(
    table: Mapping[str, Any], allowed: Mapping[str, Any] | list[str], where: str
) -> None:
    """Raise for the first key of ``table`` not in ``allowed``, with a "did you mean"."""
    for key in table:
        if key in allowed:
            continue
        here = difflib.get_close_matches(key, list(allowed), n=1, cutoff=0.6)
        if here:
            hint = f"did you mean '{here[0]}'?"
        else:
            other = difflib.get_close_matches(key, _all_keys(), n=1, cutoff=0.6)
            other += [d for d in _all_keys() if d.endswith(f".{key}")]
            hint = f"did you mean '{other[-1]}'?" if other else ""
            hint = f"{hint} allowed: {', '.join(allowed) or '(none)'}".strip()
        prefix = f"{where}." if where else ""
        raise InputError(f"{prefix}{key} is not a known key: {hint}")


@dataclass(frozen=True)
class RunConfig:
    """A checked run configuration.

    Attributes
    ----------
    values : dict
        Core table -> key -> checked value (only the keys the file sets; segments as
        :class:`~fem_racket.params.Segment` tuples, numbers as float).
    tables : dict
        Command table -> its raw key/value pairs (checked by the command that reads it).
    source : Path or None
        The file read, if any.
    """

    values: dict[str, dict[str, Any]]
    tables: dict[str, dict[str, Any]] = field(default_factory=dict)
    source: Path | None = None

    def get(self, dotted: str, default: Any = None) -> Any:
        """The checked value of ``"table.key"``, or ``default`` if the file does not set it."""
        table, _, key = dotted.partition(".")
        return self.values.get(table, {}).get(key, default)

    def table(self, name: str) -> dict[str, Any]:
        """A command table's raw key/value pairs ({} if absent)."""
        return dict(self.tables.get(name, {}))

    def defaults(self) -> dict[str, Any]:
        """The core tables as argparse dests -> values (see :mod:`fem_racket.cli.common`).

        ``segments`` (a tuple of :class:`Segment`) and ``mesh`` (a path) have no command-line
        option of their own in every command; :func:`fem_racket.cli.common.build_model` reads them.
        """
        out: dict[str, Any] = {}
        for table, keys in self.values.items():
            for key, value in keys.items():
                dest = CORE_KEYS[table][key].dest
                if (table, key) == ("frame", "preset"):
                    if "ei1_n_m2" in keys:
                        continue
                    value = PRESETS[value]
                elif (table, key) == ("contact", "clamped_cor"):
                    value = zeta_from_cor(value)
                elif (table, key) == ("frame", "mesh"):
                    value = str(self.resolve(value))
                out[dest] = value
        return out

    def resolve(self, path: str | os.PathLike) -> Path:
        """A path named in the file, relative to the file's folder."""
        p = Path(path).expanduser()
        if p.is_absolute() or self.source is None:
            return p
        return self.source.parent / p

    def simulate_kwargs(self) -> dict[str, Any]:
        """Keyword arguments of :func:`fem_racket.simulate` that the file sets."""
        d = self.defaults()
        names = ("position", "speed", "ball_mass", "kcb", "zeta", "elements", "solver")
        names += ("separation", "basis", "modes", "rtol", "atol", "t_max")
        return {n: d[n] for n in names if n in d}

    def frame(self) -> Any:
        """The frame the file describes: a Frame, a FrameMesh read from ``frame.mesh``, or None
        (the standard racket with ``ei1_n_m2``/``ei2_n_m2``/preset applied)."""
        from .mesh_io import read_mesh
        from .params import Frame, standard_frame

        d = self.defaults()
        if "mesh" in d:
            return read_mesh(d["mesh"])
        if "segments" in d:
            return Frame(d["segments"])
        if "ei1" in d or "ei2" in d:
            return standard_frame(d.get("ei1", PRESETS["standard"]), d.get("ei2"))
        return None


def parse_config(
    text: str, source: str | os.PathLike | None = None, *, command_tables: Any = None
) -> RunConfig:
    """Check the TOML ``text`` of a run file (``source`` names it in errors and anchors paths).

    Parameters
    ----------
    command_tables : iterable of str, optional
        Table names accepted besides the core ones; :data:`COMMAND_TABLES` values by default.
    """
    src = Path(source) if source is not None else None
    label = f"{src}: " if src is not None else ""
    known = set(COMMAND_TABLES.values() if command_tables is None else command_tables)
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as exc:
        raise InputError(f"{label}not valid TOML: {exc}") from None
    try:
        return _check(data, src, known)
    except InputError as exc:
        raise InputError(f"{label}{exc}") from None


def load_config(path: str | os.PathLike, *, command_tables: Any = None) -> RunConfig:
    """Read and check the run file ``path``; see :func:`parse_config`."""
    p = Path(path)
    try:
        text = p.read_text(encoding="utf-8")
    except FileNotFoundError:
        raise InputError(f"config = '{p}' is not allowed: no such file") from None
    except (OSError, UnicodeDecodeError) as exc:
        why = getattr(exc, "strerror", None) or str(exc)
        raise InputError(f"config = '{p}' cannot be read ({why}): must be a TOML file") from None
    return parse_config(text, p, command_tables=command_tables)


def _check(data: dict[str, Any], source: Path | None, known: set[str]) -> RunConfig:
    allowed_tables = list(CORE_KEYS) + sorted(known)
    _reject_unknown(data, allowed_tables, "")
    values: dict[str, dict[str, Any]] = {}
    tables: dict[str, dict[str, Any]] = {}
    for name, table in data.items():
        if not isinstance(table, dict):
            raise InputError(f"{name} = {table!r} is not allowed: must be a table [{name}]")
        if name not in CORE_KEYS:
            tables[name] = table
            continue
        _reject_unknown(table, CORE_KEYS[name], name)
        values[name] = {k: CORE_KEYS[name][k].check(f"{name}.{k}", v) for k, v in table.items()}
    _check_combinations(values)
    cfg = RunConfig(values, tables, source)
    mesh = cfg.get("frame.mesh")
    if mesh is not None and not cfg.resolve(mesh).is_file():
        raise InputError(
            f"frame.mesh = '{mesh}' is not allowed: no such file ({cfg.resolve(mesh)}; "
            "must be a mesh file, relative to the run file's folder)"
        )
    return cfg


def _check_combinations(values: dict[str, dict[str, Any]]) -> None:
    frame = values.get("frame", {})
    sources = [k for k in ("segments", "mesh") if k in frame]
    preset_like = [k for k in ("preset", "ei1_n_m2", "ei2_n_m2") if k in frame]
    if len(sources) > 1 or (sources and preset_like):
        given = ", ".join(f"frame.{k}" for k in sources + preset_like)
        raise InputError(
            f"{given} cannot be combined: describe the frame by one of preset/ei1_n_m2/ei2_n_m2, "
            "segments or mesh"
        )
    if "segments" in frame and "elements" in frame and frame["elements"] < len(frame["segments"]):
        raise InputError(
            f"frame.elements = {frame['elements']} is not allowed: must be >= the number of "
            f"segments ({len(frame['segments'])})"
        )
    contact = values.get("contact", {})
    if "zeta" in contact and "clamped_cor" in contact:
        raise InputError(
            "contact.zeta and contact.clamped_cor cannot be combined: give one (zeta follows from "
            "the clamped COR through eqs 1-4)"
        )


def _toml(value: Any) -> str:
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float):
        return repr(value) if math.isfinite(value) else ("nan" if value != value else "inf")
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(_toml(v) for v in value) + "]"
    if isinstance(value, str):
        return '"' + value.replace("\\", "\\\\").replace('"', '\\"') + '"'
    return str(value)


def toml_value(value: Any) -> str:
    """``value`` written as a TOML value (for examples and provenance)."""
    return _toml(value)
