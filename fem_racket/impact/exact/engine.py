"""Many linear impacts at once: arrays of cases in, arrays of COR and contact time out.

Public signatures (stable)::

    impacts(frame=None, *, position, offset=0.0, speed=20.0, kcb=None, zeta=None,
            ball_mass=None, ei_factor=1.0, elements=20, options=None) -> ImpactBatch

    modal_impacts(omega, values, rigid, *, speed=20.0, kcb=None, zeta=None, ball_mass=None,
                  residual_flexibility=0.0, residual_mass=0.0, options=None) -> ImpactBatch

with ``options`` an :class:`~fem_racket.impact.exact.inputs.EngineOptions` (separation,
tolerance, peak_force, modes; its defaults when None). Every case argument is a number or an
array; they broadcast together. :func:`impacts` takes a frame (a
:class:`~fem_racket.frame.model.FrameModel`, whose modes it computes once and reuses, or a
Frame/FrameMesh/None, meshed with ``elements`` cells); :func:`modal_impacts` takes any
structure's modes directly: flexible angular frequencies ``omega`` (m,) [rad/s] (or (n, m), one
row per case, for cases on different structures: many designs in one call), mode values at
each case's impact point ``values`` (n, m) [1/sqrt(kg)] and the rigid modes' summed squared
values ``rigid`` (n,) [1/kg] (1/m_R + d^2/I_R for a free frame; any number of rigid modes,
including none).

Physics: the linear ball/string spring-dashpot (K_CB, C_CB = 2 zeta sqrt(m_B K_CB)) between the
ball (point mass m_B, speed V_B0) and the structure, as :mod:`fem_racket.impact.exact.closed_form`,
solved per case from the roots of its characteristic function
(:mod:`fem_racket.impact.exact.roots`) with the modes below beta x omega_c kept and one residual
pseudo-mode for the others (:mod:`fem_racket.impact.reduction`; ``tolerance`` on the COR picks
beta, None or 0 keeps every mode given); separation, impulse and peak force in
:mod:`fem_racket.impact.exact.separation`; the compiled batch loop in
:mod:`fem_racket.impact.exact.batch`. Linear, so everything is solved at V_B0 = 1 m/s: COR and
t_c do not depend on the speed except through K_CB, and the force scales with it.
COR = -v_B(t_c)/V_B0 = J(t_c)/(m_B V_B0) - 1.

A case gives the same bits alone or in any batch: on a frame, the modes computed for it (and the
static totals standing for the others) are those it would need alone
(:func:`_frame_groups`), and the batch solves each case on its own. A case whose ball does not
leave the strings within 20 eq-11 contact times gets NaN.
"""

from __future__ import annotations

import math
from typing import Any

import numpy as np

from fem_racket.impact.exact.batch import Cases, SolveOptions, solve_cases
from fem_racket.impact.exact.impact_batch import ImpactBatch, to_batch
from fem_racket.impact.exact.inputs import (
    EngineOptions,
    Laws,
    case_laws,
    check_array,
    check_cases,
)
from fem_racket.impact.point import FIRST_MODES, ModalData
from fem_racket.impact.reduction import DEFAULT_TOLERANCE, cutoff_factor
from fem_racket.validation import InputError, show

__all__ = ["DEFAULT_TOLERANCE", "EngineOptions", "ImpactBatch", "impacts", "modal_impacts"]

#: Cases whose mode values are gathered at once.
CHUNK = 8192


def _run(data: ModalData, index: np.ndarray, scale: np.ndarray, laws: Laws, options: SolveOptions):
    """COR, t_c, peak force per unit speed and modes kept of every case, in chunks; case i's
    mode values are data.values[index[i]], its EI factor scale[i]."""
    n = index.size
    cor, tc, peak = np.empty(n), np.empty(n), np.empty(n)
    kept = np.empty(n, dtype=int)
    root_s = np.sqrt(scale)
    omega = data.omega
    for start in range(0, n, CHUNK):
        sl = slice(start, start + CHUNK)
        ix = index[sl]
        w = (omega[None, :] if omega.ndim == 1 else omega[ix]) * root_s[sl, None]
        cases = Cases(
            w, data.values[ix], data.rigid[ix], data.residual_flexibility[ix] / scale[sl],
            data.residual_mass[ix], laws.k[sl], laws.c[sl], laws.mb[sl],
        )  # fmt: skip
        cor[sl], tc[sl], peak[sl], kept[sl] = solve_cases(cases, options)
    return cor, tc, peak, kept


def _solve(options: EngineOptions) -> SolveOptions:
    """The batch's options: the cut-off of the tolerance, the peak force only with every mode
    (else :func:`_peaks` adds it)."""
    beta = cutoff_factor(options.tolerance, options.separation)
    return SolveOptions(beta, options.separation, options.peak_force and not math.isfinite(beta))


