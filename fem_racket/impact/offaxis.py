"""Impacts off the long axis: the frame bends and twists.

For a straight beam bending (deflection w(x)) and St Venant torsion (twist theta(x) about the
long axis) are uncoupled, so the free-free modes of the frame are the bending modes
(:mod:`fem_racket.frame.modal`) and the torsion modes (:mod:`fem_racket.frame.torsion`) side by
side. A ball striking the string face at (x, y), y the lateral offset from the axis, moves the
face point by::

    w(x) + y theta(x)

so in the impact's modal terms (every solver here) the torsion modes enter with the point values
y theta_k(x) [1/sqrt(kg)], the rigid roll with y / sqrt(I_p) (adding y^2 / I_p to the rigid
compliance, I_p = int rhoIp dx), and their residual totals scaled by y^2. For a rigid racket
this is the effective mass 1/M_eff = 1/M + b^2/I_cg + y^2/I_p (Brody, Cross & Lindsey 2002;
DESIGN section 10). The strings' own lateral stiffness across the face is not modelled: the ball
meets the frame through the same compound ball/string law everywhere (an assumption; the bed's
stiffness falls toward the rim, Cross 2000).

Here: the combined modal basis of one frame (:func:`combined_modes`, bending rows first then
torsion rows), the point vector at an off-axis point, the torsion part of the engine's
:class:`~fem_racket.impact.point.ModalData` and its merge with the bending part, and the check
of an offset against the head outline (:class:`~fem_racket.frame.head.HeadOutline`).
"""

from __future__ import annotations

from dataclasses import dataclass
from typing import Any

import numpy as np

from fem_racket.frame.head import DEFAULT_HEAD, HeadOutline
from fem_racket.frame.model import FrameModel
from fem_racket.frame.torsion import check_off_axis
from fem_racket.impact.point import ModalData, modes_past
from fem_racket.validation import check_finite, show

__all__ = [
    "CombinedModes",
    "check_offsets",
    "combined_modes",
    "combined_point_vector",
    "merge_modal_data",
    "torsion_modal_data",
]

#: Rigid modes of the free frame off axis: translation, rotation about the CG, roll.
RIGID_OFFAXIS = 3


@dataclass(frozen=True, eq=False)
class CombinedModes:
    """Bending and torsion modes of one frame in one basis, mass-normalised.

    Attributes
    ----------
    all_omega : ndarray, shape (3 + n,)
        Three zeros (translation, rotation about the CG, roll), then the flexible bending and
        torsion frequencies merged in ascending order [rad/s].
    all_shapes : ndarray, shape (ndof_b + ndof_t, 3 + n)
        The shapes: Hermite DOFs of bending in the first ``ndof_bending`` rows, torsion DOFs
        below.
    ndof_bending : int
    is_torsion : ndarray of bool, shape (3 + n,)
        True for the roll and the torsion modes.
    """

    all_omega: np.ndarray
    all_shapes: np.ndarray
    ndof_bending: int
    is_torsion: np.ndarray

    @property
    def omega(self) -> np.ndarray:
        """Flexible frequencies [rad/s]."""
        return self.all_omega[RIGID_OFFAXIS:]


def combined_modes(model: FrameModel, modes: int | None) -> CombinedModes:
    """The lowest ``modes`` flexible bending modes and as many torsion ones (all when None)."""
    fm = model.modes(modes)
    tm = model.torsion.modes(modes)
    nb, nt = model.fe.ndof, model.torsion.ndof
    roll = np.full(nt, 1.0 / np.sqrt(tm.polar_moment))
    omega = np.concatenate([fm.omega, tm.omega])
    order = np.argsort(omega, kind="stable")
    flex = np.zeros((nb + nt, omega.size))
    flex[:nb, : fm.omega.size] = fm.shapes
    flex[nb:, fm.omega.size :] = tm.shapes
    shapes = np.zeros((nb + nt, RIGID_OFFAXIS + omega.size))
    shapes[:nb, :2] = fm.rigid
    shapes[nb:, 2] = roll
    shapes[:, RIGID_OFFAXIS:] = flex[:, order]
    tors = np.concatenate([[False, False, True], order >= fm.omega.size])
    return CombinedModes(np.concatenate([np.zeros(3), omega[order]]), shapes, nb, tors)


def combined_point_vector(model: FrameModel, x: float, offset: float) -> np.ndarray:
    """[g_bending(x), offset g_torsion(x)]: the face point's displacement from the combined DOFs
    (x [m] along the frame, offset [m] across it)."""
    g_t = model.torsion.point_matrix(np.array([x]))[0]
    return np.concatenate([model.fe.point_vector(x), offset * g_t])


