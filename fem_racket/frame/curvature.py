"""Free-free flexible modes in curvature coordinates: the frame's stiffness without cancellation.

Why not ``K phi = omega^2 M phi`` on the Hermite DOFs. For a smooth mode the element forces
``K_e q_e`` are differences of terms ~EI w / h^3 that cancel down to ~EI beta^4 w h: the
assembled K applied to a low mode loses ``(h beta)^-4`` digits (beta^4 = rhoA omega^2 / EI), and
so does every eigen-solver working on it (relative round-off of omega_1^2 ~ eps n^4 / 500 on the
standard racket: 1e-8 at 320 cells, 3e-4 at 5 000, 7e-2 at 20 000; scaling the slope DOFs by h
changes nothing, the cancellation is in the field, not in the units). On top of that ARPACK's own
random start vector differs per process, so fine-mesh results also changed run to run.

The fix is a change of coordinates. A cubic Hermite field on a cell of length h is fixed by the
deflection and slope at its start and its curvature at both ends (k_a, k_b)::

    theta_b = theta_a + h (k_a + k_b) / 2,   w_b = w_a + h theta_a + h^2 (k_a / 3 + k_b / 6)

so the rigid motion (w_0, theta_0) and the 2n cell-end curvatures c are a basis of the 2n + 2
Hermite DOFs: q = T_r r + T_c c, T_c a double cumulative sum. In it the bending energy is exact
and block-diagonal, with no difference taken::

    q^T K q = c^T K_c c,   K_c = blockdiag(EI h / 3 [[1, 1/2], [1/2, 1]]) = L L^T

The flexible modes are M-orthogonal to the rigid ones (projector P = I - R R^T M, R the
mass-normalised rigid modes), so with y = L^T c they are the eigenvectors of the symmetric,
positive semi-definite operator (a discrete Green's function: flexibility times mass)::

    A = L^-1 T_c^T P^T M P T_c L^-T,    A y = mu y,   mu = 1 / omega^2

whose largest eigenvalues are the lowest modes. Applying A costs O(n) (cumulative sums, M from
its diagonals) and only adds and scales well-scaled numbers, so its round-off is ~eps mu_1 and
mode k's omega_k^2 is good to ~eps (omega_k / omega_1)^2 on any mesh (measured: 1e-14 on mode 1
from 5 000 to 70 000 cells). Up to DENSE_LIMIT curvature DOFs (200 cells), or when more than half
of the modes are wanted, A is formed and solved by numpy's dense ``eigh`` (no scipy to import:
``simulate`` starts faster); above, by Lanczos (scipy's ``eigsh``) from a fixed start vector.
Results repeat bit for bit (for a given BLAS thread count; the CLI and sweep workers pin one
thread). Every returned pair is checked a posteriori: ``||A y - mu y|| <= RESIDUAL_TOL ||A||`` (a
backward error; for symmetric A it bounds |d mu| by the same amount, i.e. omega_k^2 to
RESIDUAL_TOL (omega_k / omega_1)^2), else :class:`~fem_racket.validation.AccuracyError`. The
frequencies returned are Rayleigh quotients ``c^T K_c c / q^T M q`` of the final shapes. Shapes
are M-orthogonal to ~eps omega_j omega_k / omega_1^2 (1e-15 among the lowest 80 modes; only a
mesh's very highest modes, wanted only when every mode is kept, are less orthogonal).
"""

from __future__ import annotations

import numpy as np

from fem_racket.frame.fe import FrameFE
from fem_racket.lanczos import start_vector
from fem_racket.validation import AccuracyError, InputError

__all__ = ["DENSE_LIMIT", "DENSE_MAX", "RESIDUAL_TOL", "flexible_modes"]

#: Up to this many curvature DOFs (2 per cell) the operator is formed and solved densely.
DENSE_LIMIT = 400
#: Most curvature DOFs of a dense solve (when more than half of all modes are wanted): 128 MB.
DENSE_MAX = 4000
#: Largest backward error ||A y - mu y|| / ||A|| accepted for a returned mode.
RESIDUAL_TOL = 1e-9
_SQRT3_2 = np.sqrt(3.0) / 2.0


