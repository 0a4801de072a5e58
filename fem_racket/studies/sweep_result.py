"""A finished sweep as plain arrays: its variables, attributes, netCDF file and summary.

:class:`SweepResult` holds the values of every case (one row per case, the columns of
:data:`fem_racket.studies.cases.COLUMNS`) and turns them into the labelled variables of the
dataset: one dimension per swept parameter (its values the coordinate), the result variables
:data:`~fem_racket.studies.cases.VARIABLES` and the global attributes (provenance, every fixed
parameter, solver, tolerances, modes kept). Each variable's ``long_name``, ``units`` and
``description`` come from :data:`fem_racket.outputs.labels.LABELS` (short names, so that
xarray's own ``.plot()`` labels fit on one line). The same variables give the netCDF file
(:func:`fem_racket.outputs.netcdf.write_netcdf`, no xarray: what the command line writes) and
the :class:`xarray.Dataset` of :func:`fem_racket.sweep`, so ``xarray.open_dataset`` of the file
is identical to that dataset.
"""

from __future__ import annotations

import json
import math
import os
from dataclasses import dataclass, field
from functools import cached_property
from typing import Any

import numpy as np

from fem_racket.contact.bed_ball import KAWAZOE_BALL
from fem_racket.contact.linear import PAPER_CLAMPED_COR, zeta_from_cor
from fem_racket.impact.exact.separation import TIME_TOL
from fem_racket.outputs import provenance
from fem_racket.outputs.labels import label
from fem_racket.studies.cases import ALL_VARIABLES, MODES_COLUMN, result_variables
from fem_racket.studies.grid import SweepSpec, parameter
from fem_racket.studies.grid_values import pattern_label
from fem_racket.studies.law_axes import family_of, law_attributes
from fem_racket.studies.sweep_physics import STRING_AXES, fixed_label, given, regime_label

__all__ = ["BED_BALL", "KCB_LAW", "SweepResult", "swinging"]

#: What a kcb of None means.
KCB_LAW = (
    "from the speed: piecewise power law through the paper's 2.74e4, 5.0e4, 8.33e4 N/m "
    "at 20, 30, 40 m/s"
)


#: The fixed parameters of the paper's linear law only: a sweep under another law (its
#: ``contact_*`` attributes) writes neither, as its dataset holds no ``kcb_n_m``; nor does a
#: strung sweep, whose bed replaces the lumped K_CB (its ball's own law: :data:`BED_BALL`).
PAPER_LAW_ONLY = ("kcb", "zeta")
#: The ball's own law on a string bed under the paper's law (the ``ball_law`` attribute, as
#: ``simulate --string-tension`` names it; its spring and dashpot as ``contact_*``).
BED_BALL = "kawazoe-1997-ball"


def swinging(spec: SweepSpec) -> bool:
    """Whether any case swings the racket (a racket speed other than 0): only then does the
    swing's ``reference`` point mean anything."""
    return bool(np.any(np.atleast_1d(spec.values["racket_speed"]) != 0.0))