def _peaks(results: tuple, every: tuple, laws: Laws, options: EngineOptions) -> tuple:
    """``results`` with the peak force of every mode: ``every`` = (data, index, scale) of all
    the structure's modes. The modes a tolerance drops carry a ripple that moves the peak by up
    to ~1e-3 (README), so the peak is always that of every mode, as a single impact's
    (:mod:`fem_racket.impact.exact.single`)."""
    if not options.peak_force or _solve(options).peak_force:
        return results
    all_modes = SolveOptions(math.inf, options.separation, True)
    peak = _run(*every, laws, all_modes)[2]
    return results[0], results[1], peak, results[3]


def modal_impacts(
    omega: Any,
    values: Any,
    rigid: Any,
    *,
    speed: Any = 20.0,
    kcb: Any = None,
    zeta: Any = None,
    ball_mass: Any = None,
    residual_flexibility: Any = 0.0,
    residual_mass: Any = 0.0,
    options: EngineOptions | None = None,
) -> ImpactBatch:
    """Impacts on any structure given by its modes at the impact points.

    Parameters
    ----------
    omega : array_like, shape (m,) or (..., m)
        Flexible angular frequencies, ascending [rad/s] (rigid modes excluded); one row per
        case (broadcast with ``values``) when the cases are on different structures (a stiffer
        structure: omega x sqrt(factor), residual_flexibility / factor).
    values : array_like, shape (..., m)
        Mass-normalised mode values at each case's impact point [1/sqrt(kg)].
    rigid : array_like, shape (...)
        Sum of the rigid modes' squared values at the impact point [1/kg].
    speed, kcb, zeta, ball_mass : array_like
        V_B0 [m/s], K_CB [N/m] (from the speed when None), damping ratio (from the clamped COR
        0.83 when None), m_B [kg] (0.057 when None).
    residual_flexibility, residual_mass : array_like
        Sums of a^2/omega^2 [s^2/kg] and a^2 [1/kg] over modes not in ``omega``.
    options : EngineOptions, optional
        Separation criterion, COR tolerance choosing the modes kept (None or 0: all given),
        peak force; ``modes`` is not allowed (the structure's modes are those given).
    """
    options = EngineOptions() if options is None else options
    if options.modes is not None:
        raise InputError(
            f"modes = {show(options.modes)} is not allowed with modal_impacts: the modes are those "
            "given (pass fewer columns)"
        )
    check_cases(speed, kcb, zeta, ball_mass)
    omega = np.asarray(omega, dtype=float)
    values = np.asarray(values, dtype=float)
    if (
        omega.ndim == 0
        or values.shape[-1:] != omega.shape[-1:]
        or np.any(np.diff(omega, axis=-1) <= 0.0)
    ):
        raise InputError(
            f"omega = array of shape {omega.shape} is not allowed: must be ascending along its "
            f"last axis, one per column of values (shape {values.shape})"
        )
    shape = np.broadcast_shapes(
        omega.shape[:-1], values.shape[:-1], np.shape(rigid), np.shape(speed), np.shape(kcb),
        np.shape(zeta), np.shape(ball_mass), np.shape(residual_flexibility),
        np.shape(residual_mass),
    )  # fmt: skip
    n = math.prod(shape)
    m = omega.shape[-1]
    if omega.ndim > 1:
        omega = np.broadcast_to(omega, shape + (m,)).reshape(n, m)

    def flat(x):
        return np.broadcast_to(np.asarray(x, dtype=float), shape).ravel()

    data = ModalData(
        omega, np.broadcast_to(values, shape + (m,)).reshape(n, m), flat(rigid),
        flat(residual_flexibility), flat(residual_mass),
    )  # fmt: skip
    laws = case_laws(speed, kcb, zeta, ball_mass, shape)
    every = (data, np.arange(n), np.ones(n))
    results = _run(*every, laws, _solve(options))
    return to_batch(_peaks(results, every, laws, options), laws, options, shape)


