"""The strings' stretch in the impact: the bed's tension rising with its deflection (CVODE).

The linear bed (:mod:`.point`) keeps each string at its strung tension T. At a
tennis impact's 20-40 mm the strings stretch and their tension rises (measured statically in
:mod:`fem_racket.strings.stiffening`: +9.6 % nylon, +17.8 % polyester at 20 mm). Here the same
averaged (Foeppl/Kirchhoff-Carrier type) stretch acts in the dynamics: with the bed's
coordinates eta (fixed-edge modes and pseudo-mode, shapes S on the mesh, deflection u = S eta
relative to the edge) and the unit-tension matrices Gx = S^T Kxx S, Gy = S^T Kyy S
(:mod:`fem_racket.strings.membrane`), the mains and crosses strain on average by::

    eps_x = eta^T Gx eta / (2 A),   eps_y = eta^T Gy eta / (2 A)     (A: the head's area)

their tension per width rises by ``dN_x = n_m EA eps_x / W``, ``dN_y = n_c EA eps_y / L_h``, and
the bed's coordinates feel the extra force ``-(dN_x Gx + dN_y Gy) eta``. It derives from the
potential ``V = EA (l_x eps_x^2 + l_y eps_y^2) / 2`` (l_x = n_m A / W, l_y = n_c A / L_h: the
strings' total lengths), so the structure stays conservative (``stretch_energy``). Assumptions:
each direction's strain is its mean over the head (no tension wave along a string: the strings'
axial wave crosses the head in ~0.1 ms, well inside the 3-5 ms contact); the stretch is that of
the deflection relative to the edge (the ring's motion does not strain the strings); the ring is
rigid in its plane. EA is the string preset's (:mod:`fem_racket.strings.materials`, typical).

The ball's law (without an internal state) acts between the ball and the bed's point as in
:func:`fem_racket.impact.strung.impact.strung_impact`; CVODE (BDF, analytic Jacobian) integrates
to the law's end condition. With EA -> 0 this is the linear strung racket (``stretch=False``
gives exactly :func:`fem_racket.impact.ode.law_cvode.solve_law_cvode`'s equations).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from fem_racket.contact.law import ContactLaw
from fem_racket.impact.strung.point import StrungPoint
from fem_racket.strings.membrane import bed_mesh
from fem_racket.validation import InputError, show

__all__ = ["BedStretch", "bed_stretch", "solve_stretch", "stretch_energy"]


@dataclass(frozen=True, eq=False)
class BedStretch:
    """The stretch terms of a strung point's bed coordinates (module docstring).

    Attributes
    ----------
    index : ndarray of int
        Positions of the bed's coordinates in :attr:`StrungPoint.omega`.
    Gx, Gy : ndarray, shape (nb, nb)
        S^T Kxx S and S^T Kyy S [1/kg].
    cx, cy : float
        n_m EA / (W A) and n_c EA / (L_h A) [N/m^3]: dN_x = cx eta^T Gx eta / 2 [N/m], and the
        potential is (cx (eta^T Gx eta / 2)^2 + cy (eta^T Gy eta / 2)^2) / 2.
    """

    index: np.ndarray
    Gx: np.ndarray
    Gy: np.ndarray
    cx: float
    cy: float

    def tension_rise(self, eta: np.ndarray) -> tuple[float, float]:
        """(dN_x, dN_y) [N/m] at the bed coordinates ``eta``."""
        return (
            self.cx * float(eta @ self.Gx @ eta) / 2.0,
            self.cy * float(eta @ self.Gy @ eta) / 2.0,
        )

    def energy(self, eta: np.ndarray) -> np.ndarray:
        """The stretch potential V [J] at coordinates ``eta`` (shape (nb,) or (T, nb))."""
        e = np.atleast_2d(eta)
        ex = np.einsum("ti,ij,tj->t", e, self.Gx, e) / 2.0
        ey = np.einsum("ti,ij,tj->t", e, self.Gy, e) / 2.0
        return (self.cx * ex**2 + self.cy * ey**2) / 2.0


def bed_stretch(point: StrungPoint) -> BedStretch:
    """The stretch terms of ``point``'s bed (its string's EA, the head's area and pattern)."""
    bed = point.strings
    mesh = bed_mesh(float(bed.head_length_m), float(bed.head_width_m), point.refine)
    S = point.bed_shapes
    Gx = S.T @ (mesh.Kxx @ S)
    Gy = S.T @ (mesh.Kyy @ S)
    ea, area = bed.material.axial_rigidity_n, bed.area_m2
    cx = bed.mains * ea / (bed.head_width_m * area)
    cy = bed.crosses * ea / (bed.head_length_m * area)
    return BedStretch(np.flatnonzero(point.bed), Gx, Gy, cx, cy)


