"""A run file's sweep in Python: :meth:`RunConfig.sweep` = ``fem-racket sweep --config``."""

from __future__ import annotations

from typing import Any

__all__ = ["SWEEP_RUN_KEYS", "sweep_file"]

#: A :class:`fem_racket.io.config.RunConfig` (not imported: that module imports this one).
RunConfig = Any

#: ``[sweep]`` keys that set how the sweep runs or what it prints, not its values.
SWEEP_RUN_KEYS = ("out", "overwrite", "restart", "serial", "workers", "scheduler", "quiet", "json")


def sweep_file(cfg: RunConfig, *, backend: str | None = None, workers: int | None = None) -> Any:
    """The sweep ``cfg`` describes, as ``fem-racket sweep --config`` computes it: the core tables
    fix what ``[sweep]`` does not sweep, ``[sweep]`` gives the grids (arrays or strings as on the
    command line), ``peak_force`` and ``chunk_size``. Returns the dataset the command writes
    (without writing it; ``[sweep]``'s run keys :data:`SWEEP_RUN_KEYS` are the command's)."""
    from fem_racket.contact.presets import law_parameters
    from fem_racket.io.config_unused import refuse_unused
    from fem_racket.studies.grid_values import LAW_PARAMETERS, PARAMETERS
    from fem_racket.studies.sweep import sweep_result

    d = cfg.defaults()
    options = ("ei2", "solver", "separation", "basis", "modes", "rtol", "atol", "tolerance")
    refuse_unused(cfg, "sweep", {*PARAMETERS, *LAW_PARAMETERS, *options, "mesh", "segments", "law"})
    table = {k.replace("-", "_"): v for k, v in cfg.table("sweep").items()}
    settings = {**d, **{k: v for k, v in table.items() if k not in SWEEP_RUN_KEYS}}
    frame = cfg.frame() if "mesh" in d or "segments" in d else None
    grid = {n: settings[n] for n in PARAMETERS if n in settings}
    if frame is not None:  # the file's frame replaces EI1/EI2 (scale it with ei_factor)
        grid.pop("ei1", None)
        if "mesh" in d:
            grid.pop("elements", None)
    kwargs = {k: settings[k] for k in options if k in settings and not (frame and k == "ei2")}
    laws = {k: v for k, v in law_parameters(settings).items() if k in LAW_PARAMETERS}
    result = sweep_result(
        frame,
        **grid,
        **kwargs,
        law=settings.get("law", "linear"),
        peak_force=settings.get("peak_force", False),
        chunk_size=settings.get("chunk_size"),
        backend=backend,
        workers=workers,
        progress=False,
        **laws,
    )
    return result.to_xarray()
