"""Finite-element forms and assembly for the Euler-Bernoulli frame (scikit-fem).

Weak form of the free-free beam ``(EI w'')'' + rhoA w_tt = f``::

    K: a(w, v) = int EI w'' v'' dx          M: m(w, v) = int rhoA w v dx

discretised with cubic Hermite elements (``ElementLineHermite``: deflection ``u`` and slope
``u_x`` at every node). EI and rhoA are constant per cell. The point vector ``g(x)`` holds the
shape functions at ``x``, so ``w(x) = g(x) . q`` for any x, node or not.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property

import numpy as np
import scipy.sparse as sp
from skfem import Basis, BilinearForm, ElementLineHermite, ElementLineP0, MeshLine, asm
from skfem.helpers import dd, ddot

from fem_racket.display import short_repr
from fem_racket.frame.mesh import FrameMesh
from fem_racket.validation import InputError, show

__all__ = ["FrameFE", "assemble", "bending", "mass"]


@BilinearForm
def bending(u, v, w):
    """Bending stiffness integrand EI u'' v'' [N m^2 / m^4 per unit length]."""
    return w["EI"] * ddot(dd(u), dd(v))


@BilinearForm
def mass(u, v, w):
    """Consistent mass integrand rhoA u v [kg/m]."""
    return w["rhoA"] * u * v


@dataclass(frozen=True, eq=False)
class FrameFE:
    """Assembled frame: scikit-fem basis, stiffness K [N/m] and mass M [kg] (sparse CSR)."""

    mesh: FrameMesh
    basis: Basis
    K: sp.csr_matrix
    M: sp.csr_matrix

    def __repr__(self) -> str:
        return short_repr("FrameFE", [("mesh", repr(self.mesh)), ("dofs", str(self.ndof))])

    @property
    def ndof(self) -> int:
        """Number of frame DOFs (2 per node)."""
        return int(self.basis.N)

    @cached_property
    def deflection_dofs(self) -> np.ndarray:
        """DOF index of the deflection ``u`` at each node [m]."""
        return self.basis.nodal_dofs[0]

    @cached_property
    def slope_dofs(self) -> np.ndarray:
        """DOF index of the slope ``u_x`` at each node [rad]."""
        return self.basis.nodal_dofs[1]

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


def assemble(mesh: FrameMesh) -> FrameFE:
    """Assemble K and M of ``mesh`` with per-cell EI and rhoA.

    Per-cell data is passed as a P0 field (a plain 1-D array would be read as a DOF vector).
    """
    skmesh = MeshLine(np.asarray(mesh.points, dtype=float))
    basis = Basis(skmesh, ElementLineHermite())
    p0 = basis.with_element(ElementLineP0())
    K = asm(bending, basis, EI=p0.interpolate(np.asarray(mesh.EI)))
    M = asm(mass, basis, rhoA=p0.interpolate(np.asarray(mesh.rhoA)))
    return FrameFE(mesh=mesh, basis=basis, K=K.tocsr(), M=M.tocsr())
