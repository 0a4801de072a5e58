"""Parameter sweeps: many impacts -> one labelled :class:`xarray.Dataset`, saved as netCDF.

``sweep(position="0.55:0.95:9", speed=[20, 30, 40], ei1="50:3000:60:log", output="fig13.nc")``
runs every combination (the Fig 13 study of Kawazoe & Kanda 1997 with 7-9 impact points) and
returns a dataset with one dimension per swept parameter (:mod:`.grid`) and the
variables ``cor``, ``contact_time_s``, ``rebound_speed_m_s``, ``peak_force_n`` and ``kcb_n_m``.
A contact law's parameters sweep the same way:
``sweep(law="hunt-crossley", hc_exponent="1.3:1.7:5", hc_stiffness=1e6)``.

Per case only the small coupled problem is solved; assembly and modes are reused
(:mod:`fem_racket.studies.cases`).

Execution (:mod:`fem_racket.studies.executors`): serial, a local process pool (default) or a Dask
scheduler. With an output file the sweep is resumable (:mod:`fem_racket.studies.checkpoint`).
:func:`sweep_result` is the same sweep as plain arrays (:mod:`fem_racket.studies.sweep_result`),
its netCDF file written without xarray: the command line's path.
"""

from __future__ import annotations

import logging
import math
import os
import warnings
from collections.abc import Callable
from functools import partial
from pathlib import Path
from typing import Any

import numpy as np

from fem_racket.contact.presets import PRESETS
from fem_racket.frame.mesh import FrameMesh
from fem_racket.frame.segments import Frame
from fem_racket.impact.problem_checks import named_law
from fem_racket.outputs import atomic_output, atomic_outputs, check_output_path, sidecar_path
from fem_racket.studies.cases import COLUMNS, VARIABLES, check_first_case, run_chunk
from fem_racket.studies.checkpoint import Checkpoint
from fem_racket.studies.executors import BarCounts, run_chunks
from fem_racket.studies.grid import LAW_PARAMETERS, PARAMETERS, SweepSpec, chunks
from fem_racket.studies.options import field_names, take
from fem_racket.studies.sweep_options import SweepRun, SweepSolving
from fem_racket.studies.sweep_physics import OBLIQUE_AXES, STRING_AXES, given
from fem_racket.studies.sweep_result import SweepResult
from fem_racket.validation import InputError, show, work_begins

__all__ = ["VARIABLES", "run_sweep", "sweep", "sweep_result"]

log = logging.getLogger(__name__)

#: Below this many exact impacts the default backend is serial (a pool takes ~0.5 s to start;
#: the engine solves ~1e4 impacts in that time).
SERIAL_BELOW = 20000
#: Largest chunk of exact impacts (one engine call per frame; also one checkpoint file).
EXACT_CHUNK = 32768
#: Chunk of the general integrator's cases (contact laws; one compiled call for the chunk,
#: whatever the cases' frames). Each case has its own step and modes, so its result does not
#: depend on the chunk; the size is fixed all the same, so every backend and a resumed run
#: make the same batches and checkpoint files.
LAW_CHUNK = 512
#: Chunk of the string-bed and oblique cases (solved one by one; oblique cases at one angle
#: share their normal impact within a chunk, which does not change their results).
PER_CASE_CHUNK = 32


def _chunk_size(spec: SweepSpec, todo: int, workers: int) -> int:
    if given(spec.values, (*STRING_AXES, *OBLIQUE_AXES)):  # solved case by case
        return PER_CASE_CHUNK
    if spec.solver == "general":  # batches of the general integrator (see LAW_CHUNK)
        return LAW_CHUNK
    # the engine (exact solver) takes big chunks
    cap = EXACT_CHUNK if spec.solver == "exact" else 4
    return max(1, min(cap, math.ceil(todo / (4 * workers))))


def _warm_up(spec: SweepSpec, chunk: np.ndarray) -> None:
    """Solve the cases ``chunk`` here and drop them, saying nothing: a forked pool's workers
    then inherit the compiled kernels (numba's import and cached code: ~0.3-0.5 s CPU a
    process) and the frame's modes instead of each loading them. Every case is computed on
    its own, so the workers' results do not change."""
    previous = logging.root.manager.disable
    logging.disable(logging.CRITICAL)
    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            run_chunk(chunk, spec=spec)
    finally:
        logging.disable(previous)


def _prepare(spec: SweepSpec, todo: np.ndarray) -> Callable[[], None] | None:
    """What a forked pool runs first (:func:`_warm_up` of two cases) when the sweep's cases run
    compiled kernels (the engine, the general integrator); None otherwise (string beds and
    oblique balls, solved case by case; the ODE solvers)."""
    per_case = given(spec.values, (*STRING_AXES, *OBLIQUE_AXES))
    if spec.solver not in ("exact", "general") or per_case or todo.size < 2:
        return None
    return partial(_warm_up, spec, todo[:2])


