"""Short text and HTML forms of the studies' results, for terminals and notebooks.

Each result class takes its mixin: ``repr`` is one line with what a user needs at a glance
(:func:`fem_racket.display.short_repr`, units written out), ``_repr_html_`` a small table with a
unit column (:func:`fem_racket.display.html_table`), never the arrays behind them. The classes
declare ``@dataclass(repr=False)`` so that these forms are theirs.
"""

from __future__ import annotations

import math
from typing import Any

from fem_racket.display import html_table, number, short_repr

__all__ = ["CalibrationView", "DesignView", "MapView", "SobolView", "SpotsView"]


def _x(value: float) -> str:
    return "-" if value is None or math.isnan(value) else f"{number(value, 4)} x/L"


def _spot_rows(spots: Any) -> list[tuple[str, str, str]]:
    def at(v: float) -> str:
        return "-" if math.isnan(v) else number(v, 4)

    low, high = spots.power_region
    return [
        ("centre of percussion", at(spots.cop), "x/L"),
        ("mode-1 node", at(spots.node), "x/L"),
        ("max apparent COR", at(spots.max_apparent_cor), "x/L"),
        ("max ball speed", at(spots.max_ball_speed), "x/L"),
        (
            f"power region (>= {number(spots.power_fraction, 3)} of max)",
            f"{at(low)}-{at(high)}",
            "x/L",
        ),
    ]


class SpotsView:
    """``SweetSpots(cop=0.7387 x/L, node=0.7697 x/L, ...)`` and its table."""

    def __repr__(self) -> str:
        low, high = self.power_region
        return short_repr(
            "SweetSpots",
            [
                ("cop", _x(self.cop)),
                ("node", _x(self.node)),
                ("max_apparent_cor", _x(self.max_apparent_cor)),
                ("max_ball_speed", _x(self.max_ball_speed)),
                ("power_region", f"{_x(low)[:-4]}-{_x(high)}"),
            ],
        )

    def _repr_html_(self) -> str:
        return html_table("SweetSpots", _spot_rows(self), ("sweet spot", "position", "unit"))


class MapView:
    """``RacketMap('standard', 200 points 0.5-1 x/L, ...)`` and its table."""

    def __repr__(self) -> str:
        x, e = self.positions, self.apparent_cor
        return short_repr(
            "RacketMap",
            [
                ("name", repr(self.name)),
                ("points", f"{x.size} over {number(x[0], 4)}-{number(x[-1], 4)} x/L"),
                ("speed", f"{number(self.speed, 5)} m/s"),
                ("law", repr(self.law_summary()["law"])),
                ("apparent_cor", f"{number(min(e), 4)} to {number(max(e), 4)}"),
                ("node", _x(self.spots.node)),
                ("max_ball_speed", _x(self.spots.max_ball_speed)),
            ],
        )

    def _repr_html_(self) -> str:
        rows = [
            ("incoming ball speed", number(self.speed, 5), "m/s"),
            ("apparent COR e_A", f"{number(min(self.apparent_cor), 4)} to "
             f"{number(max(self.apparent_cor), 4)}", "-"),
            ("ball speed out v_out", f"{number(min(self.ball_speed_out), 4)} to "
             f"{number(max(self.ball_speed_out), 4)}", "m/s"),
            *_spot_rows(self.spots),
        ]  # fmt: skip
        return html_table(f"RacketMap '{self.name}'", rows, ("quantity", "value", "unit"))


class DesignView:
    """``DesignResult('SLSQP', cor 0.29735 -> 0.39037, ...)`` and its table."""

    def __repr__(self) -> str:
        name = self.problem.objectives[0]
        return short_repr(
            "DesignResult",
            [
                ("method", repr(self.method)),
                (name, f"{number(self.start_objective, 6)} -> {number(self.objective, 6)}"),
                ("variables", str(len(self.x))),
                ("success", str(self.success)),
                ("iterations", str(self.iterations)),
            ],
        )

    def _repr_html_(self) -> str:
        name = self.problem.objectives[0]
        rows = [(name, number(self.start_objective, 6), number(self.objective, 6), "")]
        for v, x0, x in zip(self.problem.variables, self.x_start, self.x, strict=True):
            rows.append((v.name, number(x0, 6), number(x, 6), v.unit))
        caption = f"DesignResult ({self.method}: {self.message})"
        return html_table(caption, rows, ("quantity", "start", "best", "unit"))


class SobolView:
    """``SobolIndices('cor', 10240 designs, largest ST rhoa_4 0.73)`` and its table."""

    def __repr__(self) -> str:
        top = max(range(len(self.names)), key=lambda i: self.st[i])
        return short_repr(
            "SobolIndices",
            [
                ("output", repr(self.output)),
                ("designs", str(self.designs)),
                ("mean", number(self.mean, 6)),
                ("largest_ST", f"{self.names[top]} {number(self.st[top], 3)}"),
            ],
        )

    def _repr_html_(self) -> str:
        rows = [
            (n, number(a, 3), number(b, 2), number(c, 3), number(d, 2))
            for n, a, b, c, d in zip(
                self.names, self.s1, self.s1_conf, self.st, self.st_conf, strict=True
            )
        ]
        header = ("variable", "S1 [-]", "+- [-]", "ST [-]", "+- [-]")
        return html_table(f"Sobol indices of {self.output} ({self.designs} designs)", rows, header)


class CalibrationView:
    """``Calibration('hysteretic' to 'kawazoe-1997', meets_targets=True, ...)`` and its table."""

    def __repr__(self) -> str:
        worst = max(abs(float(e)) for e in self.scaled_errors)
        return short_repr(
            "Calibration",
            [
                ("family", repr(self.family)),
                ("targets", repr(self.target_set)),
                ("meets_targets", str(self.meets_targets)),
                ("worst", f"{number(worst, 3)} x tolerance"),
            ],
        )

    def _repr_html_(self) -> str:
        rows = [
            (r["quantity"], number(r["condition"], 4), number(r["target"], 4),
             number(r["model"], 4), number(r["tolerance"], 2), "yes" if r["within"] else "NO")
            for r in self.table()
        ]  # fmt: skip
        header = ("target", "at", "target value", "model", "tolerance", "within")
        return html_table(f"Calibration of {self.family} to {self.target_set}", rows, header)
