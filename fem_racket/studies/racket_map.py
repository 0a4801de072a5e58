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
from fem_racket.contact.presets import get_law
from fem_racket.frame.mesh import FrameMesh
from fem_racket.frame.model import FrameModel
from fem_racket.frame.segments import Frame
from fem_racket.impact.problem_batch import ProblemBatch
from fem_racket.impact.solvers import make_solver
from fem_racket.impact.swing import Swing, ball_speed_out, closing_speed
from fem_racket.impact.system import SEPARATION_EVENTS
from fem_racket.studies.map_options import (
    DEFAULT_POSITIONS,
    DEFAULT_POWER_FRACTION,
    MapImpact,
    MapSetup,
)
from fem_racket.studies.options import take
from fem_racket.studies.sweetspots import (
    SweetSpots,
    centre_of_percussion,
    curve_maximum,
    mode_node_positions,
    power_region,
)
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
def _solver(name: str, tolerance: float | None, modes: int | None = None) -> Any:
    """The map's solver, made once per options (a map asks it again for each refined point)."""
    if name == "general":
        return make_solver(name, tolerance=tolerance)
    return make_solver(name, tolerance=tolerance, modes=modes)


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
        ``separation`` and ``modes`` do not apply) and ``kcb_factor`` (on the linear law's
        K_CB, or the paper's K_CB of each closing speed: a stiffer or softer string bed).

    Returns
    -------
    ndarray
        e_A = -v_B(t_c) / V_B0 at each point (NaN where the ball does not separate).
    """
    o = take(options, "an option of apparent_cor_along", MapImpact)[0]
    ball_mass, kcb, zeta, separation = o.ball_mass, o.kcb, o.zeta, o.separation
    modes, tolerance, law, kcb_factor = o.modes, o.tolerance, o.law, o.kcb_factor
    check_choice("separation", separation, SEPARATION_EVENTS)
    x = np.atleast_1d(np.asarray(positions, dtype=float))
    v = np.broadcast_to(np.asarray(speeds, dtype=float), x.shape)
    if law is not None:
        batch = ProblemBatch((model,), x.ravel(), v.ravel(), ball_mass=ball_mass, law=law)
        return _solver("general", tolerance).solve_many(batch).cor.reshape(x.shape)
    if kcb_factor != 1.0:
        check_positive("kcb_factor", kcb_factor, "")
        if kcb is None:
            kcb = np.array([kcb_from_speed(s) for s in v.ravel()]).reshape(v.shape)
        kcb = kcb * kcb_factor
    batch = ProblemBatch(
        (model,),
        x.ravel(),
        v.ravel(),
        ball_mass=ball_mass,
        kcb=None if kcb is None else np.broadcast_to(kcb, x.shape).ravel(),
        zeta=zeta,
        separation=separation,
    )
    return _solver("exact", tolerance, modes).solve_many(batch).cor.reshape(x.shape)


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
        """The contact law's name and parameters, units in the keys (``linear``: the paper's
        K_CB from the closing speed, or as given, and zeta)."""
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


def _grid(positions: Any) -> np.ndarray:
    if positions is None:
        start, stop, num = DEFAULT_POSITIONS
        return np.linspace(start, stop, num)
    x = np.atleast_1d(np.asarray(positions, dtype=float))
    if x.size < 3 or np.any(np.diff(x) <= 0.0):
        raise InputError(
            f"positions = {x.size} values is not allowed: must be at least 3 increasing x/L"
        )
    for p in (x[0], x[-1]):
        check_range("position", p, 0.0, 1.0, unit="x/L")
    return x


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
    if law is not None:
        for key, value in (("kcb", o.kcb), ("zeta", o.zeta), ("kcb_factor", o.kcb_factor)):
            if value is not None and not (key == "kcb_factor" and value == 1.0):
                raise InputError(
                    f"{key} = {show(value)} is not allowed with contact law {show(law.name)}: "
                    "it sets the linear law's K_CB and zeta only"
                )
    ball_mass = Ball(o.ball_mass).mass
    check_range("power_fraction", power_fraction, 0.0, 1.0, include_low=False)
    if o.modes is not None:
        check_integer("modes", o.modes)
    x = _grid(play.positions)
    model = frame if isinstance(frame, FrameModel) else FrameModel.build(frame, setup.elements)
    length = model.mesh.length
    swing = play.swing(length)
    v_r = swing.speed_at(x * length)
    closing = np.array([closing_speed(speed, v) for v in v_r])
    kwargs = dict(vars(o), ball_mass=ball_mass, law=law)  # MapImpact, the mass and law resolved

    def e_a(s: float) -> float:
        v = closing_speed(speed, swing.speed_at(s * length))
        return float(apparent_cor_along(model, [s], [v], **kwargs)[0])

    def v_out(s: float) -> float:
        return float(ball_speed_out(e_a(s), speed, swing.speed_at(s * length)))

    work_begins()
    e = apparent_cor_along(model, x, closing, **kwargs)
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
    return RacketMap(setup.name, x, e, vo, v_r, speed, swing, spots, length, law)