def sweep(frame: Frame | FrameMesh | None = None, **options: Any) -> Any:
    """Simulate every combination of the given parameter values.

    Parameters
    ----------
    frame : Frame or FrameMesh, optional
        The racket; the paper's standard one (its EI1 given by ``ei1``) when None.
    position, speed, ei1, ei_factor, ball_mass, zeta, kcb, elements
        Each a number (fixed), a sequence of distinct values or a string (``"20,30,40"``,
        ``"0.55:0.95:9"``, ``"50:3000:60:log"``): swept. Units and defaults as for
        :func:`fem_racket.simulate` (position x/L, speed m/s, EI1 N m^2, ball mass kg, K_CB N/m);
        ``kcb`` and ``zeta`` None follow the speed and the clamped COR 0.83; ``ei_factor``
        multiplies every segment's EI.
    racket_speed, reference, pivot
        The swing, fixed or swept like the others: the racket's speed towards the ball [m/s]
        (0 by default) at the point ``reference`` (x/L, 0.75), turning about ``pivot`` [m from
        the butt] or translating when None (:class:`fem_racket.impact.swing.Swing`). K_CB
        follows the closing speed; ``rebound_speed_m_s`` is then the ball's v_out and ``cor``
        the apparent COR.
    string_tension, pattern
        A string bed on every case (:mod:`fem_racket.studies.sweep_physics`): tension per
        string [N] and ``"16x19"``-style patterns, fixed or swept; the bed replaces K_CB and
        gives ``stringbed_stiffness_n_m`` and ``stringbed_frequency_hz``.
    angle, spin, friction
        An oblique, spinning ball on every case: angle from the face normal [deg], incoming
        spin [rpm] (+ topspin), Coulomb friction; gives ``ball_speed_out_m_s``,
        ``angle_out_deg``, ``spin_out_rpm``, ``tangential_cor`` and ``contact_regime`` (on a
        string bed too).
    side_angle, side_spin
        A 3-D oblique ball: its path's angle from the plane of the long axis [deg], in
        (-90, 90), and side spin [rpm] (+ rolling toward +y); gives ``side_angle_out_deg``,
        ``side_spin_out_rpm`` and ``racket_yaw_rate_rad_s`` (not on a string bed; 0 and 0:
        the impact in the plane, bit for bit).
    ei2 : float, optional
        Fixed top-side EI2 of the standard frame [N m^2]; 0.88 EI1 when None.
    solver, separation, basis, modes, rtol, atol
        As for :func:`fem_racket.simulate`.
    law : ContactLaw or str, optional
        A contact law other than the paper's (a law or a name of
        :data:`fem_racket.contact.presets.LAW_NAMES`); its name and fixed parameters become
        attributes and the ``kcb`` variable is NaN. With a swing the impact is the stationary
        one at the closing speed (exact for any law, :mod:`fem_racket.studies.law_cases`).
    tolerance : float or None
        COR tolerance of the exact solver's batched engine (default 1e-6; None or 0: every mode
        of ``modes``); recorded in the dataset's attributes.
    peak_force : bool
        Also compute the largest contact force (variable ``peak_force_n``; costs more).
    output : path, optional
        netCDF file to write, ``.nc`` (atomically; a .csv path: a CSV table and its JSON
        sidecar); ``overwrite`` and ``restart`` only with it.
        With it the sweep is resumable: finished cases are
        kept in ``<output>.checkpoint/`` and a rerun with the same arguments continues.
    overwrite : bool
        Replace an existing ``output``.
    restart : bool
        Discard an existing checkpoint instead of resuming it.
    backend : {"serial", "processes", "dask"}, optional
        Default: "dask" when ``scheduler`` is given, else "processes" (serial for fewer than
        :data:`SERIAL_BELOW` exact impacts and no ``workers``).
    workers : int, optional
        Processes of the local pool (backend "processes" only); all cores when None.
    scheduler : str, optional
        Dask distributed scheduler address ``tcp://HOST:PORT`` (backend "dask" only).
    chunk_size : int, optional
        Cases per task (and per checkpoint file).
    progress : bool, optional
        Progress bar with rate and ETA on stderr; None: only when stderr is a terminal.
    parameters : dict, optional
        Extra provenance (e.g. the command's options): the attribute ``run_parameters`` (JSON).
    **law_parameters
        The parameters of the law's family (:data:`fem_racket.studies.grid.LAW_PARAMETERS`:
        ``hc_stiffness``, ``hc_exponent``, ``hc_alpha``; ``k1``, ``k2``, ``hyst_exponent``;
        ``ball_stiffness``, ``ball_damping``, ``string_stiffness``, ``string_cubic``), each fixed
        or swept like the others (a dimension named after it); the law's own value when
        not given. Not with ``linear`` or a preset given by name.

    Returns
    -------
    xarray.Dataset
        Dimensions: the swept parameters; variables :data:`VARIABLES` (``peak_force_n`` only
        when asked); attributes: every fixed parameter, the solver and its tolerances, the
        flexible modes kept (``modes_kept``; ``modes`` is the request), the package version
        (provenance).
    """
    return sweep_result(frame, **options).to_xarray()


