"""The keys of a run file's core tables: their units, checks and the CLI options they set.

Each check takes the dotted key and the raw TOML value and returns the clean value or raises a
one-line :class:`~fem_racket.validation.InputError` naming the key (see :mod:`.config`).
"""

from __future__ import annotations

import difflib
import math
from collections.abc import Callable, Mapping
from dataclasses import dataclass
from typing import Any

from fem_racket.contact.linear import LinearContact
from fem_racket.contact.parameters import LawParameter
from fem_racket.contact.registry import LAW_NAMES, LiveView, family_parameters
from fem_racket.frame.hand import GRIPS
from fem_racket.frame.segments import Segment
from fem_racket.impact.incidence import MAX_COMPLIANCE_RATIO, MAX_FRICTION
from fem_racket.impact.simulate_linear import BASES
from fem_racket.impact.solvers import SOLVER_NAMES
from fem_racket.impact.system import SEPARATION_EVENTS
from fem_racket.io.config_arrays import table_array
from fem_racket.io.config_lead import lead_tables
from fem_racket.io.constants import PRESETS
from fem_racket.strings.bed import EDGES, parse_pattern
from fem_racket.strings.materials import STRINGS
from fem_racket.validation import (
    InputError,
    check_choice,
    check_finite,
    check_positive,
    check_range,
    show,
)

__all__ = ["COMMAND_TABLES", "CORE_DESTS", "CORE_KEYS", "PRESETS", "Key", "reject_unknown"]


#: Sub-command -> the table of the run file holding its own options. A command missing here
#: reads the table named after it.
COMMAND_TABLES = {
    "simulate": "simulate",
    "modes": "modes",
    "sweep": "sweep",
    "map": "map",
    "fit": "fit",
    "customise": "customise",
    "closest": "closest",
    "compare": "compare",
    "refine": "refine",
    "export-vtk": "vtk",
    "animate": "animate",
    "reproduce": "reproduce",
    "optimize": "design",
    "sensitivity": "sensitivity",
    "calibrate": "calibrate",
}


# -- value checks: (dotted name, raw TOML value) -> clean value --------------------------------
def _number(unit: str, check: Callable[..., float]) -> Callable[[str, Any], float]:
    def conv(name: str, value: Any) -> float:
        if isinstance(value, bool) or not isinstance(value, (int, float)):
            raise InputError(f"{name} = {show(value)} is not allowed: must be a number [{unit}]")
        return float(check(name, value, unit))

    return conv


def _positive(unit: str = "") -> Callable[[str, Any], float]:
    return _number(unit, check_positive)


def _interval(low: float, high: float, **kw: bool) -> Callable[[str, Any], float]:
    def check(name: str, value: float, unit: str) -> float:
        return check_range(name, value, low, high, unit=unit, **kw)

    return _number("", check)


def _integer(low: int) -> Callable[[str, Any], int]:
    def conv(name: str, value: Any) -> int:
        if isinstance(value, bool) or not isinstance(value, int) or value < low:
            raise InputError(f"{name} = {show(value)} is not allowed: must be an integer >= {low}")
        return value

    return conv


def _choice(options: tuple[str, ...]) -> Callable[[str, Any], str]:
    def conv(name: str, value: Any) -> str:
        return check_choice(name, value, options)

    return conv


def _string(name: str, value: Any) -> str:
    if not isinstance(value, str) or not value.strip():
        raise InputError(f"{name} = {show(value)} is not allowed: must be a non-empty path string")
    return value


def _boolean(name: str, value: Any) -> bool:
    if not isinstance(value, bool):
        raise InputError(f"{name} = {show(value)} is not allowed: must be true or false")
    return value


_SEGMENT_KEYS = {"length_m": "m", "ei_n_m2": "N m^2", "rhoa_kg_m": "kg/m"}


def _segments(name: str, value: Any) -> tuple[Segment, ...]:
    out = []
    items = table_array(
        name,
        value,
        list(_SEGMENT_KEYS),
        lambda item, where: reject_unknown(item, _SEGMENT_KEYS, where),
        "each segment needs all 3",
    )
    for where, item in items:
        vals = [_positive(u)(f"{where}.{k}", item[k]) for k, u in _SEGMENT_KEYS.items()]
        out.append(Segment(*vals))
    return tuple(out)


def _pattern(name: str, value: Any) -> str:
    if not isinstance(value, str):
        raise InputError(f'{name} = {show(value)} is not allowed: must be a string like "16x19"')
    parse_pattern(value, name)  # raises, naming the key
    return value