def spec_attributes(spec: SweepSpec) -> dict[str, Any]:
    """Provenance, every fixed parameter (units in the names; the paper law's only under it),
    solver and tolerances."""
    params: dict[str, Any] = {}
    strung = bool(given(spec.values, STRING_AXES))  # the bed replaces the paper's K_CB
    for name, value in spec.fixed.items():
        if (spec.law is not None or strung) and name in PAPER_LAW_ONLY:
            continue  # they describe a law not used
        if name == "reference" and not swinging(spec):
            continue  # no swing: no point whose speed it gives (as the Swing's reference)
        attr = parameter(name).attribute
        if value is None and name == "kcb":
            value = KCB_LAW
        elif value is None and name == "zeta":
            value = zeta_from_cor(PAPER_CLAMPED_COR)
        if value is not None:
            params[attr] = fixed_label(name, value)
    if spec.frame is None:
        params["ei2_n_m2"] = "0.88 ei1" if spec.ei2 is None else spec.ei2
    desc = spec.describe()
    params.update(
        frame=desc["frame"],
        solver=spec.solver,
        separation=spec.separation,
        basis=spec.basis,
        modes="all" if spec.modes is None else int(spec.modes),
        rtol=spec.rtol,
        atol=spec.atol,
        swept=" ".join(spec.dims),
        spec_sha256=spec.digest,
    )
    if spec.law is None and strung:  # the ball's own law on the bed, as simulate's
        params["ball_law"] = BED_BALL
        params.update(law_attributes(KAWAZOE_BALL, spec.values["ball_mass"]))  # contact_law too
    elif spec.law is None:
        params["contact_law"] = "linear"
    elif family_of(spec.law) is None:  # no named parameters: the law as it describes itself
        params.update(law_attributes(spec.law, spec.values["ball_mass"]))  # to the balls struck
    else:  # its parameters: fixed ones above, swept ones are dimensions
        params["contact_law"] = spec.law.name
    if spec.law is None and spec.solver == "exact" and strung:  # every mode, no tolerance
        params["tolerance"] = "all modes"
        params["tolerances"] = (
            "exact: closed form (the ball's spring-dashpot on the strung racket, every frame "
            f"and string-bed mode), separation time to {TIME_TOL:g} s plus 4 eps relative; "
            "tolerance, rtol, atol unused"
        )
    elif spec.law is None and spec.solver == "exact":
        params["tolerance"] = "all modes" if spec.tolerance is None else spec.tolerance
        params["tolerances"] = (
            "exact: closed form (batched engine), COR within 'tolerance' of every mode, "
            "separation time to 1e-14 relative; rtol, atol unused"
        )
    params["peak_force"] = "computed" if spec.peak_force else "not asked"
    prov = provenance(params)
    attrs = {k: v for k, v in prov.items() if k != "parameters"}
    attrs.update(prov["parameters"])
    return attrs


def _cell(name: str, value: Any) -> str:
    """A CSV cell: a pattern and a contact regime by their labels, numbers by repr."""
    if name == "pattern":
        return pattern_label(value)
    if name == "contact_regime":
        return "" if not np.isfinite(value) else regime_label(value)
    return repr(float(value))


def _attrs(name: str, units: str, description: str) -> dict[str, str]:
    """A variable's attributes: short ``long_name``, ``units`` (``-`` when dimensionless) and
    ``description`` (:mod:`fem_racket.outputs.labels`)."""
    return label(name, units, description).attrs()


def modes_kept(spec: SweepSpec, kept: np.ndarray) -> int | str:
    """The ``modes_kept`` attribute: the flexible modes the solver kept, one number when every
    case kept the same, else their range (the engine's COR tolerance chooses them per case)."""
    kept = kept[np.isfinite(kept)]
    if given(spec.values, STRING_AXES):
        return "all (string bed: every frame mode)"
    if kept.size == 0:
        return "none (physical basis)" if spec.basis == "physical" else "none (no case solved)"
    low, high = int(kept.min()), int(kept.max())
    return low if low == high else f"{low} to {high} (per case)"


