"""The swing of sweep cases, and why a swinging racket is the stationary one at the closing speed.

Each case's swing (racket_speed, reference, pivot: :class:`fem_racket.impact.swing.Swing`)
becomes its rigid racket motion in the :class:`~fem_racket.impact.problem_batch.ProblemBatch`
of its chunk (:func:`case_swings`). Under a contact law the solver runs a chunk as one batch of
the general integrator (:func:`fem_racket.impact.batch_solve.law_batch`): each case with its
frame's receptance, its step and modes, so its result does not depend on the chunk (nor on the
backend or a resume).

**A swinging racket.** The free frame is linear, so its motion is the rigid swing (the point x
moving towards the ball at s(x) = v + omega x, :mod:`fem_racket.impact.swing`) plus the
response to the contact force; the rigid motion carries no strain. Let the ball arrive at v_in
and the impact point move at v_r = s(x_i). In the frame's coordinates the deflection is
delta = u_B - w(x_i) with w = -v_r t + w_F (w_F: the response to F) and u_B = v_in t + u_F, so::

    delta(t) = (v_in + v_r) t + u_F(t) - w_F(t)

which is the deflection of the stationary racket struck at the closing speed v_c = v_in + v_r.
Every law's force depends on delta, delta' and its internal state (driven by the same two), so
the force history, the contact time and the end condition are those of the stationary impact at
v_c, whatever the law. The stationary ball leaves at -e_A(v_c) v_c (e_A: the stationary free
racket's COR at v_c, which a nonlinear law makes depend on v_c); the lab's ball velocity is
that plus the swing's -v_r, so the ball's speed away from the racket is::

    v_out = e_A(v_c) v_c + v_r = e_A v_in + (1 + e_A) v_r

(Brody, Cross & Lindsey 2002, ch. 11, exact here for any law), and e_A = (v_out - v_r) / v_c is
the sweep's ``cor``. The tests check v_out against CVODE started from the swing's velocity field
(:func:`fem_racket.impact.law_impact.solve_law_impact` with ``frame_velocity``).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from fem_racket.impact.swing import Swing

__all__ = ["case_swing", "case_swings"]


def case_swing(p: dict[str, Any], length: float) -> Swing:
    """The swing of one case (scalar parameter values) for a racket of ``length`` [m]."""
    return Swing.from_speed(p["racket_speed"], length, reference=p["reference"], pivot=p["pivot"])


def case_swings(p: dict[str, Any], n: int, lengths: np.ndarray) -> np.ndarray | None:
    """The swings (butt speed [m/s], turning rate [rad/s]) of ``n`` cases with parameter values
    ``p`` (swept ones arrays of one value per case, fixed ones numbers) on rackets of
    ``lengths`` [m]; None when no case's racket moves."""
    names = ("racket_speed", "reference", "pivot")
    if np.ndim(p["racket_speed"]) == 0 and p["racket_speed"] == 0.0:
        return None
    cols = [np.broadcast_to(np.asarray(p[k], dtype=object), (n,)) for k in names]
    out = np.empty((n, 2))
    for i, (v, ref, piv) in enumerate(zip(*cols, strict=True)):
        s = case_swing({"racket_speed": v, "reference": ref, "pivot": piv}, float(lengths[i]))
        out[i] = s.velocity, s.omega
    return out
