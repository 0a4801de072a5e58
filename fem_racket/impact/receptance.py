"""The frame seen from the impact point: modal receptance and the integrator's kernels.

With the contact force F piecewise linear on a uniform grid of step h (first-order hold), the
response of every free-free mode (and of the ball, a rigid "mode" of compliance 1/m_B) to a unit
hat function centred on a grid point is a closed form. At lag l >= 1::

    displacement  4 a^2 sin(omega l h) sin^2(omega h / 2) / (omega^3 h)      (rigid: l h^2)
    velocity      4 a^2 cos(omega l h) sin^2(omega h / 2) / (omega^2 h)      (rigid: h)

at lag 0 only the hat's rising half has acted, (omega h - sin omega h)/(omega^3 h) and
2 sin^2(omega h/2)/(omega^2 h) (rigid h^2/6 and h/2), and the first sample's half hat has its own
response (angle addition below). Flexible modes above the cut-off are replaced by one residual
pseudo-mode per case (DESIGN section 9): weight sum a^2 and static flexibility sum a^2/omega^2.
Used by :mod:`fem_racket.impact.general`.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = ["Receptance", "free_motion", "kernels"]


@dataclass(frozen=True, eq=False)
class Receptance:
    """The frame at the impact points of a batch of cases, in free-free modal terms.

    Attributes
    ----------
    omega : ndarray, shape (n,)
        Flexible angular frequencies [rad/s], shared by the batch.
    a : ndarray, shape (C, n)
        Mass-normalised flexible mode shapes at each case's impact point [1/sqrt(kg)].
    rigid : ndarray, shape (C, 2)
        Rigid-mode shapes (translation, rotation about the CG) at the impact point [1/sqrt(kg)].
    ball_mass : ndarray, shape (C,)
        m_B [kg].
    """

    omega: np.ndarray
    a: np.ndarray
    rigid: np.ndarray
    ball_mass: np.ndarray

    @property
    def compliance(self) -> np.ndarray:
        """1/m_B + sum a_r^2 [1/kg]: the ball's and the rigid frame's acceleration per newton."""
        return 1.0 / self.ball_mass + np.sum(self.rigid**2, axis=1)

    @property
    def clamped(self) -> bool:
        """True when there is no frame (a ball on a rigid support)."""
        return self.a.shape[1] == 0 and not np.any(self.rigid)


def _pseudo_mode(rec: Receptance, keep: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Per-case frequency [rad/s] and weight a^2 of the pseudo-mode standing for dropped modes.

    Weight sum a^2 (the dropped modes' high-frequency mobility) and static flexibility
    sum a^2 / omega^2, i.e. omega_r^2 = sum a^2 / sum (a^2 / omega^2) (DESIGN section 9).
    """
    dropped = rec.a[:, ~keep] ** 2
    mob = dropped.sum(axis=1)
    flex = np.sum(dropped / rec.omega[~keep] ** 2, axis=1)
    wr = np.sqrt(mob / np.where(flex > 0, flex, 1.0))
    return np.where(flex > 0, wr, rec.omega[~keep][0]), mob


def _hat_tables(w: np.ndarray, h: float, nsteps: int) -> tuple[np.ndarray, ...]:
    """Per unit a^2, the kernels of modes ``w`` [rad/s], shape w.shape + (N,): Kd, Kv, Hd, Hv."""
    lag = np.arange(nsteps) * h
    wh = w[..., None] * h
    half = 0.5 * wh
    phase = w[..., None] * lag
    sw, cw = np.sin(phase), np.cos(phase)
    s2 = np.sin(half) ** 2
    Kd = 4.0 * s2 / (wh * w[..., None] ** 2) * sw
    Kv = 4.0 * s2 / (wh * w[..., None]) * cw
    # lag 0: only the rising half of the hat has acted
    small = wh[..., 0] < 1e-2
    x = wh[..., 0]
    x_minus_sin = np.where(small, x**3 / 6 - x**5 / 120 + x**7 / 5040, x - np.sin(x))
    Kd[..., 0] = x_minus_sin / (x * w**2)
    Kv[..., 0] = 2.0 * s2[..., 0] / (x * w)
    # the first sample's half hat (1 - t/h on [0, h]): sin(w t - w h/2) by angle addition
    ch, sh, sinc = np.cos(half), np.sin(half), np.sin(half) / half
    Hd = (-cw + (cw * ch + sw * sh) * sinc) / w[..., None] ** 2
    Hv = (sw - (sw * ch - cw * sh) * sinc) / w[..., None]
    return Kd, Kv, Hd, Hv


def kernels(
    rec: Receptance, keep: np.ndarray, h: float, nsteps: int
) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray]:
    """Hat-function kernels Kd, Kv (lag l) and half-hat (the t = 0 sample) Hd, Hv, shape (C, N)."""
    cr = rec.compliance[:, None]
    lag = np.arange(nsteps) * h
    Kd = cr * lag * h
    Kd[:, 0] = cr[:, 0] * h * h / 6.0
    Kv = cr * h + 0.0 * lag
    Kv[:, 0] = cr[:, 0] * h / 2.0
    Hd = cr * (lag * h / 2.0 - h * h / 6.0)
    Hv = cr * h / 2.0 + 0.0 * lag
    out = [Kd, Kv, Hd, Hv]
    if keep.any():
        a2 = rec.a[:, keep] ** 2
        for k, table in enumerate(_hat_tables(rec.omega[keep], h, nsteps)):
            out[k] = out[k] + a2 @ table
    if not keep.all():
        wr, mob = _pseudo_mode(rec, keep)
        for k, table in enumerate(_hat_tables(wr, h, nsteps)):
            out[k] = out[k] + mob[:, None] * table
    return out[0], out[1], out[2], out[3]


def free_motion(
    rec: Receptance, speed: np.ndarray, frame_velocity: np.ndarray | None, t: np.ndarray
) -> tuple[np.ndarray, np.ndarray]:
    """delta and delta' without contact: ball at ``speed``, frame with initial modal velocities."""
    d = speed[:, None] * t[None, :]
    v = np.broadcast_to(speed[:, None], d.shape).copy()
    if frame_velocity is not None:
        rig, flex = frame_velocity[:, :2], frame_velocity[:, 2:]
        wr = np.sum(rec.rigid * rig, axis=1)
        d -= wr[:, None] * t
        v -= wr[:, None]
        w = rec.omega
        amp = rec.a * flex
        d -= (amp / w) @ np.sin(np.outer(w, t))
        v -= amp @ np.cos(np.outer(w, t))
    return d, v
