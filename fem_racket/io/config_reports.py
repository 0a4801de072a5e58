"""A run file's comparison and calibration in Python: :meth:`RunConfig.compare` =
``fem-racket compare A B --config`` and :meth:`RunConfig.calibrate` = ``fem-racket calibrate
--config``.

``compare`` plays every set-up alike: from the core tables it takes ``frame.elements`` (of
presets and segment frames), the ``[[frame.lead]]`` added to every one, the ball's speed and the
swing; ``[compare]`` gives ``point``, ``positions``, ``offsets``, ``grip``, ``out``. It computes
impacts: another key of the impact's tables or ``[solver]`` (``ball.mass_kg``: each set-up
brings its own ball) is refused, as the command refuses it
(:func:`fem_racket.io.config_unused.refuse_unused`). ``calibrate`` takes ``ball.mass_kg`` and
``output.out``; ``[calibrate]`` gives ``family``, ``targets``, ``out``; it skips the other keys
of the core tables, as the command skips them.
Files are written only where the method is given ``out`` or the file names one, the same files
the command writes, checked before the work.
"""

from __future__ import annotations

import os
from pathlib import Path
from typing import Any

from fem_racket.contact.linear import DEFAULT_BALL_MASS
from fem_racket.io.config_defaults import FRAME_ELEMENTS, PLAY_DEFAULTS
from fem_racket.io.config_tables import (
    choice,
    flag,
    number,
    overwrite_set,
    table_options,
    text,
    texts,
)
from fem_racket.studies.calibrate import FAMILIES, TARGET_SETS
from fem_racket.validation import InputError, show, work_begins

__all__ = ["CALIBRATE_OPTIONS", "COMPARE_OPTIONS", "calibrate_file", "compare_file"]

#: A :class:`fem_racket.io.config.RunConfig` (not imported: that module imports this one).
RunConfig = Any


#: The options of each command's table: dest -> (default, conversion); the commands' defaults.
COMPARE_OPTIONS = {
    "point": (0.75, number),
    "positions": ("0.5:1.0:200", text),
    "offsets": (None, text),
    "grip": ("firm", choice(("firm", "loose"))),
    "out": (None, texts),
    "overwrite": (False, flag),
}
CALIBRATE_OPTIONS = {
    "family": ("hysteretic", choice(tuple(sorted(FAMILIES)))),
    "targets": ("kawazoe-1997", choice(tuple(sorted(TARGET_SETS)))),
    "out": (None, text),
    "overwrite": (False, flag),
}


def _core(cfg: RunConfig, defaults: dict[str, Any]) -> dict[str, Any]:
    """The core tables' values of the options ``defaults`` names, else those defaults."""
    d = cfg.defaults()
    return {k: d.get(k, v) for k, v in defaults.items()}


def compare_file(cfg: RunConfig, rackets: Any, out: Any = None) -> list[Any]:
    """The set-ups ``rackets`` (presets, mesh files or run files, each optionally
    ``+LOCATION:GRAMS``) compared as ``fem-racket compare RACKETS --config`` compares them: the
    Reports of :func:`fem_racket.studies.compare.compare`, in order; with ``out`` (a path or a
    list of them, else ``[compare] out``) the figure (.png, .svg, .pdf) and/or maps (.nc)
    written as one set, as the command writes them: an existing one refused unless the file
    says ``overwrite``, or ``out`` is the command's default (``output/compare.png``) and holds
    an earlier compare's figure."""
    from fem_racket.io.compare_files import COMPARE_OUTPUT, check_compare_outputs, write_compare
    from fem_racket.io.config_rerun import rerun_overwrite
    from fem_racket.io.config_unused import refuse_unused
    from fem_racket.io.setups import compare_play, read_setups
    from fem_racket.studies.compare import check_compare, compare, differences

    defaults = {**PLAY_DEFAULTS, "elements": FRAME_ELEMENTS, "add_mass": None, "overwrite": False}
    core = _core(cfg, defaults)
    o = table_options(cfg, "compare", COMPARE_OPTIONS, core)
    if isinstance(rackets, (str, os.PathLike)):  # one set-up, not a list of them
        raise InputError(
            f"rackets = {show(str(rackets))} is not allowed: must be a list of set-ups, at "
            "least 2 (e.g. ['standard', 'rigid'])"
        )
    rackets = [str(r) for r in rackets]
    if len(rackets) < 2:
        raise InputError(f"rackets = {len(rackets)} given is not allowed: need at least 2")
    refuse_unused(cfg, "compare", {*defaults, *COMPARE_OPTIONS})  # as the command refuses it
    out = o["out"] if out is None else out
    outs = [Path(p) for p in ([out] if isinstance(out, (str, Path)) else out or [])]
    overwrite = rerun_overwrite(o["overwrite"], outs == [COMPARE_OUTPUT], outs)
    check_compare_outputs(outs, overwrite=overwrite)
    setups = read_setups(rackets, elements=o["elements"], leads=o["add_mass"] or [])
    play = compare_play(o)
    check_compare(setups, play)
    work_begins()
    reports = compare(setups, play)
    diffs = differences(reports)
    parameters = {"config": str(cfg.source), "rackets": rackets, **o, "out": [str(p) for p in outs]}
    if outs:
        write_compare(reports, diffs, outs, overwrite=overwrite, parameters=parameters)
    return reports


def calibrate_file(cfg: RunConfig, out: Any = None) -> Any:
    """The law ``fem-racket calibrate --config`` fits: the Calibration of
    :func:`fem_racket.studies.calibrate.calibrate` (``[calibrate] family`` to ``targets``, the
    ball of ``ball.mass_kg``); with ``out`` (else ``[calibrate] out``, else ``output.out``)
    its .toml, .json and .png written into that folder, as the command writes them."""
    from fem_racket.io.calibration_files import calibration_files, write_calibration
    from fem_racket.outputs import Target, check_targets
    from fem_racket.studies.calibrate import calibrate

    core = _core(cfg, {"ball_mass": DEFAULT_BALL_MASS, "out": None, "overwrite": False})
    o = table_options(cfg, "calibrate", CALIBRATE_OPTIONS, core)
    folder = out or o["out"]
    if folder is None and (given := overwrite_set(cfg, "calibrate")):  # as the command
        raise InputError(f"{given} is not allowed without out: nothing is written")
    files = [] if folder is None else calibration_files(folder, o["family"], o["targets"])
    check_targets([Target(f) for f in files], overwrite=o["overwrite"])
    cal = calibrate(o["family"], o["targets"], ball_mass=o["ball_mass"])
    if files:
        parameters = {"config": str(cfg.source), **o, "out": str(folder)}
        write_calibration(cal, files, parameters, ball_mass=o["ball_mass"],
                          overwrite=o["overwrite"])  # fmt: skip
    return cal
