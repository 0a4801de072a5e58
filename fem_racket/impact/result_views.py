"""Notebook forms of an :class:`~fem_racket.impact.simulate.ImpactResult`.

A one-line ``repr`` with what a user needs at a glance (COR, contact time, peak force, impact,
solver, modes, elements), an HTML table of the summary for Jupyter, and the time histories as
an ``xarray.Dataset`` (xarray is imported inside :func:`impact_dataset`). The result is typed
``Any`` here: importing its class would make an import cycle (it calls these functions).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from fem_racket.display import html_table, number, short_repr

__all__ = ["impact_dataset", "impact_html", "impact_repr"]

#: Label and unit of each summary key, in the order of the HTML table.
LABELS = {
    "cor": ("coefficient of restitution", "-"),
    "apparent_cor": ("apparent COR e_A", "-"),
    "tolerance": ("COR tolerance", "-"),
    "contact_time_s": ("contact time", "ms"),
    "rebound_speed_m_s": ("rebound speed", "m/s"),
    "peak_force_n": ("peak force", "N"),
    "position_x_over_l": ("impact point", "x/L"),
    "speed_m_s": ("impact speed", "m/s"),
    "ball_mass_kg": ("ball mass m_B", "kg"),
    "kcb_n_m": ("K_CB", "N/m"),
    "zeta": ("zeta", "-"),
    "ccb_n_s_m": ("C_CB", "N s/m"),
    "solver": ("solver", ""),
    "separation": ("end of contact", ""),
    "basis": ("basis", ""),
    "modes": ("flexible modes kept", ""),
    "elements": ("elements", ""),
    "rtol": ("rtol", "-"),
    "atol": ("atol", "-"),
}


#: Unit suffixes of summary keys (JSON style) and the unit they stand for, longest first.
SUFFIXES = (
    ("_rad_s", "rad/s"),
    ("_kg_m2", "kg m²"),
    ("_n_s_m", "N s/m"),
    ("_m_s", "m/s"),
    ("_n_m", "N/m"),
    ("_x_over_l", "x/L"),
    ("_kg", "kg"),
    ("_hz", "Hz"),
    ("_s", "s"),
    ("_m", "m"),
    ("_n", "N"),
)
#: Keys shown in another unit than their JSON one: (factor, unit).
SHOWN_IN = {"contact_time_s": 1e3}


def _label(key: str) -> tuple[str, str]:
    """(label, unit) of a summary key: :data:`LABELS`, else the key without its unit suffix."""
    if key in LABELS:
        return LABELS[key]
    for suffix, unit in SUFFIXES:
        if key.endswith(suffix):
            return key[: -len(suffix)].replace("_", " "), unit
    return key.replace("_", " "), ""


def _solver(result: Any) -> str:
    modes = "" if result.n_modes is None else f", {result.n_modes} modes"
    return f"'{result.solver}' ({result.basis}{modes}, {result.model.mesh.n_elements} elements)"


def impact_repr(result: Any) -> str:
    """``ImpactResult(cor=0.37657, contact_time=4.0401 ms, ...)``."""
    return short_repr(
        "ImpactResult",
        [
            ("cor", number(result.cor, 6)),
            ("contact_time", f"{number(result.contact_time * 1e3, 5)} ms"),
            ("peak_force", f"{number(result.peak_force, 4)} N"),
            ("position", f"{result.impact.position:g} L"),
            ("speed", f"{result.impact.speed:g} m/s"),
            ("solver", _solver(result)),
            ("output_times", str(result.t.size)),
        ],
    )


def impact_html(result: Any) -> str:
    """The summary as an HTML table (quantity, value, unit)."""
    rows = []
    for key, value in result.summary().items():
        label, unit = _label(key)
        if isinstance(value, float):
            text = number(value * SHOWN_IN.get(key, 1.0), 6)
        else:
            text = "" if value is None else str(value)
        rows.append((label, text, unit))
    return html_table("ImpactResult", rows, ("quantity", "value", "unit"))


def impact_dataset(result: Any, x: np.ndarray | None = None) -> Any:
    """Time histories as an ``xarray.Dataset`` over ``time`` [s] (and ``x`` [m] for the frame's
    deflection); the summary in ``attrs``."""
    import xarray as xr

    x = result.model.mesh.points if x is None else np.asarray(x, dtype=float)

    def var(dims: tuple[str, ...], values: np.ndarray, units: str, text: str) -> tuple:
        return dims, np.asarray(values), {"units": units, "long_name": text}

    t = ("time",)
    data = {
        "ball_displacement": var(t, result.ball_displacement, "m", "ball displacement u_B"),
        "ball_velocity": var(t, result.ball_velocity, "m/s", "ball velocity v_B"),
        "impact_point_displacement": var(
            t, result.impact_point_displacement, "m", "frame deflection at the impact point"
        ),
        "impact_point_velocity": var(
            t, result.impact_point_velocity, "m/s", "frame velocity at the impact point"
        ),
        "spring_deflection": var(t, result.deflection, "m", "delta = u_B - w(x_i)"),
        "contact_force": var(t, result.force, "N", "F = K_CB delta + C_CB delta'"),
        "frame_deflection": var(
            ("time", "x"), result.frame_field(x), "m", "frame deflection w(x, t)"
        ),
    }
    coords = {
        "time": ("time", result.t, {"units": "s", "long_name": "time"}),
        "x": ("x", x, {"units": "m", "long_name": "position from the grip end"}),
    }
    attrs = {k: v for k, v in result.summary().items() if v is not None}
    return xr.Dataset(data, coords=coords, attrs=attrs)
