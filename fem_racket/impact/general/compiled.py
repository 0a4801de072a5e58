"""The general integrator's compiled march for a batch: every case its own frame and step.

:func:`march_compiled` prepares each case's modes (those kept by the cut-off rule of
:func:`fem_racket.impact.reduction.split_modes` and its residual pseudo-mode), runs the
compiled march (:mod:`fem_racket.impact.general.kernel`, numba, imported here only), which also
integrates the outcome from the nodal histories as :mod:`fem_racket.impact.general.march` does. A
case marches on until it separates, up to ``t_max``.
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
from fem_racket.impact.general.march import GeneralOutcome
from fem_racket.impact.general.receptance import Receptance, free_motion
from fem_racket.impact.general.step import per_case
from fem_racket.impact.general.stored import Stored, joined
from fem_racket.impact.reduction import split_modes

__all__ = ["Checks", "KernelLaw", "MarchCases", "MarchOptions", "kernel_law", "march_compiled"]

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
#: Parameters per case the kernel takes (the most any law has; zeros after a law's own).
_WIDTH = 4
_STATES = {None: 0, "memory": 1, "ode": 2}
_ENDS = {"displacement": 0, "force": 1, "state": 2}


@dataclass(frozen=True, eq=False)
class KernelLaw:
    """A law as the kernel takes it: its number, state and end kinds, parameters (C, 4)."""

    law: int
    state: int
    end: int
    params: np.ndarray

    def take(self, idx: np.ndarray) -> KernelLaw:
        """The law of the cases ``idx``."""
        return KernelLaw(self.law, self.state, self.end, self.params[idx])


@dataclass(frozen=True, eq=False)
class MarchCases:
    """The batch a compiled march takes: C cases, each with its law, frame and speeds.

    Attributes
    ----------
    law : KernelLaw
        The law of every case (:func:`kernel_law`).
    rec : Receptance
        The frame at each case's impact point.
    speed : ndarray, shape (C,)
        Ball speed towards the frame at t = 0 [m/s].
    frame_velocity : ndarray, shape (C, 2 + n) or None
        Initial modal velocities of the frame [sqrt(kg) m/s]; at rest when None.
    omega_c : ndarray, shape (C,)
        Contact frequency of each case [rad/s], the scale of the mode cut-off.
    beta : float
        Flexible modes above ``beta`` x ``omega_c`` become one pseudo-mode
        (:func:`fem_racket.impact.reduction.split_modes`).
    """

    law: KernelLaw
    rec: Receptance
    speed: np.ndarray
    frame_velocity: np.ndarray | None
    omega_c: np.ndarray
    beta: float

    def take(self, idx: np.ndarray) -> MarchCases:
        """The cases ``idx``."""
        fv = self.frame_velocity
        return MarchCases(
            self.law.take(idx),
            per_case(self.rec, self.speed.size, idx),
            self.speed[idx],
            None if fv is None else fv[idx],
            self.omega_c[idx],
            self.beta,
        )


@dataclass(frozen=True)
class MarchOptions:
    """How :func:`march_compiled` marches: ``extend`` (see
    :func:`fem_racket.impact.general.kernel.march_cases`; False: the numpy march's equations,
    to round-off) and whether the outcome has the nodal ``histories`` (False: none, a coarse
    run whose COR alone is wanted)."""

    extend: bool = True
    histories: bool = True


@dataclass(frozen=True, eq=False)
class Checks:
    """What the march measured besides the outcome, per case.

    Attributes
    ----------
    stiffness : ndarray
        Largest h |dz'/dz| of an ODE state over the contact [-] (0 without one).
    flexible_energy : ndarray
        Energy of the kept flexible modes and pseudo-mode at the separation node [J].
    work, node_impulse : ndarray
        int F delta' dt [J] and int F dt [N s] over the whole steps up to the separation node
        (of the piecewise cubic through the nodal values).
    """

    stiffness: np.ndarray
    flexible_energy: np.ndarray
    work: np.ndarray
    node_impulse: np.ndarray


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
    cols += [np.zeros(ncase)] * (_WIDTH - len(cols))  # the kernel takes _WIDTH per case
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
    # columns after a case's modes: omega 1, a^2 0 (the kernel's zero modes), to a multiple of 4
    W, A2 = np.ones((ncase, -(-width // 4) * 4)), np.zeros((ncase, -(-width // 4) * 4))
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
    cases: MarchCases,
    h: np.ndarray,
    span: np.ndarray,
    t_max: np.ndarray,
    options: MarchOptions = MarchOptions(),
) -> tuple[GeneralOutcome, Checks, np.ndarray, Stored]:
    """Every case of ``cases`` with its step ``h`` [s] over ``span`` [s] (on, up to ``t_max``,
    while in contact); returns the outcome (its histories empty), the checks, a status per case
    (0 separated, 1 still in contact at t_max, 2 Newton did not converge; the outcome is NaN
    where it is not 0) and the nodal histories as stored (none without ``options.histories``;
    lay them out with :func:`fem_racket.impact.general.stored.laid_out`).

    A frame at rest: each case marches up to ``t_max`` at once (the kernel stops at its
    separation). A moving frame: over ``span``, then twice the span (up to ``t_max``) for the
    cases still in contact, whose free motion is tabulated per span. Newton's force scale and
    whether the kernels run interpreted are set by ``span`` (the same in both).
    """
    from fem_racket.impact.general import jit

    law, rec, speed, frame_velocity = cases.law, cases.rec, cases.speed, cases.frame_velocity
    W, A2, nmode, kept = _modes(rec, cases.omega_c, cases.beta)
    kind = (law.law, law.state, law.end, int(options.extend))
    ncase = speed.size
    runs = []
    todo = np.arange(ncase)
    span = span.copy()
    scale = np.abs(speed) / (rec.compliance * span)
    jit.prepare(int(np.max(np.ceil(span / h)).astype(np.int64) + 1))  # interpreted or compiled
    if frame_velocity is None:
        span = np.maximum(span, t_max)
    while todo.size:
        nsteps = np.maximum(np.ceil(span[todo] / h[todo]).astype(np.int64) + 1, ORDER + 2)
        sub = per_case(rec, ncase, todo)
        fdv = _free(sub, speed[todo], None if frame_velocity is None else frame_velocity[todo],
                    h[todo], nsteps)  # fmt: skip
        cases = (sub.compliance, h[todo], nsteps, speed[todo], scale[todo])
        from fem_racket.impact.general.kernel import march_cases

        store, start, res = march_cases(
            kind,
            law.params[todo],
            (W[todo], A2[todo], nmode[todo]),
            cases,
            fdv,
            STENCILS,
            options.histories,
        )
        again = (res[:, 2] == 1) & (span[todo] < t_max[todo])
        here = np.flatnonzero(~again)
        part = Stored(store, start[:-1], np.diff(start)).take(here)
        runs.append((todo[here], part, res[here]))
        span[todo[again]] = np.minimum(2.0 * span[todo[again]], t_max[todo[again]])
        todo = todo[again]
    stored = joined([(idx, part) for idx, part, _ in runs], ncase)
    res = np.zeros((ncase, runs[0][2].shape[1]))
    for idx, _, rc in runs:
        res[idx] = rc
    status = res[:, 2].astype(int)
    ok = status == 0
    last = np.where(ok, res[:, 0], np.maximum(stored.length - 1, 0)).astype(int)
    frac = np.where(ok, res[:, 1], 1.0)
    none = np.zeros((ncase, 0))  # the histories are laid out once, for the answers (stored)
    out = GeneralOutcome(
        contact_time=(last - 1 + frac) * h,
        ball_velocity=speed - res[:, 5] / rec.ball_mass,
        impulse=res[:, 5],
        peak_force=res[:, 6],
        step=h.copy(),
        force=none,
        deflection=none,
        rate=none,
        state=none,
        last=last,
        fraction=frac,
        kept=kept,
    )
    if not np.all(ok):
        out = _blank(out, ~ok)
    return out, Checks(res[:, 3], res[:, 4], res[:, 7], res[:, 8]), status, stored


def _blank(out: GeneralOutcome, bad: np.ndarray) -> GeneralOutcome:
    """The outcome with NaN scalars for the cases ``bad``."""
    fields = {}
    for name in ("contact_time", "ball_velocity", "impulse", "peak_force"):
        fields[name] = np.where(bad, np.nan, getattr(out, name))
    from dataclasses import replace

    return replace(out, **fields)
