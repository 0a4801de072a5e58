"""Calibration of contact laws to published targets, one parameter set for all speeds.

Two target sets:

- ``kawazoe-1997``: the paper's linear K_CB(V) on a clamped frame (a ball of m_B = 0.057 kg on
  a fixed support) has contact times pi sqrt(m_B / K_CB) = 4.53, 3.35, 2.60 ms at 20, 30, 40 m/s
  (K_CB = 2.74e4, 5.0e4, 8.33e4 N/m, section 2.1.1; tolerance 5 %), and its clamped COR is 0.83
  at every speed (eq 4; tolerance 0.01, checked at 20, 25, 30, 35 and 40 m/s).
- ``itf``: a ball on a rigid surface. ITF Rules of Tennis, Appendix I: dropped from 254 cm onto
  concrete it rebounds 135-147 cm, i.e. e = sqrt(h_out / h_in) = 0.73-0.76 at
  sqrt(2 g 2.54 m) = 7.06 m/s; its forward deformation under an 8.165 kg load (80.1 N) is
  0.56-0.74 cm. The COR of a ball on a rigid surface falls with speed (Haake, Carre & Goodwill
  2003, J. Sports Sci. 21); that is reported, not fitted (no tabulated values at hand).

Each family's parameters are fitted in log space by scipy ``least_squares`` on residuals scaled
by the targets' tolerances, so a fit meets every target when all scaled residuals are within 1.
Impacts are problems on a rigid support (:class:`~fem_racket.impact.clamped.ClampedHead`, no
mode of its own) solved by the ``general`` solver (the general integrator).
"""

from __future__ import annotations

import logging
from dataclasses import dataclass
from typing import Any

import numpy as np

from fem_racket.contact.law import ContactLaw
from fem_racket.contact.linear import Ball, check_ball_mass
from fem_racket.impact.clamped import CENTRE, ClampedHead, ClampedImpact
from fem_racket.impact.problem import Impact, ImpactProblem
from fem_racket.impact.solvers import make_solver
from fem_racket.studies.calibration_targets import (  # noqa: F401 (ITF_*: the targets' speed, load)
    FAMILIES,
    ITF_LOAD,
    ITF_SPEED,
    TARGET_SETS,
    Target,
)
from fem_racket.studies.views import CalibrationView
from fem_racket.validation import InputError, check_choice, work_begins

__all__ = [
    "FAMILIES",
    "TARGET_SETS",
    "Calibration",
    "Target",
    "calibrate",
    "clamped_histories",
    "clamped_impacts",
    "run_file_table",
]

log = logging.getLogger(__name__)


def _clamped(law: ContactLaw, speeds: Any, ball_mass: float) -> list[ClampedImpact]:
    """A ball of ``ball_mass`` [kg] under ``law`` on a rigid support at each speed [m/s], by
    the general solver (every speed in one integrator call)."""
    head, ball = ClampedHead(), Ball(ball_mass)
    problems = [
        ImpactProblem(head, Impact(CENTRE, v), ball, law)
        for v in np.atleast_1d(np.asarray(speeds, dtype=float))
    ]
    return make_solver("general").solve_many(problems)


def clamped_impacts(law: ContactLaw, speeds: Any, ball_mass: float = 0.057) -> tuple[Any, Any]:
    """COR and contact time [s] of a ball of ``ball_mass`` [kg] on a rigid support."""
    out = _clamped(law, speeds, ball_mass)
    return np.array([r.cor for r in out]), np.array([r.contact_time for r in out])


def _model_values(law: ContactLaw, targets: tuple[Target, ...], ball_mass: float) -> np.ndarray:
    speeds = sorted({t.condition for t in targets if t.quantity != "static_deflection"})
    cor, tc = clamped_impacts(law, speeds, ball_mass) if speeds else ((), ())
    out = []
    for t in targets:
        if t.quantity == "static_deflection":
            out.append(law.static_deflection(t.condition))
        else:
            i = speeds.index(t.condition)
            out.append(cor[i] if t.quantity == "cor" else tc[i])
    return np.array(out, dtype=float)


@dataclass(frozen=True, eq=False, repr=False)
class Calibration(CalibrationView):
    """A fitted law and how it meets each target."""

    family: str
    target_set: str
    law: ContactLaw
    targets: tuple[Target, ...]
    model: np.ndarray

    @property
    def scaled_errors(self) -> np.ndarray:
        """(model - target) / tolerance per target."""
        return np.array([t.scaled_error(m) for t, m in zip(self.targets, self.model, strict=True)])

    @property
    def meets_targets(self) -> bool:
        """True when every target is within its tolerance."""
        return bool(np.all(np.abs(self.scaled_errors) <= 1.0))

    def table(self) -> list[dict[str, Any]]:
        """One row per target: quantity, condition, target, model, tolerance, within."""
        return [
            {
                "quantity": t.quantity,
                "condition": t.condition,
                "target": t.value,
                "model": float(m),
                "tolerance": t.tolerance,
                "within": bool(abs(e) <= 1.0),
                "source": t.source,
            }
            for t, m, e in zip(self.targets, self.model, self.scaled_errors, strict=True)
        ]


def calibrate(
    family: str, target_set: str = "kawazoe-1997", *, ball_mass: float = 0.057
) -> Calibration:
    """Fit one parameter set of a law family to a target set (see the module docstring)."""
    check_choice("family", family, FAMILIES)
    check_choice("target_set", target_set, TARGET_SETS)
    check_ball_mass(ball_mass, "ball_mass")
    fam = FAMILIES[family]
    targets = TARGET_SETS[target_set]
    x0 = np.log(np.asarray(fam.starts[target_set], dtype=float))

    def residuals(x: np.ndarray) -> np.ndarray:
        try:
            model = _model_values(fam.build(np.exp(x)), targets, ball_mass)
        except (RuntimeError, InputError) as err:  # no separation, or Newton failed: far off
            log.debug("calibration point %s failed: %s", np.exp(x), err)
            return np.full(len(targets), 1e3)
        return np.array([t.scaled_error(m) for t, m in zip(targets, model, strict=True)])

    bounds = (np.log(fam.low), np.log(fam.high))
    work_begins()
    from scipy.optimize import least_squares  # ~0.4 s: not for a run file's check (above)

    fit = least_squares(residuals, x0, bounds=bounds, diff_step=1e-4, max_nfev=200)
    law = fam.build(np.exp(fit.x)).for_ball(ball_mass)  # its zeta: the calibration's ball's
    try:
        model = _model_values(law, targets, ball_mass)
    except RuntimeError as err:  # the integrator fails at the fitted point itself
        raise InputError(
            f"family = {family!r} cannot be fitted to targets = {target_set!r}: the fitted law "
            f"({', '.join(f'{v:.4g}' for v in np.exp(fit.x))}) cannot be integrated ({err})"
        ) from None
    return Calibration(family, target_set, law, targets, model)


def clamped_histories(
    law: ContactLaw, speeds: Any, ball_mass: float = 0.057
) -> list[tuple[np.ndarray, np.ndarray, np.ndarray]]:
    """(time [s], deflection [m], force [N]) of a ball on a rigid support at each speed."""
    return [(r.time, r.deflection, r.force) for r in _clamped(law, speeds, ball_mass)]


def run_file_table(law: ContactLaw) -> str:
    """The law as a run file's ``[contact]`` table: its declared parameters by their keys
    (units in them, as in JSON outputs)."""
    lines = ["[contact]", f'law = "{law.name}"']
    for key, value in law.describe().items():
        if key in {p.key for p in law.declared}:
            lines.append(f"{key} = {value!r}")
    return "\n".join(lines) + "\n"
