"""The general integrator's compiled march for a batch: every case its own frame and step.

:func:`march_compiled` prepares each case's modes (those kept by the cut-off rule of
:func:`fem_racket.impact.reduction.split_modes` and its residual pseudo-mode), runs the
compiled march (:mod:`fem_racket.impact.general.kernel`, numba, imported here only) and builds
the outcome as :mod:`fem_racket.impact.general.march` does, from the same nodal histories. A
case still in contact at the end of its span runs again with twice the span (up to ``t_max``).
Laws of :mod:`fem_racket.contact` have kernels (:func:`kernel_law`); another law (a user's
subclass) marches in numpy.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from fem_racket.contact.hunt_crossley import HuntCrossley
from fem_racket.contact.hysteretic import Hysteretic
from fem_racket.contact.law import ContactLaw
from fem_racket.contact.linear import LinearContact
from fem_racket.contact.series import SeriesBallString
from fem_racket.impact.general.cubic_force import ORDER, STENCILS
from fem_racket.impact.general.march import GeneralOutcome, _outcome
from fem_racket.impact.general.receptance import Receptance, free_motion
from fem_racket.impact.general.step import per_case
from fem_racket.impact.reduction import split_modes

__all__ = ["KernelLaw", "Checks", "kernel_law", "march_compiled"]

#: Parameters of each law with a kernel, in the kernel's order (the kernel_laws.LAW_IDS list).
_PARAMETERS = {
    LinearContact: lambda law: (law.stiffness, law.damping()),
    HuntCrossley: lambda law: (law.stiffness, law.exponent, law.alpha),
    Hysteretic: lambda law: (law.k1, law.k2, law.exponent),
    SeriesBallString: lambda law: (
        law.ball_stiffness,
        law.ball_damping,
        law.string_stiffness,
        law.string_cubic,
    ),
}
_STATES = {None: 0, "memory": 1, "ode": 2}
_ENDS = {"displacement": 0, "force": 1, "state": 2}


@dataclass(frozen=True, eq=False)
class KernelLaw:
    """A law as the kernel takes it: its number, state and end kinds, parameters (C, p)."""

    law: int
    state: int
    end: int
    params: np.ndarray

    def take(self, idx: np.ndarray) -> KernelLaw:
        """The law of the cases ``idx``."""
        return KernelLaw(self.law, self.state, self.end, self.params[idx])


@dataclass(frozen=True, eq=False)
class Checks:
    """What the march measured besides the outcome, per case.

    Attributes
    ----------
    stiffness : ndarray
        Largest h |dz'/dz| of an ODE state over the contact [-] (0 without one).
    flexible_energy : ndarray
        Energy of the kept flexible modes and pseudo-mode at the separation node [J].
    """

    stiffness: np.ndarray
    flexible_energy: np.ndarray


def kernel_law(law: ContactLaw, ncase: int) -> KernelLaw | None:
    """The kernel form of ``law`` (parameters broadcast to ``ncase`` rows); None when its
    class has no kernel."""
    from fem_racket.impact.general.kernel_laws import LAW_IDS

    values = _PARAMETERS.get(type(law))
    if values is None:
        return None
    cols = [np.broadcast_to(np.asarray(x, dtype=float), (ncase,)) for x in values(law)]
    if isinstance(law, Hysteretic):  # its unloading ratio (k1/k2)^(1/n), as the law has it
        cols.append((cols[0] / cols[1]) ** (1.0 / cols[2]))
    return KernelLaw(
        LAW_IDS[law.name],
        _STATES[law.state],
        _ENDS[law.end],
        np.ascontiguousarray(np.stack(cols, 1)),
    )


def _modes(rec: Receptance, omega_c: np.ndarray, beta: float):
    """Per case: the kept modes and the pseudo-mode as rows W, A2 (C, M), their count, kept."""
    ncase = rec.a.shape[0]
    kept, w2p, a2p = split_modes(rec.omega, rec.a, omega_c, beta)
    omega = np.broadcast_to(rec.omega, rec.a.shape)
    width = int(kept.max(initial=0)) + 1
    W, A2 = np.ones((ncase, width)), np.zeros((ncase, width))
    cols = np.arange(width)[None, :] < kept[:, None]
    W[:, : width - 1] = np.where(cols[:, :-1], omega[:, : width - 1], 1.0)
    A2[:, : width - 1] = np.where(cols[:, :-1], rec.a[:, : width - 1] ** 2, 0.0)
    pseudo = a2p > 0
    rows = np.arange(ncase)
    W[rows, kept] = np.where(pseudo, np.sqrt(np.where(pseudo, w2p, 1.0)), 1.0)
    A2[rows, kept] = np.where(pseudo, a2p, 0.0)
    return W, A2, kept + pseudo, kept


def _free(rec, speed, frame_velocity, h, nsteps) -> np.ndarray:
    """delta and delta' without contact (C, 2, N) on each case's grid (empty at rest)."""
    if frame_velocity is None:
        return np.zeros((0, 2, 0))
    ncase = speed.size
    out = np.zeros((ncase, 2, int(nsteps.max())))
    for c in range(ncase):
        one = per_case(rec, ncase, np.array([c]))
        t = np.arange(nsteps[c]) * h[c]
        d, v = free_motion(one, speed[c : c + 1], frame_velocity[c : c + 1], t)
        out[c, 0, : nsteps[c]], out[c, 1, : nsteps[c]] = d[0], v[0]
    return out


def march_compiled(
    law: KernelLaw,
    rec: Receptance,
    speed: np.ndarray,
    frame_velocity: np.ndarray | None,
    omega_c: np.ndarray,
    beta: float,
    h: np.ndarray,
    span: np.ndarray,
    t_max: np.ndarray,
    extend: bool = True,
) -> tuple[GeneralOutcome, Checks, np.ndarray]:
    """Every case with its step ``h`` [s] over ``span`` [s] (doubled up to ``t_max`` while in
    contact); returns the outcome, the checks and a status per case (0 separated, 1 still in
    contact at t_max, 2 Newton did not converge; the outcome is NaN where it is not 0).
    ``extend``: see :func:`fem_racket.impact.general.kernel.march_cases` (False: the numpy
    march's equations, to round-off)."""
    from fem_racket.impact.general.kernel import march_cases

    W, A2, nmode, kept = _modes(rec, omega_c, beta)
    ncase = speed.size
    status = np.full(ncase, -1)
    parts: dict[int, tuple] = {}
    todo = np.arange(ncase)
    span = span.copy()
    while todo.size:
        nsteps = np.maximum(np.ceil(span[todo] / h[todo]).astype(np.int64) + 1, ORDER + 2)
        sub = per_case(rec, ncase, todo)
        scale = np.abs(speed[todo]) / (sub.compliance * span[todo])
        fdv = _free(sub, speed[todo], None if frame_velocity is None else frame_velocity[todo],
                    h[todo], nsteps)  # fmt: skip
        H, res = march_cases(
            law.law, law.state, law.end, law.params[todo], W[todo], A2[todo], nmode[todo],
            sub.compliance, h[todo], nsteps, speed[todo], fdv, scale, STENCILS, extend,
        )  # fmt: skip
        code = res[:, 2].astype(int)
        again = (code == 1) & (span[todo] < t_max[todo])
        for i, c in enumerate(todo):
            if not again[i]:
                status[c] = code[i]
                parts[c] = (H[:, i], res[i])
        span[todo[again]] = np.minimum(2.0 * span[todo[again]], t_max[todo[again]])
        todo = todo[again]
    width = max(p[0].shape[1] for p in parts.values())
    H = np.zeros((5, ncase, width))
    res = np.zeros((ncase, 5))
    for c, (Hc, rc) in parts.items():
        H[:, c, : Hc.shape[1]], res[c] = Hc, rc
    ok = status == 0
    last = np.where(ok, res[:, 0], width - 1).astype(int)
    out = _outcome(H[0], H[1], H[2], H[3], last, np.where(ok, res[:, 1], 1.0), h, speed, rec,
                   kept)  # fmt: skip
    if not np.all(ok):
        out = _blank(out, ~ok)
    return out, Checks(res[:, 3], res[:, 4]), status


def _blank(out: GeneralOutcome, bad: np.ndarray) -> GeneralOutcome:
    """The outcome with NaN scalars for the cases ``bad``."""
    fields = {}
    for name in ("contact_time", "ball_velocity", "impulse", "peak_force"):
        fields[name] = np.where(bad, np.nan, getattr(out, name))
    from dataclasses import replace

    return replace(out, **fields)