def impacts(
    frame: Any = None,
    *,
    position: Any,
    offset: Any = 0.0,
    speed: Any = 20.0,
    kcb: Any = None,
    zeta: Any = None,
    ball_mass: Any = None,
    ei_factor: Any = 1.0,
    elements: int = 20,
    options: EngineOptions | None = None,
) -> ImpactBatch:
    """Impacts of the ball on a free frame: COR, contact time (and peak force) per case.

    Parameters
    ----------
    frame : FrameModel, Frame or FrameMesh, optional
        The racket (the paper's standard one when None). A FrameModel keeps its modes for the
        next call.
    position : array_like
        Impact points x/L from the grip end, in [0, 1].
    offset : array_like
        Lateral offsets of the impact points from the long axis [m] (0: on it); off axis the
        frame also twists (:mod:`fem_racket.impact.offaxis`).
    speed : array_like
        Incident ball speeds V_B0 [m/s].
    kcb : array_like, optional
        K_CB [N/m]; from the speed through the paper's three points when None.
    zeta : array_like, optional
        Damping ratio in [0, 1); from the clamped-frame COR 0.83 (0.0592) when None.
    ball_mass : array_like, optional
        m_B [kg]; 0.057 when None.
    ei_factor : array_like
        Factor on every EI of the frame (its modes are reused: omega x sqrt(ei_factor)).
    elements : int
        Cells when meshing a Frame.
    options : EngineOptions, optional
        Separation criterion, COR tolerance (default 1e-6), peak force, a mode limit.

    Returns
    -------
    ImpactBatch
    """
    from fem_racket.impact.model_cache import frame_model

    options = EngineOptions() if options is None else options
    check_cases(speed, kcb, zeta, ball_mass)
    check_array("ei_factor", ei_factor, "", 0.0, math.inf)
    pos = check_array("position", position, "x/L", 0.0, 1.0)
    model = frame_model(frame, elements)
    shape = np.broadcast_shapes(
        pos.shape, np.shape(speed), np.shape(kcb), np.shape(zeta), np.shape(ball_mass),
        np.shape(ei_factor), np.shape(offset),
    )  # fmt: skip
    laws = case_laws(speed, kcb, zeta, ball_mass, shape)
    scale = np.broadcast_to(np.asarray(ei_factor, dtype=float), shape).ravel()
    solve = _solve(options)
    flat_pos = np.broadcast_to(pos, shape).ravel()
    if np.any(np.asarray(offset) != 0.0):
        from fem_racket.impact.offaxis import check_offsets, engine_data

        off = np.broadcast_to(check_offsets(model, pos, offset), shape).ravel()

        def wc(rig):
            return np.sqrt(laws.k * (1.0 / laws.mb + rig))

        data, index = engine_data(model, flat_pos, off, scale, wc, solve.beta, options.modes)
        results = _run(data, index, np.ones_like(scale), laws, solve)
        if options.peak_force and not solve.peak_force:
            data, index = engine_data(model, flat_pos, off, scale, wc, math.inf, options.modes)
            results = _peaks(results, (data, index, np.ones_like(scale)), laws, options)
        return to_batch(results, laws, options, shape)
    uniq, index = np.unique(flat_pos, return_inverse=True)
    if not math.isfinite(solve.beta) or options.modes is not None:
        every = (_modal_data(model, uniq, None, options.modes), index, scale)
        results = _peaks(_run(*every, laws, solve), every, laws, options)
        return to_batch(results, laws, options, shape)
    props = model.props
    d = uniq * props.length - props.cg
    rig = 1.0 / props.mass + d * d / props.inertia
    cutoff = solve.beta * np.sqrt(laws.k * (1.0 / laws.mb + rig[index])) / np.sqrt(scale)
    results = tuple(np.empty(index.size, dtype=t) for t in (float, float, float, int))
    for rows in _frame_groups(model, cutoff):
        here, sub = np.unique(index[rows], return_inverse=True)
        data = _modal_data(model, uniq[here], float(np.max(cutoff[rows])), None)
        part = _run(data, sub.ravel(), scale[rows], laws.take(rows), solve)
        for whole, piece in zip(results, part, strict=True):
            whole[rows] = piece
    if options.peak_force:
        every = (_modal_data(model, uniq, None, None), index, scale)
        results = _peaks(results, every, laws, options)
    return to_batch(results, laws, options, shape)


def _modal_data(model, positions: np.ndarray, cutoff: float | None, limit: int | None):
    from fem_racket.impact.point import frame_modal_data

    return frame_modal_data(model, positions, cutoff, limit=limit)


def _frame_groups(model, cutoff: np.ndarray):
    """Cases grouped by the modes :func:`~fem_racket.impact.point.frame_modal_data` computes
    for each alone (its doubling from FIRST_MODES up to its own ``cutoff`` [rad/s]), so a
    case's modes and static totals do not depend on the other cases of the batch."""
    n_flex = model.fe.ndof - 2
    n = min(FIRST_MODES, n_flex)
    rows = np.arange(cutoff.size)
    while rows.size:
        top = model.modes(n).omega[-1] if n > 0 else math.inf
        done = (cutoff[rows] <= top) | (n >= n_flex)
        if done.any():
            yield rows[done]
        rows = rows[~done]
        n = min(2 * n, n_flex)