def solve_stretch(
    point: StrungPoint,
    law: ContactLaw,
    ball_mass: float,
    speed: float,
    *,
    rtol: float = 1e-10,
    atol: float = 1e-13,
) -> tuple[np.ndarray, np.ndarray]:
    """The ball under ``law`` on ``point`` with the strings' stretch, by CVODE.

    Returns the times [s] (from 0 to the contact's end) and the states [u_B, x, u_B', x']
    (x: the structure's coordinates in :attr:`StrungPoint.omega` order).
    """
    from fem_racket.impact.ode.integrators import cvode_bdf
    from fem_racket.impact.system import no_separation

    if law.state is not None:
        raise InputError(
            f"law = {show(law.name)} is not allowed with the strings' stretch: it takes a ball "
            "law without an internal state (linear, hunt-crossley)"
        )
    st = bed_stretch(point)
    b = st.index + 1  # in [u_B, x]
    n = point.omega.size + 1
    h = np.concatenate([[1.0], -point.a])
    minv = np.concatenate([[1.0 / ball_mass], np.ones(n - 1)])
    w2 = np.concatenate([[0.0], point.omega**2])
    meff = 1.0 / (1.0 / ball_mass + np.sum(point.rigid**2))
    t_est = float(law.contact_time_estimate(meff, speed))
    t_max = 40.0 * t_est
    base = np.zeros((2 * n, 2 * n))
    base[:n, n:] = np.eye(n)
    base[n:, :n] = -np.diag(w2)
    mh = minv * h

    def rhs(t: float, y: np.ndarray, yp: np.ndarray) -> None:
        eta = y[b]
        nx, ny = st.tension_rise(eta)
        F = law.force(h @ y[:n], h @ y[n:], 0.0)
        yp[:n] = y[n:]
        yp[n:] = -w2 * y[:n] - mh * F
        yp[n + b] -= nx * (st.Gx @ eta) + ny * (st.Gy @ eta)

    def jac(t: float, y: np.ndarray, yp: np.ndarray, JJ: np.ndarray) -> None:
        eta = y[b]
        nx, ny = st.tension_rise(eta)
        gx, gy = st.Gx @ eta, st.Gy @ eta
        fd, fv, _ = (float(x) for x in law.partials(h @ y[:n], h @ y[n:], 0.0))
        JJ[:, :] = base
        JJ[n:, :n] -= np.outer(mh, h) * fd
        JJ[n:, n:] -= np.outer(mh, h) * fv
        JJ[np.ix_(n + b, b)] -= nx * st.Gx + ny * st.Gy
        JJ[np.ix_(n + b, b)] -= st.cx * np.outer(gx, gx) + st.cy * np.outer(gy, gy)

    def events(t: float, y: np.ndarray, ev: np.ndarray) -> None:
        d, v = h @ y[:n], h @ y[n:]
        ev[0] = law.force(d, v, 0.0) if law.end == "force" else d

    events.terminal = [True]
    events.direction = [-1]
    y0 = np.zeros(2 * n)
    y0[n] = speed
    span = np.linspace(0.0, t_max, 16001)
    sol = cvode_bdf(rhs, jac, events, 1, rtol=rtol, atol=atol, max_num_steps=400000).solve(span, y0)
    if not sol.success:
        raise RuntimeError(f"CVODE failed: {sol.message}")
    if sol.i_events is None or len(sol.i_events) == 0:
        raise no_separation(t_max)
    return np.asarray(sol.t), np.asarray(sol.y)


def stretch_energy(point: StrungPoint, x: np.ndarray) -> np.ndarray:
    """The stretch potential [J] at the structure's coordinates ``x`` (T, n) (0 for a linear
    bed)."""
    if not point.strings.stretch:
        return np.zeros(len(x))
    st = bed_stretch(point)
    return st.energy(x[:, st.index])