def _declared(p: LawParameter) -> Callable[[str, Any], float]:
    """The check of a law parameter's key: its declared bounds."""
    return _number(p.si_unit, lambda name, value, unit: p.check(value, name))


@dataclass(frozen=True)
class Key:
    """One key of a core table: how to check it and which CLI option (argparse dest) it sets."""

    check: Callable[[str, Any], Any]
    dest: str | None
    help: str


#: The core tables: table -> key -> :class:`Key`.
CORE_KEYS: dict[str, Mapping[str, Key]] = {
    "frame": {
        "preset": Key(_choice(tuple(PRESETS)), "ei1", "standard (EI1 146 N m^2) or rigid (9999)"),
        "ei1_n_m2": Key(_positive("N m^2"), "ei1", "grip-side bending rigidity EI1"),
        "ei2_n_m2": Key(_positive("N m^2"), "ei2", "top-side bending rigidity EI2"),
        "segments": Key(_segments, "segments", "uniform segments from the grip end"),
        "mesh": Key(_string, "mesh", "mesh file with cell data EI and rhoA"),
        "elements": Key(_integer(1), "elements", "number of beam elements"),
        "lead": Key(
            lead_tables, "add_mass", "lead tape: [[frame.lead]] tables of place and mass_g"
        ),
    },
    "ball": {"mass_kg": Key(_positive("kg"), "ball_mass", "ball mass m_B")},
    "contact": LiveView(lambda: _contact_keys()),
    "impact": {
        "position_x_over_l": Key(_interval(0.0, 1.0), "position", "impact point x/L"),
        "offset_m": Key(_number("m", check_finite), "offset", "offset from the long axis"),
        "speed_m_s": Key(_positive("m/s"), "speed", "incident ball speed V_B0"),
        "racket_speed_m_s": Key(
            _number("m/s", check_finite), "racket_speed", "racket speed towards the ball"
        ),
        "reference_x_over_l": Key(_interval(0.0, 1.0), "reference", "racket speed's point x/L"),
        "pivot_m": Key(_number("m", check_finite), "pivot", "pivot of the swing from the butt"),
    },
    "hand": {  # any key holds the racket in a hand (simulate)
        "grip": Key(_choice(tuple(GRIPS)), "hand_grip", "loose or firm grip (illustrative)"),
        "mass_kg": Key(_positive("kg"), "hand_mass", "hand mass m_h"),
        "grip_start_m": Key(_interval(0.0, math.inf), "grip_start", "grip start from the butt"),
        "grip_end_m": Key(_positive("m"), "grip_end", "grip end from the butt"),
        "stiffness_n_m2": Key(
            _interval(0.0, math.inf), "grip_stiffness", "grip layer stiffness [N/m per m]"
        ),
        "damping_n_s_m2": Key(
            _interval(0.0, math.inf), "grip_damping", "grip layer damping [N s/m per m]"
        ),
        "inertia_kg_m2": Key(_positive("kg m^2"), "hand_inertia", "hand inertia about its centre"),
        "shock_window_s": Key(_positive("s"), "hand_shock_window", "window of the shock measures"),
    },
    "strings": {  # any key replaces the lumped K_CB by the string bed (simulate)
        "tension_n": Key(_positive("N"), "string_tension", "tension per string"),
        "pattern": Key(_pattern, "pattern", "string pattern MAINSxCROSSES, e.g. 16x19"),
        "head_area_cm2": Key(_positive("cm^2"), "head_area", "string-bed area"),
        "head_length_m": Key(_positive("m"), "head_length", "string-bed length along the racket"),
        "head_width_m": Key(_positive("m"), "head_width", "string-bed width across the racket"),
        "string": Key(_choice(tuple(STRINGS)), "string_material", "string material"),
        "edge": Key(_choice(EDGES), "bed_edge", "head ring follows the frame: point or hoop"),
        "stretch": Key(_boolean, "string_stretch", "strings stretch with the deflection (cvode)"),
    },
    "oblique": {  # any key runs the oblique impact (simulate; sweep and map: its axes)
        "angle_deg": Key(
            _interval(0.0, 90.0, include_high=False), "angle", "ball's path from the face normal"
        ),
        "spin_rpm": Key(_number("rpm", check_finite), "spin", "incoming spin, + topspin"),
        "friction": Key(_interval(0.0, MAX_FRICTION), "friction", "sliding friction ball/strings"),
        "ball_inertia": Key(
            _interval(0.0, 2.0 / 3.0, include_low=False), "ball_inertia", "ball's I/(m R^2)"
        ),
        "ball_radius_m": Key(_positive("m"), "ball_radius", "ball radius R"),
        "compliance_ratio": Key(
            _interval(0.0, MAX_COMPLIANCE_RATIO),
            "compliance_ratio",
            "eta^2 = k_n/k_t of the contact",
        ),
        "side_angle_deg": Key(
            _interval(-90.0, 90.0, include_low=False, include_high=False),
            "side_angle",
            "ball's path from the plane of the long axis and the normal, + toward +y",
        ),
        "side_spin_rpm": Key(_number("rpm", check_finite), "side_spin", "side spin, + rolls to +y"),
        "clamped": Key(_boolean, "clamped", "a rigid, immovable head (eqs 1-3)"),
        "face_angle_deg": Key(
            _number("deg", check_finite), "face_angle", "string plane to the horizontal"
        ),
        "path_angle_deg": Key(
            _number("deg", check_finite), "path_angle", "racket path above the horizontal"
        ),
    },
    "solver": {
        "name": Key(_choice(SOLVER_NAMES), "solver", "method: auto, exact, general, cvode or bdf"),
        "separation": Key(_choice(SEPARATION_EVENTS), "separation", "end of contact"),
        "basis": Key(_choice(BASES), "basis", "frame coordinates for the BDF solvers"),
        "modes": Key(_integer(1), "modes", "flexible modes kept"),
        "tolerance": Key(
            _interval(0.0, 0.1), "tolerance", "COR error the exact solver may make (0: every mode)"
        ),
        "rtol": Key(_positive(), "rtol", "relative tolerance of the BDF solvers"),
        "atol": Key(_positive(), "atol", "absolute tolerance of the BDF solvers"),
        "t_max_s": Key(_positive("s"), "t_max", "give up if no separation by then"),
    },
    "output": {
        "out": Key(_string, "out", "simulate's output file (other commands: their own table)"),
        "overwrite": Key(_boolean, "overwrite", "replace an existing output file"),
    },
}


