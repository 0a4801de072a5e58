"""A chunk of sweep cases -> their result values: the chunk as problems, solved by the solver.

Each chunk of a sweep becomes one :class:`~fem_racket.impact.problem_batch.ProblemBatch` (its
frames, EI factors, impact points, speeds, ball masses, the paper's K_CB and zeta or the law's
parameters, swings) that the sweep's solver solves
(:meth:`fem_racket.impact.solvers.Solver.solve_many`): the exact solver by the batched engine
to the sweep's COR tolerance, the general solver by one integrator call over the chunk, the
ODE solvers case by case with 1 us output steps (the peak force the largest over them). A
solver that takes the chunk's cases one by one but not as a batch (the general solver under
the paper's law, as simulate's) solves each as its own problem (:func:`solve_cases`). The
study chooses no method: the solver does, and refuses what simulate's refuses
(:func:`check_first_case`).

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

from typing import Any

import numpy as np

from fem_racket.frame.model import FrameModel
from fem_racket.frame.segments import PAPER_EI1, standard_frame
from fem_racket.impact.batch_solve import each_batch
from fem_racket.impact.problem_batch import BatchOutcome, ProblemBatch
from fem_racket.impact.solvers import Solver, make_solver
from fem_racket.studies.grid import LAW_PARAMETERS, SweepSpec
from fem_racket.studies.law_cases import case_swings
from fem_racket.studies.sweep_physics import (
    LATERAL_AXES,
    OBLIQUE_AXES,
    STRING_AXES,
    case_beds,
    case_incidences,
    given,
    regime_code,
)
from fem_racket.validation import InputError

__all__ = [
    "ALL_VARIABLES",
    "AXIS_VARIABLES",
    "COLUMNS",
    "MODES_COLUMN",
    "VARIABLES",
    "check_first_case",
    "clear_caches",
    "result_variables",
    "run_chunk",
    "solve_cases",
]


#: Result variables: name -> (units, description).
VARIABLES: dict[str, tuple[str, str]] = {
    "cor": ("1", "apparent coefficient of restitution (v_out - v_r)/(v_in + v_r)"),
    "contact_time_s": ("s", "contact time t_c"),
    "rebound_speed_m_s": ("m/s", "ball's speed along the face normal after impact -v_B(t_c)"),
    "peak_force_n": ("N", "largest contact force"),
    "kcb_n_m": ("N/m", "ball/string stiffness K_CB used"),
    "racket_speed_at_impact_m_s": ("m/s", "impact point's speed towards the ball before impact"),
}
#: Result variables of the string-bed and oblique axes (only with them): name -> (units,
#: description).
AXIS_VARIABLES: dict[str, tuple[str, str]] = {
    # with a string bed (string_tension, pattern)
    "stringbed_stiffness_n_m": ("N/m", "string bed's static stiffness at the impact point"),
    "stringbed_frequency_hz": ("Hz", "string bed's first frequency"),
    # with an oblique ball (angle, spin, friction); cor ... peak_force_n: its normal impact
    "ball_speed_out_m_s": ("m/s", "ball speed after an oblique impact (normal and tangential)"),
    "angle_out_deg": ("deg", "ball's outgoing angle from the face normal"),
    "spin_out_rpm": ("rpm", "ball's outgoing spin, positive = topspin"),
    "tangential_cor": ("1", "tangential coefficient of restitution"),
    "contact_regime": ("1", "contact regime: phases, negative when the first grips"),
    # with a ball across the face (side_angle, side_spin)
    "side_angle_out_deg": ("deg", "ball's outgoing angle from the plane of the long axis"),
    "side_spin_out_rpm": ("rpm", "ball's outgoing side spin, positive = rolling to +y"),
    "racket_yaw_rate_rad_s": ("rad/s", "racket's yaw rate after impact, about the face normal"),
}
#: The variables of a string bed, of an oblique ball and of one across the face (only with
#: their axes).
STRUNG_VARIABLES = ("stringbed_stiffness_n_m", "stringbed_frequency_hz")
OBLIQUE_VARIABLES = (
    "ball_speed_out_m_s",
    "angle_out_deg",
    "spin_out_rpm",
    "tangential_cor",
    "contact_regime",
)
LATERAL_VARIABLES = ("side_angle_out_deg", "side_spin_out_rpm", "racket_yaw_rate_rad_s")
#: Columns of a chunk's results: the :data:`VARIABLES`, then the flexible modes the solver kept
#: for each case (the dataset's ``modes_kept`` attribute, not a variable; NaN for the physical
#: basis and for a failed case).
COLUMNS = (*VARIABLES, *AXIS_VARIABLES, "modes_kept")
#: Every result variable, in column order.
ALL_VARIABLES = {**VARIABLES, **AXIS_VARIABLES}
MODES_COLUMN = COLUMNS.index("modes_kept")


def result_variables(spec: SweepSpec) -> list[str]:
    """The variables a sweep's dataset holds (the peak force only when asked, K_CB only under
    the paper's law, those of a string bed or an oblique ball only with their axes)."""
    left_out = set()
    if not spec.peak_force:
        left_out.add("peak_force_n")
    if spec.law is not None:  # another law has no K_CB (the column all NaN)
        left_out.add("kcb_n_m")
    if not given(spec.values, STRING_AXES):
        left_out.update(STRUNG_VARIABLES)
    else:  # the bed replaces the lumped K_CB
        left_out.add("kcb_n_m")
    if not given(spec.values, OBLIQUE_AXES):
        left_out.update(OBLIQUE_VARIABLES)
    if not given(spec.values, LATERAL_AXES):
        left_out.update(LATERAL_VARIABLES)
    return [v for v in ALL_VARIABLES if v not in left_out]


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
    if np.all(keys == keys[:1]):  # one frame (np.unique along an axis sorts rows: slow)
        uniq, frame = keys[:1], np.zeros(n, dtype=np.intp)
    else:
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
        separation=spec.problem_separation,
        swing=case_swings(p, n, lengths),
        peak_force=spec.peak_force,
        strings=case_beds(p, n),
        incidence=case_incidences(p, n),
    )


