"""Notebook forms of a :class:`~fem_racket.studies.refine.RefinementStudy`.

A one-line ``repr`` (family, meshes, the finest frequency error, COR on the finest mesh), an
HTML table per mesh for Jupyter, and an ``xarray.Dataset`` of every result (xarray is imported
inside :func:`study_dataset`). The study is typed ``Any`` here: importing its class would
make an import cycle (it calls these functions).
"""

from __future__ import annotations

from typing import Any

import numpy as np

from fem_racket.display import html_table, number, short_repr

__all__ = ["study_dataset", "study_html", "study_repr"]


def study_repr(study: Any) -> str:
    """``RefinementStudy(family='uniform', elements=5..320 (7 meshes), ...)``."""
    n = study.elements
    cor = ", ".join(
        f"{x:g} L: {number(c, 9)}" for x, c in zip(study.positions, study.cor[-1], strict=True)
    )
    return short_repr(
        "RefinementStudy",
        [
            ("family", repr(study.family)),
            ("elements", f"{n[0]}..{n[-1]} ({n.size} meshes)"),
            ("f1_error", f"{number(study.relative_error[0, 0], 2)} -> "
             f"{number(study.relative_error[-1, 0], 2)}"),
            ("cor_finest", f"{{{cor}}}"),
            ("speed", f"{study.speed:g} m/s"),
        ],
    )  # fmt: skip


def study_html(study: Any) -> str:
    """A table per mesh: relative frequency errors, COR and contact time at each point."""
    m = study.exact_frequencies_hz.size
    header = ["cells"] + [f"err f{k + 1} [-]" for k in range(m)]
    header += [f"COR at {x:g} L" for x in study.positions]
    header += [f"t_c at {x:g} L [ms]" for x in study.positions]
    rows = []
    for i, n in enumerate(study.elements):
        row: list[Any] = [int(n)]
        row += [f"{e:.3e}" for e in study.relative_error[i]]
        row += [f"{c:.9f}" for c in study.cor[i]]
        row += [f"{t * 1e3:.6f}" for t in study.contact_time_s[i]]
        rows.append(row)
    caption = (
        f"{study.family} meshes, {study.speed:g} m/s; exact frequencies "
        + ", ".join(f"{f:.3f}" for f in study.exact_frequencies_hz)
        + " Hz"
    )
    return html_table(caption, rows, header)


def study_dataset(study: Any) -> Any:
    """Every result of the study as an ``xarray.Dataset`` (units in ``attrs['units']``)."""
    import xarray as xr

    def var(dims: tuple[str, ...], values: np.ndarray, units: str, text: str) -> tuple:
        return dims, np.asarray(values), {"units": units, "long_name": text}

    cells, modes, points = ("elements",), ("elements", "mode"), ("elements", "position")
    data = {
        "frequency": var(modes, study.frequencies_hz, "Hz", "FE frequency (Rayleigh quotient)"),
        "relative_error": var(modes, study.relative_error, "1", "f_FE / f_exact - 1"),
        "cor": var(points, study.cor, "1", "coefficient of restitution"),
        "contact_time": var(points, study.contact_time_s, "s", "contact time t_c"),
        "build_time": var(cells, study.build_time_s, "s", "assembly and modes"),
        "impact_time": var(cells, study.impact_time_s, "s", "wall time per impact"),
        "modes_used": var(cells, study.impact_modes_used, "1", "flexible modes kept"),
        "exact_frequency": var(("mode",), study.exact_frequencies_hz, "Hz", "exact frequency"),
    }
    coords = {
        "elements": ("elements", study.elements, {"units": "1", "long_name": "elements"}),
        "mode": ("mode", np.arange(1, study.exact_frequencies_hz.size + 1), {"units": "1"}),
        "position": ("position", study.positions, {"units": "x/L", "long_name": "impact point"}),
    }
    attrs = {"family": study.family, "speed_m_s": study.speed}
    attrs.update({k: v for k, v in study.impact_settings.items() if v is not None})
    return xr.Dataset(data, coords=coords, attrs=attrs)
