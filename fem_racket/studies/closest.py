"""Closest racket: which listed racket is nearest a target, and the least lead to bring it there.

A racket list (the numbers retailers publish: length, mass, balance, swing weight, optionally
twistweight, stiffness RA or f1) is ranked by a scaled distance to the targets::

    d = sqrt( sum_k (gap_k / s_k)^2 ),  gap_k = distance of spec k from its target range (0 inside)

with the scales s_k of :data:`SCALES` (an assumption: differences a player would call about
equal, 10 g ~ 1 cm of balance ~ 10 kg cm^2 of swing weight ~ 1 kg cm^2 of twistweight ~ 3 RA ~
10 Hz; a spec the racket does not list adds nothing and is reported as missing). For each of
the nearest, the least lead at the allowed places that meets the mass, balance, swing-weight and
twistweight targets (:func:`fem_racket.studies.customise.plan_lead`, on the listed numbers: they
are linear in the lead; the head is the default head on a racket of that length); lead only
adds mass, so a target lighter than the racket is reported as unreachable with the reason.
Stiffness (RA, f1) is ranked on but not customised.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import numpy as np

from fem_racket.frame.catalogue import Catalogue
from fem_racket.frame.head import DEFAULT_HEAD, HeadOutline
from fem_racket.frame.lead import lead_moments
from fem_racket.frame.specs import KG_CM2
from fem_racket.studies.customise import SPECS, Target, plan_lead
from fem_racket.validation import InputError, check_integer, show

__all__ = ["SCALES", "Listed", "Match", "closest", "distance", "predicted"]

#: Scale of each spec in the distance (SI: kg, m, kg m^2, kg m^2, Hz, RA).
SCALES = {
    "mass": 0.010,
    "balance": 0.010,
    "swing_weight": 10.0 * KG_CM2,
    "twist_weight": 1.0 * KG_CM2,
    "f1": 10.0,
    "stiffness_ra": 3.0,
}


@dataclass(frozen=True)
class Listed:
    """A racket of a list: its name, catalogue numbers and stiffness RA (None if not listed)."""

    name: str
    specs: Catalogue
    stiffness_ra: float | None = None

    def value(self, key: str) -> float | None:
        """The listed value of a spec of :data:`SCALES` (SI), None when not listed."""
        return self.stiffness_ra if key == "stiffness_ra" else getattr(self.specs, key)


def distance(listed: Listed, targets: Mapping[str, Target]) -> tuple[float, list[str]]:
    """Scaled distance to the targets and the targeted specs the racket does not list."""
    total, missing = 0.0, []
    for key, t in targets.items():
        v = listed.value(key)
        if v is None:
            missing.append(key)
            continue
        gap = max(t.low - v, v - t.high, 0.0)
        total += (gap / SCALES[key]) ** 2
    return float(np.sqrt(total)), missing


def predicted(base: Catalogue, added: Mapping[str, float], head: HeadOutline) -> Catalogue:
    """Catalogue numbers after adding ``added`` (place -> kg) to a racket with ``base``."""
    d = sum((m * lead_moments(p, head) for p, m in added.items()), np.zeros(4))
    mass = base.mass + d[0]
    tw = None if base.twist_weight is None else base.twist_weight + d[3]
    return Catalogue(
        base.length,
        mass,
        (base.mass * base.balance + d[1]) / mass,
        base.swing_weight + d[2],
        tw,
        None,
    )


@dataclass(frozen=True)
class Match:
    """A listed racket, its distance and its least customisation (or why there is none)."""

    listed: Listed
    distance: float
    missing: tuple[str, ...]
    added: dict[str, float] | None
    after: Catalogue | None
    reason: str | None

    def summary(self) -> dict:
        """JSON-ready, units in the keys."""
        out = {
            "name": self.listed.name,
            "distance": self.distance,
            "not_listed": list(self.missing),
            "listed": {**self.listed.specs.as_dict(), "stiffness_ra": self.listed.stiffness_ra},
            "reachable": self.added is not None,
        }
        if self.added is not None and self.after is not None:
            out["added_mass_g"] = sum(self.added.values()) * 1e3
            out["placement_g"] = {p: m * 1e3 for p, m in self.added.items()}
            out["after"] = self.after.as_dict()
        else:
            out["reason"] = self.reason
        return out


def closest(
    rackets: Sequence[Listed],
    targets: Mapping[str, Target],
    places: Sequence[str],
    count: int = 3,
) -> list[Match]:
    """The ``count`` rackets nearest the targets (nearest first), each with its least lead.

    ``targets``: keys of :data:`SCALES` -> :class:`Target` (SI); those of
    :data:`fem_racket.studies.customise.SPECS` are customised.
    """
    count = check_integer("count", count)
    if not rackets:
        raise InputError("rackets = [] is not allowed: the list has no racket")
    for key in targets:
        if key not in SCALES:
            raise InputError(f"target = {show(key)} is not allowed: must be one of {list(SCALES)}")
    if not targets:
        raise InputError("targets = none is not allowed: give at least one target")
    ranked = sorted(((distance(r, targets), i, r) for i, r in enumerate(rackets)))
    lead_targets = {k: t for k, t in targets.items() if k in SPECS}
    out = []
    for (d, missing), _, r in ranked[:count]:
        head = DEFAULT_HEAD.on_frame(r.specs.length)
        for p in places:  # a bad place is the user's error, not this racket's limit
            lead_moments(p, head)
        try:
            added = plan_lead(r.specs, lead_targets, places, head) if lead_targets else {}
        except InputError as exc:
            out.append(Match(r, d, tuple(missing), None, None, str(exc)))
            continue
        out.append(Match(r, d, tuple(missing), added, predicted(r.specs, added, head), None))
    return out
