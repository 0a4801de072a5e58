"""Parameter sweeps: many impacts -> one labelled :class:`xarray.Dataset`, saved as netCDF.

``sweep(position="0.55:0.95:9", speed=[20, 30, 40], ei1="50:3000:60:log", output="fig13.nc")``
runs every combination (the Fig 13 study of Kawazoe & Kanda 1997 with 7-9 impact points) and
returns a dataset with one dimension per swept parameter (see :mod:`fem_racket.grid`) and the
variables ``cor``, ``contact_time_s``, ``rebound_speed_m_s``, ``peak_force_n`` and ``kcb_n_m``.

Per case only the small coupled problem is solved. Assembly and the free-free modes are built
once per mesh in each process; an EI change that scales every segment (EI1 with EI2 = 0.88 EI1,
or ``ei_factor``) reuses them through :meth:`FrameModel.scaled` (omega ~ sqrt(factor)). The
default ``exact`` solver runs :func:`fem_racket.integrators.exact_outcome` (no histories, peak
force maximised on the closed form) at unit speed: the system is linear, so at fixed K_CB the
COR and t_c do not depend on the speed and the force scales with it; cases differing only in
speed share one solve. The BDF solvers run :func:`fem_racket.simulate` with 1 us output steps
(peak force over those).

Execution (:mod:`fem_racket.executors`): serial, a local process pool (default) or a Dask
scheduler. With an output file the sweep is resumable (:mod:`fem_racket.checkpoint`).
"""

from __future__ import annotations

import logging
import math
import os
from collections import OrderedDict
from pathlib import Path
from typing import Any

import numpy as np

from .checkpoint import Checkpoint
from .executors import BACKENDS, run_chunks
from .grid import PARAMETERS, REFERENCE_EI1, SweepSpec, chunks
from .impact import simulate
from .integrators import exact_outcome
from .mesh import FrameMesh
from .model import DEFAULT_MODES, FrameModel
from .outputs import atomic_output, check_output_path, provenance
from .params import (
    PAPER_CLAMPED_COR,
    Frame,
    LinearContact,
    kcb_from_speed,
    standard_frame,
    zeta_from_cor,
)
from .system import modal_system
from .validation import InputError, check_choice

__all__ = ["VARIABLES", "clear_caches", "run_chunk", "sweep"]

log = logging.getLogger(__name__)

#: Result variables: name -> (units, description).
VARIABLES: dict[str, tuple[str, str]] = {
    "cor": ("1", "coefficient of restitution -v_B(t_c)/V_B0"),
    "contact_time_s": ("s", "contact time t_c"),
    "rebound_speed_m_s": ("m/s", "ball rebound speed -v_B(t_c)"),
    "peak_force_n": ("N", "largest contact force"),
    "kcb_n_m": ("N/m", "ball/string stiffness K_CB used"),
}
#: What a kcb of None means.
KCB_LAW = (
    "from the speed: piecewise power law through the paper's 2.74e4, 5.0e4, 8.33e4 N/m "
    "at 20, 30, 40 m/s"
)
#: Below this many exact impacts the default backend is serial (a pool takes ~0.5 s to start).
SERIAL_BELOW = 200
#: Output step of the BDF solvers in sweeps [s] (their peak force is the maximum over it).
BDF_OUTPUT_STEP = 1e-6

# Per-process caches (each pool or Dask worker fills its own).
_BASE: dict[tuple, FrameModel] = {}
_SCALED: OrderedDict[tuple, FrameModel] = OrderedDict()
_POINT: OrderedDict[tuple, np.ndarray] = OrderedDict()
_UNIT: OrderedDict[tuple, tuple[float, float, float]] = OrderedDict()


def _remember(cache: OrderedDict, key: tuple, value: Any, size: int) -> Any:
    cache[key] = value
    if len(cache) > size:
        cache.popitem(last=False)
    return value


def clear_caches() -> None:
    """Forget the models, point vectors and unit-speed outcomes cached in this process."""
    for cache in (_BASE, _SCALED, _POINT, _UNIT):
        cache.clear()


