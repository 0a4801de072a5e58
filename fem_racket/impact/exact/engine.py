"""Many linear impacts at once: arrays of cases in, arrays of COR and contact time out.

Public signature (stable)::

    impacts(frame=None, *, position, speed=20.0, kcb=None, zeta=None, ball_mass=None,
            ei_factor=1.0, elements=20, separation="displacement",
            tolerance=1e-6, peak_force=False, modes=None) -> ImpactBatch

    modal_impacts(omega, values, rigid, *, speed=20.0, kcb=None, zeta=None, ball_mass=None,
                  ei_factor=1.0, residual_flexibility=0.0, residual_mass=0.0,
                  separation="displacement", tolerance=1e-6, peak_force=False) -> ImpactBatch

Every case argument is a number or an array; they broadcast together. :func:`impacts` takes a
frame (a :class:`~fem_racket.frame.model.FrameModel`, whose modes it computes once and reuses,
or a Frame/FrameMesh/None, meshed with ``elements`` cells); :func:`modal_impacts` takes any
structure's modes directly: flexible angular frequencies ``omega`` (m,) [rad/s] (or (n, m), one
row per case, for cases on different structures: many designs in one call), mode values at
each case's impact point ``values`` (n, m) [1/sqrt(kg)] and the rigid modes' summed squared
values ``rigid`` (n,) [1/kg] (1/m_R + d^2/I_R for a free frame; any number of rigid modes,
including none).

Physics: the linear ball/string spring-dashpot (K_CB, C_CB = 2 zeta sqrt(m_B K_CB)) between the
ball (point mass m_B, speed V_B0) and the structure, as :mod:`fem_racket.impact.exact.closed_form`,
solved per case from the roots of its characteristic function
(:mod:`fem_racket.impact.exact.roots`) with the modes
below beta x omega_c kept and one residual pseudo-mode for the others
(:mod:`fem_racket.impact.reduction`;
``tolerance`` on the COR picks beta, None or 0 keeps every mode given); separation, impulse and
peak force in :mod:`fem_racket.impact.exact.separation`; the batch loop in
:mod:`fem_racket.impact.exact.batch`. Linear, so everything is
solved at V_B0 = 1 m/s: COR and t_c do not depend on the speed except through K_CB, and the
force scales with it.
COR = -v_B(t_c)/V_B0 = J(t_c)/(m_B V_B0) - 1.

A case whose ball does not leave the strings within 20 eq-11 contact times gets NaN.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from fem_racket.contact.linear import (
    DEFAULT_BALL_MASS,
    KCB_SPEED_RANGE,
    PAPER_CLAMPED_COR,
    check_ball_mass,
    kcb_from_speed,
    zeta_from_cor,
)
from fem_racket.impact.exact.batch import Cases, SolveOptions, solve_cases
from fem_racket.impact.reduction import DEFAULT_TOLERANCE, check_tolerance, cutoff_factor
from fem_racket.impact.system import SEPARATION_EVENTS
from fem_racket.validation import InputError, check_choice, check_integer

__all__ = ["DEFAULT_TOLERANCE", "ImpactBatch", "impacts", "modal_impacts"]

#: Cases whose mode values are gathered at once.
CHUNK = 8192


@dataclass(frozen=True, eq=False)
class ImpactBatch:
    """Outcomes of many impacts, one entry per case (arrays of the broadcast shape).

    Attributes
    ----------
    cor : ndarray
        Coefficient of restitution -v_B(t_c)/V_B0 (NaN: no separation).
    contact_time : ndarray
        t_c [s].
    rebound_speed : ndarray
        -v_B(t_c) [m/s].
    peak_force : ndarray or None
        Largest contact force [N], only when asked.
    kcb, zeta : ndarray
        K_CB [N/m] and damping ratio used.
    modes : ndarray of int
        Flexible modes kept per case (besides the residual pseudo-mode).
    tolerance : float or None
        The COR tolerance asked for (None: every mode).
    """

    cor: np.ndarray
    contact_time: np.ndarray
    rebound_speed: np.ndarray
    peak_force: np.ndarray | None
    kcb: np.ndarray
    zeta: np.ndarray
    modes: np.ndarray
    tolerance: float | None


def _check_array(name: str, value: Any, unit: str, low: float, high: float, *, closed_high=True):
    arr = np.asarray(value, dtype=float) if value is not None else None
    if arr is None:
        return None
    bad = ~np.isfinite(arr) | (arr < low) | ((arr > high) if closed_high else (arr >= high))
    if low == 0.0 and name not in ("position", "zeta"):
        bad |= arr <= 0.0
    if np.any(bad):
        v = float(arr.ravel()[int(np.argmax(bad.ravel()))])
        unit_txt = f" {unit}" if unit else ""
        rng = "> 0" if high == math.inf else f"in [{low:g}, {high:g}{']' if closed_high else ')'}"
        raise InputError(f"{name} = {v!r}{unit_txt} is not allowed: must be {rng}")
    return arr


def _laws(speed, kcb, zeta, ball_mass, shape):
    """K_CB, zeta, C_CB and m_B per case (flattened)."""
    v = np.broadcast_to(speed, shape).ravel()
    if kcb is None:
        uniq, inv = np.unique(v, return_inverse=True)
        k = np.array([kcb_from_speed(x) for x in uniq])[inv]
    else:
        k = np.broadcast_to(kcb, shape).ravel().astype(float)
    z = zeta_from_cor(PAPER_CLAMPED_COR) if zeta is None else zeta
    z = np.broadcast_to(z, shape).ravel().astype(float)
    mb = np.broadcast_to(DEFAULT_BALL_MASS if ball_mass is None else ball_mass, shape).ravel()
    mb = mb.astype(float)
    return v, k, z, 2.0 * z * np.sqrt(mb * k), mb


def _run(
    omega, values_at, index, rigid, flex, mass, scale, laws, separation, tolerance, want_peak, shape
):
    """Solve every case in chunks; values_at[index[i]] are case i's mode values."""
    v, k, z, c, mb = laws
    beta = cutoff_factor(tolerance, separation)
    n = v.size
    cor, tc, peak = np.empty(n), np.empty(n), np.empty(n)
    kept = np.empty(n, dtype=int)
    root_s = np.sqrt(scale)
    for start in range(0, n, CHUNK):
        sl = slice(start, start + CHUNK)
        ix = index[sl]
        w = (omega[None, :] if omega.ndim == 1 else omega[ix]) * root_s[sl, None]
        cases = Cases(w, values_at[ix], rigid[ix], flex[ix] / scale[sl], mass[ix], k[sl], c[sl],
                      mb[sl])  # fmt: skip
        cor[sl], tc[sl], peak[sl], kept[sl] = solve_cases(
            cases, SolveOptions(beta, separation, want_peak)
        )
    return ImpactBatch(
        cor=cor.reshape(shape),
        contact_time=tc.reshape(shape),
        rebound_speed=(cor * v).reshape(shape),
        peak_force=(peak * v).reshape(shape) if want_peak else None,
        kcb=k.reshape(shape),
        zeta=z.reshape(shape),
        modes=kept.reshape(shape),
        tolerance=check_tolerance(tolerance),
    )


