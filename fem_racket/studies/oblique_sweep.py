"""Oblique impacts over a grid of incidence angle, incoming spin and friction, and side angle
and side spin (a 3-D ball crossing the face, as ``simulate --side-angle --side-spin``).

Each incidence angle and side angle set one normal speed V cos(side angle) cos(angle), so its
normal impact is computed once and every spin, friction and side spin there marches only the
tangential contact over its force history (milliseconds each). On the free racket the grid is one
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

from fem_racket.impact.batch_solve import LATERAL_EXTRA
from fem_racket.impact.incidence import Incidence
from fem_racket.impact.incidence_idle import (
    CONTACT_FIELDS,
    refuse_idle_contact,
    refuse_idle_incidence,
)
from fem_racket.impact.oblique.solve import oblique_on
from fem_racket.impact.problem import ImpactProblem
from fem_racket.impact.problem_batch import ProblemBatch
from fem_racket.impact.simulate import PROBLEM_OPTIONS
from fem_racket.impact.simulate_oblique import normal_impact
from fem_racket.impact.solvers import make_solver
from fem_racket.validation import InputError, check_positive, show

__all__ = ["OUTPUTS", "SIDE_OUTPUTS", "ObliqueSweep", "oblique_map", "oblique_sweep"]

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
#: Outputs across the face, as ``sweep``'s dataset names them (outgoing side angle [deg], side
#: spin [rpm] and the racket's yaw rate [rad/s]), when the ball crosses the face.
SIDE_OUTPUTS = LATERAL_EXTRA


@dataclass(frozen=True)
class ObliqueSweep:
    """Outputs over the grid, each of shape (angles, spins, frictions), then (side angles, side
    spins) when either side axis is given.

    Attributes
    ----------
    angle_deg, spin_rpm, friction : ndarray
        The axes.
    outputs : dict of str to ndarray
        :data:`OUTPUTS` (floats), :data:`SIDE_OUTPUTS` (floats) when a side axis is given or
        the base incidence crosses the face, and ``contact_regime`` (strings).
    side_angle_deg, side_spin_rpm : ndarray or None
        The side axes [deg] and [rpm]; None unless either is given.
    """

    angle_deg: np.ndarray
    spin_rpm: np.ndarray
    friction: np.ndarray
    outputs: dict[str, np.ndarray]
    side_angle_deg: np.ndarray | None = None
    side_spin_rpm: np.ndarray | None = None

    def __getitem__(self, key: str) -> np.ndarray:
        return self.outputs[key]


def _axis(name: str, values: Any) -> np.ndarray:
    a = np.atleast_1d(np.asarray(values, dtype=float))
    if a.ndim != 1 or a.size == 0:
        raise InputError(f"{name} = {show(values)} is not allowed: must be one or more numbers")
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
    side_angles: Any = None,
    side_spins: Any = None,
    **kwargs: Any,
) -> ObliqueSweep:
    """Oblique impacts at every (angle, spin, friction[, side angle, side spin]).

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
        Ball inertia, radius, eta^2 (and friction, side angle and side spin when their axes
        are None).
    clamped : bool
        A clamped head instead of the free racket.
    side_angles : sequence of float, optional
        Angles of the ball's path from the plane of the long axis and the face normal [deg], in
        (-90, 90), positive toward +y (``simulate --side-angle``); the ``base`` incidence's
        when None. Given (or ``side_spins``), the grid gains the axes (side angles, side
        spins) and the outputs :data:`SIDE_OUTPUTS`.
    side_spins : sequence of float, optional
        Incoming side spins [rpm], positive = rolling toward +y (``simulate --side-spin``);
        the ``base`` incidence's when None.
    **kwargs
        The normal impact's other arguments
        (:func:`fem_racket.impact.simulate_oblique.normal_impact`).
    """
    base = Incidence() if base is None else base
    a = _axis("angles", angles)
    s = _axis("spins", spins)
    f = _axis("frictions", (base.friction,) if frictions is None else frictions)
    b = _axis("side_angles", (base.side_angle,) if side_angles is None else side_angles)
    w = _axis("side_spins", (base.side_spin,) if side_spins is None else side_spins)
    v = check_positive("speed", speed, "m/s")
    sided = side_angles is not None or side_spins is not None
    shape = (a.size, s.size, f.size) + ((b.size, w.size) if sided else ())
    # every case's incidence first: each value is checked before any work
    incidences = [
        dataclasses.replace(base, angle=x, spin=spin, friction=mu, side_angle=y, side_spin=z)
        for x in a for spin in s for mu in f for y in b for z in w
    ]  # fmt: skip
    _refuse_idle(base, {"angle": a, "spin": s, "side_angle": b, "side_spin": w}, frictions, f)
    side = sided or base.lateral
    if clamped:
        got = _clamped(frame, incidences, v, kwargs, side)
    else:
        got = _solved(frame, incidences, v, kwargs, side=side)
    got = {key: values.reshape(shape) for key, values in got.items()}
    sides = (b, w) if sided else (None, None)
    return ObliqueSweep(a, s, f, got, *sides)


def _refuse_idle(base: Incidence, axes: dict, frictions: Any, f: np.ndarray) -> None:
    """Refuse the contact's parameters (the ``frictions`` axis given, at any value; ``base``'s
    away from their defaults) when every case is head-on and spinless (all ``axes`` 0): no
    tangential force acts in any (:func:`~fem_racket.impact.incidence_idle.refuse_idle_contact`,
    as simulate and sweep refuse them)."""
    default = Incidence()
    idle = {n: getattr(base, n) for n in CONTACT_FIELDS if getattr(base, n) != getattr(default, n)}
    if frictions is not None:  # the axis replaces the base's friction
        idle.pop("friction", None)
        idle["frictions"] = f.tolist()
    refuse_idle_contact({**axes, **idle})


def _clamped(
    frame: Any, incidences: list, speed: float, kwargs: dict, side: bool
) -> dict[str, np.ndarray]:
    """The oblique outcomes of ``incidences`` on a clamped head, one normal impact (eqs 1-3)
    per normal speed (angle and side angle)."""
    normals: dict[tuple[float, float], Any] = {}
    rows = []
    for inc in incidences:
        key = (inc.angle, inc.side_angle)
        if key not in normals:
            normals[key] = normal_impact(frame, inc.components(speed)[0], clamped=True, **kwargs)
        rows.append(oblique_on(normals[key], inc, speed).summary())
    names = OUTPUTS + (SIDE_OUTPUTS if side else ())
    got = {k: np.array([r[k] for r in rows], dtype=float) for k in names}
    got["contact_regime"] = np.array([r["contact_regime"] for r in rows], dtype=object)
    return got


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
        The ball's angle, spin, side angle and side spin and the contact's parameters (as
        ``simulate --angle --spin --side-angle --side-spin``).
    speed : float
        Incident ball speed [m/s].
    **kwargs
        The normal impact's other arguments.

    Returns
    -------
    dict of str to ndarray
        ``position_x_over_l``, :data:`OUTPUTS` and, when the incidence crosses the face (a
        side angle or side spin), :data:`SIDE_OUTPUTS` (floats), ``contact_regime`` (strings),
        each of shape (positions,).
    """
    if not isinstance(incidence, Incidence):
        raise InputError(f"incidence = {incidence!r} is not allowed: must be an Incidence")
    refuse_idle_incidence(incidence)  # its contact's parameters head-on and spinless
    x = _axis("positions", positions)
    v = check_positive("speed", speed, "m/s")
    if "position" in kwargs:
        raise InputError("position is not allowed with positions: give the impact points once")
    got = _solved(frame, [incidence] * x.size, v, kwargs, x, side=incidence.lateral)
    return {"position_x_over_l": x, **got}


def _solved(
    frame: Any,
    incidences: list,
    speed: float,
    kwargs: dict,
    positions: Any = None,
    *,
    side: bool = False,
) -> dict[str, np.ndarray]:
    """The oblique outcomes of ``incidences`` at ``speed`` (and ``positions``) on the free
    racket, by the solver of ``kwargs`` (``simulate``'s options) over one ProblemBatch;
    :data:`SIDE_OUTPUTS` too with ``side``."""
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
    got.update({k: np.asarray(out.extra[k], dtype=float) for k in SIDE_OUTPUTS if side})
    got["contact_regime"] = np.asarray(out.extra["contact_regime"], dtype=object)
    return got
