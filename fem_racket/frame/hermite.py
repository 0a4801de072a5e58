"""Closed-form cubic Hermite beam element matrices, exact to round-off on any mesh.

For a cell of length h with constant EI and rhoA, in the DOF order (w_a, w'_a, w_b, w'_b)::

    K_e = EI / h^3 [[12, 6h, -12, 6h], [6h, 4h^2, -6h, 2h^2],
                    [-12, -6h, 12, -6h], [6h, 2h^2, -6h, 4h^2]]
    M_e = rhoA h / 420 [[156, 22h, 54, -13h], [22h, 4h^2, 13h, -3h^2],
                        [54, 13h, 156, -22h], [-13h, -3h^2, -22h, 4h^2]]

These are the same integrals as :func:`fem_racket.frame.forms.assemble` (``int EI w'' v''`` and
``int rhoA w v``), but scikit-fem's ``ElementLineHermite`` is an ``ElementGlobal``: it builds its
shape functions per cell from monomials in global x, which loses precision as (x / h)^3 grows. The
assembled matrices then differ from the exact ones by ~4e-12 (relative, largest entry) at 20
elements, ~1e-9 at 80, ~5e-7 at 640 and ~1e-2 at 20 000 elements of the standard racket.
:func:`assemble_closed_form` returns the same :class:`~fem_racket.forms.FrameFE` (scikit-fem
basis, same DOF numbering) with exact matrices; :meth:`FrameModel.build` uses it on every mesh.

:func:`strain_energy` evaluates q^T K q as a sum of squares of element curvatures (2-point Gauss,
exact for the linear curvature of a cubic), which avoids the cancellation of q^T (K q) (K q of a
smooth field loses ~(h beta)^-4 of its digits; see :mod:`fem_racket.frame.curvature`).
"""

from __future__ import annotations

from collections import OrderedDict

import numpy as np
import scipy.sparse as sp
from skfem import Basis, ElementLineHermite, MeshLine

from fem_racket.frame.forms import FrameFE
from fem_racket.frame.mesh import FrameMesh

__all__ = ["assemble_closed_form", "rayleigh_frequencies", "strain_energy"]

_K = np.array([[12, 6, -12, 6], [6, 4, -6, 2], [-12, -6, 12, -6], [6, 2, -6, 4]], dtype=float)
_M = np.array(
    [[156, 22, 54, -13], [22, 4, 13, -3], [54, 13, 156, -22], [-13, -3, -22, 4]], dtype=float
)
#: Power of h in each entry of the DOF order (w, w', w, w'): entry (i, j) carries h^(p_i + p_j).
_P = np.array([0, 1, 0, 1])


#: Bases kept for the most recent node sets (building one costs ~1.5 ms, more than assembling:
#: design studies assemble thousands of frames on one mesh).
_BASES: OrderedDict[bytes, Basis] = OrderedDict()
_BASES_KEPT = 8


def _basis(points: np.ndarray) -> Basis:
    """The scikit-fem Hermite basis on ``points``, shared by equal node sets (read-only)."""
    key = points.tobytes()
    basis = _BASES.get(key)
    if basis is None:
        basis = Basis(MeshLine(points), ElementLineHermite())
        _BASES[key] = basis
        if len(_BASES) > _BASES_KEPT:
            _BASES.popitem(last=False)
    else:
        _BASES.move_to_end(key)
    return basis


def _cell_dofs(fe_basis: Basis) -> np.ndarray:
    """DOF indices (w_a, w'_a, w_b, w'_b) of each cell, shape (ncells, 4)."""
    u, ux = fe_basis.nodal_dofs
    return np.column_stack([u[:-1], ux[:-1], u[1:], ux[1:]])


def assemble_closed_form(mesh: FrameMesh) -> FrameFE:
    """K [N/m] and M [kg] of ``mesh`` from the closed-form element matrices (see module doc).

    The returned :class:`~fem_racket.forms.FrameFE` has the same basis and DOF numbering as
    :func:`fem_racket.frame.forms.assemble`; only the round-off of K and M differs.
    """
    p = np.asarray(mesh.points, dtype=float)
    basis = _basis(p)
    h = np.diff(p)
    scale = h[:, None, None] ** (_P[:, None] + _P[None, :])
    ke = (mesh.EI / h**3)[:, None, None] * _K * scale
    me = (mesh.rhoA * h / 420.0)[:, None, None] * _M * scale
    dofs = _cell_dofs(basis)
    rows = np.repeat(dofs, 4, axis=1).ravel()
    cols = np.tile(dofs, (1, 4)).ravel()
    n = basis.N
    K = sp.csr_matrix((ke.ravel(), (rows, cols)), shape=(n, n))
    M = sp.csr_matrix((me.ravel(), (rows, cols)), shape=(n, n))
    return FrameFE(mesh=mesh, basis=basis, K=K, M=M)


def strain_energy(fe: FrameFE, q: np.ndarray) -> np.ndarray:
    """Twice the bending strain energy q^T K q [J] (per column of ``q``), cancellation-free.

    Sums EI * h * (k_a^2 + k_a k_b + k_b^2) / 3 over cells, k_a and k_b being the curvature at the
    cell ends; exact for cubic Hermite fields.
    """
    q = np.asarray(q, dtype=float)
    p = fe.mesh.points
    h = np.diff(p)[:, None] if q.ndim == 2 else np.diff(p)
    u, t = q[fe.deflection_dofs], q[fe.slope_dofs]
    chord = (u[1:] - u[:-1]) / h
    ka = (6.0 * chord - 4.0 * t[:-1] - 2.0 * t[1:]) / h
    kb = (-6.0 * chord + 2.0 * t[:-1] + 4.0 * t[1:]) / h
    ei = fe.mesh.EI[:, None] if q.ndim == 2 else fe.mesh.EI
    return np.sum(ei * h * (ka * ka + ka * kb + kb * kb) / 3.0, axis=0)


def rayleigh_frequencies(fe: FrameFE, shapes: np.ndarray) -> np.ndarray:
    """Rayleigh-quotient frequencies [Hz] of mode ``shapes`` (ndof, n), cancellation-free energy."""
    shapes = np.asarray(shapes, dtype=float)
    kinetic = np.einsum("ij,ij->j", shapes, fe.M @ shapes)
    return np.sqrt(strain_energy(fe, shapes) / kinetic) / (2.0 * np.pi)
