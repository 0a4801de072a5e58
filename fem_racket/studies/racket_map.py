"""Power maps: the apparent COR e_A and the ball speed v_out along the frame, with sweet spots.

For a racket, an incoming ball speed v_in and a swing (:class:`fem_racket.impact.swing.Swing`),
every point x of a position grid is struck at the closing speed v_in + v_r(x) (v_r the speed of
that point towards the ball), which sets K_CB through the speed law unless K_CB is given; the
stationary free racket's COR there is e_A(x), and the ball leaves at
v_out(x) = e_A v_in + (1 + e_A) v_r (Brody, Cross & Lindsey 2002, ch. 11; exact for the linear
law, :mod:`fem_racket.impact.swing`). Sweet spots: :mod:`fem_racket.studies.sweetspots`.

:func:`apparent_cor_along` is the one place the impacts are solved: the whole grid as one
:class:`~fem_racket.impact.problem_batch.ProblemBatch` that the solver answers (the exact
solver's batched engine, frame modes computed once; under a contact law other than the paper's,
the general solver's one integrator call, every mode available, those far above the contact
frequency as one residual mode). The identity for v_out holds for any law: the impact
of a swinging free racket is the stationary one at the closing speed
(:mod:`fem_racket.studies.law_cases` derives it), e_A depending on that speed.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache
from typing import Any

import numpy as np

from fem_racket.contact.linear import Ball, kcb_from_speed
from fem_racket.contact.presets import check_linear_options, get_law
from fem_racket.frame.mesh import FrameMesh
from fem_racket.frame.model import FrameModel
from fem_racket.frame.segments import Frame
from fem_racket.impact.closing import closing_speed
from fem_racket.impact.problem import ImpactProblem
from fem_racket.impact.problem_batch import ProblemBatch
from fem_racket.impact.solvers import make_solver
from fem_racket.impact.swing import Swing, ball_speed_out
from fem_racket.impact.system import SEPARATION_EVENTS
from fem_racket.studies.map_options import (
    DEFAULT_POSITIONS,
    DEFAULT_POWER_FRACTION,
    MapImpact,
    MapSetup,
    map_grid,
    map_model,
)
from fem_racket.studies.options import take
from fem_racket.studies.sweetspots import (
    SweetSpots,
    centre_of_percussion,
    curve_maximum,
    mode_node_positions,
    power_region,
)
from fem_racket.studies.swing_points import check_swing_at
from fem_racket.studies.views import MapView
from fem_racket.validation import (
    InputError,
    check_choice,
    check_integer,
    check_positive,
    check_range,
    show,
    work_begins,
)

__all__ = [
    "DEFAULT_POSITIONS",
    "DEFAULT_POWER_FRACTION",
    "RacketMap",
    "apparent_cor_along",
    "racket_map",
]


@lru_cache(maxsize=16)
def _solver(name: str, **options: Any) -> Any:
    """The map's solver, made once per options (a map asks it again for each refined point);
    it refuses an option it cannot use (``modes`` for ``general``)."""
    return make_solver(name, **options)


def _prepared(
    model: FrameModel, positions: Any, speeds: Any, options: dict[str, Any]
) -> tuple[Any, ProblemBatch, tuple[int, ...]]:
    """The solver, the batch of the impacts and the grid's shape (:func:`apparent_cor_along`);
    an option the solver or the law cannot use, given in ``options``, refused in one line."""
    o = take(options, "an option of apparent_cor_along", MapImpact)[0]
    kcb, kcb_factor, law = o.kcb, o.kcb_factor, o.law
    check_choice("separation", o.separation, SEPARATION_EVENTS)
    x = np.atleast_1d(np.asarray(positions, dtype=float))
    v = np.broadcast_to(np.asarray(speeds, dtype=float), x.shape)
    solver = {k: options[k] for k in ("tolerance", "modes") if k in options}
    if law is not None and solver.get("modes", 0) is None:  # None: every mode, as the general
        del solver["modes"]  # integrator keeps them anyway
    solver.setdefault("tolerance", o.tolerance)
    if law is not None:  # the linear law's options, if given, refused by the batch
        if "kcb_factor" in options:  # given, at any value
            raise InputError(
                f"kcb_factor = {show(kcb_factor)} is not allowed with contact law "
                f"{show(law.name)}: it scales the linear law's K_CB only",
                parameter="kcb_factor",
                value=kcb_factor,
            )
        check_linear_options(law, kcb=options.get("kcb"), zeta=options.get("zeta"))
        linear = {k: options[k] for k in ("separation",) if k in options}
        if linear:  # refused as simulate refuses them (the problem's check of its law)
            ImpactProblem.build(model, position=float(x.flat[0]), law=law, **linear)
        batch = ProblemBatch((model,), x.ravel(), v.ravel(), ball_mass=o.ball_mass, law=law)
        return _solver("general", **solver), batch, x.shape
    if kcb_factor != 1.0:
        check_positive("kcb_factor", kcb_factor, "")
        if kcb is None:
            kcb = np.array([kcb_from_speed(s) for s in v.ravel()]).reshape(v.shape)
        kcb = kcb * kcb_factor
    batch = ProblemBatch(
        (model,),
        x.ravel(),
        v.ravel(),
        ball_mass=o.ball_mass,
        kcb=None if kcb is None else np.broadcast_to(kcb, x.shape).ravel(),
        zeta=o.zeta,
        separation=o.separation,
    )
    solver.setdefault("modes", o.modes)
    return _solver("exact", **solver), batch, x.shape


def apparent_cor_along(
    model: FrameModel, positions: np.ndarray, speeds: np.ndarray, **options: Any
) -> np.ndarray:
    """e_A of the stationary free frame struck at each position (x/L) at each closing speed.

    Parameters
    ----------
    model : FrameModel
    positions : array of float
        Impact points x/L.
    speeds : array of float
        Closing speed v_in + v_r at each point [m/s] (sets K_CB unless ``kcb`` is given).
    **options
        The fields of :class:`~fem_racket.studies.map_options.MapImpact`: ``ball_mass``,
        ``kcb``, ``zeta``, ``separation``, ``modes``, ``tolerance``, ``law`` (a ContactLaw:
        the general integrator and the law's own end condition; ``kcb``, ``zeta``,
        ``separation``, ``modes`` and ``kcb_factor`` are then refused) and ``kcb_factor`` (on
        the linear law's K_CB, or the paper's K_CB of each closing speed: a stiffer or softer
        string bed).

    Returns
    -------
    ndarray
        e_A = -v_B(t_c) / V_B0 at each point (NaN where the ball does not separate).
    """
    solver, batch, shape = _prepared(model, positions, speeds, options)
    return solver.solve_many(batch).cor.reshape(shape)


@dataclass(frozen=True, eq=False, repr=False)
class RacketMap(MapView):
    """e_A and v_out along one racket, with its sweet spots.

    Attributes
    ----------
    name : str
        Label of the racket.
    positions : ndarray
        Impact points x/L.
    apparent_cor : ndarray
        e_A at each point (at its closing speed).
    ball_speed_out : ndarray
        v_out [m/s].
    racket_speed : ndarray
        v_r, the point's speed towards the ball before impact [m/s].
    speed : float
        Incoming ball speed v_in [m/s].
    swing : Swing
    spots : SweetSpots
    length : float
        Racket length L [m].
    law : ContactLaw or None
        The contact law as the map's ball meets it (a LinearContact referred to that ball:
        :meth:`~fem_racket.contact.linear.LinearContact.for_ball`); None: the paper's.
    """

    name: str
    positions: np.ndarray
    apparent_cor: np.ndarray
    ball_speed_out: np.ndarray
    racket_speed: np.ndarray
    speed: float
    swing: Swing
    spots: SweetSpots
    length: float
    law: Any = None

    def law_summary(self) -> dict[str, Any]:
        """The contact law's name and parameters, units in the keys, as the map's ball meets
        it (a LinearContact's zeta that ball's; ``linear``: the paper's K_CB from the closing
        speed, or as given, and zeta)."""
        return {"law": "linear"} if self.law is None else self.law.describe()

    def summary(self, curves: bool = True) -> dict[str, Any]:
        """JSON-ready: sweet spots (x/L) and, with ``curves``, the curves; units in the keys."""
        out: dict[str, Any] = {"racket": self.name, "length_m": self.length}
        out.update(self.spots.summary())
        out.update(self.swing.summary())
        out["contact"] = self.law_summary()
        if curves:
            out["curves"] = {
                "position_x_over_l": self.positions.tolist(),
                "apparent_cor": self.apparent_cor.tolist(),
                "ball_speed_out_m_s": self.ball_speed_out.tolist(),
                "racket_speed_at_impact_m_s": self.racket_speed.tolist(),
            }
        return out


def racket_map(frame: Frame | FrameMesh | FrameModel | None = None, **options: Any) -> RacketMap:
    """e_A and v_out along a racket, and its sweet spots.

    Parameters
    ----------
    frame : Frame, FrameMesh or FrameModel, optional
        The racket (the paper's standard one when None).
    **options
        The fields of :class:`~fem_racket.studies.map_options.MapSetup` (its
        :class:`~fem_racket.studies.map_options.MapPlay`'s among them) and
        :class:`~fem_racket.studies.map_options.MapImpact` (checked with a "did you mean"):

    name : str
        Its label in tables and plots.
    speed : float
        Incoming ball speed v_in [m/s].
    racket_speed, reference, pivot
        The swing: speed [m/s] of the point ``reference`` (x/L) towards the ball, turning
        about ``pivot`` [m from the butt] or translating when None
        (:meth:`Swing.from_speed`). ``pivot`` also sets the centre of percussion.
    positions : array of float, optional
        Impact points x/L (increasing, at least 3); :data:`DEFAULT_POSITIONS` when None.
    ball_mass, kcb, zeta, separation, modes, elements, tolerance
        As for :func:`fem_racket.simulate`.
    power_fraction : float
        The power region is where v_out >= power_fraction x its maximum.
    law : ContactLaw or str, optional
        The ball/string law (a law or a name of :data:`fem_racket.contact.presets.LAW_NAMES`);
        the paper's linear law (K_CB, zeta) when None or ``"linear"``. Another law runs the
        general integrator and takes neither ``kcb`` nor ``zeta``.
    kcb_factor : float
        Factor on the linear law's K_CB (:func:`apparent_cor_along`).

    Returns
    -------
    RacketMap
    """
    setup, o, _ = take(options, "an option of racket_map", MapSetup, MapImpact)
    play, pivot, power_fraction = setup.play, setup.play.pivot, setup.power_fraction
    speed = check_positive("speed", play.speed, "m/s")
    law = get_law(o.law) if isinstance(o.law, str) else o.law
    ball_mass = Ball(o.ball_mass).mass
    check_range("power_fraction", power_fraction, 0.0, 1.0, include_low=False)
    if o.modes is not None:
        check_integer("modes", o.modes)
    x = map_grid(play.positions)
    model = map_model(frame, setup.elements if "elements" in options else None)
    length = model.mesh.length
    swing = play.swing(length)
    lumped = {k: v for k, v in (("kcb", o.kcb), ("zeta", o.zeta)) if v is not None}
    check_swing_at(model, speed, swing, x, {"ball_mass": ball_mass, "law": law, **lumped})
    v_r = swing.speed_at(x * length)
    closing = np.array([closing_speed(speed, v) for v in v_r])
    # the MapImpact options given (the solver and the law refuse those they cannot use)
    kwargs = {k: v for k, v in vars(o).items() if k in options}
    kwargs.update(ball_mass=ball_mass, law=law)
    solver, batch, _ = _prepared(model, x, closing, kwargs)  # every check before any work

    def e_a(s: float) -> float:
        v = closing_speed(speed, swing.speed_at(s * length))
        return float(apparent_cor_along(model, [s], [v], **kwargs)[0])

    def v_out(s: float) -> float:
        return float(ball_speed_out(e_a(s), speed, swing.speed_at(s * length)))

    work_begins()
    e = solver.solve_many(batch).cor
    vo = ball_speed_out(e, speed, v_r)
    nodes = mode_node_positions(model, 2)
    swinging = swing.velocity != 0.0 or swing.omega != 0.0
    spots = SweetSpots(
        cop=np.nan if pivot is None else centre_of_percussion(model.props, pivot) / length,
        mode1_nodes=tuple(float(n) for n in nodes[0]),
        mode2_nodes=tuple(float(n) for n in nodes[1]) if len(nodes) > 1 else (),
        node=float(nodes[0].max()) if nodes[0].size else np.nan,
        max_apparent_cor=curve_maximum(x, e, e_a),
        max_ball_speed=curve_maximum(x, vo, v_out) if swinging else np.nan,
        power_region=power_region(x, vo, power_fraction),
        power_fraction=power_fraction,
    )
    v_r = np.asarray(v_r, dtype=float)
    struck = None if law is None else law.for_ball(ball_mass)  # as each case's problem holds it
    return RacketMap(setup.name, x, e, vo, v_r, speed, swing, spots, length, struck)