class _Coordinates:
    """Curvature coordinates of a frame: the maps T_c, T_c^T, L^-1, L^-T and the operator A."""

    def __init__(self, fe: FrameFE, rigid: np.ndarray) -> None:
        self.fe = fe
        self.h = np.diff(fe.mesh.points)[:, None]
        self.u, self.t = fe.deflection_dofs, fe.slope_dofs
        self.rigid = rigid
        self.m_rigid = fe.mass_product(rigid)
        #: L = s [[1, 0], [1/2, sqrt(3)/2]] per cell, s = sqrt(EI h / 3).
        self.s = np.sqrt(fe.mesh.EI * np.diff(fe.mesh.points) / 3.0)[:, None]

    @property
    def size(self) -> int:
        """Number of curvature DOFs (2 per cell)."""
        return 2 * self.h.shape[0]

    def nodal(self, c: np.ndarray) -> np.ndarray:
        """q = T_c c: Hermite DOFs of the field with curvatures ``c`` (rows k_a, k_b per cell)
        and w_0 = theta_0 = 0, per column."""
        h = self.h
        ka, kb = c[0::2], c[1::2]
        zero = np.zeros((1, c.shape[1]))
        theta = np.vstack([zero, np.cumsum(h * (ka + kb) / 2.0, axis=0)])
        dw = h * theta[:-1] + h * h * (ka / 3.0 + kb / 6.0)
        q = np.empty((self.fe.ndof, c.shape[1]))
        q[self.u] = np.vstack([zero, np.cumsum(dw, axis=0)])
        q[self.t] = theta
        return q

    def nodal_transpose(self, f: np.ndarray) -> np.ndarray:
        """T_c^T f for nodal loads ``f`` (force on each deflection, moment on each slope)."""
        h = self.h

        def after(a: np.ndarray) -> np.ndarray:  # row e: sum of rows e+1.. of a
            total = np.cumsum(a[::-1], axis=0)[::-1]
            return np.vstack([total[1:], np.zeros((1, a.shape[1]))])

        fw = after(f[self.u])[:-1]  # force beyond the end of each cell
        g = after(f[self.t])[:-1] + after(h * fw)
        out = np.empty((self.size, f.shape[1]))
        out[0::2] = h / 2.0 * g + h * h / 3.0 * fw
        out[1::2] = h / 2.0 * g + h * h / 6.0 * fw
        return out

    def solve_lt(self, y: np.ndarray) -> np.ndarray:
        """c = L^-T y."""
        kb = y[1::2] / (self.s * _SQRT3_2)
        c = np.empty_like(y)
        c[0::2] = y[0::2] / self.s - 0.5 * kb
        c[1::2] = kb
        return c

    def solve_l(self, g: np.ndarray) -> np.ndarray:
        """y = L^-1 g."""
        ya = g[0::2] / self.s
        y = np.empty_like(g)
        y[0::2] = ya
        y[1::2] = (g[1::2] / self.s - 0.5 * ya) / _SQRT3_2
        return y

    def shapes(self, y: np.ndarray) -> np.ndarray:
        """Hermite DOFs of the flexible fields y (rigid content removed): P T_c L^-T y."""
        q = self.nodal(self.solve_lt(y))
        return q - self.rigid @ (self.m_rigid.T @ q)

    def apply(self, y: np.ndarray) -> np.ndarray:
        """A y (columns), see the module docstring."""
        y = np.asarray(y, dtype=float).reshape(self.size, -1)
        q = self.shapes(y)
        return self.solve_l(self.nodal_transpose(self.fe.mass_product(q)))


def flexible_modes(fe: FrameFE, rigid: np.ndarray, n_modes: int) -> tuple[np.ndarray, np.ndarray]:
    """The lowest ``n_modes`` flexible free-free modes (see the module docstring).

    Parameters
    ----------
    fe : FrameFE
        Assembled frame (only M, the mesh and the DOF numbering are used).
    rigid : ndarray, shape (ndof, 2)
        Mass-normalised rigid-body modes.
    n_modes : int
        1 <= n_modes <= 2 * cells.

    Returns
    -------
    omega : ndarray, shape (n_modes,)
        Angular frequencies [rad/s], ascending.
    shapes : ndarray, shape (ndof, n_modes)
        Mass-normalised shapes (phi^T M phi = 1), M-orthogonal to the rigid modes.

    Raises
    ------
    AccuracyError
        When a returned pair fails the residual check.
    """
    coords = _Coordinates(fe, rigid)
    n = coords.size
    dense = n <= DENSE_LIMIT or 2 * n_modes > n
    if dense and n > DENSE_MAX:
        raise InputError(
            f"modes = {n_modes} is not allowed with {fe.mesh.n_elements} elements: at most "
            f"{n // 2} (half of all modes; every mode is computed only up to "
            f"{DENSE_MAX // 2} elements)",
            parameter="modes",
            value=n_modes,
        )
    if dense:  # every pair, the top n_modes kept
        A = coords.apply(np.eye(n))
        mu, y = np.linalg.eigh(0.5 * (A + A.T))
        mu, y = mu[n - n_modes :], y[:, n - n_modes :]
    else:
        import scipy.sparse.linalg as spla

        op = spla.LinearOperator((n, n), matvec=coords.apply, matmat=coords.apply, dtype=float)
        mu, y = spla.eigsh(op, k=n_modes, which="LA", v0=start_vector(n))
    order = np.argsort(-mu, kind="stable")
    mu, y = mu[order], y[:, order]
    y /= np.linalg.norm(y, axis=0)
    residual = np.linalg.norm(coords.apply(y) - y * mu, axis=0)
    bad = ~(residual <= RESIDUAL_TOL * mu[0])
    if np.any(bad):
        k = int(np.argmax(bad))
        raise AccuracyError(
            f"elements = {fe.mesh.n_elements}: free-free mode {k + 1} failed its accuracy check "
            f"(relative residual {residual[k] / mu[0]:.1e} > {RESIDUAL_TOL:.0e}); "
            "this mesh cannot be solved to the stated accuracy"
        )
    q = coords.shapes(y)
    kinetic = np.einsum("ij,ij->j", q, fe.mass_product(q))
    # Rayleigh quotient: strain energy c^T K_c c = y^T y = 1 exactly in these coordinates.
    omega = 1.0 / np.sqrt(kinetic)
    return omega, q * omega
