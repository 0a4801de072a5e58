"""Natural modes of the coupled ball + frame system and the modal split of the ball velocity.

Kawazoe & Kanda (1997), section 4.2. Without damping (zeta = 0) the ball + free frame system in
the frame's mass-normalised free-free modal coordinates x = [u_B, eta] (see
:func:`fem_racket.impact.system.modal_system`) is::

    M x'' + K x = 0,   M = diag(m_B, 1, ..., 1),   K = diag(0, omega_f^2) + K_CB h h^T,
    h = [1, -a],       a = mode shapes at the impact point.

Its mass-normalised eigenvectors psi_j (eigenvalues Omega_j^2) and the initial state x(0) = 0,
x'(0) = V_B0 e_0 give the ball velocity as a sum of system modes (eq 13)::

    dX_1/dt = V_T + V_R + V_1 cos Omega_1 t + V_2 cos Omega_2 t + ...      (13)
    V_j = m_B V_B0 psi_j[0]^2

The two zero-frequency system modes (the frame moving rigidly with the ball riding on an
undeformed spring) carry V_T + V_R: V_T is the projection on the common translation (eq 8),
V_R the rest of that two-dimensional space (eq 9). Since sum_j psi_j psi_j^T = M^-1, the terms
add up to the impact speed at t = 0::

    V_B0 = V_T + V_R + V_1 + V_2 + ...                                       (14)
    V_I  = V_1 + V_2 + ...                                                   (15)

where V_I is the rigid frame's vibration term (eq 10): the zero-frequency space does not depend on
the frame's rigidity. When the impact point is a node of frame mode k (a_k = 0) that mode does
not couple to the ball: Omega = omega_k is a system frequency and its V vanishes (Figs 11b, 12b).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from fem_racket.contact.linear import Ball, LinearContact
from fem_racket.display import number, short_repr
from fem_racket.frame.model import DEFAULT_MODES, FrameModel
from fem_racket.impact.problem import Impact

__all__ = ["CoupledModes", "coupled_modes"]

#: Relative size below which a system eigenvalue is taken as a rigid-body zero.
ZERO_TOL = 1e-9


@dataclass(frozen=True, eq=False)
class CoupledModes:
    """Undamped natural modes of ball + free frame for one impact point.

    Attributes
    ----------
    omega : ndarray, shape (n,)
        System angular frequencies Omega_j [rad/s], ascending, excluding the two rigid modes.
    shapes : ndarray, shape (1 + m, n)
        Mass-normalised system mode shapes in the coordinates [u_B, eta] (ball, then the
        frame's modal coordinates, rigid modes first).
    velocity_terms : ndarray, shape (n,)
        V_j [m/s] of eq 13 for each system mode.
    v_translation, v_rotation : float
        V_T and V_R [m/s] (eqs 8-9).
    frame_shapes : ndarray, shape (ndof, m)
        The frame's free-free shapes (rigid, then flexible) used as coordinates.
    frame_omega : ndarray, shape (m,)
        Their angular frequencies [rad/s] (two zeros first).
    impact_values : ndarray, shape (m,)
        a: the frame shapes' deflection at the impact point.
    impact : Impact
        Impact point (x/L) and speed V_B0 [m/s].
    ball_mass, kcb : float
        m_B [kg] and K_CB [N/m].
    """

    omega: np.ndarray
    shapes: np.ndarray
    velocity_terms: np.ndarray
    v_translation: float
    v_rotation: float
    frame_shapes: np.ndarray
    frame_omega: np.ndarray
    impact_values: np.ndarray
    impact: Impact
    ball_mass: float
    kcb: float

    @property
    def frequencies(self) -> np.ndarray:
        """System natural frequencies [Hz] (rigid modes excluded)."""
        return self.omega / (2.0 * np.pi)

    def __repr__(self) -> str:
        f = self.frequencies
        return short_repr(
            "CoupledModes",
            [
                ("position", f"{self.impact.position:g} L"),
                ("speed", f"{self.impact.speed:g} m/s"),
                ("modes", str(f.size)),
                ("f1", f"{number(f[0])} Hz" if f.size else "-"),
                ("V_T", f"{number(self.v_translation)} m/s"),
                ("V_R", f"{number(self.v_rotation)} m/s"),
                ("V_I", f"{number(self.v_vibration)} m/s"),
            ],
        )

    @property
    def frame_frequencies(self) -> np.ndarray:
        """The free frame's own flexible frequencies [Hz]."""
        return self.frame_omega[2:] / (2.0 * np.pi)

    @property
    def v_vibration(self) -> float:
        """V_I = sum of the V_j [m/s] (eq 15)."""
        return float(np.sum(self.velocity_terms))

    def terms(self, t: np.ndarray) -> np.ndarray:
        """The terms of eq 13 at times ``t`` [s]: columns V_T, V_R, V_1 cos Omega_1 t, ... [m/s].

        Returns
        -------
        ndarray, shape (len(t), 2 + n)
        """
        t = np.atleast_1d(np.asarray(t, dtype=float))
        vib = self.velocity_terms * np.cos(np.outer(t, self.omega))
        rig = np.broadcast_to([self.v_translation, self.v_rotation], (t.size, 2))
        return np.hstack([rig, vib])

    def ball_velocity(self, t: np.ndarray) -> np.ndarray:
        """dX_1/dt of eq 13 at times ``t`` [s], in m/s (undamped ball on the strings)."""
        return self.terms(t).sum(axis=1)

    def deflection(self, t: np.ndarray) -> np.ndarray:
        """Spring deflection delta(t) = u_B - w(x_i) [m] of the undamped impact."""
        t = np.atleast_1d(np.asarray(t, dtype=float))
        h = np.concatenate([[1.0], -self.impact_values])
        amp = self.ball_mass * self.impact.speed * self.shapes[0] * (h @ self.shapes) / self.omega
        return np.sin(np.outer(t, self.omega)) @ amp

    def ball_amplitude(self, j: int) -> float:
        """Ball displacement in system mode ``j`` (0-based, flexible modes) [m per unit mode]."""
        return float(self.shapes[0, j])

    def frame_dofs(self, j: int) -> np.ndarray:
        """Frame Hermite DOFs of system mode ``j`` (0-based, flexible modes)."""
        return self.frame_shapes @ self.shapes[1:, j]


def coupled_modes(
    model: FrameModel,
    position: float,
    *,
    speed: float = 20.0,
    ball_mass: float | None = None,
    kcb: float | None = None,
    modes: int | None = DEFAULT_MODES,
) -> CoupledModes:
    """Natural modes of the undamped ball + frame system and the V_j of eq 13.

    Parameters
    ----------
    model : FrameModel
        The frame (its free-free modes are reused).
    position : float
        Impact point x/L from the grip end, in [0, 1].
    speed : float
        Incident ball speed V_B0 [m/s]; also sets K_CB when ``kcb`` is None.
    ball_mass : float, optional
        m_B [kg]; 0.057 by default.
    kcb : float, optional
        K_CB [N/m]; :func:`fem_racket.contact.linear.kcb_from_speed` when None.
    modes : int or None
        Flexible frame modes kept (None: all).

    Returns
    -------
    CoupledModes
    """
    import scipy.linalg as sla

    impact = Impact(position, speed)
    m_b = Ball().mass if ball_mass is None else Ball(ball_mass).mass
    k_cb = LinearContact.for_speed(impact.speed, kcb=kcb).stiffness
    fm = model.modes(modes)
    phi, om = fm.all_shapes, fm.all_omega
    a = phi.T @ model.fe.point_vector(position * model.mesh.length)
    h = np.concatenate([[1.0], -a])
    mdiag = np.concatenate([[m_b], np.ones(a.size)])
    K = np.diag(np.concatenate([[0.0], om**2])) + k_cb * np.outer(h, h)
    lam, psi = sla.eigh(K, np.diag(mdiag))
    psi = psi / np.sqrt(np.einsum("ij,i,ij->j", psi, mdiag, psi))
    zero = np.abs(lam) <= ZERO_TOL * np.max(np.abs(lam))
    if int(zero.sum()) != 2:
        raise RuntimeError(f"expected 2 rigid system modes, found {int(zero.sum())}")
    v0 = impact.speed
    rigid_total = m_b * v0 * float(np.sum(psi[0, zero] ** 2))
    # Common translation: the frame's translation mode (index 0) with the ball riding along.
    tr = np.zeros(a.size + 1)
    tr[1] = 1.0
    tr[0] = a[0]
    v_t = m_b * v0 * tr[0] ** 2 / float(tr @ (mdiag * tr))
    flex = ~zero
    shapes = psi[:, flex]
    shapes = shapes * np.where(shapes[0] < 0.0, -1.0, 1.0)  # ball moves positively
    return CoupledModes(
        omega=np.sqrt(lam[flex]),
        shapes=shapes,
        velocity_terms=m_b * v0 * shapes[0] ** 2,
        v_translation=v_t,
        v_rotation=rigid_total - v_t,
        frame_shapes=phi,
        frame_omega=om,
        impact_values=a,
        impact=impact,
        ball_mass=m_b,
        kcb=k_cb,
    )