def check_offsets(
    model: FrameModel, positions: Any, offsets: Any, head: HeadOutline | None = None
) -> np.ndarray:
    """``offsets`` [m] as a float array if every (position x/L, offset) lies on the head (or
    offset = 0, the long axis) of a frame with torsion data, else an InputError naming the
    first that does not."""
    y = np.asarray(offsets, dtype=float)
    for v in np.ravel(y):
        check_finite("offset", v, "m")
    if np.any(y != 0.0):
        check_off_axis(model.mesh, f"offset = {show(float(y[y != 0.0].flat[0]))} m")
        outline = (head or DEFAULT_HEAD).on_frame(model.mesh.length)
        x = np.broadcast_to(np.asarray(positions, dtype=float), np.broadcast(positions, y).shape)
        for xi, yi in zip(np.ravel(x), np.ravel(np.broadcast_to(y, x.shape)), strict=True):
            outline.check(float(xi) * model.mesh.length, float(yi))
    return y


def torsion_modal_data(
    model: FrameModel,
    positions: np.ndarray,
    offsets: np.ndarray,
    cutoff: float | None,
    limit: int | None = None,
) -> ModalData:
    """The torsion part of :func:`~fem_racket.impact.point.frame_modal_data` at points
    (``positions`` x/L, ``offsets`` [m]): values y theta_k(x), rigid y^2/I_p, residuals y^2 x
    the torsion totals. Every torsion mode when the model is small enough for a dense solve
    (or ``cutoff`` None); else the modes up to ``cutoff`` [rad/s] and static totals for the
    others. ``limit``: exactly that many modes, no totals (a plain truncation)."""
    tors = model.torsion
    n_flex = tors.ndof - 1
    from fem_racket.frame.torsion import DENSE_LIMIT

    if limit is not None or cutoff is None or tors.ndof <= DENSE_LIMIT:
        tm = tors.modes(None if limit is None else min(int(limit), n_flex))
    else:
        tm = modes_past(tors.modes, n_flex, cutoff)
    x = np.asarray(positions, dtype=float) * model.mesh.length
    y = np.asarray(offsets, dtype=float)
    theta = tors.point_matrix(x) @ tm.shapes
    values = y[:, None] * theta
    rigid = y * y / tm.polar_moment
    zero = np.zeros(x.size)
    if tm.complete or limit is not None:
        return ModalData(tm.omega, values, rigid, zero, zero)
    totals = tors.static_totals(x)
    flex = np.maximum(totals[:, 0] - (theta**2 / tm.omega**2).sum(axis=1), 0.0)
    mass = np.maximum(totals[:, 1] - (theta**2).sum(axis=1), 0.0)
    return ModalData(tm.omega, values, rigid, y * y * flex, y * y * mass)


def merge_modal_data(
    bending: ModalData, index: np.ndarray, torsion: ModalData, ei_factor: np.ndarray
) -> ModalData:
    """Bending data at the points ``index`` (one per row of ``torsion``) with every EI times
    ``ei_factor`` (omega x sqrt, flexibility / factor; torsion unchanged) merged with the
    torsion data: per-row frequencies, ascending."""
    s = np.asarray(ei_factor, dtype=float)
    n = s.size
    wb = np.broadcast_to(bending.omega, (n, bending.omega.size)) * np.sqrt(s)[:, None]
    wt = np.broadcast_to(torsion.omega, (n, torsion.omega.size))
    omega = np.concatenate([wb, wt], axis=1)
    values = np.concatenate([bending.values[index], torsion.values], axis=1)
    order = np.argsort(omega, axis=1, kind="stable")
    return ModalData(
        np.take_along_axis(omega, order, axis=1),
        np.take_along_axis(values, order, axis=1),
        bending.rigid[index] + torsion.rigid,
        bending.residual_flexibility[index] / s + torsion.residual_flexibility,
        bending.residual_mass[index] + torsion.residual_mass,
    )


def engine_data(
    model: FrameModel,
    positions: np.ndarray,
    offsets: np.ndarray,
    ei_factor: np.ndarray,
    wc_rigid: Any,
    beta: float,
    modes: int | None,
) -> tuple[ModalData, np.ndarray]:
    """The engine's data for cases at (``positions`` x/L, ``offsets`` [m]) with EI factors
    ``ei_factor`` (flat arrays of one length): merged modal data per distinct case (EI already
    applied) and each case's row. ``wc_rigid(rigid)``: the cases' contact frequencies [rad/s]
    from their rigid compliances, for the cut-off ``beta`` x omega_c (inf: every mode)."""
    from fem_racket.impact.point import frame_modal_data

    keys = np.column_stack([positions, offsets, ei_factor])
    uniq, index = np.unique(keys, axis=0, return_inverse=True)
    index = index.ravel()
    upos, bidx = np.unique(uniq[:, 0], return_inverse=True)
    props = model.props
    d = uniq[:, 0] * props.length - props.cg
    rig = 1.0 / props.mass + d * d / props.inertia + uniq[:, 1] ** 2 / model.torsion.polar_moment
    cutoff = None
    if np.isfinite(beta):
        wc = np.asarray(wc_rigid(rig[index]))
        cutoff = float(np.max(beta * wc / np.sqrt(np.minimum(ei_factor, 1.0))))
    bending = frame_modal_data(model, upos, cutoff, limit=modes)
    torsion = torsion_modal_data(model, uniq[:, 0], uniq[:, 1], cutoff, limit=modes)
    return merge_modal_data(bending, bidx.ravel(), torsion, uniq[:, 2]), index
