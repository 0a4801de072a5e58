"""A fitted contact law's files (``fem-racket calibrate --out DIR``, and the run file's
:meth:`~fem_racket.io.config.RunConfig.calibrate`): ``<family>-<targets>.toml`` (the law as a
run file's ``[contact]`` table), ``.json`` (parameters, the fit table, provenance) and ``.png``
(force-deflection loops and force histories on a rigid support at each target speed).
"""

from __future__ import annotations

import json
from collections.abc import Mapping
from pathlib import Path
from typing import Any

from fem_racket.outputs import Target, atomic_outputs, json_ready, provenance

__all__ = ["calibration_files", "calibration_summary", "write_calibration"]


def calibration_files(out: str | Path, family: str, targets: str) -> list[Path]:
    """The three files a calibration of ``family`` to ``targets`` writes into the folder
    ``out``: .toml, .json, .png."""
    return [Path(out) / f"{family}-{targets}{s}" for s in (".toml", ".json", ".png")]


def calibration_summary(cal: Any) -> dict[str, Any]:
    """What the command prints with ``--json``: the family, the target set, whether every
    target is met, the law's parameters and the fit table."""
    return {
        "family": cal.family,
        "targets": cal.target_set,
        "meets_targets": cal.meets_targets,
        "law": cal.law.describe(),
        "fit": cal.table(),
    }


def write_calibration(
    cal: Any, files: list[Path], parameters: Mapping[str, Any], *, ball_mass: float,
    overwrite: bool = False,
) -> None:  # fmt: skip
    """Write the files of the Calibration ``cal`` (:func:`calibration_files`) as one set,
    ``parameters`` in their provenance; the loops at the targets' speeds with a ball of
    ``ball_mass`` [kg]."""
    from fem_racket.io.law_plots import plot_law_loops
    from fem_racket.studies.calibrate import clamped_histories, run_file_table

    meta = provenance(dict(parameters))
    speeds = sorted({t.condition for t in cal.targets if t.quantity != "static_deflection"})
    histories = clamped_histories(cal.law, speeds, ball_mass)
    targets = [Target(f) for f in files]
    with atomic_outputs(targets, overwrite=overwrite) as (toml, js, png):
        toml.write_text(run_file_table(cal.law), encoding="utf-8")
        data = json_ready({"provenance": meta, **calibration_summary(cal)})
        js.write_text(json.dumps(data, indent=2) + "\n", encoding="utf-8")
        title = f"{cal.family} fitted to {cal.target_set} (rigid support)"
        plot_law_loops(histories, speeds, png, title=title, meta=meta, overwrite=True)
