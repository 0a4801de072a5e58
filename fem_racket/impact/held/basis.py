"""The modes of the hand-held racket: undamped modes of frame + hand, with the grip damping in
modal coordinates (:class:`HeldBasis`), computed once per racket and hand.

The held structure (:mod:`fem_racket.frame.hand`) has two rigid-body modes of frame + hand (the
grip layer is not stretched) and flexible modes omega_f, mass normalised; the grip damping
becomes a full matrix D = Phi_f^T C_held Phi_f (not modal), which acts on no rigid mode. The
impacts on it: :mod:`fem_racket.impact.held.modal`.
"""

from __future__ import annotations

from dataclasses import dataclass, field

import numpy as np

from fem_racket.frame.fe import FrameFE
from fem_racket.frame.hand import Hand, held_frame
from fem_racket.validation import AccuracyError, InputError, show

__all__ = ["HeldBasis", "held_basis"]


#: The second eigenvalue of (K_held, M_held) (a rigid-body mode) must be below this fraction of
#: the third (the first flexible mode).
RIGID = 1e-6


@dataclass(frozen=True, eq=False)
class HeldBasis:
    """Undamped modes of frame + hand with the grip damping in modal coordinates.

    Attributes
    ----------
    fe : FrameFE
    hand : Hand
    rigid : ndarray, shape (n + 2, 2)
        Mass-normalised rigid-body modes (frame DOFs, then u_h, theta_h).
    shapes : ndarray, shape (n + 2, m)
        Mass-normalised flexible modes, ascending.
    omega : ndarray, shape (m,)
        Their angular frequencies [rad/s].
    damping : ndarray, shape (m, m)
        D = Phi_f^T C_held Phi_f [1/s].
    """

    fe: FrameFE
    hand: Hand
    rigid: np.ndarray
    shapes: np.ndarray
    omega: np.ndarray
    damping: np.ndarray
    _free: dict[int, tuple[np.ndarray, np.ndarray, np.ndarray]] = field(
        default_factory=dict, repr=False
    )

    @property
    def hand_row(self) -> int:
        """Index of the hand's translation u_h among the DOFs."""
        return self.fe.ndof

    def free_eig(self, n: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """Eigenvalues mu, eigenvectors W and W^-1 of B for the lowest ``n`` flexible modes, cached
        per n: the free vibration after separation, y' = B y, B = [[0, I], [-Omega^2, -D]]."""
        if n not in self._free:
            B = np.zeros((2 * n, 2 * n))
            B[:n, n:] = np.eye(n)
            B[n:, :n] = -np.diag(self.omega[:n] ** 2)
            B[n:, n:] = -self.damping[:n, :n]
            mu, W = np.linalg.eig(B)
            self._free[n] = (mu, W, np.linalg.inv(W))
        return self._free[n]


def held_basis(fe: FrameFE, hand: Hand) -> HeldBasis:
    """The modes of the frame with ``hand`` on its grip ; once per racket.

    The grip layer must have stiffness: without it the hand is a free body whose rigid motion
    the grip damping would couple to the frame's.
    """
    if not hand.stiffness > 0.0:
        raise InputError(
            f"grip stiffness = {show(hand.stiffness)} N/m^2 is not allowed with the modal held "
            "solver: must be > 0 (use solver 'cvode' or 'bdf': fem_racket.simulate_held)",
            parameter="grip stiffness",
            value=hand.stiffness,
        )
    import scipy.linalg as sla  # here, not at import: the CLI's --help stays without scipy

    held = held_frame(fe, hand)
    w2, phi = sla.eigh(held.K, held.M)
    # With a stiff grip layer frame + hand has exactly two rigid-body modes (zero up to
    # round-off, ~1e-16 of the largest eigenvalue), far below the first flexible one.
    if not abs(w2[1]) < RIGID * w2[2]:
        raise AccuracyError(
            "the held racket's rigid-body modes are not separated from its flexible ones "
            f"(eigenvalues {w2[1]:.3g} and {w2[2]:.3g} rad^2/s^2); use solver 'cvode' or 'bdf' "
            "(fem_racket.simulate_held)"
        )
    shapes = phi[:, 2:]
    return HeldBasis(
        fe=fe,
        hand=hand,
        rigid=phi[:, :2],
        shapes=shapes,
        omega=np.sqrt(w2[2:]),
        damping=shapes.T @ held.C @ shapes,
    )