def _contact_keys() -> dict[str, Key]:
    """The [contact] table: the paper's law, the law's name and every registered family's
    declared parameters (:mod:`fem_racket.contact.registry`: a law registered later adds its
    keys)."""
    kcb, zeta = LinearContact.declared
    return {
        kcb.key: Key(_declared(kcb), kcb.name, kcb.help),
        zeta.key: Key(_declared(zeta), zeta.name, zeta.help),
        "clamped_cor": Key(
            _interval(0.0, 1.0, include_low=False), "zeta", "clamped-frame COR fixing zeta"
        ),
        "law": Key(_choice(LAW_NAMES), "law", "ball/string law: linear, a family or a preset"),
        **{
            p.key: Key(_declared(p), p.name, f"{family} law: {p.name} [{p.unit}]")
            for family, declared in family_parameters().items()
            for p in declared
        },
    }


#: The argparse dests the core tables own; a command table may not set them.
CORE_DESTS = frozenset(k.dest for t in CORE_KEYS.values() for k in t.values() if k.dest)


def _all_keys() -> list[str]:
    return [f"{t}.{k}" for t, keys in CORE_KEYS.items() for k in keys]


def reject_unknown(
    table: Mapping[str, Any], allowed: Mapping[str, Any] | list[str], where: str
) -> None:
    """Raise for the first key of ``table`` not in ``allowed``, with a "did you mean"."""
    for key in table:
        if key in allowed:
            continue
        here = difflib.get_close_matches(key, list(allowed), n=1, cutoff=0.6)
        if not where and COMMAND_TABLES.get(key, key) in allowed:  # [export-vtk] for [vtk]
            hint = f"did you mean '{COMMAND_TABLES[key]}'? (the table of fem-racket {key})"
        elif here:
            hint = f"did you mean '{here[0]}'?"
        else:
            other = difflib.get_close_matches(key, _all_keys(), n=1, cutoff=0.6)
            other += [d for d in _all_keys() if d.endswith(f".{key}")]
            hint = f"did you mean '{other[-1]}'?" if other else ""
            hint = f"{hint} allowed: {', '.join(allowed) or '(none)'}".strip()
        prefix = f"{where}." if where else ""
        raise InputError(f"{prefix}{key} is not a known key: {hint}")