@dataclass
class SweepResult:
    """The outcome of a sweep (:func:`fem_racket.studies.sweep.sweep_result`).

    Attributes
    ----------
    spec : SweepSpec
        What was swept.
    values : ndarray, shape (cases, len(COLUMNS))
        One row per case in C order of the dimensions: the variables, then the modes kept.
    backend : str
        Where it ran ("serial", "processes" or "dask").
    parameters : dict, optional
        Extra provenance (the attribute ``run_parameters``, JSON).
    """

    spec: SweepSpec
    values: np.ndarray
    backend: str
    parameters: dict[str, Any] | None = field(default=None)

    @property
    def failed(self) -> int:
        """Number of cases that failed (NaN in every variable)."""
        return int(np.count_nonzero(np.isnan(self.values[:, 0])))

    @cached_property
    def attrs(self) -> dict[str, Any]:
        """The dataset's global attributes (made once: the file and the dataset share the
        creation time)."""
        attrs = spec_attributes(self.spec)
        attrs["modes_kept"] = modes_kept(self.spec, self.values[:, MODES_COLUMN])
        attrs["backend"] = self.backend
        attrs["failed_cases"] = self.failed
        if self.parameters:
            attrs["run_parameters"] = json.dumps(self.parameters, sort_keys=True, default=str)
        return attrs

    def coordinates(self) -> dict[str, tuple[tuple[str, ...], np.ndarray, dict[str, str]]]:
        """Each swept parameter's values: name -> ((name,), values, attributes of its
        :func:`~fem_racket.outputs.labels.label`; a pattern's labels as CF flags)."""
        out = {}
        for name, vals in self.spec.axes.items():
            attrs: dict[str, Any] = _attrs(name, parameter(name).unit, parameter(name).description)
            if name == "pattern":
                attrs["flag_values"] = [int(v) for v in vals]
                attrs["flag_meanings"] = " ".join(pattern_label(v) for v in vals)
            out[name] = ((name,), vals, attrs)
        return out

    def data_variables(self) -> dict[str, tuple[tuple[str, ...], np.ndarray, dict[str, str]]]:
        """The result variables: name -> (dimensions, values, attributes of its
        :func:`~fem_racket.outputs.labels.label`)."""
        spec, keep = self.spec, result_variables(self.spec)
        out = {
            name: (spec.dims, self.values[:, k].reshape(spec.shape), _attrs(name, u, t))
            for k, (name, (u, t)) in enumerate(ALL_VARIABLES.items())
            if name in keep
        }
        if "contact_regime" in out:  # CF flags naming the codes present
            dims, values, attrs = out["contact_regime"]
            codes = sorted({float(c) for c in values.ravel() if np.isfinite(c)})
            if codes:
                attrs = {
                    **attrs,
                    "flag_values": codes,
                    "flag_meanings": " ".join(regime_label(c) for c in codes),
                }
            out["contact_regime"] = (dims, values, attrs)
        return out

    def write(self, path: str | os.PathLike) -> None:
        """Write the netCDF file (no xarray; inside an ``atomic_output``)."""
        from fem_racket.outputs.netcdf import write_netcdf

        # variables before coordinates, as xarray writes a dataset made like to_xarray's
        write_netcdf(path, {**self.data_variables(), **self.coordinates()}, self.attrs)

    def write_csv(self, path: str | os.PathLike, sidecar: str | os.PathLike) -> None:
        """Write the CSV table (one row per case: the swept values, then the variables; units
        in the headers; a pattern and a contact regime by their labels) and its JSON sidecar
        (the attributes), inside an ``atomic_outputs``."""
        import csv

        spec, keep = self.spec, result_variables(self.spec)
        names = list(spec.axes)
        header = [f"{n} [{label(n, parameter(n).unit).units}]" for n in names]
        header += [f"{v} [{label(v, ALL_VARIABLES[v][0]).units}]" for v in keep]
        cols = [list(ALL_VARIABLES).index(v) for v in keep]
        where = np.unravel_index(np.arange(spec.size), spec.shape) if names else ()
        with open(path, "w", newline="", encoding="utf-8") as fh:
            w = csv.writer(fh)
            w.writerow(header)
            for i in range(spec.size):
                row = [_cell(n, spec.axes[n][k[i]]) for n, k in zip(names, where, strict=True)]
                row += [_cell(v, self.values[i, c]) for v, c in zip(keep, cols, strict=True)]
                w.writerow(row)
        with open(sidecar, "w", encoding="utf-8") as fh:
            json.dump(self.attrs, fh, indent=2, default=str, allow_nan=True)
            fh.write("\n")

    def to_xarray(self) -> Any:
        """The labelled :class:`xarray.Dataset` (what :func:`fem_racket.sweep` returns)."""
        import xarray as xr

        return xr.Dataset(self.data_variables(), coords=self.coordinates(), attrs=dict(self.attrs))

    def summary(self) -> dict[str, Any]:
        """Cases, dimensions, the COR range (NaN when no case solved), solver, law (and the
        ball's own law on a string bed under the paper's), backend."""
        cor = self.values[:, 0]
        solved = cor[np.isfinite(cor)]
        bed = {"ball_law": self.attrs["ball_law"]} if "ball_law" in self.attrs else {}
        return {
            "impacts": self.spec.size,
            "dims": dict(zip(self.spec.dims, map(int, self.spec.shape), strict=True)),
            "cor_min": float(solved.min()) if solved.size else math.nan,
            "cor_max": float(solved.max()) if solved.size else math.nan,
            "solver": self.attrs["solver"],
            "contact_law": self.attrs["contact_law"],
            **bed,
            "backend": self.backend,
        }
