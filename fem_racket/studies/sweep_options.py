"""The options of a sweep besides its grid: how the cases are solved and where the sweep runs.

:func:`fem_racket.sweep` and :func:`fem_racket.studies.sweep.sweep_result` take them as
keywords (checked with a "did you mean", :func:`fem_racket.studies.options.take`); the sweep
itself (:func:`fem_racket.studies.sweep.run_sweep`) takes these two small dataclasses.
"""

from __future__ import annotations

import os
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from fem_racket.impact.settings import DEFAULTS, UNSET
from fem_racket.studies.executors import BACKENDS, check_scheduler
from fem_racket.validation import InputError, check_choice, check_integer, show

__all__ = ["OUTPUT_SUFFIXES", "SOLVING_DEFAULTS", "SweepRun", "SweepSolving"]

#: Suffixes of a sweep's output file: netCDF, or a CSV table (with its JSON sidecar).
OUTPUT_SUFFIXES = (".nc", ".csv")
#: The effective value of each :class:`SweepSolving` option left :data:`UNSET` (not given).
#: (simulate's: :data:`~fem_racket.impact.settings.DEFAULTS`, the displacement separation).
SOLVING_DEFAULTS: dict[str, Any] = {
    "separation": "displacement",
    **{n: getattr(DEFAULTS, n) for n in ("basis", "modes", "rtol", "atol", "tolerance")},
}
#: The backend each run option belongs to.
_BACKEND_OF = {"workers": "processes", "scheduler": "dask"}


@dataclass(frozen=True)
class SweepSolving:
    """How the cases are solved (see :func:`fem_racket.sweep`).

    Attributes
    ----------
    ei2 : float or None
        Fixed top-side EI2 of the standard frame [N m^2] (0.88 EI1 when None).
    solver : str
        As for :func:`fem_racket.simulate` ("auto" picks).
    separation, basis, modes, rtol, atol
        As for :func:`fem_racket.simulate`; :data:`~fem_racket.impact.settings.UNSET` when not
        given (then :data:`SOLVING_DEFAULTS`: "displacement", "modal", 80 modes, 1e-10,
        1e-12), so that an option given at its default is refused where any other value is
        (the solver and the law see only what was given, as simulate's do).
    law : ContactLaw, str or None
        A contact law other than the paper's.
    tolerance : float or None
        COR tolerance of the exact solver's batched engine (None: every mode); UNSET when not
        given (then 1e-6).
    peak_force : bool
        Also compute the largest contact force.
    """

    ei2: float | None = None
    solver: str = "auto"
    separation: Any = UNSET
    basis: Any = UNSET
    modes: Any = UNSET
    rtol: Any = UNSET
    atol: Any = UNSET
    law: Any = None
    tolerance: Any = UNSET
    peak_force: bool = False


@dataclass(frozen=True)
class SweepRun:
    """Where the sweep runs and what it writes (see :func:`fem_racket.sweep`).

    Attributes
    ----------
    output : path or None
        netCDF (or .csv) file to write; with it the sweep is resumable.
    overwrite, restart : bool
        Replace an existing ``output``; discard an existing checkpoint.
    backend : {"serial", "processes", "dask"} or None
    workers : int or None
    scheduler : str or None
        Dask scheduler address ``tcp://HOST:PORT``.
    chunk_size : int or None
        Cases per task and checkpoint file.
    progress : bool or None
        Progress bar on stderr (None: when stderr is a terminal).
    parameters : dict or None
        Extra provenance (the attribute ``run_parameters``).
    """

    output: str | os.PathLike | None = None
    overwrite: bool = False
    restart: bool = False
    backend: str | None = None
    workers: int | None = None
    scheduler: str | None = None
    chunk_size: int | None = None
    progress: bool | None = None
    parameters: dict[str, Any] | None = None

    def __post_init__(self) -> None:
        """Refuse, in one line, a value that is not allowed or an option that would do
        nothing: overwrite or restart without an output, an output that is neither netCDF nor
        CSV, workers or a scheduler with another backend than theirs."""
        if self.output is None:
            for name in ("overwrite", "restart"):
                if getattr(self, name):
                    raise InputError(
                        f"{name} = {show(getattr(self, name))} is not allowed without output: "
                        "it acts on the output file and its checkpoint"
                    )
        elif Path(self.output).suffix.lower() not in OUTPUT_SUFFIXES:
            raise InputError(
                f"output = {show(str(self.output))} is not allowed: must end in .nc (netCDF) "
                "or .csv (a table and its JSON sidecar)"
            )
        if self.backend is not None:
            check_choice("backend", self.backend, BACKENDS)
        for name in ("workers", "chunk_size"):
            if getattr(self, name) is not None:
                check_integer(name, getattr(self, name))
        if self.scheduler is not None:
            check_scheduler(self.scheduler)  # before any checkpoint folder is made
        for name, own in _BACKEND_OF.items():
            backend = self.backend or ("dask" if self.scheduler is not None else own)
            if getattr(self, name) is not None and backend != own:
                raise InputError(
                    f"{name} = {show(getattr(self, name))} is not allowed with backend "
                    f"{backend!r}: it is the {own!r} backend's"
                )
