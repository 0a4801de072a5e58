"""A run file's sweep in Python: :meth:`RunConfig.sweep` = ``fem-racket sweep --config``."""

from __future__ import annotations

from typing import Any

__all__ = ["sweep_file"]

#: A :class:`fem_racket.io.config.RunConfig` (not imported: that module imports this one).
RunConfig = Any


def _where(run: dict[str, Any], backend: str | None, workers: int | None) -> dict[str, Any]:
    """Where the cases run, as the command picks it from ``[sweep]`` ``serial``, ``workers`` and
    ``scheduler`` (serial, a Dask scheduler, a local pool of ``workers``; none: the library
    picks); the method's ``backend`` and ``workers`` win, as the command line's options do."""
    from fem_racket.studies.executors import check_scheduler

    serial, scheduler = run.get("serial", False), run.get("scheduler")
    if workers is not None:  # as --workers on the command line: over the file's serial = true
        serial = False
    else:
        workers = run.get("workers")
    if backend is None:
        backend = "serial" if serial else ("dask" if scheduler else None)
        if workers is not None and backend is None:
            backend = "processes"
    if scheduler is not None:
        check_scheduler(scheduler)
    return {"backend": backend, "workers": workers, "scheduler": scheduler}


def sweep_file(cfg: RunConfig, *, backend: str | None = None, workers: int | None = None) -> Any:
    """The sweep ``cfg`` describes, as ``fem-racket sweep --config`` computes it: the core tables
    fix what ``[sweep]`` does not sweep, ``[sweep]`` gives the grids (arrays or strings as on the
    command line), ``peak_force`` and ``chunk_size``. Returns the dataset the command writes
    (without writing it). Of ``[sweep]``'s run keys, all checked as the command checks them
    (:mod:`fem_racket.io.config_run_keys`), ``serial``, ``workers`` and ``scheduler`` say where
    the cases run, the others only what the command writes and prints. ``backend`` and
    ``workers``: as :func:`fem_racket.sweep`, over the file's."""
    from fem_racket.contact.presets import law_parameters
    from fem_racket.io.config_defaults import DEFAULTS
    from fem_racket.io.config_run_keys import RUN_KEYS, run_keys
    from fem_racket.io.config_unused import refuse_unused
    from fem_racket.studies.grid_values import LAW_PARAMETERS, PARAMETERS
    from fem_racket.studies.sweep import sweep_result

    d = cfg.defaults()
    options = ("ei2", "solver", "separation", "basis", "modes", "rtol", "atol", "tolerance")
    refuse_unused(cfg, "sweep", {*PARAMETERS, *LAW_PARAMETERS, *options, "mesh", "segments", "law"})
    table = {k.replace("-", "_"): v for k, v in cfg.table("sweep").items()}
    where = _where(run_keys("sweep", table), backend, workers)
    settings = {**d, **{k: v for k, v in table.items() if k not in RUN_KEYS["sweep"]}}
    frame = cfg.frame() if "mesh" in d or "segments" in d else None
    grid = {n: settings[n] for n in PARAMETERS if n in settings}
    if frame is not None:  # the file's frame replaces EI1/EI2 (scale it with ei_factor)
        grid.pop("ei1", None)
        if "mesh" in d:
            grid.pop("elements", None)
    kwargs = {k: settings[k] for k in options if k in settings and not (frame and k == "ei2")}
    # a key at simulate's default is not given (as on the command line): the sweep refuses
    # what is given, at any value, where simulate refuses it
    kwargs = {k: v for k, v in kwargs.items() if k not in DEFAULTS or v != DEFAULTS[k]}
    laws = {k: v for k, v in law_parameters(settings).items() if k in LAW_PARAMETERS}
    result = sweep_result(
        frame,
        **grid,
        **kwargs,
        law=None if settings.get("law", "linear") == "linear" else settings["law"],  # at default
        peak_force=settings.get("peak_force", False),
        chunk_size=settings.get("chunk_size"),
        **where,
        progress=False,
        **laws,
    )
    return result.to_xarray()
