"""One impact with any contact law: receptance, initial racket motion, the run.

Builds the impact-point :class:`~fem_racket.impact.general.receptance.Receptance` of a frame, turns
an initial racket velocity field into modal velocities, runs the general integrator (or CVODE) and
rebuilds the ball and frame histories at the output times
(:mod:`fem_racket.impact.general.histories`: every coordinate driven exactly by the integrator's
piecewise-cubic force).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from fem_racket.contact.law import ContactLaw
from fem_racket.frame.model import FrameModel
from fem_racket.impact.general.histories import law_histories, memory_at, ode_state_at
from fem_racket.impact.general.integrator import GeneralOutcome, solve_general
from fem_racket.impact.general.receptance import Receptance
from fem_racket.impact.ode.law_cvode import solve_law_cvode
from fem_racket.impact.offaxis import RIGID_OFFAXIS, combined_modes, combined_point_vector
from fem_racket.impact.reduction import DEFAULT_TOLERANCE
from fem_racket.impact.system import output_times
from fem_racket.validation import AccuracyError, InputError, check_choice, check_finite, show

__all__ = [
    "LAW_SOLVERS",
    "LawOptions",
    "LawRun",
    "modal_velocity",
    "receptance",
    "solve_law_impact",
]

#: Integrators of an impact under any contact law.
LAW_SOLVERS = ("general", "cvode")


@dataclass(frozen=True)
class LawOptions:
    """How :func:`solve_law_impact` solves an impact.

    Attributes
    ----------
    solver : {"general", "cvode"}
        :func:`~fem_racket.impact.general.integrator.solve_general` (all modes available,
        truncated and stepped for the COR ``tolerance`` unless ``steps``/``beta`` are given) or
        :func:`~fem_racket.impact.ode.law_cvode.solve_law_cvode` (all modes, ``rtol``/``atol``).
    output_step : float or None
        Spacing of the output times [s]; None: only t = 0 and t_c.
    t_max : float or None
        Give up if the ball has not separated by then [s].
    rtol, atol : float
        CVODE's tolerances.
    tolerance : float or None
        The general integrator's COR tolerance [-] (None: every mode).
    steps : int or None
        The general integrator's steps per estimated contact time (no halving).
    beta : float or None
        The general integrator's mode cut-off factor.
    """

    solver: str = "general"
    output_step: float | None = 1e-5
    t_max: float | None = None
    rtol: float = 1e-10
    atol: float = 1e-12
    tolerance: float | None = DEFAULT_TOLERANCE
    steps: int | None = None
    beta: float | None = None


def receptance(
    model: FrameModel, positions: Any, ball_mass: Any, modes: int | None = None, offset: float = 0.0
) -> Receptance:
    """The frame's modal shapes at impact points ``positions`` (x/L), one case each; off axis
    (``offset`` [m]) bending and torsion, three rigid modes (:mod:`fem_racket.impact.offaxis`)."""
    pos = np.atleast_1d(np.asarray(positions, dtype=float))
    mb = np.broadcast_to(np.asarray(ball_mass, dtype=float), pos.shape).copy()
    if offset != 0.0:  # point by point, as below
        cm = combined_modes(model, modes)
        L = model.mesh.length
        a = np.array([cm.all_shapes.T @ combined_point_vector(model, p * L, offset) for p in pos])
        return Receptance(cm.omega, a[:, RIGID_OFFAXIS:], a[:, :RIGID_OFFAXIS], mb)
    fm = model.modes(modes)
    # the four shape functions of each point, added in order: a point's values do not depend
    # on the others asked with it
    a = model.fe.field_values(pos * model.mesh.length, fm.all_shapes)
    return Receptance(fm.omega, a[:, 2:], a[:, :2], mb)


def modal_velocity(
    model: FrameModel, frame_velocity: Any, modes: int | None = None, offset: float = 0.0
) -> np.ndarray:
    """Initial modal velocities [sqrt(kg) m/s] of the frame, rigid modes first.

    Parameters
    ----------
    frame_velocity : (v, omega) or array
        ``(v, omega)``: the racket moving rigidly, its centre of gravity at v [m/s] and turning at
        omega [rad/s] about it (positive v along the ball's travel, positive omega turning the tip
        that way); or the modal velocities themselves, 2 rigid + the flexible modes kept.
        Off axis (``offset`` != 0) only ``(v, omega)``: the modes are bending and torsion.
    """
    fm = model.modes(modes)
    n = 2 + fm.omega.size
    arr = np.asarray(frame_velocity, dtype=float)
    if arr.shape == (2,):
        v = check_finite("frame_velocity v", arr[0], "m/s")
        w = check_finite("frame_velocity omega", arr[1], "rad/s")
        qd = model.fe.rigid_motion(v, w, about=fm.props.cg)
        if offset != 0.0:  # the rigid field lies in the bending rows of the combined modes
            shapes = combined_modes(model, modes).all_shapes[: model.fe.ndof]
            return shapes.T @ (model.fe.M @ qd)
        return fm.all_shapes.T @ (model.fe.M @ qd)
    if offset != 0.0:
        raise InputError(
            f"frame_velocity of shape {arr.shape} is not allowed with offset = {show(offset)} m: "
            "must be (v [m/s], omega [rad/s])"
        )
    if arr.shape != (n,) or not np.all(np.isfinite(arr)):
        raise InputError(
            f"frame_velocity of shape {arr.shape} is not allowed: must be (v [m/s], omega "
            f"[rad/s]) or {n} finite modal velocities (2 rigid + {n - 2} flexible)"
        )
    return arr


def run_law(
    law: ContactLaw,
    model: FrameModel,
    position: float,
    ball_mass: float,
    speed: float,
    *,
    frame_velocity: np.ndarray | None,
    options: LawOptions,
    offset: float = 0.0,
) -> GeneralOutcome:
    """:func:`solve_general` for one impact on ``model`` (all its modes available; the general
    integrator's ``options``)."""
    rec = receptance(model, position, ball_mass, None, offset)
    fv = None if frame_velocity is None else frame_velocity[None, :]
    o = options
    try:
        return solve_general(
            law, rec, speed, frame_velocity=fv, tolerance=o.tolerance, steps=o.steps, beta=o.beta,
            t_max=o.t_max,
        )  # fmt: skip
    except RuntimeError as err:  # a step's Newton iteration diverged: one line naming the case
        raise AccuracyError(
            f"law {law.label()} at {speed:g} m/s, x/L = {position:g}: the general integrator "
            f"failed ({err}); solver 'cvode' may succeed"
        ) from None


@dataclass(frozen=True, eq=False)
class LawRun:
    """Histories of one impact under a contact law, in modal frame coordinates.

    Attributes
    ----------
    t : ndarray, shape (nt,)
        Output times [s], the last the contact time.
    ball_displacement, ball_velocity : ndarray, shape (nt,)
        u_B [m], v_B [m/s].
    modal_displacement, modal_velocity : ndarray, shape (nt, 2 + n)
        Frame coordinates (rigid modes first) and rates.
    state : ndarray, shape (nt,)
        The law's internal state [m] (zeros for a law without one).
    peak_force : float
        Largest contact force [N].
    """

    t: np.ndarray
    ball_displacement: np.ndarray
    ball_velocity: np.ndarray
    modal_displacement: np.ndarray
    modal_velocity: np.ndarray
    state: np.ndarray
    peak_force: float


def solve_law_impact(
    law: ContactLaw,
    model: FrameModel,
    position: float,
    ball_mass: float,
    speed: float,
    *,
    frame_velocity: Any = None,
    offset: float = 0.0,
    options: LawOptions | None = None,
) -> LawRun:
    """One impact of the ball at ``position`` (x/L) and ``speed`` [m/s] under ``law``.

    ``frame_velocity``: see :func:`modal_velocity`. ``offset`` [m]: off the long axis the frame
    also twists (:mod:`fem_racket.impact.offaxis`). ``options``: the solver and its settings
    (:class:`LawOptions`; its defaults when None).
    """
    o = LawOptions() if options is None else options
    solver = o.solver
    check_choice("solver", solver, LAW_SOLVERS)
    x_i = position * model.mesh.length
    if offset != 0.0:
        cm = combined_modes(model, None)
        all_omega, a = cm.all_omega, cm.all_shapes.T @ combined_point_vector(model, x_i, offset)
    else:
        fm = model.modes(None)
        all_omega, a = fm.all_omega, fm.all_shapes.T @ model.fe.point_vector(x_i)
    fv = None if frame_velocity is None else modal_velocity(model, frame_velocity, None, offset)
    if solver == "cvode":
        tr = solve_law_cvode(
            law,
            all_omega,
            a,
            ball_mass,
            speed,
            frame_velocity=fv,
            rtol=o.rtol,
            atol=o.atol,
            t_max=o.t_max,
            output_step=o.output_step,
        )
        n = tr.n
        t, y = tr.t, tr.y
        d = y[:, :n] @ np.concatenate([[1.0], -a])
        v = y[:, n : 2 * n] @ np.concatenate([[1.0], -a])
        z = y[:, -1] if law.state == "ode" else np.maximum.accumulate(d)
        peak = float(np.max(np.concatenate([law.force(d, v, z), tr.peaks])))  # grid, maxima
        if o.output_step is None:
            t, y, z = t[[0, -1]], y[[0, -1]], z[[0, -1]]
        return LawRun(t, y[:, 0], y[:, n], y[:, 1:n], y[:, n + 1 : 2 * n], z, peak)
    out = run_law(
        law, model, position, ball_mass, speed, frame_velocity=fv, options=o, offset=offset
    )
    tc = float(out.contact_time[0])
    t = output_times(o.output_step, tc)
    x, v = law_histories(out, all_omega, a, ball_mass, speed, fv, t)
    z = np.zeros_like(t)
    if law.state == "memory":
        z = memory_at(out, t, x[:, 0] - x[:, 1:] @ a, v[:, 0] - v[:, 1:] @ a)
    elif law.state == "ode":
        z = ode_state_at(law, out, t)
    return LawRun(t, x[:, 0], v[:, 0], x[:, 1:], v[:, 1:], z, float(out.peak_force[0]))
