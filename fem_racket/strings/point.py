"""The string bed seen from impact points: fixed-edge modes, static stiffness and residuals.

For each impact point (x, y) on the head [m, from the head's centre] the bed gives, in the form
the impact engines take for a structure (:class:`fem_racket.impact.point.ModalData`):

- its fixed-edge angular frequencies omega_j and mass-normalised mode values at the point,
  psi_j = q^T phi_j (q: the mean over the ball's contact disk, :func:`disk_load`);
- its static compliance at the point, c = q^T K^-1 q = sum over *every* mode of psi_j^2/omega_j^2
  (one sparse solve), and q^T M^-1 q = sum over every mode of psi_j^2; the modes not computed
  enter through ``residual_flexibility = c - sum_kept psi^2/omega^2`` and
  ``residual_mass = q^T M^-1 q - sum_kept psi^2``, as a frame's do.

The static stiffness ``1/c`` is the bed's stiffness at the point (``stringbed_stiffness_n_m``).
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np

from fem_racket.strings.bed import StringBed
from fem_racket.strings.membrane import bed_mesh, disk_load, unit_modes

__all__ = [
    "DEFAULT_BED_MODES",
    "DEFAULT_REFINE",
    "BedPointData",
    "bed_point_data",
    "edge_transmission",
]

#: Fixed-edge modes computed by default (the rest enter through the residuals).
DEFAULT_BED_MODES = 40
#: Refinements of the disk mesh by default (1 024 quadratic triangles, 2 113 nodes).
DEFAULT_REFINE = 4


@dataclass(frozen=True, eq=False)
class BedPointData:
    """A bed's modal data at impact points (see the module docstring).

    Attributes
    ----------
    omega : ndarray, shape (m,)
        Fixed-edge angular frequencies, ascending [rad/s].
    values : ndarray, shape (p, m)
        Mode values at each point (disk means) [1/sqrt(kg)].
    compliance : ndarray, shape (p,)
        Static compliance c at each point [m/N].
    residual_flexibility, residual_mass : ndarray, shape (p,)
        Sums of psi^2/omega^2 [s^2/kg] and psi^2 [1/kg] over the modes not in ``omega``.
    shapes : ndarray, shape (n, m)
        Mass-normalised mode shapes on the interior DOFs [1/sqrt(kg)] (for pictures).
    residual_shapes : ndarray, shape (n, p)
        Static displacement of the modes not in ``omega`` under a unit load at each point
        [m/N]: K^-1 q - sum_kept phi psi / omega^2.
    """

    omega: np.ndarray
    values: np.ndarray
    compliance: np.ndarray
    residual_flexibility: np.ndarray
    residual_mass: np.ndarray
    shapes: np.ndarray
    residual_shapes: np.ndarray

    @property
    def stiffness(self) -> np.ndarray:
        """Static stiffness 1/c at each point [N/m]."""
        return 1.0 / self.compliance

    @property
    def frequencies_hz(self) -> np.ndarray:
        """Fixed-edge frequencies [Hz]."""
        return self.omega / (2.0 * math.pi)


def bed_point_data(
    bed: StringBed,
    points: np.ndarray,
    modes: int = DEFAULT_BED_MODES,
    refine: int = DEFAULT_REFINE,
) -> BedPointData:
    """The bed's modes and static totals at ``points`` (shape (p, 2): x along the racket, y
    across, from the head's centre [m]).

    Parameters
    ----------
    bed : StringBed
    points : array_like, shape (p, 2) or (2,)
        Impact points [m].
    modes : int
        Fixed-edge modes computed (the others enter through the residuals).
    refine : int
        Refinements of the disk mesh (:func:`fem_racket.strings.membrane.bed_mesh`).
    """
    from scipy.sparse.linalg import splu

    pts = np.atleast_2d(np.asarray(points, dtype=float))
    L, W = float(bed.head_length_m), float(bed.head_width_m)
    ratio = float(bed.n_x / bed.n_y)
    mesh = bed_mesh(L, W, refine)
    q = disk_load(mesh, pts, bed.load_radius_m)
    K = (ratio * mesh.Kxx + mesh.Kyy).tocsc()
    u_unit = splu(K).solve(q)
    c_unit = np.einsum("ij,ij->j", q, u_unit)
    m_unit = np.einsum("ij,ij->j", q, splu(mesh.M1.tocsc()).solve(q))
    w_u, phi = unit_modes(L, W, ratio, refine, int(modes))
    v_u = q.T @ phi  # (p, m)
    scale_w = math.sqrt(bed.n_y / bed.rho_s)
    flex = np.maximum(c_unit - (v_u**2 / w_u**2).sum(axis=1), 0.0) / bed.n_y
    mass = np.maximum(m_unit - (v_u**2).sum(axis=1), 0.0) / bed.rho_s
    residual = (u_unit - phi @ (v_u / w_u**2).T) / bed.n_y
    return BedPointData(
        w_u * scale_w,
        v_u / math.sqrt(bed.rho_s),
        c_unit / bed.n_y,
        flex,
        mass,
        phi / math.sqrt(bed.rho_s),
        residual,
    )


def edge_transmission(
    bed: StringBed, points: np.ndarray, refine: int = DEFAULT_REFINE
) -> tuple[np.ndarray, np.ndarray]:
    """The bed's static edge transmission to ``points``: the edge DOFs' positions (n_e, 2) [m,
    from the head's centre] and weights T (p, n_e) [-] such that a static edge displacement
    u_e moves the bed's mean over the ball's disk by ``T @ u_e``::

        T = q_e - K_ei K_ii^-1 q_i      (sum of T = 1: a uniform edge displacement translates)

    By reciprocity T also spreads the contact force over the edge (the reactions on the frame).
    """
    from scipy.sparse.linalg import splu

    pts = np.atleast_2d(np.asarray(points, dtype=float))
    mesh = bed_mesh(float(bed.head_length_m), float(bed.head_width_m), refine)
    q = disk_load(mesh, pts, bed.load_radius_m, full=True)
    ratio = float(bed.n_x / bed.n_y)
    K_ii = (ratio * mesh.Kxx + mesh.Kyy).tocsc()
    K_ie = ratio * mesh.Kxx_ib + mesh.Kyy_ib
    z = splu(K_ii).solve(np.ascontiguousarray(q[mesh.interior]))
    T = q[mesh.edge] - K_ie.T @ z
    return mesh.edge_points, np.asarray(T).T