def _check_common(speed, kcb, zeta, ball_mass, ei_factor, separation, tolerance):
    check_choice("separation", separation, SEPARATION_EVENTS)
    check_tolerance(tolerance)
    low, high = KCB_SPEED_RANGE
    if kcb is None:
        _check_array("speed", speed, "m/s", low, high)
    else:
        _check_array("speed", speed, "m/s", 0.0, math.inf)
        _check_array("kcb", kcb, "N/m", 0.0, math.inf)
    _check_array("zeta", zeta, "", 0.0, 1.0, closed_high=False)
    _check_array("ball_mass", ball_mass, "kg", 0.0, math.inf)
    if ball_mass is not None:  # a plausible ball (grams typed as kg named)
        for m in np.unique(np.asarray(ball_mass, dtype=float)):
            check_ball_mass(m, "ball_mass")
    _check_array("ei_factor", ei_factor, "", 0.0, math.inf)


def modal_impacts(
    omega: Any,
    values: Any,
    rigid: Any,
    *,
    speed: Any = 20.0,
    kcb: Any = None,
    zeta: Any = None,
    ball_mass: Any = None,
    ei_factor: Any = 1.0,
    residual_flexibility: Any = 0.0,
    residual_mass: Any = 0.0,
    separation: str = "displacement",
    tolerance: float | None = DEFAULT_TOLERANCE,
    peak_force: bool = False,
) -> ImpactBatch:
    """Impacts on any structure given by its modes at the impact points.

    Parameters
    ----------
    omega : array_like, shape (m,) or (..., m)
        Flexible angular frequencies, ascending [rad/s] (rigid modes excluded); one row per
        case (broadcast with ``values``) when the cases are on different structures.
    values : array_like, shape (..., m)
        Mass-normalised mode values at each case's impact point [1/sqrt(kg)].
    rigid : array_like, shape (...)
        Sum of the rigid modes' squared values at the impact point [1/kg].
    speed, kcb, zeta, ball_mass, ei_factor : array_like
        V_B0 [m/s], K_CB [N/m] (from the speed when None), damping ratio (from the clamped COR
        0.83 when None), m_B [kg] (0.057 when None), factor on every EI (omega x sqrt).
    residual_flexibility, residual_mass : array_like
        Sums of a^2/omega^2 [s^2/kg] and a^2 [1/kg] over modes not in ``omega``.
    separation : {"displacement", "force"}
    tolerance : float or None
        COR tolerance choosing the modes kept (None or 0: all given).
    peak_force : bool
        Also compute the largest contact force.
    """
    _check_common(speed, kcb, zeta, ball_mass, ei_factor, separation, tolerance)
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
        omega.shape[:-1],
        values.shape[:-1],
        np.shape(rigid),
        np.shape(speed),
        np.shape(kcb),
        np.shape(zeta),
        np.shape(ball_mass),
        np.shape(ei_factor),
        np.shape(residual_flexibility),
        np.shape(residual_mass),
    )
    n = math.prod(shape)
    m = omega.shape[-1]
    vals = np.broadcast_to(values, shape + (m,)).reshape(n, m)
    if omega.ndim > 1:
        omega = np.broadcast_to(omega, shape + (m,)).reshape(n, m)

    def flat(x):
        return np.broadcast_to(np.asarray(x, dtype=float), shape).ravel()

    laws = _laws(speed, kcb, zeta, ball_mass, shape)
    return _run(
        omega,
        vals,
        np.arange(n),
        flat(rigid),
        flat(residual_flexibility),
        flat(residual_mass),
        flat(ei_factor),
        laws,
        separation,
        tolerance,
        peak_force,
        shape,
    )


