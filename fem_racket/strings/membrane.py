"""The string bed as a finite-element membrane (scikit-fem, quadratic triangles), edge fixed.

Weak form of ``rho_s w'' = N_x w_xx + N_y w_yy + p`` with w = 0 on the head's ellipse::

    K = N_x Kxx + N_y Kyy,   Kxx = int w_x v_x,   Kyy = int w_y v_y,   M = rho_s int w v

The mesh is scikit-fem's unit disk (``MeshTri.init_circle``: refined, boundary nodes pushed to
the circle) mapped to the ellipse x = (L_h/2) X, y = (W/2) Y, so the boundary nodes lie on the
head's outline; element ``ElementTriP2``. Only the ratio N_x/N_y shapes the modes: they are
computed once per head, pattern ratio and mesh for N_y = rho_s = 1 and scaled (omega by
sqrt(N_y/rho_s), mass-normalised shapes by 1/sqrt(rho_s), compliance by 1/N_y), so a tension
sweep reuses them.

The ball loads the bed over a disk of radius a centred on the impact point: its "deflection at the
point" is the disk's mean, ``w_bar = q^T u``, q the load vector of a unit uniform pressure on the
disk divided by the disk's area (polar Gauss quadrature of the disk). The disk must lie on the
meshed bed, a polygon inscribed in the ellipse (:mod:`fem_racket.strings.reach` says where).
The static stiffness k = 1/(q^T K^-1 q) is what a stringbed-stiffness meter reports for that
loading; its closed form on a circular membrane (uniform tension N, radius R) is
``k = 2 pi N / (ln(R/a) + 1/4)`` (mean over the disk of the exact axisymmetric solution; a rigid
disk of radius a gives the textbook ``2 pi N / ln(R/a)``).
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import lru_cache

import numpy as np

from fem_racket.lanczos import start_vector
from fem_racket.strings.edge import bed_edge, clearance
from fem_racket.validation import InputError

__all__ = ["BedMesh", "bed_mesh", "disk_load", "unit_modes"]

#: Radial Gauss points and angles of the disk quadrature. Not exact for the P2 field's kinks
#: across element edges inside the disk: measured error of the static stiffness against the
#: closed form ~5e-4 at refine 4 and ~1e-4 at refine 5 (6 x 32 points gave ~1e-3).
RADIAL_POINTS = 16
ANGLES = 64


@dataclass(frozen=True, eq=False)
class BedMesh:
    """The membrane on one head ellipse: basis, unit matrices and the interior DOFs.

    Attributes
    ----------
    basis : skfem.CellBasis
        P2 basis on the ellipse mesh (coordinates from the head's centre [m]).
    Kxx, Kyy, M1 : scipy.sparse.csr_matrix
        int w_x v_x, int w_y v_y [-] and int w v [m^2] on the interior DOFs.
    interior : ndarray
        The DOFs off the fixed edge.
    semi_axes : (float, float)
        L_h/2 and W/2 [m].
    Kxx_ib, Kyy_ib : scipy.sparse.csr_matrix
        The same forms between the interior and the edge DOFs (the edge's static transmission).
    edge : ndarray
        The edge DOFs.
    edge_lines : (ndarray, ndarray)
        The meshed bed's straight edges as half-planes ``n . p >= h``: inward unit normals n,
        shape (k, 2), and levels h, shape (k,) [m] (the bed is the convex polygon of the
        ellipse's boundary nodes; :func:`fem_racket.strings.edge.bed_edge`).
    """

    basis: object
    Kxx: object
    Kyy: object
    M1: object
    interior: np.ndarray
    semi_axes: tuple[float, float]
    Kxx_ib: object
    Kyy_ib: object
    edge: np.ndarray
    edge_lines: tuple[np.ndarray, np.ndarray]

    @property
    def edge_points(self) -> np.ndarray:
        """(x, y) of the edge DOFs from the head's centre [m], shape (n_edge, 2)."""
        return np.asarray(self.basis.doflocs[:, self.edge]).T


@lru_cache(maxsize=16)
def bed_mesh(length_m: float, width_m: float, refine: int) -> BedMesh:
    """The membrane matrices of the ellipse ``length_m`` x ``width_m`` (``refine`` refinements of
    scikit-fem's disk; 4 gives 1 024 triangles)."""
    from skfem import BilinearForm, CellBasis, ElementTriP2, MeshTri, asm

    disk = MeshTri.init_circle(refine)
    ax, ay = 0.5 * length_m, 0.5 * width_m
    mesh = MeshTri(np.array([ax * disk.p[0], ay * disk.p[1]]), disk.t)
    basis = CellBasis(mesh, ElementTriP2())

    @BilinearForm
    def xx(u, v, _):
        return u.grad[0] * v.grad[0]

    @BilinearForm
    def yy(u, v, _):
        return u.grad[1] * v.grad[1]

    @BilinearForm
    def mass(u, v, _):
        return u * v

    edge = basis.get_dofs().all()
    interior = basis.complement_dofs(edge)
    full = [asm(f, basis) for f in (xx, yy, mass)]
    sub = [m[interior][:, interior].tocsr() for m in full]
    ib = [m[interior][:, edge].tocsr() for m in full[:2]]
    lines = bed_edge(length_m, width_m, refine)
    return BedMesh(basis, *sub, interior, (ax, ay), *ib, edge, lines)


def disk_load(mesh: BedMesh, points: np.ndarray, radius: float, full: bool = False) -> np.ndarray:
    """Load vectors q (interior DOFs, or every DOF when ``full``; one column per point) of a
    unit mean over the disk of ``radius`` [m] around each point (x, y) [m]; a disk off the
    meshed bed is refused (:func:`fem_racket.strings.reach.on_bed` first, to name the
    reachable points)."""
    pts = np.atleast_2d(points)
    off = clearance(mesh.edge_lines, pts) < radius
    if np.any(off):
        x0, y0 = pts[np.argmax(off)]
        raise InputError(
            f"impact point = ({x0:.6g}, {y0:.6g}) m is not allowed: the contact disk of radius "
            f"{radius:g} m must lie on the string bed"
        )
    r, wr = np.polynomial.legendre.leggauss(RADIAL_POINTS)
    r = 0.5 * radius * (r + 1.0)
    wr = 0.5 * radius * wr * r  # r dr
    th = 2.0 * np.pi * np.arange(ANGLES) / ANGLES
    dx = np.outer(r, np.cos(th)).ravel()
    dy = np.outer(r, np.sin(th)).ravel()
    w = np.repeat(wr, ANGLES) * (2.0 * np.pi / ANGLES)
    cols = []
    for x0, y0 in pts:
        P = mesh.basis.probes(np.array([x0 + dx, y0 + dy]))
        q = np.asarray(P.T @ w).ravel() / w.sum()
        cols.append(q if full else q[mesh.interior])
    return np.column_stack(cols)


@lru_cache(maxsize=32)
def unit_modes(
    length_m: float, width_m: float, ratio: float, refine: int, count: int
) -> tuple[np.ndarray, np.ndarray]:
    """The lowest ``count`` fixed-edge modes for N_x = ``ratio``, N_y = 1, rho_s = 1:
    angular frequencies [rad/s in these units] and M1-normalised shapes (interior DOFs)."""
    from scipy.sparse.linalg import eigsh

    mesh = bed_mesh(length_m, width_m, refine)
    K = (ratio * mesh.Kxx + mesh.Kyy).tocsc()
    count = min(count, K.shape[0] - 2)
    v0 = start_vector(K.shape[0])
    lam, phi = eigsh(K, k=count, M=mesh.M1.tocsc(), sigma=0.0, which="LM", v0=v0)
    order = np.argsort(lam)
    lam, phi = lam[order], phi[:, order]
    phi /= np.sqrt(np.einsum("ij,ij->j", phi, mesh.M1 @ phi))
    return np.sqrt(lam), phi
