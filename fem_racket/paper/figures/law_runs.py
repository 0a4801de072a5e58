"""The paper's impacts under another contact law than its linear K_CB (``reproduce --law``).

The paper replaces the nonlinear ball/string restoring force by a linear spring K_CB fitted per
impact speed (section 2.1.1). Under a contact law (:mod:`fem_racket.contact`) the figures are
drawn with that law instead, through the general integrator
(:func:`fem_racket.impact.general.integrator.solve_general`), many impacts per call (on the
clamped frame: :func:`fem_racket.studies.calibrate.clamped_impacts`):

- the paper's "no damping" curves (zeta = 0) become the law's *elastic counterpart*, the same
  law with its losses removed (:meth:`~fem_racket.contact.law.ContactLaw.elastic`):
  Hunt-Crossley with alpha = 0, a hysteretic law with k2 = k1 (its loading branch both ways), a
  spring-dashpot without its dashpot. A Kelvin-Voigt ball in series with a string bed has none
  (its state equation needs C_b > 0), so those curves are left out for it;
- the rigid-frame closed forms become: the COR of eq 12 (momentum and energy conservation on a
  rigid free frame: the same for every elastic law) and, for eq 11, the elastic counterpart's
  contact time of a mass striking a rigid support (its ``contact_time_estimate``, exact for a
  power law), with the ball and the frame's effective mass at the impact point combined into
  the reduced mass 1 / (1/m_B + 1/M + d^2/I);
- the equivalent K_CB of a law at a speed is the paper's own definition: the stiffness whose
  clamped half period is the law's clamped contact time, K = m_B (pi / T_c)^2 (section 2.1.1,
  the contact time taken as half the period).
"""

from __future__ import annotations

import math
from dataclasses import replace

import numpy as np

from fem_racket.contact.law import ContactLaw
from fem_racket.frame.model import FrameModel
from fem_racket.impact.general.integrator import solve_general
from fem_racket.impact.law_impact import receptance
from fem_racket.paper.figures.data import FigureData

__all__ = [
    "equivalent_kcb",
    "free_impacts",
    "law_title",
    "rigid_contact_time",
]


def law_title(law: ContactLaw) -> str:
    """The law's name for titles and labels (a preset's name when it is one)."""
    from fem_racket.contact.presets import PRESETS

    return next((name for name, p in PRESETS.items() if p is law), law.name)


def law_figure(
    name: str,
    title: str,
    tables: dict[str, dict[str, np.ndarray]],
    values: dict[str, float],
    law: ContactLaw | None,
) -> FigureData:
    """A figure drawn with ``law``: its name after the ``title`` (``", NAME law"``) and in
    :attr:`FigureData.law`; None: the paper's linear K_CB, the title as given."""
    if law is None:
        return FigureData(name, title, tables, values)
    return FigureData(name, f"{title}, {law_title(law)} law", tables, values, law=law_title(law))


def free_impacts(
    law: ContactLaw,
    model: FrameModel,
    positions: np.ndarray,
    speeds: np.ndarray | float,
    ball_mass: float,
    *,
    flexible: int | None = None,
) -> tuple[np.ndarray, np.ndarray]:
    """COR [-] and contact time [s] of the ball striking the free ``model`` at rest, one case per
    entry of ``positions`` (x/L) and ``speeds`` [m/s] (broadcast).

    ``flexible``: keep only that many flexible modes (e.g. 1 for "rigid modes + mode 1"); all
    (with the integrator's own truncation) when None.
    """
    pos, speed = np.broadcast_arrays(
        np.asarray(positions, dtype=float), np.asarray(speeds, dtype=float)
    )
    rec = receptance(model, pos.ravel(), ball_mass)
    beta = None  # the tolerance's own cut-off; every mode kept of a truncated basis
    if flexible is not None:
        rec = replace(rec, omega=rec.omega[:flexible], a=rec.a[:, :flexible])
        beta = math.inf
    out = solve_general(law, rec, speed.ravel().copy(), beta=beta)
    cor = -out.ball_velocity / speed.ravel()
    return cor.reshape(pos.shape), out.contact_time.reshape(pos.shape)


def equivalent_kcb(contact_time: np.ndarray, ball_mass: float) -> np.ndarray:
    """K_CB [N/m] whose clamped half period is ``contact_time`` [s]: m_B (pi / T_c)^2."""
    return ball_mass * (np.pi / np.asarray(contact_time)) ** 2


def rigid_contact_time(
    law: ContactLaw, model: FrameModel, positions: np.ndarray, speed: float, ball_mass: float
) -> np.ndarray:
    """The eq 11 counterpart: ``law``'s contact time for the reduced mass of the ball and the
    rigid free frame at ``positions`` (x/L) [s]."""
    rec = receptance(model, np.asarray(positions, dtype=float), ball_mass)
    return np.asarray(law.contact_time_estimate(1.0 / rec.compliance, speed), dtype=float)