def sweep_solver(spec: SweepSpec) -> Solver:
    """The solver of a sweep, made with the options the sweep was given
    (:meth:`SweepSpec.solver_options`): it takes and refuses them as simulate's does. The ODE
    solvers on the paper's law also give the peak force over 1 us output times, as they give
    an oblique ball's tangential contact the normal impact's histories at them; under another
    law (or on a string bed) no histories."""
    options = spec.solver_options()
    if spec.solver in ("cvode", "bdf") and not given(spec.values, STRING_AXES):
        histories = spec.law is None or given(spec.values, OBLIQUE_AXES)
        options["output_step"] = BDF_OUTPUT_STEP if histories else None
    return make_solver(spec.solver, **options)


def check_first_case(spec: SweepSpec) -> None:
    """Refuse, before any work and in simulate's line, what the sweep's solver refuses of its
    cases: the first case as its problem (the problem's own checks), then by the solver
    (:meth:`~fem_racket.impact.solvers.Solver.check`), as simulate checks an impact; the
    grid's checks (:meth:`SweepSpec.build`) hold the other cases to the same."""
    sweep_solver(spec).check(chunk_problems(spec, np.zeros(1, dtype=np.int64)).problem(0))


def solve_cases(solver: Solver, batch: ProblemBatch) -> BatchOutcome:
    """The outcome of ``batch`` by ``solver``: the batch whole where the solver takes it as one
    (:meth:`~fem_racket.impact.solvers.Solver.check_batch`), else each case as its own problem,
    checked and solved as simulate's (:func:`~fem_racket.impact.batch_solve.each_batch`: the
    general solver takes a batch only under a law other than the paper's, a problem under any
    law)."""
    try:
        solver.check_batch(batch)
    except InputError:  # the batch is refused, not its cases: each_batch checks every case
        return each_batch(solver, batch)  # and raises what the solver refuses of one
    return solver.solve_many(batch)


def run_chunk(chunk: np.ndarray, *, spec: SweepSpec) -> np.ndarray:
    """Results of the cases ``chunk`` (flat indices), shape (len(chunk), len(COLUMNS)): the
    :data:`VARIABLES`, then the flexible modes kept.

    A case whose ball does not separate within the time limit, whose solver fails or refuses
    it (:class:`~fem_racket.validation.AccuracyError`), or any of whose values is not finite,
    gets NaN in every variable (the sweep reports how many); any other error stops the sweep.
    """
    chunk = np.asarray(chunk)
    outcome = solve_cases(sweep_solver(spec), chunk_problems(spec, chunk))
    out = np.full((chunk.size, len(COLUMNS)), np.nan)
    base = outcome.columns()
    out[:, : len(VARIABLES)] = base[:, :-1]
    out[:, MODES_COLUMN] = base[:, -1]
    for name, values in outcome.extra.items():
        if name == "contact_regime":
            values = [regime_code(v) for v in values]
        out[:, COLUMNS.index(name)] = values
    # the tangential COR is NaN without tangential speed (head-on without spin: 0/0)
    computed = [COLUMNS.index(v) for v in result_variables(spec) if v != "tangential_cor"]
    out[~np.all(np.isfinite(out[:, computed]), axis=1)] = np.nan
    # a failed case's cause is noted by the solver; the sweep counts them once at its end
    return out
