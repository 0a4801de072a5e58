"""Run-file keys a command would ignore: refused where they change the impacts it computes.

A command reads from the core tables only the keys it has options for
(:mod:`fem_racket.cli.options.runfile`). For a command computing impacts
(:data:`IMPACT_COMMANDS`) a key of the impact's tables (:data:`IMPACT_TABLES`) it has no option
for would state another impact than the one computed: :func:`refuse_unused` refuses it in one
line. Other commands skip such keys, so one run file serves them all; so do all commands for
``[solver]`` and ``[output]`` (how, not what, is computed) and for keys a command spans itself.
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any

from fem_racket.frame.segments import PAPER_EI1
from fem_racket.impact.swing import DEFAULT_REFERENCE
from fem_racket.io.config_keys import CORE_DESTS, CORE_KEYS
from fem_racket.validation import InputError, show

__all__ = [
    "CORE_ONLY",
    "IMPACT_COMMANDS",
    "IMPACT_TABLES",
    "NEUTRAL",
    "refuse_core_only",
    "refuse_unused",
]

#: Core tables whose keys change the impacts a command computes.
IMPACT_TABLES = ("frame", "ball", "contact", "impact", "hand", "strings", "oblique")
#: Commands that compute impacts -> the core keys they span themselves (their own grid or list:
#: map's positions and offsets, refine's positions and element counts, the design's zone and
#: speeds), skipped. Every other key of :data:`IMPACT_TABLES` such a command has no option for is
#: refused: it would compute another impact than the file states. Other commands (modes, fit,
#: customise, closest, compare, reproduce, calibrate) skip the keys they have no option for, as
#: all commands do for ``[solver]`` and ``[output]`` (how, not what, is computed).
IMPACT_COMMANDS: dict[str, tuple[str, ...]] = {
    "simulate": (),
    "sweep": (),
    "export-vtk": (),
    "animate": (),
    "map": ("impact.position_x_over_l", "impact.offset_m"),
    "refine": ("impact.position_x_over_l", "frame.elements"),
    "optimize": ("impact.position_x_over_l", "impact.speed_m_s"),
    "sensitivity": ("impact.position_x_over_l", "impact.speed_m_s"),
}
#: Option (argparse dest) -> the value that changes nothing: the racket at rest, on the axis,
#: the standard frame (``frame.preset = "standard"``), the swing's default reference point. A
#: swing's point other than that (or a pivot) without a swing is refused by the commands that
#: have the option, as on their command line (``--reference`` needs ``--racket-speed``).
NEUTRAL = {"racket_speed": 0.0, "offset": 0.0, "ei1": PAPER_EI1, "reference": DEFAULT_REFERENCE}
#: Options (argparse dests) only the core tables set: a command's own table may set them only
#: where the command spans them itself (sweep's axes, refine's element counts); it may always
#: set its own ``out``/``overwrite``.
CORE_ONLY = CORE_DESTS - {"out", "overwrite"}


def refuse_unused(cfg: Any, command: str, dests: Iterable[str]) -> None:
    """Refuse the first key of :data:`IMPACT_TABLES` in ``cfg`` (a RunConfig) whose option
    (argparse dest) is not in ``dests`` when ``command`` computes impacts.

    A key at its :data:`NEUTRAL` value changes nothing and passes.

    Raises
    ------
    InputError
        Naming the dotted key, its value and the command.
    """
    if command not in IMPACT_COMMANDS:
        return
    dests, values = set(dests), cfg.defaults()
    for table in IMPACT_TABLES:
        for key in cfg.values.get(table, {}):
            dotted, dest = f"{table}.{key}", CORE_KEYS[table][key].dest
            if dest in dests or dotted in IMPACT_COMMANDS[command]:
                continue
            if values.get(dest) == NEUTRAL.get(dest, ...):
                continue  # changes nothing
            raise InputError(
                f"{dotted} = {show(cfg.get(dotted))} is not allowed with fem-racket {command}: "
                "it has no such option, so the key would be ignored; remove it"
            )


def refuse_core_only(where: str, dest: str) -> None:
    """Refuse a command's table key ``where`` (dotted, e.g. ``map.speed``) that sets ``dest``, an
    option only the core tables set (:data:`CORE_ONLY`), naming the core keys that set it.
    Nothing happens for another option.

    Raises
    ------
    InputError
        ``map.speed is not allowed here: set impact.speed_m_s instead``.
    """
    if dest in CORE_ONLY:
        core = [f"{t}.{k}" for t, ks in CORE_KEYS.items() for k, v in ks.items() if v.dest == dest]
        raise InputError(f"{where} is not allowed here: set {' or '.join(core)} instead")
