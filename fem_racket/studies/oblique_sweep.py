"""Oblique impacts over a grid of incidence angle, incoming spin and friction.

Each incidence angle sets one normal speed V cos(angle), so its normal impact is computed once
and every spin and friction at that angle marches only the tangential contact over its force
history (milliseconds each). On the free racket the grid is one
:class:`~fem_racket.impact.problem_batch.ProblemBatch` that the solver answers, as
``fem-racket sweep --angle ... --spin ... --friction ...`` does
(:func:`fem_racket.impact.batch_solve.each_batch` shares the normal impacts); a clamped head
(eqs 1-3 in closed form, not a solver's structure) by
:func:`fem_racket.impact.simulate_oblique.normal_impact`.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass
from typing import Any

import numpy as np

from fem_racket.impact.incidence import Incidence
from fem_racket.impact.oblique.solve import oblique_on
from fem_racket.impact.problem import ImpactProblem
from fem_racket.impact.problem_batch import ProblemBatch
from fem_racket.impact.simulate import PROBLEM_OPTIONS
from fem_racket.impact.simulate_oblique import normal_impact
from fem_racket.impact.solvers import make_solver
from fem_racket.validation import InputError, check_positive

__all__ = ["OUTPUTS", "ObliqueSweep", "oblique_map", "oblique_sweep"]

#: Scalar outputs of each case (keys of
#: :meth:`fem_racket.impact.oblique.solve.ObliqueResult.summary`).
OUTPUTS = (
    "ball_speed_out_m_s",
    "angle_out_deg",
    "spin_out_rpm",
    "tangential_cor",
    "cor",
    "contact_time_s",
)


@dataclass(frozen=True)
class ObliqueSweep:
    """Outputs over the grid, each of shape (angles, spins, frictions).

    Attributes
    ----------
    angle_deg, spin_rpm, friction : ndarray
        The axes.
    outputs : dict of str to ndarray
        :data:`OUTPUTS` (floats) and ``contact_regime`` (strings).
    """

    angle_deg: np.ndarray
    spin_rpm: np.ndarray
    friction: np.ndarray
    outputs: dict[str, np.ndarray]

    def __getitem__(self, key: str) -> np.ndarray:
        return self.outputs[key]


def _axis(name: str, values: Any) -> np.ndarray:
    a = np.atleast_1d(np.asarray(values, dtype=float))
    if a.ndim != 1 or a.size == 0:
        raise InputError(f"{name} = {values!r} is not allowed: must be one or more numbers")
    return a


def oblique_sweep(
    frame: Any = None,
    *,
    angles: Any,
    spins: Any = (0.0,),
    frictions: Any = None,
    speed: float = 20.0,
    base: Incidence | None = None,
    clamped: bool = False,
    **kwargs: Any,
) -> ObliqueSweep:
    """Oblique impacts at every (angle, spin, friction).

    Parameters
    ----------
    frame : optional
        The racket (as :func:`fem_racket.impact.simulate.simulate`); None with ``clamped``.
    angles : sequence of float
        Incidence angles from the face normal [deg].
    spins : sequence of float
        Incoming spins [rpm], positive = topspin.
    frictions : sequence of float, optional
        Friction coefficients; the ``base`` incidence's when None.
    speed : float
        Incident ball speed [m/s].
    base : Incidence, optional
        Ball inertia, radius, eta^2 (and friction when ``frictions`` is None).
    clamped : bool
        A clamped head instead of the free racket.
    **kwargs
        The normal impact's other arguments
        (:func:`fem_racket.impact.simulate_oblique.normal_impact`).
    """
    base = Incidence() if base is None else base
    a = _axis("angles", angles)
    s = _axis("spins", spins)
    f = _axis("frictions", (base.friction,) if frictions is None else frictions)
    v = check_positive("speed", speed, "m/s")
    shape = (a.size, s.size, f.size)
    out = {k: np.empty(shape) for k in OUTPUTS}
    regime = np.empty(shape, dtype=object)
    cases = [dataclasses.replace(base, angle=x) for x in a]  # checks every angle first
    if not clamped:
        incidences = [
            dataclasses.replace(inc, spin=spin, friction=mu) for inc in cases for spin in s
            for mu in f
        ]  # fmt: skip
        got = _solved(frame, incidences, v, kwargs)
        for key in (*OUTPUTS, "contact_regime"):
            got[key] = got[key].reshape(shape)
        return ObliqueSweep(a, s, f, got)
    for i, inc in enumerate(cases):
        normal = normal_impact(frame, inc.components(v)[0], clamped=clamped, **kwargs)
        for j, spin in enumerate(s):
            for k, mu in enumerate(f):
                res = oblique_on(normal, dataclasses.replace(inc, spin=spin, friction=mu), v)
                summary = res.summary()
                for key in OUTPUTS:
                    out[key][i, j, k] = summary[key]
                regime[i, j, k] = summary["contact_regime"]
    return ObliqueSweep(a, s, f, {**out, "contact_regime": regime})


def oblique_map(
    frame: Any = None,
    *,
    positions: Any,
    incidence: Incidence,
    speed: float = 20.0,
    **kwargs: Any,
) -> dict[str, np.ndarray]:
    """The oblique outcome over impact points along the face of the free racket.

    Parameters
    ----------
    frame : optional
        The racket (as :func:`fem_racket.impact.simulate.simulate`).
    positions : sequence of float
        Impact points x/L.
    incidence : Incidence
        The ball's angle, spin and the contact's parameters.
    speed : float
        Incident ball speed [m/s].
    **kwargs
        The normal impact's other arguments.

    Returns
    -------
    dict of str to ndarray
        ``position_x_over_l`` and :data:`OUTPUTS` (floats), ``contact_regime`` (strings), each
        of shape (positions,).
    """
    x = _axis("positions", positions)
    v = check_positive("speed", speed, "m/s")
    if "position" in kwargs:
        raise InputError("position is not allowed with positions: give the impact points once")
    return {"position_x_over_l": x, **_solved(frame, [incidence] * x.size, v, kwargs, x)}


def _solved(
    frame: Any, incidences: list, speed: float, kwargs: dict, positions: Any = None
) -> dict[str, np.ndarray]:
    """The oblique outcomes of ``incidences`` at ``speed`` (and ``positions``) on the free
    racket, by the solver of ``kwargs`` (``simulate``'s options) over one ProblemBatch."""
    problem_kw = {k: w for k, w in kwargs.items() if k in PROBLEM_OPTIONS}
    solver_kw = {k: w for k, w in kwargs.items() if k not in PROBLEM_OPTIONS}
    problem = ImpactProblem.build(frame, speed=speed, **problem_kw)
    per_case: dict[str, Any] = {"incidence": incidences}
    if positions is not None:
        per_case["position"] = positions
    batch = ProblemBatch.of(problem, **per_case)
    out = make_solver(solver_kw.pop("solver", "auto"), **solver_kw).solve_many(batch)
    got = {k: np.asarray(out.extra[k], dtype=float) for k in OUTPUTS if k in out.extra}
    got.update(cor=out.cor, contact_time_s=out.contact_time)
    got["contact_regime"] = np.asarray(out.extra["contact_regime"], dtype=object)
    return got
