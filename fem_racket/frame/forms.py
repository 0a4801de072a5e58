"""Finite-element forms and assembly for the Euler-Bernoulli frame (scikit-fem).

Weak form of the free-free beam ``(EI w'')'' + rhoA w_tt = f``::

    K: a(w, v) = int EI w'' v'' dx          M: m(w, v) = int rhoA w v dx

discretised with cubic Hermite elements (``ElementLineHermite``: deflection ``u`` and slope
``u_x`` at every node, see :mod:`fem_racket.frame.fe`). EI and rhoA are constant per cell.
Impacts use the closed-form element matrices of :mod:`fem_racket.frame.hermite` (the same
integrals, exact to round-off on any mesh); this module is the scikit-fem reference they are
tested against, and is imported only where it is used. The torsion model
(:mod:`fem_racket.frame.torsion`) assembles its Lagrange forms (:func:`twist` and :func:`mass`)
by the same :func:`cell_matrices`.
"""

from __future__ import annotations

import numpy as np
from skfem import BilinearForm, ElementLineP0, asm
from skfem.helpers import dd, ddot, dot, grad

from fem_racket.frame.fe import FrameFE, hermite_basis
from fem_racket.frame.mesh import FrameMesh

__all__ = ["FrameFE", "assemble", "bending", "cell_matrices", "mass", "twist"]


@BilinearForm
def bending(u, v, w):
    """Bending stiffness integrand EI u'' v'' [N m^2 / m^4 per unit length], EI the per-cell
    ``rigidity``."""
    return w["rigidity"] * ddot(dd(u), dd(v))


@BilinearForm
def twist(u, v, w):
    """Torsion stiffness integrand GJ u' v' [N m^2 / m^2 per unit length], GJ the per-cell
    ``rigidity``."""
    return w["rigidity"] * dot(grad(u), grad(v))


@BilinearForm
def mass(u, v, w):
    """Consistent mass integrand ``density`` u v: rhoA [kg/m] in bending, rhoIp [kg m] in
    torsion."""
    return w["density"] * u * v


def cell_matrices(basis, stiffness, rigidity, density):
    """(K, M), sparse CSR, of the form ``stiffness`` and of :func:`mass` on ``basis``.

    Parameters
    ----------
    basis : skfem.CellBasis
        The basis on the frame's 1-D mesh.
    stiffness : skfem.BilinearForm
        :func:`bending` or :func:`twist`.
    rigidity, density : array_like, shape (cells,)
        Per-cell EI or GJ [N m^2] and rhoA [kg/m] or rhoIp [kg m]; passed as P0 fields (a plain
        1-D array would be read as a DOF vector).
    """
    p0 = basis.with_element(ElementLineP0())
    K = asm(stiffness, basis, rigidity=p0.interpolate(np.asarray(rigidity)))
    M = asm(mass, basis, density=p0.interpolate(np.asarray(density)))
    return K.tocsr(), M.tocsr()


def assemble(mesh: FrameMesh) -> FrameFE:
    """Assemble K and M of ``mesh`` with per-cell EI and rhoA by scikit-fem."""
    K, M = cell_matrices(hermite_basis(mesh.points), bending, mesh.EI, mesh.rhoA)
    return FrameFE.from_matrices(mesh, K, M)
