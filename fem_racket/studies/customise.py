"""Customise a racket: the least lead, at allowed places, that meets catalogue targets.

With m_p >= 0 kg at each allowed place p, every number is linear in the masses
(:mod:`fem_racket.frame.lead`, per kg of lead at p: 1, x_p, s_p, t_p)::

    M = M0 + sum m_p,  M B = M0 B0 + sum m_p x_p,  SW = SW0 + sum m_p s_p,  TW = TW0 + sum m_p t_p

and a balance window lo <= B <= hi is linear too (M0 B0 + sum m_p x_p >= lo (M0 + sum m_p)).
So the least total added mass meeting targets (each a value or a range) is a linear programme,
solved by scipy.optimize.linprog (HiGHS). An unreachable set of targets is refused naming, for
the first target that fails, the range reachable while the others hold.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass

import numpy as np

from fem_racket.frame.catalogue import Catalogue, catalogue
from fem_racket.frame.head import DEFAULT_HEAD, HeadOutline
from fem_racket.frame.lead import Lead, add_lead, lead_moments
from fem_racket.frame.mesh import FrameMesh
from fem_racket.frame.specs import KG_CM2
from fem_racket.validation import InputError, show

__all__ = ["SPECS", "Customisation", "Target", "customise", "plan_lead"]

#: Targets a customisation can meet -> (unit shown, factor from SI to it).
SPECS = {
    "mass": ("kg", 1.0),
    "balance": ("m", 1.0),
    "swing_weight": ("kg cm^2", 1.0 / KG_CM2),
    "twist_weight": ("kg cm^2", 1.0 / KG_CM2),
}
#: Column of each linear spec in :func:`fem_racket.frame.lead.lead_moments`.
_COLUMN = {"mass": 0, "swing_weight": 2, "twist_weight": 3}
#: Grams per kg (the programme's unknowns are grams, for scaling).
_G = 1e3


@dataclass(frozen=True)
class Target:
    """A target: ``low <= value <= high`` (SI: kg, m, kg m^2); a value has low == high."""

    low: float
    high: float

    def __post_init__(self) -> None:
        lo, hi = float(self.low), float(self.high)
        if not (np.isfinite(lo) and np.isfinite(hi) and 0.0 < lo <= hi):
            raise InputError(f"target = {show((lo, hi))} is not allowed: need 0 < low <= high")
        object.__setattr__(self, "low", lo)
        object.__setattr__(self, "high", hi)


@dataclass(frozen=True, eq=False)
class Customisation:
    """The least lead meeting the targets.

    Attributes
    ----------
    added : dict
        Place -> added mass [kg] (every allowed place, 0 where none goes).
    mesh : FrameMesh
        The customised frame.
    before, after : Catalogue
        Catalogue numbers of the frame and of the customised mesh (recomputed from it).
    """

    added: dict[str, float]
    mesh: FrameMesh
    before: Catalogue
    after: Catalogue

    @property
    def total(self) -> float:
        """Total added mass [kg]."""
        return float(sum(self.added.values()))

    def summary(self) -> dict:
        """JSON-ready: ``added_mass_g``, the placement per place [g], before and after."""
        return {
            "added_mass_g": self.total * _G,
            "placement_g": {p: m * _G for p, m in self.added.items()},
            "before": self.before.as_dict(),
            "after": self.after.as_dict(),
        }


def _rows(
    base: Catalogue, coef: np.ndarray, targets: Mapping[str, Target]
) -> tuple[np.ndarray, np.ndarray]:
    """A_ub g <= b_ub for the targets, g in grams, each row scaled to unit size."""
    a_rows, b_rows = [], []
    m0 = base.mass
    for name, t in targets.items():
        if name == "balance":  # lo (M0 + sum m) <= M0 B0 + sum m x <= hi (M0 + sum m)
            x = coef[:, 1]
            a_rows += [(t.low - x) / _G, (x - t.high) / _G]
            b_rows += [m0 * (base.balance - t.low), m0 * (t.high - base.balance)]
            continue
        c = coef[:, _COLUMN[name]] / _G
        v0 = _base_value(base, name)
        a_rows += [-c, c]
        b_rows += [v0 - t.low, t.high - v0]
    a, b = np.array(a_rows), np.array(b_rows)
    scale = np.maximum(np.abs(a).max(axis=1), 1e-300)
    return a / scale[:, None], b / scale


def _base_value(base: Catalogue, name: str) -> float:
    value = getattr(base, name)
    if value is None:
        raise InputError(
            f"{name.replace('_', '-')} target is not allowed for this frame: it carries no "
            "polar mass per length rhoIp, so its twistweight is unknown"
        )
    return float(value)


def _solve(coef: np.ndarray, base: Catalogue, targets: Mapping[str, Target], cost: np.ndarray):
    from scipy.optimize import linprog

    a, b = _rows(base, coef, targets) if targets else (None, None)
    return linprog(cost, A_ub=a, b_ub=b, bounds=(0, None), method="highs")


def _value(base: Catalogue, coef: np.ndarray, name: str, grams: np.ndarray) -> float:
    kg = grams / _G
    if name == "balance":
        return (base.mass * base.balance + kg @ coef[:, 1]) / (base.mass + kg.sum())
    return _base_value(base, name) + kg @ coef[:, _COLUMN[name]]


def _reachable(
    base: Catalogue, coef: np.ndarray, name: str, others: Mapping[str, Target]
) -> tuple[float, float]:
    """Range of ``name`` while ``others`` hold (balance by bisection on feasibility)."""
    if name != "balance":
        c = coef[:, _COLUMN[name]]
        ends = []
        for sign in (1.0, -1.0):
            res = _solve(coef, base, others, sign * c)
            if res.status == 3:  # unbounded: no lead limit in that direction
                ends.append(-sign * np.inf)
            else:
                ends.append(_value(base, coef, name, res.x) if res.status == 0 else np.nan)
        return ends[0], ends[1]
    zero = np.zeros(coef.shape[0])
    res = _solve(coef, base, others, zero)
    if res.status != 0:
        return np.nan, np.nan
    # the balances reachable form an interval: bisect on "B >= b feasible" and "B <= b feasible"
    top = max(float(coef[:, 1].max()), base.balance) * 2.0
    ends = []
    for below in (True, False):
        good = bad = _value(base, coef, "balance", res.x)
        bad = 1e-12 if below else top
        for _ in range(60):
            mid = 0.5 * (good + bad)
            window = Target(1e-12, mid) if below else Target(mid, top)
            ok = _solve(coef, base, {**others, name: window}, zero).status == 0
            good, bad = (mid, bad) if ok else (good, mid)
        ends.append(good)
    return ends[0], ends[1]


def _refuse(base: Catalogue, coef: np.ndarray, targets: Mapping[str, Target]) -> InputError:
    """The first target outside its reachable range while the others hold, else the first
    outside its range alone."""
    for together in (True, False):
        for name, t in targets.items():
            others = {k: v for k, v in targets.items() if k != name} if together else {}
            lo, hi = _reachable(base, coef, name, others)
            if np.isnan(lo) or (lo <= t.high and t.low <= hi):
                continue
            unit, f = SPECS[name]
            with_others = " with the other targets" if others else ""
            return InputError(
                f"{name.replace('_', '-')} = {t.low * f:.6g}..{t.high * f:.6g} {unit} is not "
                f"reachable: with lead at the allowed places{with_others} it can reach "
                f"[{lo * f:.6g}, {hi * f:.6g}] {unit}"
            )
    return InputError("targets are not reachable together with lead at the allowed places")


def plan_lead(
    base: Catalogue, targets: Mapping[str, Target], places: Sequence[str], head: HeadOutline
) -> dict[str, float]:
    """Place -> least lead [kg] bringing a racket with catalogue numbers ``base`` to
    ``targets`` (module docstring); no mesh needed (the numbers are linear in the masses).

    Raises
    ------
    InputError
        For an unknown target or place, or targets no lead at these places reaches (naming the
        reachable range).
    """
    for name in targets:
        if name not in SPECS:
            raise InputError(f"target = {show(name)} is not allowed: must be one of {list(SPECS)}")
    places = list(dict.fromkeys(str(p).strip() for p in places))
    if not places:
        raise InputError("places = [] is not allowed: give at least one place for the lead")
    coef = np.array([lead_moments(p, head) for p in places])
    res = _solve(coef, base, targets, np.ones(len(places)))
    if res.status != 0:
        raise _refuse(base, coef, targets)
    grams = np.where(res.x > 1e-9, res.x, 0.0)
    return {p: float(g / _G) for p, g in zip(places, grams, strict=True)}


def customise(
    mesh: FrameMesh,
    targets: Mapping[str, Target],
    places: Sequence[str],
    head: HeadOutline | None = None,
) -> Customisation:
    """The least total lead at ``places`` meeting ``targets``, on the mesh (:func:`plan_lead`).

    Parameters
    ----------
    mesh : FrameMesh
        The racket.
    targets : mapping
        Keys of :data:`SPECS` -> :class:`Target` (SI).
    places : sequence of str
        Allowed places (:data:`fem_racket.frame.clock.PLACES` or distances from the butt [m]).
    head : HeadOutline, optional
        The head (the default head on a racket of this length when None).

    Returns
    -------
    Customisation
        Its ``after`` numbers recomputed from the customised mesh.
    """
    head = head or DEFAULT_HEAD.on_frame(mesh.length)
    before = catalogue(mesh)
    added = plan_lead(before, targets, places, head)
    custom = add_lead(mesh, [Lead(p, m) for p, m in added.items()], head)
    return Customisation(added, custom, before, catalogue(custom))
