"""What a run file cannot be combined with on the command line: ``--config`` given twice
(:class:`OneFile`), and a frame from two places (:func:`refuse_frame_clash`): the file's mesh or
segments with ``--ei1``/``--ei2``, or the command line's ``--mesh`` with the file's preset,
EI1, EI2, segments or element count. Each is refused in one line rather than one side silently
dropped (:mod:`fem_racket.cli.options.runfile` calls these)."""

from __future__ import annotations

from collections.abc import Iterable, Mapping
from typing import TYPE_CHECKING, Any

from fem_racket.cli.options.once import Once
from fem_racket.validation import InputError, show

if TYPE_CHECKING:
    from fem_racket.io.config import RunConfig

__all__ = ["UNDER_MESH", "OneFile", "refuse_frame_clash"]

#: The file's frame settings (argparse dests) a mesh file on the command line would replace.
UNDER_MESH = ("ei1", "ei2", "segments", "elements")


class OneFile(Once):
    """Store ``--config``, refusing it given a second time (else the last file would be read
    and the first silently dropped)."""

    reason = "a command reads one run file"


def refuse_frame_clash(
    cfg: RunConfig,
    values: Mapping[str, Any],
    given: Iterable[str],
    keys: Mapping[str, str],
    path: str,
) -> None:
    """Refuse a frame stated both in the file and on the command line.

    Parameters
    ----------
    cfg : RunConfig
        The run file.
    values : mapping
        dest -> value the file gives the command.
    given : iterable of str
        The dests the command line sets.
    keys : mapping
        dest -> the file's dotted key that sets it.
    path : str
        The run file, as named on the command line.

    Raises
    ------
    InputError
        ``--ei1`` with the file's ``frame.mesh``; ``--mesh`` with the file's ``frame.ei1_n_m2``
        (or preset, EI2, segments, elements) at a value other than the paper's frame
        (``preset = "standard"``, EI1 146 N m^2 and 20 elements change nothing).
    """
    from fem_racket.io.config_defaults import FRAME_ELEMENTS
    from fem_racket.io.config_unused import NEUTRAL

    given = set(given)
    frame_file = {"segments", "mesh"} & set(values)
    clash = {"ei1", "ei2"} & given
    if frame_file and clash and "mesh" not in given:
        opts = ", ".join(f"--{d}" for d in sorted(clash))
        key = "frame." + next(iter(sorted(frame_file)))
        raise InputError(f"{opts} cannot be combined with {key} from {path}: remove one of them")
    if "mesh" not in given:
        return
    file_values, neutral = cfg.defaults(), {**NEUTRAL, "elements": FRAME_ELEMENTS}
    for dest in UNDER_MESH:
        if dest in file_values and file_values[dest] != neutral.get(dest, ...):
            key = keys[dest] + ("" if dest == "segments" else f" = {show(cfg.get(keys[dest]))}")
            raise InputError(
                f"--mesh cannot be combined with {key} from {path}: the mesh file gives the "
                "frame's cells, EI and rhoA; remove one of them"
            )
