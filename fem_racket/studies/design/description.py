"""A design problem's description (JSON-able, for provenance and history files) and its digest.

The digest is the SHA-256 of the description with sorted keys: a history
(:mod:`.history`) belongs to the one problem whose digest it records.
"""

from __future__ import annotations

import hashlib
import json
from dataclasses import asdict
from typing import Any

__all__ = ["ProblemDescription"]


class ProblemDescription:
    """:meth:`describe` and :attr:`digest` of a design problem (a base of
    :class:`~.problem.DesignProblem`, whose fields they read)."""

    def describe(self) -> dict[str, Any]:
        """A JSON-able description (provenance, history files)."""
        return {
            "segment_lengths_m": list(self.segment_lengths),
            "start": self.start.tolist(),
            "variables": [
                {"name": v.name, "low": v.low, "high": v.high, "unit": v.unit, "log": v.log}
                for v in self.variables
            ],
            "mass_positions_x_over_l": list(self.mass_positions),
            "mass_width_m": self.mass_width,
            "zone": {
                "description": self.zone.description,
                "positions_x_over_l": self.zone.positions.tolist(),
                "weights": self.zone.weights.tolist(),
            },
            "speeds_m_s": list(self.speeds),
            "swing": None if self.swing is None else self._swing(),
            "constraints": [
                {"name": c.name, "low": c.low, "high": c.high, "tolerance": c.tolerance}
                for c in self.constraints
            ],
            "objectives": list(self.objectives),
            "link_ei": self.link_ei,
            "link_rhoa": self.link_rhoa,
            "stiffness_cost_per_n_m2": self.stiffness_cost,
            "region_x_over_l": self.region.tolist(),
            "power_fraction": self.power_fraction,
            "ball_mass_kg": self.ball_mass,
            "zeta": self.zeta,
            "elements": self.elements,
            "modes": "by tolerance" if self.modes is None else self.modes,
            "tolerance": self.tolerance,
            **(
                {
                    "ei_stations_x_over_l": list(self.ei_stations),
                    "rhoa_stations_x_over_l": list(self.rhoa_stations),
                    "interpolation": self.interpolation,
                }
                if self.ei_stations or self.rhoa_stations
                else {}
            ),
            **({} if self.law is None else {"law": self.law.describe()}),
        } | ({"hand": asdict(self.hand), "shock_window_s": self.shock_window} if self.shock else {})

    def _swing(self) -> dict[str, Any]:
        """The swing's description; its ``reference_x_over_l`` only with a swing (a racket
        speed other than 0: at rest no point's speed is given, as a sweep's file writes it)."""
        s = self.swing
        reference = {"reference_x_over_l": s.reference} if s.head_speed != 0.0 else {}
        return {
            "head_speed_m_s": s.head_speed,
            **reference,
            "pivot_m": s.pivot,
            "exponent": s.exponent,
            "reference_inertia_kg_m2": s.reference_inertia,
        }

    @property
    def digest(self) -> str:
        """SHA-256 of :meth:`describe` (a history file belongs to one problem)."""
        text = json.dumps(self.describe(), sort_keys=True, default=str)
        return hashlib.sha256(text.encode()).hexdigest()
