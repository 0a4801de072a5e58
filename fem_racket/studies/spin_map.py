"""Spin over the face: the oblique ball's outgoing spin and angle at every point of the strings.

Every grid point (x along the frame, y across it) on the head outline
(:class:`~fem_racket.frame.head.HeadOutline`) is struck by the same oblique, spinning ball
(:class:`~fem_racket.impact.incidence.Incidence`: angle from the face normal in the plane of the
long axis, spin, friction; a side angle and side spin across the face, whose outgoing side spin
and angle and the racket's yaw rate are then mapped too), as ``fem-racket simulate --angle ...
--offset ...`` strikes one point: its normal impact at V cos(side angle) cos(angle) (the frame
bending and twisting off the axis, :mod:`fem_racket.impact.offaxis`), then the tangential
contact over it (:mod:`fem_racket.impact.oblique.solve`; the free racket recoils along its axis
as a rigid body, so the spin varies over the face only through the normal impact). The grid is
one :class:`~fem_racket.impact.problem_batch.ProblemBatch` the solver answers. Points off the
face are NaN.
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from fem_racket.contact.linear import DEFAULT_BALL_MASS
from fem_racket.frame.head import DEFAULT_HEAD, HeadOutline
from fem_racket.frame.model import DEFAULT_MODES, FrameModel
from fem_racket.impact.incidence import Incidence
from fem_racket.impact.incidence_idle import refuse_idle_incidence
from fem_racket.impact.problem_batch import ProblemBatch
from fem_racket.impact.reduction import DEFAULT_TOLERANCE
from fem_racket.impact.solvers import make_solver
from fem_racket.studies.face_map import FaceGrid, increasing
from fem_racket.studies.map_options import check_map_points
from fem_racket.studies.spin_defaults import SPIN_OFFSETS, SPIN_POSITIONS, SPIN_REFUSES
from fem_racket.validation import InputError, check_positive

__all__ = [
    "SIDE_FIELDS",
    "SPIN_FIELDS",
    "SPIN_OFFSETS",
    "SPIN_POSITIONS",
    "SPIN_REFUSES",
    "SpinMap",
    "map_fields",
    "spin_map",
]

#: The mapped outputs: field -> (unit, label).
SPIN_FIELDS = {
    "spin_out_rpm": ("rpm", "outgoing spin [rpm] (+ topspin)"),
    "angle_out_deg": (
        "deg",
        "outgoing angle from the outward face normal [deg] (> 90: the ball keeps moving forward)",
    ),
    "ball_speed_out_m_s": ("m/s", "outgoing ball speed [m/s]"),
}
#: The outputs across the face, mapped too when the ball crosses it (a side angle or side spin,
#: as ``simulate --side-angle/--side-spin`` reports them): field -> (unit, label).
SIDE_FIELDS = {
    "side_spin_out_rpm": ("rpm", "outgoing side spin [rpm] (+ rolling to +y)"),
    "side_angle_out_deg": ("deg", "outgoing angle from the plane of the long axis [deg]"),
    "racket_yaw_rate_rad_s": ("rad/s", "racket's yaw rate after impact [rad/s]"),
}


def map_fields(incidence: Incidence) -> dict[str, tuple[str, str]]:
    """The fields a spin map of ``incidence`` holds: :data:`SPIN_FIELDS`, and
    :data:`SIDE_FIELDS` when the ball crosses the face."""
    return {**SPIN_FIELDS, **(SIDE_FIELDS if incidence.lateral else {})}


@dataclass(frozen=True, eq=False)
class SpinMap(FaceGrid):
    """The oblique outcome over the string face of one racket, on its
    :class:`~fem_racket.studies.face_map.FaceGrid` (``name``, ``positions``, ``offsets``).

    Attributes
    ----------
    fields : dict of str to ndarray, shape (ny, nx)
        :func:`map_fields` of the incidence (NaN off the face).
    regimes : ndarray of str, shape (ny, nx)
        The contact regime at each point ("" off the face).
    incidence : Incidence
    speed : float
        Incident ball speed [m/s].
    head : HeadOutline
    length : float
        L [m].
    """

    fields: dict[str, np.ndarray]
    regimes: np.ndarray
    incidence: Incidence
    speed: float
    head: HeadOutline
    length: float

    def extreme(self, key: str = "spin_out_rpm") -> tuple[float, float, float, float, float]:
        """(min, its x/L, max, its x/L, its y [m]) of a field over the face."""
        v = self.fields[key]
        lo = np.unravel_index(int(np.nanargmin(v)), v.shape)
        hi = np.unravel_index(int(np.nanargmax(v)), v.shape)
        return (
            float(v[lo]),
            float(self.positions[lo[1]]),
            float(v[hi]),
            float(self.positions[hi[1]]),
            float(self.offsets[hi[0]]),
        )

    def forward(self) -> tuple[int, int]:
        """(points where the ball keeps moving forward, points on the face): the normal
        rebound is negative there (COR < 0, near the tip and the rim of a free racket), so its
        ``angle_out_deg`` from the outward face normal is over 90 in size (180 head-on)."""
        angle = self.fields["angle_out_deg"]
        face = np.isfinite(angle)
        return int(np.count_nonzero(np.abs(angle[face]) > 90.0)), int(np.count_nonzero(face))

    def summary(self) -> dict[str, Any]:
        """JSON-ready, units in the keys."""
        out: dict[str, Any] = {"racket": self.name, "speed_m_s": self.speed}
        out.update(self.incidence.summary())
        for key in self.fields:
            lo, x_lo, hi, x_hi, y_hi = self.extreme(key)
            out[f"{key}_min"], out[f"{key}_max"] = lo, hi
        lo, x_lo, hi, x_hi, y_hi = self.extreme()
        out.update(max_spin_x_over_l=x_hi, max_spin_offset_m=y_hi)
        out["contact_regimes"] = sorted({str(r) for r in self.regimes.ravel() if r})
        return out


def spin_map(
    model: FrameModel,
    *,
    positions: Any,
    offsets: Any,
    incidence: Incidence,
    speed: float = 20.0,
    name: str = "racket",
    options: dict[str, Any] | None = None,
) -> SpinMap:
    """The oblique outcome over the string face (module docstring).

    Parameters
    ----------
    model : FrameModel
        The racket, with torsion data when an offset is not 0.
    positions, offsets : array of float
        x/L and y [m] of the grid (increasing, at least 2 each).
    incidence : Incidence
        Angle, spin and friction of the ball (and its inertia, radius, eta^2): one ball for
        every point. Its contact parameters (friction, inertia, radius, eta^2) away from their
        defaults are refused on a head-on, spinless ball, whose tangential force is zero
        (:func:`~fem_racket.impact.incidence_idle.refuse_idle_incidence`, as simulate's).
    speed : float
        Incident ball speed [m/s].
    name : str
        Label of the racket.
    options : dict, optional
        ``ball_mass``, ``kcb``, ``zeta``, ``separation``, ``modes``, ``tolerance``, ``law``
        (a ContactLaw: solved by the general solver, which refuses ``modes``; ``kcb``,
        ``zeta`` and ``separation`` are the paper's law's) and ``head`` (the 100 in^2 outline).
    """
    refuse_idle_incidence(incidence)  # before any work, as simulate refuses it
    opts = dict(options or {})
    head = (opts.pop("head", None) or DEFAULT_HEAD).on_frame(model.mesh.length)
    unknown = set(opts) - {"ball_mass", "kcb", "zeta", "separation", "modes", "tolerance", "law"}
    if unknown:
        raise InputError(f"options = {sorted(unknown)} is not allowed: unknown spin-map options")
    law = opts.pop("law", None)
    tolerance = opts.pop("tolerance", DEFAULT_TOLERANCE)  # the default asks for nothing: the
    solver_options = {}  # normal impacts' histories then keep every mode (as simulate's)
    if tolerance != DEFAULT_TOLERANCE:
        solver_options["tolerance"] = tolerance
    if law is None or "modes" in opts:  # the general solver refuses modes given with a law
        solver_options["modes"] = opts.pop("modes", DEFAULT_MODES)
    solver = make_solver("exact" if law is None else "general", **solver_options)
    speed = check_positive("speed", speed, "m/s")
    check_map_points(int(np.size(positions)), int(np.size(offsets)))
    x = increasing("positions", positions, 2)
    y = increasing("offsets", offsets, 2)
    X, Y = np.meshgrid(x, y)
    face = head.contains(X * model.mesh.length, Y)
    fields = {k: np.full(X.shape, np.nan) for k in map_fields(incidence)}
    regimes = np.full(X.shape, "", dtype=object)
    if np.any(face):
        n = int(np.count_nonzero(face))
        batch = ProblemBatch(
            (model,),
            X[face],
            speed,
            offset=Y[face],
            ball_mass=opts.get("ball_mass") or DEFAULT_BALL_MASS,
            kcb=opts.get("kcb"),
            zeta=opts.get("zeta"),
            law=law,
            separation=opts.get("separation"),  # refused with a law by the batch
            incidence=(incidence,) * n,
        )
        out = solver.solve_many(batch)
        for key in fields:
            fields[key][face] = out.extra[key]
        regimes[face] = out.extra["contact_regime"]
    return SpinMap(name, x, y, fields, regimes, incidence, speed, head, model.mesh.length)
