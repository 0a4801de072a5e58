"""The assembled frame: stiffness and mass on the cubic Hermite DOFs, and fields from them.

Cubic Hermite elements carry the deflection ``u`` and the slope ``u_x`` at every node, numbered
node by node: ``u`` of node i is DOF 2i and ``u_x`` is DOF 2i + 1 (scikit-fem's numbering of
``ElementLineHermite`` on a line mesh, so its basis and these matrices agree). The point vector
``g(x)`` holds the shape functions at ``x``, so ``w(x) = g(x) . q`` for any x, node or not.

K and M come from :func:`fem_racket.frame.hermite.assemble_closed_form` (closed-form element
matrices, what :class:`~fem_racket.frame.model.FrameModel` uses) or from scikit-fem's weak forms
(:func:`fem_racket.frame.forms.assemble`); scikit-fem itself is imported only when its basis is
asked for, so an impact never pays for it.
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

__all__ = ["FrameFE", "hermite_basis", "nodal_dofs"]


def nodal_dofs(n_nodes: int) -> tuple[np.ndarray, np.ndarray]:
    """DOF indices of the deflection ``u`` and of the slope ``u_x`` at each of ``n_nodes``."""
    u = np.arange(0, 2 * n_nodes, 2)
    return u, u + 1


def hermite_basis(points: np.ndarray) -> Basis:
    """scikit-fem's cubic Hermite basis on the line mesh through ``points`` [m] (its DOFs are
    numbered as in the module docstring)."""
    from skfem import Basis, ElementLineHermite, MeshLine

    return Basis(MeshLine(np.asarray(points, dtype=float)), ElementLineHermite())


@dataclass(frozen=True, eq=False)
class FrameFE:
    """Assembled frame: stiffness K [N/m] and mass M [kg] (sparse CSR) on the Hermite DOFs of
    ``mesh`` (numbered as in the module docstring)."""

    mesh: FrameMesh
    K: sp.csr_matrix
    M: sp.csr_matrix

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
        return self.field_matrix(np.array([float(x)]), 0).toarray().ravel()

    def field_matrix(self, x: np.ndarray, order: int = 0) -> sp.csr_matrix:
        """Matrix R with R @ q = d^order w / dx^order at the points ``x`` [m].

        Uses the closed-form cubic Hermite shape functions of the cell holding each point, so
        order 0 gives deflection [m], 1 slope [rad], 2 curvature [1/m].
        """
        import scipy.sparse as sp

        if order not in (0, 1, 2):
            raise InputError(f"order = {show(order)} is not allowed: must be 0, 1 or 2")
        x = np.atleast_1d(np.asarray(x, dtype=float))
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
        rows = np.repeat(np.arange(x.size), 4)
        return sp.csr_matrix(
            (np.column_stack(n).ravel(), (rows, cols.ravel())), shape=(x.size, self.ndof)
        )

    def rigid_motion(self, translation: float, rotation: float, about: float = 0.0) -> np.ndarray:
        """DOF vector of the rigid motion w(x) = translation + rotation * (x - about)."""
        q = np.zeros(self.ndof)
        q[self.deflection_dofs] = translation + rotation * (self.mesh.points - about)
        q[self.slope_dofs] = rotation
        return q
