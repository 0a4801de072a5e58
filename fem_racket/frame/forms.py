"""Finite-element forms and assembly for the Euler-Bernoulli frame (scikit-fem).

Weak form of the free-free beam ``(EI w'')'' + rhoA w_tt = f``::

    K: a(w, v) = int EI w'' v'' dx          M: m(w, v) = int rhoA w v dx

discretised with cubic Hermite elements (``ElementLineHermite``: deflection ``u`` and slope
``u_x`` at every node, see :mod:`fem_racket.frame.fe`). EI and rhoA are constant per cell.
Impacts use the closed-form element matrices of :mod:`fem_racket.frame.hermite` (the same
integrals, exact to round-off on any mesh); this module is the scikit-fem reference they are
tested against, and is imported only where it is used.
"""

from __future__ import annotations

import numpy as np
from skfem import BilinearForm, ElementLineP0, asm
from skfem.helpers import dd, ddot

from fem_racket.frame.fe import FrameFE, hermite_basis
from fem_racket.frame.mesh import FrameMesh

__all__ = ["FrameFE", "assemble", "bending", "mass"]


@BilinearForm
def bending(u, v, w):
    """Bending stiffness integrand EI u'' v'' [N m^2 / m^4 per unit length]."""
    return w["EI"] * ddot(dd(u), dd(v))


@BilinearForm
def mass(u, v, w):
    """Consistent mass integrand rhoA u v [kg/m]."""
    return w["rhoA"] * u * v


def assemble(mesh: FrameMesh) -> FrameFE:
    """Assemble K and M of ``mesh`` with per-cell EI and rhoA by scikit-fem.

    Per-cell data is passed as a P0 field (a plain 1-D array would be read as a DOF vector).
    """
    basis = hermite_basis(mesh.points)
    p0 = basis.with_element(ElementLineP0())
    K = asm(bending, basis, EI=p0.interpolate(np.asarray(mesh.EI)))
    M = asm(mass, basis, rhoA=p0.interpolate(np.asarray(mesh.rhoA)))
    return FrameFE.from_matrices(mesh, K.tocsr(), M.tocsr())
