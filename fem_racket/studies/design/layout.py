"""The layout of a design problem's parameter vector, and the design variables' unit box.

The racket is a stepped beam of fixed length L whose segments (between fixed boundaries x/L) each
have a bending rigidity EI_k [N m^2] and mass per length rhoA_k [kg/m], plus optional masses added
at chosen positions (strips, :mod:`fem_racket.frame.masses`). Its full parameter vector is::

    p = [EI_1 .. EI_n, rhoA_1 .. rhoA_n, m_1 .. m_a, x_1 .. x_a]

(x_k the added masses' centres x/L), followed by the contact law's string-bed parameters
(:attr:`ParameterLayout.law_names`): the factor on the paper's K_CB(v) for its linear law, k_s and
k_3 for the series law. With ``ei_stations`` (``rhoa_stations``) the EI (rhoA)
entries are instead the values of a smooth profile at those control points x/L, interpolated
between them and averaged over each mesh cell (:mod:`.profiles`); their count is the stations'.

Any subset of p is free (the design variables, each with bounds); the rest keeps the starting
racket's values. With ``link_ei`` one variable "ei" is EI_1 and every EI_k keeps its starting ratio
EI_k / EI_1 (the paper's Fig 13 varies EI1 with EI2 = 0.88 EI1 this way). EI variables are searched
on a log scale, so the unit box u in [0, 1]^n_var maps to them logarithmically
(:meth:`.variables.Variable.from_unit`).
"""

from __future__ import annotations

from dataclasses import replace

import numpy as np

from fem_racket.contact.law import ContactLaw
from fem_racket.contact.series import SeriesBallString
from fem_racket.studies.design.variables import Variable

__all__ = ["ParameterLayout"]


class ParameterLayout:
    """The parameter vector p of a design problem and its design variables x (a base of
    :class:`~.problem.DesignProblem`, whose fields it reads)."""

    segment_lengths: tuple[float, ...]
    start: np.ndarray
    variables: tuple[Variable, ...]
    ei_stations: tuple[float, ...]
    rhoa_stations: tuple[float, ...]
    law: ContactLaw | None

    @property
    def n_segments(self) -> int:
        """Number of design segments."""
        return len(self.segment_lengths)

    @property
    def n_ei(self) -> int:
        """Number of EI entries of p (control points or segments)."""
        return len(self.ei_stations) or self.n_segments

    @property
    def n_rhoa(self) -> int:
        """Number of rhoA entries of p (control points or segments)."""
        return len(self.rhoa_stations) or self.n_segments

    @property
    def law_names(self) -> tuple[str, ...]:
        """The contact law's entries at the end of p (see the module docstring)."""
        if self.law is None:
            return ("kcb_factor",)
        if isinstance(self.law, SeriesBallString):
            return ("string_stiffness", "string_cubic")
        return ()

    def law_values(self, x: np.ndarray) -> dict[str, np.ndarray]:
        """The law entries of p for design variables ``x`` (shape (..., n_var)), by name."""
        p = self.parameters(x)
        k = len(self.law_names)
        tail = p[..., p.shape[-1] - k :]
        return {name: tail[..., j] for j, name in enumerate(self.law_names)}

    def design_law(self, x: np.ndarray) -> ContactLaw | None:
        """The contact law of one design ``x`` (1-D): the problem's law with the design's
        string bed (series law), or None for the paper's linear law (its K_CB factor is
        ``law_values(x)["kcb_factor"]``)."""
        if not isinstance(self.law, SeriesBallString):
            return self.law
        values = self.law_values(np.asarray(x, dtype=float))
        return replace(
            self.law,
            string_stiffness=float(values["string_stiffness"]),
            string_cubic=float(values["string_cubic"]),
        )

    @property
    def length(self) -> float:
        """Frame length L [m]."""
        return float(sum(self.segment_lengths))

    @property
    def names(self) -> list[str]:
        """Variable names."""
        return [v.name for v in self.variables]

    @property
    def n_var(self) -> int:
        """Number of design variables."""
        return len(self.variables)

    @property
    def lower(self) -> np.ndarray:
        """Lower bounds [SI]."""
        return np.array([v.low for v in self.variables])

    @property
    def upper(self) -> np.ndarray:
        """Upper bounds [SI]."""
        return np.array([v.high for v in self.variables])

    @property
    def x_start(self) -> np.ndarray:
        """The starting racket's design variables, clipped into the bounds [SI]."""
        x = self.start[[v.index for v in self.variables]]
        return np.clip(x, self.lower, self.upper)

    def to_unit(self, x: np.ndarray) -> np.ndarray:
        """Design variables [SI], shape (..., n_var) -> unit box."""
        x = np.asarray(x, dtype=float)
        return np.stack([v.to_unit(x[..., k]) for k, v in enumerate(self.variables)], -1)

    def from_unit(self, u: np.ndarray) -> np.ndarray:
        """Unit box -> design variables [SI]."""
        u = np.clip(np.asarray(u, dtype=float), 0.0, 1.0)
        return np.stack([v.from_unit(u[..., k]) for k, v in enumerate(self.variables)], -1)

    def parameters(self, x: np.ndarray) -> np.ndarray:
        """Full parameter vector(s) p for design variables ``x`` (shape (..., n_var))."""
        x = np.asarray(x, dtype=float)
        p = np.broadcast_to(self.start, x.shape[:-1] + self.start.shape).copy()
        n, r = self.n_ei, self.n_rhoa
        for k, v in enumerate(self.variables):
            if v.name == "ei":
                p[..., :n] = x[..., k, None] * self.start[:n] / self.start[0]
            elif v.name == "rhoa":
                p[..., n : n + r] = x[..., k, None] * self.start[n : n + r] / self.start[n]
            else:
                p[..., v.index] = x[..., k]
        return p

    def stiffness(self, x: np.ndarray) -> np.ndarray:
        """EI_1 of each design [N m^2] (priced by ``stiffness_cost``)."""
        return self.parameters(x)[..., 0]
