"""The hand-held racket by the integrators, sampled: cvode / bdf during contact, then the free
vibration of frame and hand, and the shock measures from the samples.

During contact the integrators of :func:`fem_racket.impact.held.grip.simulate_held` run; after
separation the frame and hand vibrate freely (ball gone), a linear system y' = A_s y of the held
structure, y = [x, x'], A_s = [[0, I], [-M^-1 K, -M^-1 C]], stepped from the integrator's state
at t_c by its propagator exp(A_s dt) (exact for a linear system). The shock measures do not
depend on the output step (:mod:`fem_racket.impact.held.flow`): during contact the grip force's
extrema are root-found by the integrator and the energy int F_v^2 dt is the Gramians' from its
states (:func:`~fem_racket.impact.held.grip.simulate_held`); after it both come from the exact
flow between the samples.
"""

from __future__ import annotations

from typing import Any

import numpy as np

from fem_racket.frame.hand import Hand, held_frame
from fem_racket.frame.model import FrameModel
from fem_racket.impact.held.flow import flow_energy, flow_extrema
from fem_racket.impact.held.grip import HeldImpact, simulate_held
from fem_racket.impact.problem import ImpactProblem
from fem_racket.validation import InputError, show

__all__ = ["history_columns", "sampled_impact", "shock_grid"]

#: Grid points per contact time on which the free vibration's extrema are sought (one per
#: ~2.6 us on the standard racket; a grid 4 times finer moved its peak by 2e-12).
SCAN = 1024


def shock_grid(step: float, tc: float, window: float) -> tuple[np.ndarray, np.ndarray]:
    """Output times during contact (k step, then t_c) and after it (t_c + k step, then T)."""
    on = np.arange(0.0, tc, step)
    on = np.append(on[on < tc * (1 - 1e-12)], tc)
    off = tc + np.arange(step, window - tc, step)
    return on, np.append(off[off < window * (1 - 1e-12)], window)


def history_columns(t, force, grip, rigid) -> dict[str, np.ndarray]:
    return {
        "time [s]": t,
        "contact force [N]": force,
        "grip force [N]": grip,
        "grip force rigid part [N]": rigid,
        "grip force vibration part [N]": grip - rigid,
    }


def _free_grip(model: FrameModel, hand: Hand, state: np.ndarray, s: np.ndarray, scan: float):
    """The freely vibrating held racket from the state at t_c (module docstring): its grip
    force [N] at times ``s`` after t_c (uniform steps but the last), its energy [N^2 s] and its
    values on a grid of ``scan`` [s] and at the extrema between (:func:`flow_extrema`) [N]."""
    from scipy.linalg import expm

    held = held_frame(model.fe, hand)
    n = held.K.shape[0]
    minv = np.linalg.inv(held.M)
    A = np.zeros((2 * n, 2 * n))
    A[:n, n:] = np.eye(n)
    A[n:, :n], A[n:, n:] = -minv @ held.K, -minv @ held.C
    row = held.grip[held.n_frame]
    out_row = -np.concatenate([hand.stiffness * row, hand.damping * row])
    y = np.empty((s.size, 2 * n))
    y[0] = state
    if s.size > 2:
        step = expm(A * (s[1] - s[0]))
        for k in range(1, s.size - 1):
            y[k] = step @ y[k - 1]
    if s.size > 1:
        y[-1] = expm(A * (s[-1] - s[-2])) @ y[-2]
    values = flow_extrema(A, out_row, state, float(s[-1]), scan)
    return y @ out_row, flow_energy(A, out_row, s, y), values


def sampled_impact(problem: ImpactProblem, solver: str, window: float, tolerances: Any):
    """The integrators' path: (e_A, t_c, peak F, peak F_h, RMS), histories, what it used; the
    shock measures independent of the output step (module docstring). ``tolerances``: its
    ``output_step``, ``rtol`` and ``atol``."""
    held = problem.structure
    model, hand = held.model, held.hand
    step, rtol, atol = tolerances.output_step, tolerances.rtol, tolerances.atol
    r: HeldImpact = simulate_held(problem, solver=solver, output_step=step, rtol=rtol, atol=atol)
    tc = r.contact_time
    if not window > tc:
        raise InputError(
            f"window = {show(window)} s is not allowed: must exceed the contact time ({tc:.4g} s)"
        )
    _, off = shock_grid(step, tc, window)
    s = np.append(0.0, off - tc)  # from t_c
    free, energy, values = _free_grip(model, hand, r.state, s, tc / SCAN)
    energy += r.grip_vibration_energy
    free = free[1:]
    peak = max(r.peak_grip_force, float(np.max(np.abs(values))))
    out = (r.cor, tc, r.peak_force, peak, float(np.sqrt(energy / window)))
    zeros = np.zeros_like(off)
    hist = history_columns(
        np.concatenate([r.t, off]),
        np.concatenate([r.contact_force, zeros]),
        np.concatenate([r.grip_force, free]),
        np.concatenate([r.grip_force_rigid, zeros]),
    )
    return out, hist, {"modes": model.fe.ndof + 2, "rtol": rtol, "atol": atol}
