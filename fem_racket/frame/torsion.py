"""The frame in torsion about its long axis: finite elements, free-free modes, polar moment.

St Venant torsion of the free-free shaft ``(GJ theta')' = rhoIp theta_tt`` (theta: twist angle
[rad], GJ [N m^2] and rhoIp [kg m] constant per cell, the mesh cell data ``GJ`` and ``rhoIp``)
in weak form::

    K: a(theta, v) = int GJ theta' v' dx        M: m(theta, v) = int rhoIp theta v dx

on the frame's own 1-D mesh, with scikit-fem's Lagrange line elements (``ElementLineP2``, or
``ElementLineP1``): frequencies converge as h^(2p) (p the polynomial order) against the exact
stepped shaft (:mod:`fem_racket.frame.torsion_exact`) when the steps are nodes. The free-free
problem has one rigid mode, the roll theta = 1/sqrt(I_p) (I_p = int rhoIp dx, the polar moment
about the long axis, the "twistweight" of stringers in kg cm^2), exact in these spaces, and
flexible modes, mass-normalised (``phi.T M phi = I``), sign fixed by a positive tip twist.

Bending and torsion of a straight beam are uncoupled, so the torsion modes add to the bending
ones at an off-axis point: see :mod:`fem_racket.impact.offaxis`.
"""

from __future__ import annotations

from dataclasses import dataclass, field
from functools import cached_property

import numpy as np

from fem_racket.frame.mesh import FrameMesh
from fem_racket.frame.segments import Frame
from fem_racket.lanczos import start_vector
from fem_racket.validation import InputError, check_choice, check_integer

#: What a frame without torsion data needs to be struck off its long axis, for messages.
TORSION_DATA = (
    "a frame with cell data GJ and rhoIp (torsion segments, or a mesh written by "
    "fem-racket fit --twist-weight)"
)

__all__ = ["ORDERS", "TorsionModel", "TorsionModes", "check_off_axis"]

#: Polynomial orders of the torsion elements.
ORDERS = (1, 2)
#: Above this many DOFs the modes come from a sparse shift-invert solve, not a dense one.
DENSE_LIMIT = 2000


@dataclass(frozen=True, eq=False)
class TorsionModes:
    """Free-free torsion modes, mass-normalised.

    Attributes
    ----------
    omega : ndarray, shape (n,)
        Flexible angular frequencies, ascending [rad/s].
    shapes : ndarray, shape (ndof, n)
        Flexible mode shapes (twist per DOF) [rad / sqrt(kg m^2)].
    polar_moment : float
        I_p [kg m^2]; the roll mode is 1/sqrt(I_p) everywhere.
    complete : bool
        True when these are all the model's flexible modes.
    """

    omega: np.ndarray
    shapes: np.ndarray
    polar_moment: float
    complete: bool

    @property
    def frequencies(self) -> np.ndarray:
        """Flexible natural frequencies [Hz]."""
        return self.omega / (2.0 * np.pi)


def check_off_axis(
    frame: FrameMesh | Frame, given: str, where: str = "this frame", allowed: str = ""
) -> None:
    """Refuse what the user ``given`` (``"offset = 0.02 m"``, ``"side_angle = 10.0 deg"``) on
    ``frame`` without torsion data, naming the racket (``where``) and what is allowed there
    (``allowed``; default: the long axis, 0) or what makes it allowed (:data:`TORSION_DATA`)."""
    if frame.has_torsion if isinstance(frame, FrameMesh) else frame.torsion is not None:
        return
    raise InputError(
        f"{given} is not allowed on {where}: it has no torsion data (GJ, rhoIp), so it is struck "
        f"on its long axis only: {allowed or 'must be 0'}; off the axis, give {TORSION_DATA}"
    )