def impacts(
    frame: Any = None,
    *,
    position: Any,
    speed: Any = 20.0,
    kcb: Any = None,
    zeta: Any = None,
    ball_mass: Any = None,
    ei_factor: Any = 1.0,
    elements: int = 20,
    separation: str = "displacement",
    tolerance: float | None = DEFAULT_TOLERANCE,
    peak_force: bool = False,
    modes: int | None = None,
    offset: Any = 0.0,
) -> ImpactBatch:
    """Impacts of the ball on a free frame: COR, contact time (and peak force) per case.

    Parameters
    ----------
    frame : FrameModel, Frame or FrameMesh, optional
        The racket (the paper's standard one when None). A FrameModel keeps its modes for the
        next call.
    position : array_like
        Impact points x/L from the grip end, in [0, 1].
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
    separation : {"displacement", "force"}
        End of contact: delta back to 0 (the paper's) or the contact force back to 0.
    tolerance : float or None
        COR tolerance (default 1e-6) choosing the modes kept per case; None or 0: every mode.
    peak_force : bool
        Also compute the largest contact force [N].
    modes : int, optional
        Use only the lowest ``modes`` flexible modes (a plain truncation, as
        ``simulate(modes=...)``), then drop those the tolerance does not need. None: the modes
        below the cut-off are computed and the others enter through static solves.
    offset : array_like
        Lateral offsets of the impact points from the long axis [m] (0: on it); off axis the
        frame also twists (:mod:`fem_racket.impact.offaxis`).

    Returns
    -------
    ImpactBatch
    """
    from fem_racket.impact.model_cache import frame_model
    from fem_racket.impact.point import frame_modal_data

    _check_common(speed, kcb, zeta, ball_mass, ei_factor, separation, tolerance)
    pos = _check_array("position", position, "x/L", 0.0, 1.0)
    model = frame_model(frame, elements)
    shape = np.broadcast_shapes(
        pos.shape,
        np.shape(speed),
        np.shape(kcb),
        np.shape(zeta),
        np.shape(ball_mass),
        np.shape(ei_factor),
        np.shape(offset),
    )
    laws = _laws(speed, kcb, zeta, ball_mass, shape)
    scale = np.broadcast_to(np.asarray(ei_factor, dtype=float), shape).ravel()
    if modes is not None:
        check_integer("modes", modes)
    if np.any(np.asarray(offset) != 0.0):
        from fem_racket.impact.offaxis import check_offsets, engine_data

        off = np.broadcast_to(check_offsets(model, pos, offset), shape).ravel()
        _, k, _, _, mb = laws
        data, index = engine_data(
            model,
            np.broadcast_to(pos, shape).ravel(),
            off,
            scale,
            lambda rig: np.sqrt(k * (1.0 / mb + rig)),
            cutoff_factor(tolerance, separation),
            modes,
        )
        return _run(
            data.omega, data.values, index, data.rigid, data.residual_flexibility,
            data.residual_mass, np.ones_like(scale), laws, separation, tolerance, peak_force,
            shape,
        )  # fmt: skip
    uniq, index = np.unique(np.broadcast_to(pos, shape).ravel(), return_inverse=True)
    beta = cutoff_factor(tolerance, separation)
    cutoff = None
    if math.isfinite(beta):
        _, k, _, _, mb = laws
        props = model.props
        d = uniq * props.length - props.cg
        rig = 1.0 / props.mass + d * d / props.inertia
        wc = np.sqrt(k * (1.0 / mb + rig[index]))
        cutoff = float(np.max(beta * wc / np.sqrt(scale)))
    data = frame_modal_data(model, uniq, cutoff, limit=modes)
    return _run(
        data.omega,
        data.values,
        index,
        data.rigid,
        data.residual_flexibility,
        data.residual_mass,
        scale,
        laws,
        separation,
        tolerance,
        peak_force,
        shape,
    )
