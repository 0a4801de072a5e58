"""Run-file keys a command would ignore: refused where they change the impacts it computes.

A command reads from the core tables only the keys it has options for
(:mod:`fem_racket.cli.options.runfile`). For a command computing impacts
(:data:`IMPACT_COMMANDS`) a key of the impact's tables (:data:`IMPACT_TABLES`) or of
``[solver]`` it has no option for would state another impact, or another way of computing it,
than the one computed: :func:`refuse_unused` refuses it in one line, for the command
(``--config``) and its Python method alike. Other commands skip such keys, so one run file
serves them all; so do all commands for ``[output]`` and for keys a command spans itself.
"""

from __future__ import annotations

from collections.abc import Iterable
from typing import Any

from fem_racket.contact.linear import DEFAULT_BALL_MASS, PAPER_CLAMPED_COR, zeta_from_cor
from fem_racket.frame.segments import PAPER_EI1
from fem_racket.io.config_defaults import DEFAULTS
from fem_racket.io.config_keys import COMMAND_TABLES, CORE_DESTS, CORE_KEYS
from fem_racket.validation import InputError, show

__all__ = [
    "CORE_ONLY",
    "IMPACT_COMMANDS",
    "IMPACT_TABLES",
    "NEUTRAL",
    "SPANNED_WITH",
    "refuse_core_only",
    "refuse_unused",
]

#: Core tables whose keys change the impacts a command computes; ``[solver]``'s say how.
IMPACT_TABLES = ("frame", "ball", "contact", "impact", "hand", "strings", "oblique", "solver")
#: Commands that compute impacts -> the core keys they span themselves (their own grid or list:
#: map's and compare's positions, refine's positions and element counts, the design's zone and
#: speeds), skipped. Every other key of :data:`IMPACT_TABLES` such a command has no option for is
#: refused: it would compute another impact than the file states. Other commands (modes, fit,
#: customise, closest, reproduce, calibrate) skip the keys they have no option for, as all
#: commands do for ``[output]`` (where, not what, is written).
IMPACT_COMMANDS: dict[str, tuple[str, ...]] = {
    "simulate": (),
    "sweep": (),
    "export-vtk": (),
    "animate": (),
    "map": ("impact.position_x_over_l",),
    "compare": ("impact.position_x_over_l",),
    "refine": ("impact.position_x_over_l", "frame.elements"),
    "optimize": ("impact.position_x_over_l", "impact.speed_m_s"),
    "sensitivity": ("impact.position_x_over_l", "impact.speed_m_s"),
}
#: Core keys a command spans only when its option (argparse dest) is given, on the command line
#: or in its own table: ``map``'s and ``compare``'s offsets. Without it the command stays on the
#: long axis, and a key off the axis is refused (a one-offset face is not a map: ``--offsets``
#: takes at least 2).
SPANNED_WITH = {"impact.offset_m": "offsets"}
#: Option (argparse dest) -> the value that changes nothing: the racket at rest, on the axis,
#: the standard frame (``frame.preset = "standard"``), the paper's ball and clamped COR,
#: ``simulate``'s solver defaults (:data:`~fem_racket.io.config_defaults.DEFAULTS`) and the
#: swing's reference point not given (the file's at its default is read as not given:
#: :meth:`~fem_racket.io.config_file.RunFile.defaults`). A swing's point given (or a pivot)
#: without a swing is refused by the commands that have the option, as on their command line
#: (``--reference`` needs ``--racket-speed``).
NEUTRAL = {
    **DEFAULTS,
    "racket_speed": 0.0,
    "ei1": PAPER_EI1,
    "reference": None,
    "ball_mass": DEFAULT_BALL_MASS,
    "zeta": zeta_from_cor(PAPER_CLAMPED_COR),
}
#: Options (argparse dests) only the core tables set: a command's own table may set them only
#: where the command spans them itself (sweep's axes, refine's element counts); it may always
#: set its own ``out``/``overwrite``.
CORE_ONLY = CORE_DESTS - {"out", "overwrite"}


def refuse_unused(cfg: Any, command: str, dests: Iterable[str], given: Iterable[str] = ()) -> None:
    """Refuse the first key of :data:`IMPACT_TABLES` in ``cfg`` (a RunConfig) whose option
    (argparse dest) is not in ``dests`` when ``command`` computes impacts.

    A key at its :data:`NEUTRAL` value changes nothing and passes; a key of
    :data:`SPANNED_WITH` passes when its option is in ``given`` (the options
    the command line sets) or in the command's own table.

    Raises
    ------
    InputError
        Naming the dotted key, its value and the command.
    """
    if command not in IMPACT_COMMANDS:
        return
    dests, values = set(dests), cfg.defaults()
    table = cfg.table(COMMAND_TABLES.get(command, command))
    given = set(given) | {k.replace("-", "_") for k in table}
    for name in IMPACT_TABLES:
        for key in cfg.values.get(name, {}):
            dotted, dest = f"{name}.{key}", CORE_KEYS[name][key].dest
            if values.get(dest) == NEUTRAL.get(dest, ...):
                continue  # changes nothing
            if dotted in SPANNED_WITH and SPANNED_WITH[dotted] in dests:
                if SPANNED_WITH[dotted] in given:
                    continue
                option = SPANNED_WITH[dotted]
                raise InputError(
                    f"{dotted} = {show(cfg.get(dotted))} is not allowed with fem-racket {command} "
                    f"without --{option}: it stays on the long axis, so the key would be ignored; "
                    f"span the face with --{option} (or {option} in "
                    f"[{COMMAND_TABLES.get(command, command)}], at least 2 values) or remove it"
                )
            if dest in dests or dotted in IMPACT_COMMANDS[command]:
                continue
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
