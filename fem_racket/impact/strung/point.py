"""The strung racket seen from the ball: the frame and the string bed in series at the impact point.

The ball's own law acts between the ball and the bed at the impact point (x_i, y_i); the bed's
edge moves with the frame. The coupling used (an assumption, stated here and in the README):

1. **The head ring moves with the frame** (``edge``; :mod:`fem_racket.impact.strung.frame`).
   ``"point"`` (default): the bed's edge is displaced uniformly by the frame's motion at the
   impact point, w(x_i) + y_i theta(x_i) (the static edge transmission to the point is then
   exactly 1: a uniformly displaced membrane translates rigidly); this is the paper's point
   contact when the bed is very stiff. ``"hoop"``: each edge point (x_e, y_e) moves with the
   frame's bending and twist there, w(x_e) + y_e theta(x_e), and the bed's static edge
   transmission T (:func:`fem_racket.strings.point.edge_transmission`) averages them: the frame
   is seen through a_k = sum_e T_e (w_k(x_e) + y_e theta_k(x_e)) and, by reciprocity, receives
   the contact force spread over the edge as T F. T reproduces linear functions, so the rigid
   modes are the same either way; only the frame's bending and twist differ. On the racket's
   axis (y_i = 0) the twist is not excited (T is mirror symmetric) and the bending modes alone
   are used; off it the torsion modes and the rigid roll join them (3 rigid modes).
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

from fem_racket.frame.model import FrameModel
from fem_racket.impact.problem_checks import bed_coordinates
from fem_racket.impact.strung.frame import FrameAtPoint, frame_at_point
from fem_racket.strings.bed import StringBed
from fem_racket.strings.point import DEFAULT_BED_MODES, DEFAULT_REFINE, bed_point_data

__all__ = ["StrungPoint", "clamped_point", "strung_point"]


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
    rigid_count : int
        Rigid modes first in ``omega``: 2 (translation, rotation), 3 off the axis (roll), 0 on
        a clamped frame.
    frame_shapes : ndarray, shape (ndof, n_frame)
        The frame coordinates' shapes (bending Hermite DOFs in the first ``ndof_bending`` rows,
        torsion DOFs below), in the order they are listed [1/sqrt(kg)].
    ndof_bending : int
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
    rigid_count: int = 2
    frame_shapes: np.ndarray | None = None
    ndof_bending: int = 0

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
        """Values of the rigid modes at the point [1/sqrt(kg)] (translation first)."""
        return self.a[: self.rigid_count]

    @property
    def flexible(self) -> tuple[np.ndarray, np.ndarray]:
        """(omega, a) of the flexible coordinates, frame and bed."""
        return self.omega[self.rigid_count :], self.a[self.rigid_count :]


#: Bed modes whose value at the point is below this fraction of the largest are left out: in
#: series with the frame they are never excited (antisymmetric modes at a point on an axis).
SILENT = 1e-9


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


def _assemble(frame: FrameAtPoint | None, w_bed, a_bed, shapes, data, where) -> StrungPoint:
    """Frame (rigid values first) and bed coordinates in one ascending list (no frame: the
    bed on a clamped frame)."""
    rc = 0 if frame is None else frame.rigid
    w_frame = np.zeros(0) if frame is None else frame.omega
    w = np.concatenate([w_frame, w_bed])
    a = np.concatenate([np.zeros(0) if frame is None else frame.a[rc:], a_bed])
    is_bed = np.concatenate([np.zeros(w_frame.size, bool), np.ones(w_bed.size, bool)])
    order = np.argsort(w, kind="stable")
    bed_order = order[is_bed[order]] - w_frame.size  # the bed's coordinates as they are listed
    frame_shapes, nb = None, 0
    if frame is not None:
        listed = np.concatenate([np.arange(rc), rc + order[~is_bed[order]]])
        frame_shapes, nb = frame.shapes[:, listed], frame.ndof_bending
    return StrungPoint(
        np.concatenate([np.zeros(rc), w[order]]),
        np.concatenate([np.zeros(0) if frame is None else frame.a[:rc], a[order]]),
        np.concatenate([np.zeros(rc, bool), is_bed[order]]),
        float(data.stiffness[0]),
        data.frequencies_hz,
        *where,
        shapes[:, bed_order],
        rc,
        frame_shapes,
        nb,
    )


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
    L = model.mesh.length
    point = bed_coordinates(bed, position, lateral_m, L, bed.head_centre, refine)
    frame = frame_at_point(model, bed, position, point, refine)
    where = (bed, float(position), float(lateral_m), refine)
    return _assemble(frame, *_bed_modes(bed, point, bed_modes, refine), where)


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
    bed_coordinates(bed, bed.head_centre + p[0], p[1], 1.0, bed.head_centre, refine)  # on it
    where = (bed, None, float(p[1]), refine)
    return _assemble(None, *_bed_modes(bed, p, bed_modes, refine), where)