def _model(spec: SweepSpec, elements: int, ei1: float | None, ei_factor: float) -> tuple:
    """(key, model) of a case's frame, built from cached assembly and modes."""
    if spec.frame is None and spec.ei2 is not None:  # EI2 fixed: not a scaling of EI1
        base_key, factor = (spec.frame_key, elements, ei1, spec.ei2), ei_factor
    elif spec.frame is None:
        base_key, factor = (spec.frame_key, elements), ei_factor * ei1 / REFERENCE_EI1
    else:
        base_key, factor = (spec.frame_key, elements), ei_factor
    base = _BASE.get(base_key)
    if base is None:
        if spec.frame is None:
            frame = standard_frame(REFERENCE_EI1 if spec.ei2 is None else ei1, spec.ei2)
        else:
            frame = spec.frame
        base = _BASE[base_key] = FrameModel.build(frame, elements)
        base.modes(spec.modes)
    if factor == 1.0:
        return base_key + (1.0,), base
    key = base_key + (factor,)
    model = _SCALED.get(key)
    if model is None:
        model = _remember(_SCALED, key, base.scaled(factor), 256)
    return key, model


def _point_vector(key: tuple, model: FrameModel, position: float) -> np.ndarray:
    pkey = key[:-1] + (position,)
    g = _POINT.get(pkey)
    if g is None:
        g = _remember(_POINT, pkey, model.fe.point_vector(position * model.mesh.length), 4096)
    return g


def _case(spec: SweepSpec, p: dict[str, Any]) -> tuple[float, ...]:
    """The result values (in :data:`VARIABLES` order) of one case."""
    speed, mass = p["speed"], p["ball_mass"]
    kcb = kcb_from_speed(speed) if p["kcb"] is None else p["kcb"]
    zeta = zeta_from_cor(PAPER_CLAMPED_COR) if p["zeta"] is None else p["zeta"]
    key, model = _model(spec, p["elements"], p["ei1"], p["ei_factor"])
    if spec.solver != "exact":
        r = simulate(
            model,
            position=p["position"],
            speed=speed,
            ball_mass=mass,
            kcb=kcb,
            zeta=zeta,
            solver=spec.solver,
            separation=spec.separation,
            basis=spec.basis,
            modes=spec.modes,
            output_step=BDF_OUTPUT_STEP,
            rtol=spec.rtol,
            atol=spec.atol,
        )
        return r.cor, r.contact_time, -r.rebound_velocity, r.peak_force, kcb
    ukey = (*key, p["position"], mass, kcb, zeta, spec.separation, spec.modes)
    unit = _UNIT.get(ukey)
    if unit is None:
        fm = model.modes(spec.modes)
        g = _point_vector(key, model, p["position"])
        ccb = LinearContact(kcb, zeta).damping(mass)
        system = modal_system(fm.all_omega, fm.all_shapes, g, mass, kcb, ccb, 1.0)
        o = exact_outcome(system, separation=spec.separation)
        unit = _remember(_UNIT, ukey, (-o.rebound_velocity, o.contact_time, o.peak_force), 65536)
    cor, tc, peak = unit
    return cor, tc, cor * speed, peak * speed, kcb


def run_chunk(chunk: np.ndarray, *, spec: SweepSpec) -> np.ndarray:
    """Results of the cases ``chunk`` (flat indices), shape (len(chunk), len(VARIABLES))."""
    out = np.empty((len(chunk), len(VARIABLES)))
    for row, index in enumerate(chunk):
        out[row] = _case(spec, spec.case(int(index)))
    return out


def _attributes(spec: SweepSpec) -> dict[str, Any]:
    """Provenance, every fixed parameter (units in the names), solver and tolerances."""
    params: dict[str, Any] = {}
    for name, value in spec.fixed.items():
        attr = PARAMETERS[name].attribute
        if value is None and name == "kcb":
            value = KCB_LAW
        elif value is None and name == "zeta":
            value = zeta_from_cor(PAPER_CLAMPED_COR)
        if value is not None:
            params[attr] = value
    if spec.frame is None:
        params["ei2_n_m2"] = "0.88 ei1" if spec.ei2 is None else spec.ei2
    desc = spec.describe()
    params.update(
        frame=desc["frame"],
        solver=spec.solver,
        separation=spec.separation,
        basis=spec.basis,
        modes="all" if spec.modes is None else int(spec.modes),
        rtol=spec.rtol,
        atol=spec.atol,
        swept=" ".join(spec.dims),
        spec_sha256=spec.digest,
    )
    if spec.solver == "exact":
        params["tolerances"] = "exact: closed form, separation time to 1e-15 s; rtol, atol unused"
    prov = provenance(params)
    attrs = {k: v for k, v in prov.items() if k != "parameters"}
    attrs.update(prov["parameters"])
    return attrs


