"""A chunk of sweep cases -> their result values, with the frames cached per process.

Each process (the caller, a pool worker or a Dask worker) keeps the assembled frame and its
free-free modes per mesh (``FrameModel``); EI changes that scale every segment reuse them
(omega ~ sqrt(factor), no eigen-solve).

Exact solver: the batched engine (:func:`fem_racket.impact.exact.engine.impacts`) on all the chunk's
cases of one frame at once, to the sweep's COR tolerance; every case is solved at
V_B0 = 1 m/s (the system is linear), so results do not depend on how cases are chunked.
Another contact law: the chunk's cases batched per frame, the law's parameters per case
(:mod:`fem_racket.studies.law_cases`).
BDF solvers: :func:`fem_racket.simulate` per case with 1 us output steps, the peak force being
the largest over them.

A swing (racket_speed, reference, pivot; :mod:`fem_racket.impact.swing`) enters through the
closing speed v_in + v_r of each case, at which the stationary racket is struck (K_CB follows
it), and the ball leaves at v_out = e_A v_in + (1 + e_A) v_r; under any contact law too
(:mod:`fem_racket.studies.law_cases` derives it). The BDF solvers start from the swing's
velocity field instead.
"""

from __future__ import annotations

import logging
from collections import OrderedDict
from typing import Any

import numpy as np

from fem_racket.contact.linear import LinearContact
from fem_racket.frame.model import FrameModel
from fem_racket.frame.segments import PAPER_EI1, standard_frame
from fem_racket.impact.exact.engine import EngineOptions, impacts
from fem_racket.impact.simulate import simulate
from fem_racket.impact.swing import ball_speed_out, closing_speed
from fem_racket.impact.system import NoSeparationError
from fem_racket.studies.grid import SweepSpec
from fem_racket.studies.law_cases import case_swing, law_chunk
from fem_racket.validation import AccuracyError

__all__ = ["COLUMNS", "MODES_COLUMN", "VARIABLES", "clear_caches", "result_variables", "run_chunk"]

log = logging.getLogger(__name__)

#: Result variables: name -> (units, description).
VARIABLES: dict[str, tuple[str, str]] = {
    "cor": ("1", "apparent coefficient of restitution (v_out - v_r)/(v_in + v_r)"),
    "contact_time_s": ("s", "contact time t_c"),
    "rebound_speed_m_s": ("m/s", "ball speed after impact -v_B(t_c) (v_out with a swing)"),
    "peak_force_n": ("N", "largest contact force"),
    "kcb_n_m": ("N/m", "ball/string stiffness K_CB used"),
    "racket_speed_at_impact_m_s": ("m/s", "impact point's speed towards the ball before impact"),
}
#: Column of the peak force in a chunk's results (computed only when asked).
PEAK_COLUMN = list(VARIABLES).index("peak_force_n")
#: Columns of a chunk's results: the :data:`VARIABLES`, then the flexible modes the solver kept
#: for each case (the dataset's ``modes_kept`` attribute, not a variable; NaN for the physical
#: basis and for a failed case).
COLUMNS = (*VARIABLES, "modes_kept")
MODES_COLUMN = COLUMNS.index("modes_kept")


def result_variables(spec: SweepSpec) -> list[str]:
    """The variables a sweep's dataset holds (the peak force only when asked)."""
    return [v for v in VARIABLES if spec.peak_force or v != "peak_force_n"]


#: Output step of the BDF solvers in sweeps [s] (their peak force is the maximum over it).
BDF_OUTPUT_STEP = 1e-6

# Per-process caches (each pool or Dask worker fills its own).
_BASE: dict[tuple, FrameModel] = {}
_SCALED: OrderedDict[tuple, FrameModel] = OrderedDict()


def _remember(cache: OrderedDict, key: tuple, value: Any, size: int) -> Any:
    cache[key] = value
    if len(cache) > size:
        cache.popitem(last=False)
    return value


def clear_caches() -> None:
    """Forget the models cached in this process."""
    for cache in (_BASE, _SCALED):
        cache.clear()


def _base(spec: SweepSpec, elements: int, ei1: float | None) -> tuple[tuple, FrameModel]:
    """(key, model) of the unscaled frame of a case, assembled once per process."""
    if spec.frame is None and spec.ei2 is not None:  # EI2 fixed: not a scaling of EI1
        base_key = (spec.frame_key, elements, ei1, spec.ei2)
    else:
        base_key = (spec.frame_key, elements)
    base = _BASE.get(base_key)
    if base is None:
        if spec.frame is None:
            frame = standard_frame(PAPER_EI1 if spec.ei2 is None else ei1, spec.ei2)
        else:
            frame = spec.frame
        base = _BASE[base_key] = FrameModel.build(frame, elements)
    return base_key, base


