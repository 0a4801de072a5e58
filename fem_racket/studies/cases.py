"""A chunk of sweep cases -> their result values: the chunk as problems, solved by the solver.

Each chunk of a sweep becomes one :class:`~fem_racket.impact.problem_batch.ProblemBatch` (its
frames, EI factors, impact points, speeds, ball masses, the paper's K_CB and zeta or the law's
parameters, swings) that the sweep's solver solves
(:meth:`fem_racket.impact.solvers.Solver.solve_many`): the exact solver by the batched engine
to the sweep's COR tolerance, the general solver by one integrator call over the chunk, the
ODE solvers case by case with 1 us output steps (the peak force the largest over them). The
study chooses no method: the solver does.

Each process (the caller, a pool worker or a Dask worker) keeps the assembled frame and its
free-free modes per mesh (``FrameModel``); EI changes that scale every segment are the batch's
EI factors on it (omega ~ sqrt(factor), no eigen-solve).

A swing (racket_speed, reference, pivot; :mod:`fem_racket.impact.swing`) enters as each case's
rigid racket motion: the exact and general solvers strike the stationary racket at the closing
speed v_in + v_r (K_CB follows it) and the ball leaves at v_out = e_A v_in + (1 + e_A) v_r,
under any contact law (:mod:`fem_racket.studies.law_cases` derives it); the ODE solvers start
from the swing's velocity field.
"""

from __future__ import annotations

import logging
from typing import Any

import numpy as np

from fem_racket.frame.model import FrameModel
from fem_racket.frame.segments import PAPER_EI1, standard_frame
from fem_racket.impact.problem_batch import ProblemBatch
from fem_racket.impact.solvers import Solver, make_solver
from fem_racket.studies.grid import LAW_PARAMETERS, SweepSpec
from fem_racket.studies.law_cases import case_swings

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

# Per-process cache (each pool or Dask worker fills its own).
_BASE: dict[tuple, FrameModel] = {}


def clear_caches() -> None:
    """Forget the models cached in this process."""
    _BASE.clear()


def _base(spec: SweepSpec, elements: int, ei1: float | None) -> FrameModel:
    """The unscaled frame of a case, assembled once per process."""
    if spec.frame is None and spec.ei2 is not None:  # EI2 fixed: not a scaling of EI1
        key = (spec.frame_key, elements, ei1, spec.ei2)
    else:
        key = (spec.frame_key, elements)
    base = _BASE.get(key)
    if base is None:
        if spec.frame is None:
            frame = standard_frame(PAPER_EI1 if spec.ei2 is None else ei1, spec.ei2)
        else:
            frame = spec.frame
        base = _BASE[key] = FrameModel.build(frame, elements)
    return base


def _factor(spec: SweepSpec, ei1: Any, ei_factor: Any) -> Any:
    """The factor on every EI of the base frame (see :func:`_base`)."""
    if spec.frame is None and spec.ei2 is None:
        return ei_factor * ei1 / PAPER_EI1
    return ei_factor


def chunk_problems(spec: SweepSpec, chunk: np.ndarray) -> ProblemBatch:
    """The cases ``chunk`` (flat indices) of a sweep as one batch of problems."""
    p = spec.case_arrays(chunk)
    n = len(chunk)
    elements = np.broadcast_to(p["elements"], n)
    ei1 = np.broadcast_to(np.nan if p["ei1"] is None else np.asarray(p["ei1"], float), n)
    # one frame per element count, and per EI1 when EI2 is fixed; EI1 otherwise scales it
    split_ei1 = spec.frame is None and spec.ei2 is not None
    keys = np.column_stack([elements, ei1 if split_ei1 else np.zeros(n)])
    uniq, frame = np.unique(keys, axis=0, return_inverse=True)
    models = tuple(_base(spec, int(cells), float(e1) if split_ei1 else None) for cells, e1 in uniq)
    frame = frame.ravel()
    lengths = np.array([m.mesh.length for m in models])[frame]
    law = None
    if spec.law is not None:
        named = {k: p[k] for k in LAW_PARAMETERS if k in spec.values}
        law = spec.case_law(named, n)
    return ProblemBatch(
        models,
        position=p["position"],
        speed=p["speed"],
        frame=frame,
        ei_factor=_factor(spec, ei1, p["ei_factor"]),
        offset=p["offset"],
        ball_mass=p["ball_mass"],
        kcb=p["kcb"],
        zeta=p["zeta"],
        law=law,
        separation=spec.separation if spec.law is None else None,
        swing=case_swings(p, n, lengths),
        peak_force=spec.peak_force,
    )


def sweep_solver(spec: SweepSpec) -> Solver:
    """The solver of a sweep, with the sweep's options."""
    if spec.solver == "exact":
        return make_solver("exact", tolerance=spec.tolerance, modes=spec.modes)
    if spec.solver == "general":
        return make_solver("general", tolerance=spec.tolerance)
    options: dict[str, Any] = {"rtol": spec.rtol, "atol": spec.atol, "output_step": None}
    if spec.law is None:  # the paper's law: its modes, basis, and the peak force over 1 us
        options.update(basis=spec.basis, modes=spec.modes, output_step=BDF_OUTPUT_STEP)
    return make_solver(spec.solver, **options)


def run_chunk(chunk: np.ndarray, *, spec: SweepSpec) -> np.ndarray:
    """Results of the cases ``chunk`` (flat indices), shape (len(chunk), len(COLUMNS)): the
    :data:`VARIABLES`, then the flexible modes kept.

    A case whose ball does not separate within the time limit, whose solver fails or refuses
    it (:class:`~fem_racket.validation.AccuracyError`), or any of whose values is not finite,
    gets NaN in every variable (the sweep reports how many); any other error stops the sweep.
    """
    chunk = np.asarray(chunk)
    out = sweep_solver(spec).solve_many(chunk_problems(spec, chunk)).columns()
    # K_CB is NaN under another contact law than the paper's (it has none)
    computed = [
        k
        for k, v in enumerate(VARIABLES)
        if (spec.peak_force or k != PEAK_COLUMN) and (spec.law is None or v != "kcb_n_m")
    ]
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
