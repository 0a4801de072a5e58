"""The outcome of one linear impact without histories: contact time, rebound velocity and peak
force from the closed form (:mod:`fem_racket.impact.exact.closed_form`), for sweeps and checks.

Only the contact force's amplitudes are needed: they follow from the eigenvalues alone (residues
of the Laplace transform of delta, no eigenvectors), and the peak force is maximised on the
closed form.
"""

from __future__ import annotations

from dataclasses import dataclass

from fem_racket.impact.exact.closed_form import ModalClosedForm, peak_force, separation_time
from fem_racket.impact.system import SEPARATION_EVENTS, CoupledSystem
from fem_racket.validation import check_choice

__all__ = ["ImpactOutcome", "exact_outcome"]


@dataclass(frozen=True)
class ImpactOutcome:
    """Scalar outcome of one impact, without time histories.

    Attributes
    ----------
    contact_time : float
        t_c [s].
    rebound_velocity : float
        Ball velocity at separation [m/s] (negative: rebounding).
    peak_force : float
        Largest contact force during contact [N], maximised on the closed form.
    peak_time : float
        When it occurs [s].
    """

    contact_time: float
    rebound_velocity: float
    peak_force: float
    peak_time: float


def exact_outcome(
    system: CoupledSystem, *, separation: str = "displacement", t_max: float | None = None
) -> ImpactOutcome:
    """Contact time, rebound velocity and peak force from the closed form, without histories.

    The same closed form and separation search as :func:`solve_exact` (whose
    ``output_step=None`` result it matches to round-off), with the contact force's amplitudes
    from the eigenvalues alone (no eigenvectors), plus the exact maximum of the contact force.
    """
    check_choice("separation", separation, SEPARATION_EVENTS)
    cf = ModalClosedForm(system, histories=False)
    tc = separation_time(cf, separation, system.contact_time_estimate(), t_max)
    rebound = cf.v0 - cf.impulse(tc) / cf.mb
    peak, t_peak = peak_force(cf, tc)
    return ImpactOutcome(tc, rebound, peak, t_peak)
