"""The strung racket seen from the ball: the frame and the string bed in series at the impact point.

The ball's own law acts between the ball and the bed at the impact point (x_i, y_i); the bed's
edge moves with the frame. The coupling used (an assumption, stated here and in the README):

1. **The head ring moves with the frame** (``edge``). ``"point"`` (default): the bed's edge is
   displaced uniformly by the frame's deflection w(x_i) at the impact point (the static edge
   transmission to the point is then exactly 1: a uniformly displaced membrane translates
   rigidly); this is the paper's point contact when the bed is very stiff. ``"hoop"``: each edge
   point moves with the frame's deflection at its own x (the beam's bending along the hoop), and
   the bed's static edge transmission T (:func:`fem_racket.strings.point.edge_transmission`)
   averages them: the frame is seen through a_k = sum_e T_e phi_k(x_e) and, by reciprocity,
   receives the contact force spread over the edge as T F. T reproduces linear functions, so
   the rigid modes are the same either way; only the frame's bending differs. The frame's twist
   is not passed to the edge in either.
2. **The bed passes the contact force to the frame.** The force of the bed's edge on the frame is
   the contact force F; the inertia of the bed's motion relative to its edge (its fixed-edge
   modes) is not fed back to the frame, and the bed's mass moving with its edge is already part
   of the frame's measured mass distribution (the paper's 0.360 kg racket is strung).

With these, the ball sees the sum of two receptances, the frame's at x_i (free-free modes,
rigid modes included) and the bed's at the point (fixed-edge modes, edge at rest)::

    u_p(s) = [ sum_frame a_k^2 / (s^2 + omega_k^2) + sum_bed psi_j^2 / (s^2 + omega_j^2) ] (-F)

so the strung racket is one linear structure in modal form whose flexible modes are the frame's
and the bed's together: every impact path (the exact engine for a linear ball, the general
integrator and CVODE for any law) takes it unchanged. The bed's modes above those computed enter
through one pseudo-mode with their static flexibility and mass at the point
(:mod:`fem_racket.strings.point`), as the engine's reduction does for a frame. A very stiff bed
(tension -> infinity: omega_j -> infinity, compliance -> 0) leaves the frame alone: the paper's
model.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import Any

import numpy as np

from fem_racket.contact.law import ContactLaw
from fem_racket.contact.linear import LinearContact
from fem_racket.frame.model import FrameModel
from fem_racket.strings.bed import StringBed
from fem_racket.strings.point import (
    DEFAULT_BED_MODES,
    DEFAULT_REFINE,
    bed_point_data,
    edge_transmission,
)
from fem_racket.validation import InputError, check_positive, show

__all__ = [
    "BALL_STIFFNESS",
    "BALL_ZETA",
    "StrungPoint",
    "check_strung_problem",
    "clamped_point",
    "kawazoe_ball",
    "strung_point",
]


@dataclass(frozen=True, eq=False)
class StrungPoint:
    """Frame + bed at one impact point, in the modal form of the impact paths.

    Attributes
    ----------
    omega : ndarray, shape (n,)
        Every coordinate's angular frequency: the frame's two rigid modes (0) first, then the
        frame's and the bed's flexible modes (and the bed's pseudo-mode), ascending [rad/s].
    a : ndarray, shape (n,)
        Mass-normalised values at the impact point [1/sqrt(kg)].
    bed : ndarray of bool, shape (n,)
        True for the bed's coordinates.
    bed_stiffness : float
        The bed's static stiffness at the point [N/m].
    bed_frequencies_hz : ndarray
        The bed's lowest fixed-edge frequencies [Hz].
    strings : StringBed
        The bed.
    position : float or None
        Impact point x/L on the frame (None: the clamped bed alone).
    lateral_m : float
        Offset of the impact point from the racket's axis [m].
    refine : int
        Refinements of the bed's mesh (:func:`fem_racket.strings.membrane.bed_mesh`).
    bed_shapes : ndarray, shape (n_interior, n_bed)
        The bed coordinates' shapes on the mesh's interior DOFs, in the order they are listed
        (for pictures) [1/sqrt(kg)].
    """

    omega: np.ndarray
    a: np.ndarray
    bed: np.ndarray
    bed_stiffness: float
    bed_frequencies_hz: np.ndarray
    strings: StringBed
    position: float | None
    lateral_m: float
    refine: int
    bed_shapes: np.ndarray

    def describe(self) -> dict[str, Any]:
        """The bed and the impact point on it, JSON-ready, units in the keys."""
        return {
            **self.strings.describe(),
            "stringbed_stiffness_n_m": self.bed_stiffness,
            "stringbed_frequencies_hz": [float(f) for f in self.bed_frequencies_hz[:3]],
            "offset_m": self.lateral_m,
        }

    @property
    def rigid(self) -> np.ndarray:
        """Values of the two rigid modes at the point [1/sqrt(kg)]."""
        return self.a[:2]

    @property
    def flexible(self) -> tuple[np.ndarray, np.ndarray]:
        """(omega, a) of the flexible coordinates, frame and bed."""
        return self.omega[2:], self.a[2:]


#: The ``kawazoe-1997-ball``: a linear ball, spring k_b [N/m] and damping ratio zeta_b [-], whose
#: series with the paper's racket as strung (246 N, 16x19, nylon, clamped, centre) gives the
#: paper's clamped contact time 4.53 ms at 20 m/s and COR 0.83 (fitted and tabulated by
#: :mod:`fem_racket.studies.bed_ball`, where its limits are stated).
BALL_STIFFNESS = 137357.7927
BALL_ZETA = 0.400824089


def kawazoe_ball(ball_mass: float, separation: str = "displacement") -> ContactLaw:
    """The ``kawazoe-1997-ball`` as a contact law for a ball of ``ball_mass`` [kg]: spring
    k_b and dashpot 2 zeta_b sqrt(m_B k_b)."""
    mass = check_positive("ball_mass", ball_mass, "kg")
    return LinearContact(BALL_STIFFNESS, BALL_ZETA, mass, separation)


#: Bed modes whose value at the point is below this fraction of the largest are left out: in
#: series with the frame they are never excited (antisymmetric modes at a point on an axis).
SILENT = 1e-9


def bed_coordinates(
    bed: StringBed, position: float, lateral_m: float, frame_length_m: float, centre: float
) -> np.ndarray:
    """The impact point on the bed [m, from the head's centre], checked to lie on the head."""
    x, y = (position - centre) * frame_length_m, lateral_m
    ax, ay = 0.5 * bed.head_length_m, 0.5 * bed.head_width_m
    if (x / ax) ** 2 + (y / ay) ** 2 >= 1.0:
        lo, hi = centre - ax / frame_length_m, centre + ax / frame_length_m
        raise InputError(
            f"position = {show(position)} x/L, lateral {show(lateral_m)} m is not allowed with "
            f"the string bed: must lie on the head ({lo:.3f} to {hi:.3f} x/L on the axis)"
        )
    return np.array([x, y])


def _bed_modes(bed: StringBed, point: np.ndarray, bed_modes: int, refine: int):
    """The bed's heard modes at ``point`` [m] with its pseudo-mode: (omega, values, shapes on
    the interior DOFs, data); the pseudo-mode's shape is the residual static shape per unit
    pseudo-coordinate (its value at the point a_p)."""
    data = bed_point_data(bed, point[None], bed_modes, refine)
    heard = np.abs(data.values[0]) > SILENT * np.max(np.abs(data.values[0]))
    w_bed, a_bed = data.omega[heard], data.values[0][heard]
    shapes = data.shapes[:, heard]
    flex, mass = float(data.residual_flexibility[0]), float(data.residual_mass[0])
    if flex > 0.0 and mass > 0.0:  # the bed's pseudo-mode
        w_bed = np.append(w_bed, math.sqrt(mass / flex))
        a_bed = np.append(a_bed, math.sqrt(mass))
        shapes = np.column_stack([shapes, data.residual_shapes[:, 0] * math.sqrt(mass) / flex])
    return w_bed, a_bed, shapes, data


def _assemble(w_frame, a_frame, w_bed, a_bed, shapes, data, where) -> StrungPoint:
    """Frame (rigid values first) and bed coordinates in one ascending list."""
    w = np.concatenate([w_frame, w_bed])
    a = np.concatenate([a_frame[2:], a_bed])
    is_bed = np.concatenate([np.zeros(w_frame.size, bool), np.ones(w_bed.size, bool)])
    order = np.argsort(w, kind="stable")
    bed_order = order[is_bed[order]] - w_frame.size  # the bed's coordinates as they are listed
    return StrungPoint(
        np.concatenate([[0.0, 0.0], w[order]]),
        np.concatenate([a_frame[:2], a[order]]),
        np.concatenate([[False, False], is_bed[order]]),
        float(data.stiffness[0]),
        data.frequencies_hz,
        *where,
        shapes[:, bed_order],
    )


def check_strung_problem(problem: Any) -> None:
    """Refuse, in one line, what an impact problem with a string bed cannot take: a hand, a
    racket moving before impact, the lumped K_CB's kcb and zeta, a point off the head."""
    if not isinstance(problem.strings, StringBed):
        raise InputError(f"strings = {problem.strings!r} is not allowed: must be a StringBed")
    at_rest = "the strung racket is free and at rest"
    lumped = "the bed replaces the lumped K_CB (give the ball's own law as law)"
    refused = {
        "hand": (problem.held, at_rest),
        "swing": (problem.swing is not None, at_rest),
        "frame_velocity": (problem.frame_velocity is not None, at_rest),
        "kcb": (problem.kcb is not None, lumped),
        "zeta": (problem.zeta is not None, lumped),
    }
    for key, (given, why) in refused.items():
        if given:
            raise InputError(f"{key} is not allowed with a string bed: {why}")
    bed = problem.strings
    bed_coordinates(bed, problem.impact.position, 0.0, problem.model.mesh.length, bed.head_centre)


def strung_point(
    model: FrameModel,
    bed: StringBed,
    position: float,
    lateral_m: float = 0.0,
    *,
    bed_modes: int = DEFAULT_BED_MODES,
    refine: int = DEFAULT_REFINE,
) -> StrungPoint:
    """The strung racket at the impact point ``position`` (x/L), ``lateral_m`` off the axis,
    the bed centred at ``bed.head_centre``, its ring moving with the frame as ``bed.edge``
    says (module docstring).

    Every frame mode of ``model`` is used (rigid modes first).
    """
    edge, centre = bed.edge, bed.head_centre
    L = model.mesh.length
    point = bed_coordinates(bed, position, lateral_m, L, centre)
    fm = model.modes(None)
    if edge == "point":
        a_frame = fm.all_shapes.T @ model.fe.point_vector(position * L)
    else:
        xy, T = edge_transmission(bed, point[None], refine)
        R = model.fe.field_matrix(centre * L + xy[:, 0], 0)  # frame deflection at the edge
        a_frame = (T[0] @ (R @ fm.all_shapes)).ravel()
    where = (bed, float(position), float(lateral_m), refine)
    return _assemble(fm.omega, a_frame, *_bed_modes(bed, point, bed_modes, refine), where)


def clamped_point(
    bed: StringBed,
    point: tuple[float, float] = (0.0, 0.0),
    *,
    bed_modes: int = DEFAULT_BED_MODES,
    refine: int = DEFAULT_REFINE,
) -> StrungPoint:
    """The bed on a clamped frame (its edge fixed) at ``point`` [m from the head's centre]: the
    structure of the paper's clamped-frame targets (eqs 1-4), rigid values 0."""
    p = np.asarray(point, dtype=float)
    bed_coordinates(bed, bed.head_centre + p[0], p[1], 1.0, bed.head_centre)  # on it
    where = (bed, None, float(p[1]), refine)
    return _assemble(np.zeros(0), np.zeros(2), *_bed_modes(bed, p, bed_modes, refine), where)