def _factor(spec: SweepSpec, ei1: Any, ei_factor: Any) -> Any:
    """The factor on every EI of the base frame (see :func:`_base`)."""
    if spec.frame is None and spec.ei2 is None:
        return ei_factor * ei1 / PAPER_EI1
    return ei_factor


def _model(spec: SweepSpec, elements: int, ei1: float | None, ei_factor: float) -> tuple:
    """(key, model) of a case's frame, built from cached assembly and modes (BDF solvers)."""
    base_key, base = _base(spec, elements, ei1)
    factor = _factor(spec, ei1, ei_factor)
    base.modes(spec.modes)
    if factor == 1.0:
        return base_key + (1.0,), base
    key = base_key + (factor,)
    model = _SCALED.get(key)
    if model is None:
        model = _remember(_SCALED, key, base.scaled(factor), 256)
    return key, model


def _case(spec: SweepSpec, p: dict[str, Any]) -> tuple[float, ...]:
    """The result values (in :data:`VARIABLES` order) of one case of a BDF solver."""
    speed, mass = p["speed"], p["ball_mass"]
    _, model = _model(spec, p["elements"], p["ei1"], p["ei_factor"])
    swing = case_swing(p, model.mesh.length)
    v_r = float(swing.speed_at(p["position"] * model.mesh.length))
    if spec.law is not None:  # any contact law: one impact by CVODE, from the swing's motion
        closing_speed(speed, v_r)  # ball and racket must close
        r = simulate(
            model,
            position=p["position"],
            offset=p["offset"],
            speed=speed,
            ball_mass=mass,
            law=spec.case_law(p),
            solver=spec.solver,
            output_step=None,
            rtol=spec.rtol,
            atol=spec.atol,
            swing=swing if swing.velocity or swing.omega else None,
        )
        return r.cor, r.contact_time, r.ball_speed_out, r.peak_force, np.nan, v_r, r.n_modes
    law = LinearContact.for_speed(closing_speed(speed, v_r), kcb=p["kcb"], zeta=p["zeta"])
    kcb, zeta = law.stiffness, law.zeta
    r = simulate(
        model,
        position=p["position"],
        offset=p["offset"],
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
        swing=swing,
    )
    kept = np.nan if r.n_modes is None else r.n_modes  # None: the physical basis
    return r.cor, r.contact_time, r.ball_speed_out, r.peak_force, kcb, v_r, kept


def _racket_speeds(p: dict[str, Any], rows: np.ndarray, length: float) -> np.ndarray:
    """v_r [m/s] of the cases ``rows`` of ``case_arrays`` values ``p`` (swept or fixed): one
    swing per distinct (racket_speed, reference, pivot), evaluated at its cases' points."""
    names = ("racket_speed", "reference", "pivot")
    cols = [
        np.broadcast_to(np.asarray(p[k], dtype=object), (rows.size,))
        if np.ndim(p[k]) == 0
        else np.asarray(p[k])[rows]
        for k in names
    ]
    x = np.asarray(p["position"], dtype=float)
    x = np.broadcast_to(x if x.ndim == 0 else x[rows], rows.shape) * length
    groups: dict[tuple, Any] = {}
    if all(np.ndim(p[k]) == 0 for k in names):
        groups[tuple(p[k] for k in names)] = slice(None)
    else:
        for i, key in enumerate(zip(*cols, strict=True)):
            groups.setdefault(key, []).append(i)
    out = np.empty(rows.size)
    for key, idx in groups.items():
        out[idx] = case_swing(dict(zip(names, key, strict=True)), length).speed_at(x[idx])
    return out