def _write(result: SweepResult, path: Path, overwrite: bool) -> None:
    """The result file: CSV (+ its JSON sidecar) for a .csv path, else netCDF."""
    if path.suffix.lower() == ".csv":
        with atomic_outputs([path, sidecar_path(path)], overwrite=overwrite) as (tmp, side):
            result.write_csv(tmp, side)
    else:
        with atomic_output(path, overwrite=overwrite) as tmp:
            result.write(tmp)


def sweep_result(frame: Frame | FrameMesh | None = None, **options: Any) -> SweepResult:
    """:func:`sweep` (the same keywords, checked with a "did you mean") as plain arrays, the
    netCDF file written without xarray: what the command line runs (xarray's imports cost it
    more than the Fig 13 sweep's 1 260 impacts).

    Returns
    -------
    SweepResult
        The values of every case, the attributes; ``to_xarray()`` gives :func:`sweep`'s dataset.
    """
    solving, run, grid = take(
        options, "a sweep parameter", SweepSolving, SweepRun, extra=(*PARAMETERS, *LAW_PARAMETERS)
    )
    return run_sweep(frame, grid, solving, run)


def run_sweep(
    frame: Frame | FrameMesh | None, grid: dict[str, Any], solving: SweepSolving, run: SweepRun
) -> SweepResult:
    """The sweep of ``grid`` (parameter name -> values) on ``frame``, solved as ``solving``
    says and run as ``run`` says (:func:`sweep`)."""
    law = solving.law
    params = sorted(k for k, v in grid.items() if k in LAW_PARAMETERS and v is not None)
    if isinstance(law, str) and params and law in ("linear", *PRESETS):
        why = "it is built from kcb and zeta" if law == "linear" else "it is a preset"
        raise InputError(f"law parameters {params} are not allowed with law {show(law)}: {why}")
    spec_options = {k: getattr(solving, k) for k in field_names(SweepSolving)}
    # the paper's law named with a string bed is refused, as simulate's (its K_CB is both)
    spec_options["law"] = named_law(law, given(grid, STRING_AXES) or None)
    spec = SweepSpec.build(frame, **grid, **spec_options)
    # the solver refuses, before any work, what it would refuse of the cases (as simulate's)
    check_first_case(spec)
    output, overwrite, backend, workers = run.output, run.overwrite, run.backend, run.workers
    scheduler, chunk_size = run.scheduler, run.chunk_size  # (checked by SweepRun)
    if output is not None:
        output = check_output_path(output, overwrite=overwrite)
    work_begins()
    n_vars = len(COLUMNS)
    values = np.full((spec.size, n_vars), np.nan)
    done = np.zeros(spec.size, dtype=bool)
    ckpt = None
    if output is not None:
        ckpt = Checkpoint(
            output, spec.digest, spec.describe(), spec.size, n_vars, restart=run.restart
        )
    try:
        if ckpt is not None:
            done, values = ckpt.load()
        todo = np.flatnonzero(~done)
        log.info(
            "sweep of %d impacts over %s: %d from the checkpoint, %d to compute",
            spec.size,
            ", ".join(spec.dims) or "no dimension",
            spec.size - todo.size,
            todo.size,
        )

        def finished(chunk: np.ndarray, result: np.ndarray) -> None:
            values[chunk] = result
            if ckpt is not None:
                ckpt.save(chunk, result)

        if backend is None:  # workers ask for a local pool
            small = spec.solver == "exact" and todo.size < SERIAL_BELOW and workers is None
            backend = "dask" if scheduler is not None else ("serial" if small else "processes")
        n_workers = workers or (os.cpu_count() or 1)
        size = chunk_size or _chunk_size(spec, todo.size, 1 if backend == "serial" else n_workers)
        run_chunks(
            run_chunk,
            chunks(todo, size),
            finished,
            kwargs={"spec": spec},
            backend=backend,
            workers=workers,
            scheduler=scheduler,
            progress=run.progress,
            counts=BarCounts(spec.size, spec.size - todo.size),
            prepare=_prepare(spec, todo),
        )
        result = SweepResult(spec, values, backend, run.parameters)
        if result.failed:
            first = int(np.flatnonzero(np.isnan(result.values[:, 0]))[0])
            log.warning(
                "%d of %d cases failed: NaN in the dataset, first: case %d",
                result.failed,
                spec.size,
                first,
            )
        if output is not None:
            _write(result, Path(output), overwrite)
            ckpt.remove()
            log.info("wrote %s", output)
    except BaseException as exc:
        if ckpt is not None and ckpt.cases:
            exc.add_note(
                f"the checkpoint '{ckpt.folder}' holds {ckpt.cases} of {spec.size} cases: "
                "rerun the same command to resume"
            )
        raise
    finally:
        if ckpt is not None:
            ckpt.close()
    return result
