"""The assembled frame: stiffness and mass on the cubic Hermite DOFs, and fields from them.

Cubic Hermite elements carry the deflection ``u`` and the slope ``u_x`` at every node, numbered
node by node: ``u`` of node i is DOF 2i and ``u_x`` is DOF 2i + 1 (scikit-fem's numbering of
``ElementLineHermite`` on a line mesh, so its basis and these matrices agree). The point vector
``g(x)`` holds the shape functions at ``x``, so ``w(x) = g(x) . q`` for any x, node or not.

K and M come from :func:`fem_racket.frame.hermite.assemble_closed_form` (closed-form element
matrices, what :class:`~fem_racket.frame.model.FrameModel` uses) or from scikit-fem's weak forms
(:func:`fem_racket.frame.forms.assemble`). Both are banded: DOF j couples only with DOFs
j - 3 ... j + 3 (the two nodes of each cell), so they are held as their seven diagonals,
``bands[3 + d, j] = A[j, j + d]``. :meth:`FrameFE.mass_product` applies M from them with the
operations, in the order, of scipy's CSR product (so its results are the same to the bit), and
the sparse matrices :attr:`FrameFE.K` and :attr:`FrameFE.M` are built only when asked for: the
modes and an impact need neither scipy.sparse nor scikit-fem (whose basis is also built only on
demand), which keeps the command line's start short.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property
from typing import TYPE_CHECKING

import numpy as np

from fem_racket.display import short_repr
from fem_racket.frame.mesh import FrameMesh
from fem_racket.validation import InputError, show

if TYPE_CHECKING:
    import scipy.sparse as sp
    from skfem import Basis

__all__ = ["BANDWIDTH", "FrameFE", "bands_of", "hermite_basis", "nodal_dofs"]

#: Farthest diagonal of K and M holding entries: DOF j couples with j - 3 ... j + 3.
BANDWIDTH = 3


def nodal_dofs(n_nodes: int) -> tuple[np.ndarray, np.ndarray]:
    """DOF indices of the deflection ``u`` and of the slope ``u_x`` at each of ``n_nodes``."""
    u = np.arange(0, 2 * n_nodes, 2)
    return u, u + 1


def hermite_basis(points: np.ndarray) -> Basis:
    """scikit-fem's cubic Hermite basis on the line mesh through ``points`` [m] (its DOFs are
    numbered as in the module docstring)."""
    from skfem import Basis, ElementLineHermite, MeshLine

    return Basis(MeshLine(np.asarray(points, dtype=float)), ElementLineHermite())


def bands_of(A: sp.spmatrix) -> np.ndarray:
    """The diagonals d = -3 ... 3 of the banded matrix ``A``: ``bands[3 + d, j] = A[j, j + d]``
    (0 where j + d falls outside), shape (7, n)."""
    n = A.shape[0]
    bands = np.zeros((2 * BANDWIDTH + 1, n))
    for k, d in enumerate(range(-BANDWIDTH, BANDWIDTH + 1)):
        rows = slice(max(0, -d), min(n, n - d))
        bands[k, rows] = A.diagonal(d)
    return bands


def _sparse(bands: np.ndarray) -> sp.csr_matrix:
    """The CSR matrix with these diagonals, storing every coupling of two DOFs of one cell (also
    where the sum over the cells happens to be 0, as an assembly would)."""
    import scipy.sparse as sp

    n = bands.shape[1]
    rows = np.arange(n)
    offsets = np.arange(-BANDWIDTH, BANDWIDTH + 1)[:, None]
    cols = rows + offsets
    # u of node i (even row) couples with node i-1's and i+1's DOFs: d = -2 ... 3; u_x: -3 ... 2
    coupled = np.where(rows % 2 == 0, offsets > -BANDWIDTH, offsets < BANDWIDTH)
    keep = (cols >= 0) & (cols < n) & coupled
    i = np.broadcast_to(rows, bands.shape)[keep]
    return sp.csr_matrix((bands[keep], (i, cols[keep])), shape=(n, n))


@dataclass(frozen=True, eq=False)
class FrameFE:
    """Assembled frame: stiffness K [N/m] and mass M [kg] on the Hermite DOFs of ``mesh``
    (numbered as in the module docstring), held as their diagonals.

    Attributes
    ----------
    mesh : FrameMesh
    K_bands, M_bands : ndarray, shape (7, ndof)
        ``bands[3 + d, j] = K[j, j + d]`` (resp. M), d = -3 ... 3, see :func:`bands_of`.
    """

    mesh: FrameMesh
    K_bands: np.ndarray
    M_bands: np.ndarray

    @classmethod
    def from_matrices(cls, mesh: FrameMesh, K: sp.spmatrix, M: sp.spmatrix) -> FrameFE:
        """The frame with these assembled (banded) matrices."""
        return cls(mesh, bands_of(K), bands_of(M))

    @cached_property
    def K(self) -> sp.csr_matrix:
        """Stiffness matrix [N/m], sparse CSR (built on first use)."""
        return _sparse(self.K_bands)

    @cached_property
    def M(self) -> sp.csr_matrix:
        """Mass matrix [kg], sparse CSR (built on first use)."""
        return _sparse(self.M_bands)

    def mass_product(self, q: np.ndarray) -> np.ndarray:
        """M @ q for a DOF vector or the columns of ``q`` [kg m], without scipy.

        The diagonals are added in the order of the columns of M, starting from zero, as
        scipy's CSR product does, so the result is the same to the bit.
        """
        q = np.asarray(q, dtype=float)
        n = self.ndof
        out = np.zeros(q.shape)
        for k, d in enumerate(range(-BANDWIDTH, BANDWIDTH + 1)):
            lo, hi = max(0, -d), min(n, n - d)
            band = self.M_bands[k, lo:hi]
            out[lo:hi] += (band[:, None] if q.ndim == 2 else band) * q[lo + d : hi + d]
        return out

    def __repr__(self) -> str:
        return short_repr("FrameFE", [("mesh", repr(self.mesh)), ("dofs", str(self.ndof))])

    @property
    def ndof(self) -> int:
        """Number of frame DOFs (2 per node)."""
        return 2 * int(self.mesh.points.size)

    @cached_property
    def deflection_dofs(self) -> np.ndarray:
        """DOF index of the deflection ``u`` at each node [m]."""
        return nodal_dofs(self.mesh.points.size)[0]

    @cached_property
    def slope_dofs(self) -> np.ndarray:
        """DOF index of the slope ``u_x`` at each node [rad]."""
        return nodal_dofs(self.mesh.points.size)[1]

    @cached_property
    def basis(self) -> Basis:
        """scikit-fem's cubic Hermite basis on the mesh (the same DOF numbering)."""
        return hermite_basis(self.mesh.points)

    def point_vector(self, x: float) -> np.ndarray:
        """g(x): Hermite shape functions at ``x`` [m], so that w(x) = g(x) @ q.

        Exact closed-form values (``basis.probes`` gives the same up to ~1e-12 round-off).
        """
        cols, values = self._shape_values(np.array([float(x)]), 0)
        g = np.zeros(self.ndof)
        g[cols[0]] = values[0]
        return g

    def field_matrix(self, x: np.ndarray, order: int = 0) -> sp.csr_matrix:
        """Matrix R with R @ q = d^order w / dx^order at the points ``x`` [m].

        Uses the closed-form cubic Hermite shape functions of the cell holding each point, so
        order 0 gives deflection [m], 1 slope [rad], 2 curvature [1/m].
        """
        import scipy.sparse as sp

        x = np.atleast_1d(np.asarray(x, dtype=float))
        cols, values = self._shape_values(x, order)
        rows = np.repeat(np.arange(x.size), 4)
        return sp.csr_matrix((values.ravel(), (rows, cols.ravel())), shape=(x.size, self.ndof))

    def field_values(self, x: np.ndarray, q: np.ndarray, order: int = 0) -> np.ndarray:
        """``field_matrix(x, order) @ q`` without scipy: d^order w / dx^order at the points
        ``x`` [m] of the field ``q`` (or of each column), shape (x.size,) or (x.size, columns).

        The four shape functions of each point are added in the order of the sparse product, so
        the result is the same to the bit.
        """
        cols, values = self._shape_values(np.atleast_1d(np.asarray(x, dtype=float)), order)
        q = np.asarray(q, dtype=float)
        out = np.zeros((cols.shape[0], *q.shape[1:]))
        for k in range(4):
            out += (values[:, k, None] if q.ndim == 2 else values[:, k]) * q[cols[:, k]]
        return out

    def _shape_values(self, x: np.ndarray, order: int) -> tuple[np.ndarray, np.ndarray]:
        """DOF indices and values of the order-th derivative of the 4 shape functions that are
        nonzero at each point ``x`` [m], both of shape (x.size, 4)."""
        if order not in (0, 1, 2):
            raise InputError(f"order = {show(order)} is not allowed: must be 0, 1 or 2")
        p = self.mesh.points
        tol = 1e-12 * p[-1]
        if np.any((x < -tol) | (x > p[-1] + tol)) or not np.all(np.isfinite(x)):
            raise InputError(f"x is not allowed: every point must lie in [0, {p[-1]:g}] m")
        x = np.clip(x, 0.0, p[-1])
        cell = np.clip(np.searchsorted(p, x, side="right") - 1, 0, p.size - 2)
        h = p[cell + 1] - p[cell]
        s = (x - p[cell]) / h
        if order == 0:
            n = [
                1 - 3 * s**2 + 2 * s**3,
                h * (s - 2 * s**2 + s**3),
                3 * s**2 - 2 * s**3,
                h * (-(s**2) + s**3),
            ]
        elif order == 1:
            n = [
                (-6 * s + 6 * s**2) / h,
                1 - 4 * s + 3 * s**2,
                (6 * s - 6 * s**2) / h,
                -2 * s + 3 * s**2,
            ]
        else:
            n = [(-6 + 12 * s) / h**2, (-4 + 6 * s) / h, (6 - 12 * s) / h**2, (-2 + 6 * s) / h]
        u, ux = self.deflection_dofs, self.slope_dofs
        cols = np.column_stack([u[cell], ux[cell], u[cell + 1], ux[cell + 1]])
        return cols, np.column_stack(n)

    def rigid_motion(self, translation: float, rotation: float, about: float = 0.0) -> np.ndarray:
        """DOF vector of the rigid motion w(x) = translation + rotation * (x - about)."""
        q = np.zeros(self.ndof)
        q[self.deflection_dofs] = translation + rotation * (self.mesh.points - about)
        q[self.slope_dofs] = rotation
        return q