def _engine_chunk(spec: SweepSpec, chunk: np.ndarray) -> np.ndarray:
    """Results of the exact solver for the cases ``chunk``: one engine call per frame."""
    p = spec.case_arrays(chunk)
    n = len(chunk)
    out = np.full((n, len(COLUMNS)), np.nan)
    elements = np.broadcast_to(p["elements"], n)
    ei1 = np.broadcast_to(np.nan if p["ei1"] is None else p["ei1"], n)
    # One group per base frame: per element count, and per EI1 when EI2 is fixed.
    split_ei1 = spec.frame is None and spec.ei2 is not None
    keys = np.column_stack([elements, ei1 if split_ei1 else np.zeros(n)])
    uniq, group = np.unique(keys, axis=0, return_inverse=True)
    group = group.ravel()
    for g, (cells, e1) in enumerate(uniq):
        rows = np.flatnonzero(group == g)
        try:
            out[rows] = _engine_group(spec, p, rows, int(cells), float(e1) if split_ei1 else None)
        except (AccuracyError, np.linalg.LinAlgError) as exc:  # the frame cannot be solved
            log.warning("%d cases failed (NaN in the results): %s", rows.size, exc)
    # a failed case (any computed value not finite) is NaN in every variable
    computed = [k for k in range(len(VARIABLES)) if spec.peak_force or k != PEAK_COLUMN]
    out[~np.all(np.isfinite(out[:, computed]), axis=1)] = np.nan
    failed = np.flatnonzero(np.isnan(out[:, 0]))
    if failed.size:
        log.warning(
            "%d cases failed (NaN in the results: no separation within 20 contact times, or "
            "the frame failed its accuracy check), first: case %d",
            failed.size,
            chunk[failed[0]],
        )
    return out


def _engine_group(
    spec: SweepSpec, p: dict[str, Any], rows: np.ndarray, cells: int, ei1: float | None
) -> np.ndarray:
    """Results of the cases ``rows`` of one base frame (``cells`` elements, EI1 when EI2 is
    fixed) by one engine call, shape (len(rows), len(COLUMNS))."""

    def take(value: Any, rows: np.ndarray) -> Any:
        return value if np.ndim(value) == 0 else np.asarray(value)[rows]

    out = np.full((rows.size, len(COLUMNS)), np.nan)
    _, model = _base(spec, cells, ei1)
    factor = _factor(spec, take(p["ei1"], rows), take(p["ei_factor"], rows))
    v_in = np.broadcast_to(np.asarray(take(p["speed"], rows), dtype=float), rows.shape)
    v_r = _racket_speeds(p, rows, model.mesh.length)
    closing = v_in + v_r
    for i in np.flatnonzero(~(closing > 0.0))[:1]:
        closing_speed(v_in[i], v_r[i])  # refuses it, naming the speeds
    b = impacts(
        model,
        position=take(p["position"], rows),
        offset=take(p["offset"], rows),
        speed=closing,
        kcb=take(p["kcb"], rows),
        zeta=take(p["zeta"], rows),
        ball_mass=take(p["ball_mass"], rows),
        ei_factor=factor,
        options=EngineOptions(spec.separation, spec.tolerance, spec.peak_force, spec.modes),
    )
    v_out = ball_speed_out(b.cor, v_in, v_r)
    cols = [b.cor, b.contact_time, v_out, b.peak_force, b.kcb, v_r, b.modes]
    for k, col in enumerate(cols):
        if col is not None:
            out[:, k] = np.broadcast_to(col, rows.shape)
    return out


def run_chunk(chunk: np.ndarray, *, spec: SweepSpec) -> np.ndarray:
    """Results of the cases ``chunk`` (flat indices), shape (len(chunk), len(COLUMNS)): the
    :data:`VARIABLES`, then the flexible modes kept.

    A case whose ball does not separate within the time limit, whose solver fails or refuses
    it (:class:`~fem_racket.validation.AccuracyError`), or any of whose values is not finite,
    gets NaN in every variable (the sweep reports how many); any other error stops the sweep.
    """
    if spec.law is not None and spec.solver == "general":
        return law_chunk(spec, chunk, _model)
    if spec.solver == "exact" and spec.law is None:
        return _engine_chunk(spec, np.asarray(chunk))
    out = np.empty((len(chunk), len(COLUMNS)))
    # K_CB is NaN under another contact law than the paper's (it has none)
    checked = [k for k, v in enumerate(VARIABLES) if spec.law is None or v != "kcb_n_m"]
    for row, index in enumerate(chunk):
        try:
            out[row] = _case(spec, spec.case(int(index)))
        except (NoSeparationError, AccuracyError, RuntimeError, np.linalg.LinAlgError) as exc:
            log.warning("case %d failed (NaN in the results): %s", index, exc)
            out[row] = np.nan
            continue
        if not np.all(np.isfinite(out[row, checked])):
            log.warning("case %d failed (NaN in the results): a result is not finite", index)
            out[row] = np.nan
    return out
