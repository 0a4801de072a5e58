"""The power map of the whole string face: e_A and v_out over (x, y), and the power area.

Every grid point (x along the frame, y across it) on the head outline
(:class:`~fem_racket.frame.head.HeadOutline`) is struck at the closing speed v_in + v_r(x) (the
swing is a rigid motion in the bending plane, so v_r does not depend on y); the frame bends and
twists (:mod:`fem_racket.impact.offaxis`), and the ball leaves at
v_out = e_A v_in + (1 + e_A) v_r (Brody, Cross & Lindsey 2002, ch. 11). The whole face is one
:class:`~fem_racket.impact.problem_batch.ProblemBatch`, which the exact solver answers by one
call of its batched engine. Points off the face are NaN.

Power area: the area of the face where e_A >= ``power_fraction`` x its maximum (Hatze 1994's
"effective power region"; quality rackets > 100 cm^2), in cm^2. Each grid node stands for the
cell of the trapezoid rule around it (dx dy, halved on the grid's edges), so the area converges
as the grid is refined (first order where the level line crosses cells).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from fem_racket.contact.linear import DEFAULT_BALL_MASS, Ball
from fem_racket.frame.head import DEFAULT_HEAD, HeadOutline
from fem_racket.frame.model import DEFAULT_MODES, FrameModel
from fem_racket.frame.torsion import check_off_axis
from fem_racket.impact.closing import closing_speed
from fem_racket.impact.problem_batch import ProblemBatch
from fem_racket.impact.reduction import DEFAULT_TOLERANCE
from fem_racket.impact.solvers import make_solver
from fem_racket.impact.swing import Swing, ball_speed_out
from fem_racket.studies.map_options import check_at_rest, check_map_points
from fem_racket.studies.sweetspots import centre_of_percussion, mode_node_positions
from fem_racket.studies.swing_points import check_swing_at
from fem_racket.validation import InputError, check_positive, check_range, show

__all__ = ["DEFAULT_AREA_FRACTION", "FaceGrid", "FaceMap", "face_map"]

#: Default fraction of the maximum e_A bounding the power area.
DEFAULT_AREA_FRACTION = 0.9


@dataclass(frozen=True, eq=False)
class FaceGrid:
    """The grid of a map over the string face of one racket (:class:`FaceMap`,
    :class:`~fem_racket.studies.spin_map.SpinMap`).

    Attributes
    ----------
    name : str
    positions : ndarray, shape (nx,)
        x/L of the grid.
    offsets : ndarray, shape (ny,)
        y [m] of the grid.
    """

    name: str
    positions: np.ndarray
    offsets: np.ndarray


@dataclass(frozen=True, eq=False)
class FaceMap(FaceGrid):
    """e_A and v_out over the string face of one racket, on its :class:`FaceGrid` (``name``,
    ``positions``, ``offsets``).

    Attributes
    ----------
    apparent_cor, ball_speed_out : ndarray, shape (ny, nx)
        e_A and v_out [m/s] (NaN off the face).
    racket_speed : ndarray, shape (nx,)
        v_r [m/s] before impact.
    speed : float
        v_in [m/s].
    swing : Swing
    head : HeadOutline
    length : float
        L [m].
    power_fraction : float
    power_area_cm2 : float
        Area where e_A >= power_fraction x max e_A [cm^2].
    max_apparent_cor : tuple of float
        (x/L, y [m], e_A) of the grid's largest e_A.
    node : float
        The outermost node of the first bending mode [x/L] (the node line across the face).
    cop : float
        Centre of percussion [x/L] for the pivot (NaN without one).
    """

    apparent_cor: np.ndarray
    ball_speed_out: np.ndarray
    racket_speed: np.ndarray
    speed: float
    swing: Swing
    head: HeadOutline
    length: float
    power_fraction: float
    power_area_cm2: float
    max_apparent_cor: tuple[float, float, float]
    node: float
    cop: float

    def summary(self, grid: bool = False) -> dict[str, Any]:
        """JSON-ready, units in the keys (the grids with ``grid``)."""
        x, y, e = self.max_apparent_cor
        out: dict[str, Any] = {
            "racket": self.name,
            "length_m": self.length,
            "head_length_m": self.head.length_m,
            "head_width_m": self.head.width_m,
            "head_centre_x_over_l": self.head.centre,
            "power_area_cm2": self.power_area_cm2,
            "power_fraction": self.power_fraction,
            "max_apparent_cor": e,
            "max_apparent_cor_x_over_l": x,
            "max_apparent_cor_offset_m": y,
            "node_x_over_l": self.node,
            "cop_x_over_l": self.cop,
            **self.swing.summary(),
        }
        if grid:
            out["grid"] = {
                "position_x_over_l": self.positions.tolist(),
                "offset_m": self.offsets.tolist(),
                "apparent_cor": _listed(self.apparent_cor),
                "ball_speed_out_m_s": _listed(self.ball_speed_out),
            }
        return out


def _listed(a: np.ndarray) -> list:
    return [[None if v != v else float(v) for v in row] for row in a]


def _weights(v: np.ndarray) -> np.ndarray:
    """Trapezoid-rule weights of the grid ``v``."""
    w = np.zeros(v.size)
    if v.size > 1:
        h = np.diff(v)
        w[:-1] += h / 2
        w[1:] += h / 2
    return w


def power_area(x_m: np.ndarray, y_m: np.ndarray, e: np.ndarray, fraction: float) -> float:
    """Area [cm^2] where ``e`` (ny, nx; NaN off the face) >= fraction x its maximum."""
    if not np.any(np.isfinite(e)):
        return float("nan")
    top = np.nanmax(e)
    inside = np.isfinite(e) & (e >= fraction * top)
    return float(np.sum(np.outer(_weights(y_m), _weights(x_m)) * inside) * 1e4)


#: What a racket without torsion data is mapped with (its allowed "offsets").
AXIS_ONLY = "map it without offsets (along its axis)"


def face_map(
    frame: Any = None,
    *,
    positions: Any,
    offsets: Any,
    name: str = "racket",
    speed: float = 20.0,
    racket_speed: float = 0.0,
    reference: float | None = None,
    pivot: float | None = None,
    options: dict[str, Any] | None = None,
) -> FaceMap:
    """e_A and v_out over the string face.

    Parameters
    ----------
    frame : FrameModel, Frame or FrameMesh, optional
        The racket, with torsion data (the standard racket when None).
    positions : array of float
        x/L of the grid (increasing).
    offsets : array of float
        y [m] of the grid (increasing).
    name, speed, racket_speed, reference, pivot
        As for :func:`fem_racket.studies.racket_map.racket_map`.
    options : dict, optional
        ``ball_mass``, ``kcb``, ``zeta``, ``separation``, ``modes``, ``tolerance`` (as for
        :func:`fem_racket.simulate`), ``elements``, ``head``
        (:class:`HeadOutline`, the 100 in^2 default) and ``power_fraction`` (default 0.9).
    """
    opts = dict(options or {})
    head = opts.pop("head", None) or DEFAULT_HEAD
    fraction = check_range(
        "power_fraction", opts.pop("power_fraction", DEFAULT_AREA_FRACTION), 0.0, 1.0,
        include_low=False,
    )  # fmt: skip
    elements = opts.pop("elements", None)
    if elements is not None and isinstance(frame, FrameModel):
        raise InputError(
            f"elements = {show(elements)} is not allowed with a FrameModel: it is meshed "
            "already (give a Frame or a FrameMesh to mesh)",
            parameter="elements",
            value=elements,
        )
    check_at_rest(racket_speed, reference)  # the pivot sets the centre of percussion
    unknown = set(opts) - {"ball_mass", "kcb", "zeta", "separation", "modes", "tolerance"}
    if unknown:
        raise InputError(f"options = {sorted(unknown)} is not allowed: unknown face-map options")
    opts.setdefault("modes", DEFAULT_MODES)
    opts.setdefault("tolerance", DEFAULT_TOLERANCE)
    opts["ball_mass"] = Ball(opts.get("ball_mass") or DEFAULT_BALL_MASS).mass
    speed = check_positive("speed", speed, "m/s")
    check_map_points(int(np.size(positions)), int(np.size(offsets)))
    x = increasing("positions", positions, 2)
    y = increasing("offsets", offsets, 2)
    model = frame if isinstance(frame, FrameModel) else FrameModel.build(frame, elements or 20)
    if np.any(y != 0.0):  # off the long axis: named with this racket
        check_off_axis(
            model.mesh,
            f"offsets = {show(y.tolist())} m",
            where=f"racket {name!r}",
            allowed=AXIS_ONLY,
        )
    length = model.mesh.length
    head = head.on_frame(length)
    swing = Swing.from_speed(racket_speed, length, reference=reference, pivot=pivot)
    lumped = {k: opts[k] for k in ("ball_mass", "kcb", "zeta") if opts.get(k) is not None}
    check_swing_at(model, speed, swing, x, lumped)  # where the library refuses it, before work
    v_r = np.asarray(swing.speed_at(x * length), dtype=float)
    closing = np.array([closing_speed(speed, v) for v in v_r])
    X, Y = np.meshgrid(x, y)
    face = head.contains(X * length, Y)
    e = np.full(X.shape, np.nan)
    if np.any(face):
        cols = np.nonzero(face)[1]
        solver = make_solver("exact", tolerance=opts.pop("tolerance"), modes=opts.pop("modes"))
        batch = ProblemBatch((model,), X[face], closing[cols], offset=Y[face], **opts)
        e[face] = solver.solve_many(batch).cor
    vo = ball_speed_out(e, speed, v_r[None, :])
    k = np.unravel_index(int(np.nanargmax(e)), e.shape) if np.any(face) else None
    best = (float(x[k[1]]), float(y[k[0]]), float(e[k])) if k else (np.nan, np.nan, np.nan)
    nodes = mode_node_positions(model, 1)[0]
    cop = np.nan if pivot is None else centre_of_percussion(model.props, pivot) / length
    return FaceMap(
        name, x, y, e, vo, v_r, speed, swing, head, length, fraction,
        power_area(x * length, y, e, fraction), best,
        float(nodes.max()) if nodes.size else np.nan, float(cop),
    )  # fmt: skip


def increasing(name: str, values: Any, minimum: int) -> np.ndarray:
    """``values`` as an array of at least ``minimum`` increasing finite numbers, or refused."""
    v = np.atleast_1d(np.asarray(values, dtype=float))
    if v.size < minimum or not np.all(np.isfinite(v)) or np.any(np.diff(v) <= 0.0):
        raise InputError(
            f"{name} = {v.size} values is not allowed: must be at least {minimum} increasing "
            "finite numbers",
            parameter=name,
            value=values,  # as given (a run file's key is named by it)
        )
    return v