def _dataset(spec: SweepSpec, values: np.ndarray) -> Any:
    import xarray as xr

    coords = {
        name: (
            name,
            vals,
            {"units": PARAMETERS[name].unit, "long_name": PARAMETERS[name].description},
        )
        for name, vals in spec.axes.items()
    }
    data = {
        name: (spec.dims, values[:, k].reshape(spec.shape), {"units": unit, "long_name": text})
        for k, (name, (unit, text)) in enumerate(VARIABLES.items())
    }
    return xr.Dataset(data, coords=coords, attrs=_attributes(spec))


def _chunk_size(spec: SweepSpec, todo: int, workers: int) -> int:
    cap = 128 if spec.solver == "exact" else 4
    return max(1, min(cap, math.ceil(todo / (4 * workers))))


def sweep(
    frame: Frame | FrameMesh | None = None,
    *,
    position: Any = None,
    speed: Any = None,
    ei1: Any = None,
    ei2: float | None = None,
    ei_factor: Any = None,
    ball_mass: Any = None,
    zeta: Any = None,
    kcb: Any = None,
    elements: Any = None,
    solver: str = "exact",
    separation: str = "displacement",
    basis: str = "modal",
    modes: int | None = DEFAULT_MODES,
    rtol: float = 1e-10,
    atol: float = 1e-12,
    output: str | os.PathLike | None = None,
    overwrite: bool = False,
    restart: bool = False,
    backend: str | None = None,
    workers: int | None = None,
    scheduler: str | None = None,
    chunk_size: int | None = None,
    progress: bool | None = None,
) -> Any:
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
    ei2 : float, optional
        Fixed top-side EI2 of the standard frame [N m^2]; 0.88 EI1 when None.
    solver, separation, basis, modes, rtol, atol
        As for :func:`fem_racket.simulate`.
    output : path, optional
        netCDF file to write (atomically). With it the sweep is resumable: finished cases are
        kept in ``<output>.checkpoint/`` and a rerun with the same arguments continues.
    overwrite : bool
        Replace an existing ``output``.
    restart : bool
        Discard an existing checkpoint instead of resuming it.
    backend : {"serial", "processes", "dask"}, optional
        Default: "dask" when ``scheduler`` is given, else "processes" (serial for fewer than
        :data:`SERIAL_BELOW` exact impacts).
    workers : int, optional
        Processes of the local pool; all cores when None.
    scheduler : str, optional
        Dask distributed scheduler address ``tcp://HOST:PORT``.
    chunk_size : int, optional
        Cases per task (and per checkpoint file).
    progress : bool, optional
        Progress bar with rate and ETA on stderr; None: only when stderr is a terminal.

    Returns
    -------
    xarray.Dataset
        Dimensions: the swept parameters; variables :data:`VARIABLES`; attributes: every fixed
        parameter, the solver and its tolerances, the package version (provenance).
    """
    spec = SweepSpec.build(
        frame,
        position=position,
        speed=speed,
        ei1=ei1,
        ei2=ei2,
        ei_factor=ei_factor,
        ball_mass=ball_mass,
        zeta=zeta,
        kcb=kcb,
        elements=elements,
        solver=solver,
        separation=separation,
        basis=basis,
        modes=modes,
        rtol=rtol,
        atol=atol,
    )
    if backend is not None:
        check_choice("backend", backend, BACKENDS)
    for name, value in (("workers", workers), ("chunk_size", chunk_size)):
        if value is not None and (
            isinstance(value, bool) or not isinstance(value, int) or value < 1
        ):
            raise InputError(f"{name} = {value!r} is not allowed: must be an integer >= 1")
    n_vars = len(VARIABLES)
    values = np.full((spec.size, n_vars), np.nan)
    done = np.zeros(spec.size, dtype=bool)
    ckpt = None
    if output is not None:
        output = check_output_path(output, overwrite=overwrite)
        if restart:
            Checkpoint.discard(output)
        ckpt = Checkpoint(output, spec.digest, spec.describe(), spec.size, n_vars)
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

    if backend is None:
        small = spec.solver == "exact" and todo.size < SERIAL_BELOW
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
        progress=progress,
        total=spec.size,
        initial=spec.size - todo.size,
    )
    ds = _dataset(spec, values)
    if output is not None:
        with atomic_output(Path(output), overwrite=overwrite) as tmp:
            ds.to_netcdf(tmp)
        ckpt.remove()
        log.info("wrote %s", output)
    return ds
