"""A run file's reproduction in Python: :func:`reproduce_file` = ``fem-racket reproduce
--config``.

The paper's parameters are fixed: the command takes from the run file only the contact law of
``[contact]`` (``law`` and its parameters: the figures redrawn with it), ``output.overwrite``
and its own table ``[reproduce]`` (``out``, ``report``, ``quick``, ``overwrite``, ``format``,
``dpi``). This function does the same and writes the same files. It is not a method of the run
file (:class:`~fem_racket.io.config.RunConfig`): the figures (:mod:`fem_racket.paper`) sit above
the run files (:mod:`fem_racket.io`) in the layering.
"""

from __future__ import annotations

import os
from typing import Any

from fem_racket.io.config_tables import choice, flag, number, table_options, text
from fem_racket.io.figure_files import DEFAULT_DPI, FIGURE_FORMATS
from fem_racket.paper.constants import DEFAULT_OUT, DEFAULT_REPORT

__all__ = [
    "DEFAULT_OUT",
    "DEFAULT_REPORT",
    "REPRODUCE_OPTIONS",
    "destinations",
    "reproduce_file",
]

#: ``[reproduce]``'s options: dest -> (default, conversion), the command's defaults.
REPRODUCE_OPTIONS = {
    "out": (None, text),
    "report": (None, text),
    "quick": (False, flag),
    "overwrite": (False, flag),
    "format": (None, choice(FIGURE_FORMATS)),
    "dpi": (DEFAULT_DPI, number),
}


def destinations(law: str, out: str | None, report: str | None) -> tuple[str, str]:
    """The output folder and the report, defaulted: the paper's folder and REPRODUCTION.md, or
    under a contact ``law`` other than ``"linear"`` a folder of the law's own with its report
    inside."""
    if law == "linear":
        return out or DEFAULT_OUT, report or DEFAULT_REPORT
    out = out or f"{DEFAULT_OUT}/{law}"
    return out, report or f"{out}/{DEFAULT_REPORT}"


def reproduce_file(
    cfg: Any, out: str | os.PathLike | None = None, report: str | os.PathLike | None = None
) -> Any:
    """Reproduce the paper as ``fem-racket reproduce --config`` does on the run file ``cfg``
    (a :class:`~fem_racket.io.config.RunConfig`): every figure's data and figure into ``out``
    (else ``[reproduce] out``, else the command's folder) and the report to ``report`` (else
    ``[reproduce] report``, else the command's), files an earlier reproduction wrote replaced.

    Returns
    -------
    Reproduction
        Of :func:`fem_racket.paper.reproduce.reproduce`: the claims, the files written and the
        seconds each figure took.
    """
    from fem_racket.contact.presets import get_law, law_parameters
    from fem_racket.paper.reproduce import reproduce

    d = cfg.defaults()
    core = {"law": d.get("law", "linear"), **law_parameters(d)}
    o = table_options(
        cfg, "reproduce", REPRODUCE_OPTIONS, {**core, "overwrite": d.get("overwrite", False)}
    )
    law = get_law(o["law"], **law_parameters(o))
    given = (str(out) if out else o["out"], str(report) if report else o["report"])
    folder, where = destinations(o["law"], *given)
    parameters = {"config": str(cfg.source), **o, "out": folder, "report": where}
    return reproduce(folder, where, quick=o["quick"], overwrite=o["overwrite"],
                     parameters=parameters, fmt=o["format"] or "png", dpi=o["dpi"],
                     progress=False, law=law)  # fmt: skip
