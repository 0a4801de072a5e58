"""A frame's modes at impact points, in the form the batched engine takes, cached per process.

The engine (:mod:`fem_racket.impact.exact.engine`) needs, per impact point x_i, only the structure's
flexible angular frequencies omega_f, the mass-normalised mode values a_f = phi_f(x_i), the sum
of the rigid modes' squared values (1/m_R + d^2/I_R for a free frame, d = x_i - x_CG) and, when
not every mode was computed, the totals of the missing modes' a^2/omega^2 and a^2. For a frame
model these come from its free-free modes (:meth:`fem_racket.frame.model.FrameModel.modes`, the
lowest n computed once and cached) and two sparse static solves per impact point::

    sum_all a_f^2 / omega_f^2 = g^T u,   K u = g - M R R^T g   (rigid modes R removed)
    sum_all a_f^2             = g^T M^-1 g - sum_r a_r^2

(g: the Hermite point vector at x_i; the solution u of the singular K is fixed by pinning the
deflection at both ends and then made M-orthogonal to R). A structure with more parts (a hand,
added masses) supplies the same quantities from its own modes.

Scaling every EI by s scales omega by sqrt(s) and the flexibility by 1/s and leaves the shapes:
the data here is for the model as given; the engine applies s per case.
"""

from __future__ import annotations

import weakref
from collections.abc import Callable
from dataclasses import dataclass
from typing import Any

import numpy as np

from fem_racket.frame.model import FrameModel

__all__ = ["ModalData", "clear_cache", "frame_modal_data"]

#: Flexible modes first asked of a model; doubled until they reach the cut-off frequency.
FIRST_MODES = 24


@dataclass(frozen=True, eq=False)
class ModalData:
    """What the engine needs of a structure at a set of impact points.

    Attributes
    ----------
    omega : ndarray, shape (m,)
        Flexible angular frequencies, ascending [rad/s].
    values : ndarray, shape (p, m)
        Mode values at each impact point [1/sqrt(kg)].
    rigid : ndarray, shape (p,)
        Sum of the rigid modes' squared values at each point [1/kg].
    residual_flexibility, residual_mass : ndarray, shape (p,)
        Sum of a^2/omega^2 [s^2/kg] and of a^2 [1/kg] over the modes not in ``omega``.
    """

    omega: np.ndarray
    values: np.ndarray
    rigid: np.ndarray
    residual_flexibility: np.ndarray
    residual_mass: np.ndarray


# Per model: the static totals per impact point (positions as x/L).
_TOTALS: weakref.WeakKeyDictionary = weakref.WeakKeyDictionary()
_SOLVERS: weakref.WeakKeyDictionary = weakref.WeakKeyDictionary()


def clear_cache() -> None:
    """Forget the static solves kept for the models of this process."""
    _TOTALS.clear()
    _SOLVERS.clear()


def _factorised(model: FrameModel):
    """(solve K with both end deflections pinned, solve M), factorised once per model."""
    solvers = _SOLVERS.get(model)
    if solvers is None:
        import scipy.sparse.linalg as spla

        fe = model.fe
        u = fe.deflection_dofs
        free = np.setdiff1d(np.arange(fe.ndof), [u[0], u[-1]])
        K = fe.K.tocsc()[free][:, free].tocsc()
        solvers = (free, spla.splu(K).solve, spla.splu(fe.M.tocsc()).solve)
        _SOLVERS[model] = solvers
    return solvers


def _totals(model: FrameModel, positions: np.ndarray, R: np.ndarray) -> np.ndarray:
    """Sum over every flexible mode of a^2/omega^2 and of a^2 at each position, shape (p, 2)."""
    cache = _TOTALS.setdefault(model, {})
    missing = [float(p) for p in positions if float(p) not in cache]
    if missing:
        fe = model.fe
        free, solve_k, solve_m = _factorised(model)
        G = fe.field_matrix(np.asarray(missing) * fe.mesh.length, 0).toarray().T  # (ndof, p)
        f = G - fe.M @ (R @ (R.T @ G))
        u = np.zeros_like(G)
        u[free] = solve_k(np.ascontiguousarray(f[free]))
        u -= R @ (R.T @ (fe.M @ u))
        flex = np.einsum("ij,ij->j", G, u)
        rig = ((R.T @ G) ** 2).sum(axis=0)
        mass = np.einsum("ij,ij->j", G, solve_m(G)) - rig
        for p, a, b in zip(missing, flex, mass, strict=True):
            cache[p] = (a, b)
    return np.array([cache[float(p)] for p in positions])


def modes_past(modes: Callable[[int], Any], cap: int, cutoff: float) -> Any:
    """``modes(n)`` for n = :data:`FIRST_MODES`, doubled (at most ``cap``) until the highest
    angular frequency ``omega[-1]`` reaches ``cutoff`` [rad/s] or all ``cap`` modes are in."""
    n = min(FIRST_MODES, cap)
    found = modes(n)
    while found.omega.size < cap and found.omega[-1] < cutoff:
        n = min(2 * n, cap)
        found = modes(n)
    return found


def frame_modal_data(
    model: FrameModel, positions: np.ndarray, cutoff: float | None, limit: int | None = None
) -> ModalData:
    """Modes of ``model`` at impact points ``positions`` (x/L) up to angular frequency ``cutoff``.

    Parameters
    ----------
    model : FrameModel
    positions : ndarray
        Impact points x/L.
    cutoff : float or None
        Every mode below it is included [rad/s]; the others only through their totals (static
        solves). None: every mode (or ``limit``), no totals.
    limit : int, optional
        Exactly this many flexible modes (all when fewer), the others left out entirely (a
        plain truncation, as ``simulate(modes=...)``); ``cutoff`` is then not used.
    """
    positions = np.asarray(positions, dtype=float)
    n_flex = model.fe.ndof - 2
    cap = n_flex if limit is None else min(int(limit), n_flex)
    fm = (
        model.modes(cap)
        if cutoff is None or limit is not None
        else modes_past(model.modes, cap, cutoff)
    )
    x = positions * model.mesh.length
    values = model.fe.field_values(x, fm.shapes)
    rigid = (model.fe.field_values(x, fm.rigid) ** 2).sum(axis=1)
    zero = np.zeros(positions.size)
    if cutoff is None or fm.omega.size >= cap or limit is not None:
        return ModalData(fm.omega, values, rigid, zero, zero)
    totals = _totals(model, positions, fm.rigid)
    flex = np.maximum(totals[:, 0] - (values**2 / fm.omega**2).sum(axis=1), 0.0)
    mass = np.maximum(totals[:, 1] - (values**2).sum(axis=1), 0.0)
    return ModalData(fm.omega, values, rigid, flex, mass)
