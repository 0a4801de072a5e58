"""A run file's checked contents (:class:`RunFile`): its core tables' values, its command
tables, where it was read from; :func:`parse_run_file` and :func:`load_run_file` read and check
one (the run file's format: :mod:`fem_racket.io.config`).

:class:`~fem_racket.io.config.RunConfig` is a RunFile with a method per command. What reads a
run file without running a command on it (a compared set-up, :mod:`fem_racket.io.setups`) loads
a RunFile: this module imports none of the commands' modules, which import that one.
"""

from __future__ import annotations

import math
import os
import tomllib
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

from fem_racket.contact.linear import zeta_from_cor
from fem_racket.display import plain
from fem_racket.impact.constants import DEFAULT_REFERENCE
from fem_racket.io.config_keys import COMMAND_TABLES, CORE_KEYS, PRESETS, reject_unknown
from fem_racket.validation import InputError, show

__all__ = ["RunFile", "load_run_file", "parse_run_file", "toml_value"]


@dataclass(frozen=True)
class RunFile:
    """A checked run file.

    Attributes
    ----------
    values : dict
        Core table -> key -> checked value (only the keys the file sets; segments as
        :class:`~fem_racket.frame.segments.Segment` tuples, numbers as float).
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
        The swing's reference point at its default (``config --example`` writes it) is left
        out: not given, as ``--reference`` left out (None, resolved where the swing is built).
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
                elif (table, key) == ("impact", "reference_x_over_l"):
                    if value == DEFAULT_REFERENCE:  # at its default: not given (the swing's)
                        continue
                out[dest] = value
        return out

    def resolve(self, path: str | os.PathLike) -> Path:
        """A path named in the file, relative to the file's folder."""
        p = Path(path).expanduser()
        if p.is_absolute() or self.source is None:
            return p
        return self.source.parent / p

    def simulate_kwargs(self) -> dict[str, Any]:
        """Keywords of :func:`fem_racket.simulate` for the file's impact: the impact point and
        offset, the ball, the contact law, the solver and its options. A frame other than
        ``frame.elements``, a swing, a hand, a string bed, an oblique ball or ``[simulate]
        output_step`` (not at its default) is refused, in one line naming the keys: those need
        :meth:`RunConfig.simulate`. See :func:`fem_racket.io.config_kwargs.simulate_keywords`."""
        from fem_racket.io.config_kwargs import simulate_keywords

        return simulate_keywords(self)

    def frame(self) -> Any:
        """The frame the file describes: a Frame, a FrameMesh read from ``frame.mesh``, or None
        (the standard racket with ``ei1_n_m2``/``ei2_n_m2``/preset applied)."""
        from fem_racket.frame.plausible import check_implement
        from fem_racket.frame.segments import Frame, standard_frame
        from fem_racket.io.mesh_files import read_mesh

        d = self.defaults()
        if "mesh" in d:
            return read_mesh(d["mesh"])
        if "segments" in d:  # an implausible frame refused, as the commands refuse it
            return check_implement(Frame(d["segments"]), "frame.segments")
        if "ei1" in d or "ei2" in d:
            return standard_frame(d.get("ei1", PRESETS["standard"]), d.get("ei2"))
        return None


def parse_run_file(
    text: str, source: str | os.PathLike | None = None, *, command_tables: Any = None
) -> RunFile:
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


def load_run_file(path: str | os.PathLike, *, command_tables: Any = None) -> RunFile:
    """Read and check the run file ``path``; see :func:`parse_run_file`."""
    p = Path(path)
    try:
        text = p.read_text(encoding="utf-8")
    except FileNotFoundError:
        raise InputError(f"config = '{p}' is not allowed: no such file") from None
    except (OSError, UnicodeDecodeError) as exc:
        why = getattr(exc, "strerror", None) or str(exc)
        raise InputError(f"config = '{p}' cannot be read ({why}): must be a TOML file") from None
    return parse_run_file(text, p, command_tables=command_tables)


def _check(data: dict[str, Any], source: Path | None, known: set[str]) -> RunFile:
    allowed_tables = list(CORE_KEYS) + sorted(known)
    reject_unknown(data, allowed_tables, "")
    values: dict[str, dict[str, Any]] = {}
    tables: dict[str, dict[str, Any]] = {}
    for name, table in data.items():
        if not isinstance(table, dict):
            raise InputError(f"{name} = {show(table)} is not allowed: must be a table [{name}]")
        if name not in CORE_KEYS:
            tables[name] = table
            continue
        reject_unknown(table, CORE_KEYS[name], name)
        values[name] = {k: CORE_KEYS[name][k].check(f"{name}.{k}", v) for k, v in table.items()}
    _check_combinations(values)
    cfg = RunFile(values, tables, source)
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
    if "mesh" in frame and "elements" in frame:  # as --mesh with --elements on the command line
        raise InputError(
            f"frame.elements = {frame['elements']} is not allowed with frame.mesh: the mesh file "
            "gives the cells and their EI and rhoA; remove one of them"
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
    value = plain(value)  # np.float64(0.5) as 0.5, np.bool_ as true, arrays as lists
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float):
        if math.isfinite(value):
            return repr(value)
        return "nan" if value != value else ("-inf" if value < 0 else "inf")
    if isinstance(value, (list, tuple)):
        return "[" + ", ".join(_toml(v) for v in value) + "]"
    if isinstance(value, str):
        return '"' + value.replace("\\", "\\\\").replace('"', '\\"') + '"'
    return str(value)


def toml_value(value: Any) -> str:
    """``value`` written as a TOML value (for examples and provenance)."""
    return _toml(value)
