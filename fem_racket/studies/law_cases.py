"""Sweep cases under a contact law: a chunk of cases, whatever their frames, in one batch.

The cases of a chunk run as one batch of
:func:`fem_racket.impact.general.integrator.solve_general`: each case's frame (mesh, EI
scaling) at its impact point (:func:`fem_racket.impact.general.batches.stack_receptances`),
positions, speeds, ball masses and the law's parameters (:mod:`fem_racket.studies.law_axes`)
as arrays of one value per case, which is what makes the general integrator cheap per impact
(``scripts/bench_kernels.py``). Every case has its own step and modes, so its result does not
depend on the chunk (nor on the backend or a resume).

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

import logging
from collections.abc import Callable
from typing import Any

import numpy as np

from fem_racket.impact.general.batches import stack_receptances
from fem_racket.impact.general.integrator import solve_general
from fem_racket.impact.law_impact import receptance
from fem_racket.impact.swing import Swing, ball_speed_out, closing_speed
from fem_racket.impact.system import NoSeparationError
from fem_racket.studies.grid import LAW_PARAMETERS, SweepSpec

__all__ = ["case_swing", "law_chunk"]

log = logging.getLogger(__name__)


def case_swing(p: dict[str, Any], length: float) -> Swing:
    """The swing of one case (scalar parameter values) for a racket of ``length`` [m]."""
    return Swing.from_speed(p["racket_speed"], length, reference=p["reference"], pivot=p["pivot"])


def law_chunk(spec: SweepSpec, chunk: np.ndarray, model_of: Callable[..., tuple]) -> np.ndarray:
    """Results (cor, t_c, v_out, peak force, NaN for K_CB, v_r, flexible modes) of the cases
    ``chunk``; the modes are those given to the integrator (every mode of the frame's mesh, as
    :func:`fem_racket.simulate` reports under a law).

    ``model_of(spec, elements, ei1, ei_factor) -> (key, FrameModel)`` gives each case's frame
    (cached by the caller). Every case of the chunk, whatever its frame, goes to one call of
    the general integrator at the sweep's COR tolerance; each case is computed on its own (its
    frame, its step), so its result does not depend on the chunk it is in. A case the
    integrator cannot vouch for, or whose ball does not separate within its time limit, gives
    NaN, with a warning.
    """
    cases = [spec.case(int(i)) for i in chunk]
    groups: dict[tuple, list[int]] = {}
    models: dict[tuple, Any] = {}
    for row, p in enumerate(cases):
        key, model = model_of(spec, p["elements"], p["ei1"], p["ei_factor"])
        groups.setdefault(key, []).append(row)
        models[key] = model
    order = np.array([r for rows in groups.values() for r in rows])
    frame = [models[k] for k, rows in groups.items() for _ in rows]  # in the order of ``order``
    parts = []
    for key, rows in groups.items():
        mass = np.array([cases[r]["ball_mass"] for r in rows])
        parts.append(receptance(models[key], [cases[r]["position"] for r in rows], mass))
    rec = stack_receptances(parts)
    length = np.array([m.mesh.length for m in frame])
    swings = [case_swing(cases[r], ln) for r, ln in zip(order, length, strict=True)]
    pos = np.array([cases[r]["position"] for r in order])
    speed = np.array([cases[r]["speed"] for r in order])
    v_r = np.array([sw.speed_at(x * ln) for sw, x, ln in zip(swings, pos, length, strict=True)])
    closing = np.array([closing_speed(v, w) for v, w in zip(speed, v_r, strict=True)])
    named = {k: [cases[r][k] for r in order] for k in LAW_PARAMETERS if k in spec.values}
    law = spec.case_law(named, len(order))
    out = np.full((len(cases), 7), np.nan)
    try:
        o = solve_general(law, rec, closing, tolerance=spec.tolerance, refused="nan")
    except (NoSeparationError, RuntimeError) as exc:
        log.warning("%d cases failed (NaN in the results): %s", len(cases), exc)
        return out
    bad = int(np.sum(~np.isfinite(o.ball_velocity)))
    if bad:
        log.warning(
            "%d cases could not be computed within tolerance %s or did not separate (NaN in "
            "the results)",
            bad,
            spec.tolerance,
        )
    e_a = -o.ball_velocity / closing
    out[order, 0] = e_a
    out[order, 1] = o.contact_time
    out[order, 2] = ball_speed_out(e_a, speed, v_r)
    out[order, 3] = o.peak_force
    out[order, 5] = v_r
    out[order, 6] = [m.modes(None).omega.size for m in frame]
    return out