@dataclass(eq=False)
class TorsionModel:
    """The assembled torsion problem of a frame mesh (with cell data GJ and rhoIp).

    Parameters
    ----------
    mesh : FrameMesh
    order : {1, 2}
        Polynomial order of the Lagrange elements.
    """

    mesh: FrameMesh
    order: int = 2
    _modes: dict[int, TorsionModes] = field(default_factory=dict, repr=False)

    def __post_init__(self) -> None:
        if not self.mesh.has_torsion:
            raise InputError(
                "torsion: the frame has no cell data GJ and rhoIp (give torsion segments or "
                "mesh cell data) and so takes impacts on the long axis only (offset 0)"
            )
        check_choice("torsion element order", str(self.order), [str(o) for o in ORDERS])

    @cached_property
    def basis(self):
        """scikit-fem's Lagrange basis of order :attr:`order` on the mesh."""
        from skfem import Basis, ElementLineP1, ElementLineP2, MeshLine

        element = ElementLineP1() if self.order == 1 else ElementLineP2()
        return Basis(MeshLine(np.asarray(self.mesh.points, dtype=float)), element)

    @cached_property
    def matrices(self):
        """(K, M), sparse CSR [N m^2 / m, kg m^2 per unit twist]."""
        from fem_racket.frame.forms import cell_matrices, twist

        return cell_matrices(self.basis, twist, self.mesh.GJ, self.mesh.rhoIp)

    @property
    def ndof(self) -> int:
        """Number of DOFs."""
        return int(self.basis.N)

    @property
    def polar_moment(self) -> float:
        """I_p = int rhoIp dx [kg m^2] (exact for the piecewise-constant cells)."""
        return float(np.sum(self.mesh.rhoIp * np.diff(self.mesh.points)))

    def point_matrix(self, x: np.ndarray) -> np.ndarray:
        """Rows of twist interpolation at points ``x`` [m], shape (p, ndof)."""
        x = np.clip(np.atleast_1d(np.asarray(x, dtype=float)), 0.0, self.mesh.length)
        return self.basis.probes(x[None, :]).toarray()

    def modes(self, n_modes: int | None = None) -> TorsionModes:
        """The lowest ``n_modes`` flexible modes (all when None), cached."""
        n_flex = self.ndof - 1
        n = n_flex if n_modes is None else min(check_integer("modes", n_modes), n_flex)
        for have, m in self._modes.items():
            if have >= n:
                return _truncated(m, n)
        K, M = self.matrices
        if self.ndof <= DENSE_LIMIT:
            from scipy.linalg import eigh

            w2, vec = eigh(K.toarray(), M.toarray(), subset_by_index=(1, n))
        else:
            from scipy.sparse.linalg import eigsh

            w0 = np.sqrt(np.min(self.mesh.GJ / self.mesh.rhoIp)) / self.mesh.length
            w2, vec = eigsh(
                K.tocsc(), n + 1, M.tocsc(), sigma=-(w0**2), which="LM", v0=start_vector(K.shape[0])
            )
            order = np.argsort(w2)[1:]
            w2, vec = w2[order], vec[:, order]
        # mass-normalise again (eigsh's normalisation is looser) and fix signs: tip twist > 0
        vec /= np.sqrt(np.einsum("ij,ij->j", vec, M @ vec))
        tip = self.point_matrix(np.array([self.mesh.length]))[0] @ vec
        vec *= np.where(tip < 0.0, -1.0, 1.0)
        m = TorsionModes(np.sqrt(np.maximum(w2, 0.0)), vec, self.polar_moment, n == n_flex)
        self._modes[n] = m
        return m

    def static_totals(self, x: np.ndarray) -> np.ndarray:
        """Sum over every flexible mode of theta^2/omega^2 [s^2/(kg m^2)] and of theta^2
        [1/(kg m^2)] at points ``x`` [m], shape (p, 2), by two sparse solves (as the bending
        totals of :mod:`fem_racket.impact.point`)."""
        import scipy.sparse.linalg as spla

        K, M = self.matrices
        G = self.point_matrix(x).T  # (ndof, p)
        r = np.ones(self.ndof) / np.sqrt(self.polar_moment)  # the roll mode
        f = G - np.outer(M @ r, r @ G)
        u = np.zeros_like(G)
        u[1:] = spla.splu(K.tocsc()[1:, 1:]).solve(np.ascontiguousarray(f[1:]))
        u -= np.outer(r, r @ (M @ u))
        flex = np.einsum("ij,ij->j", G, u)
        mass = np.einsum("ij,ij->j", G, spla.splu(M.tocsc()).solve(G)) - (r @ G) ** 2
        return np.column_stack([flex, mass])


def _truncated(m: TorsionModes, n: int) -> TorsionModes:
    if n >= m.omega.size:
        return m
    return TorsionModes(m.omega[:n], m.shapes[:, :n], m.polar_moment, False)
