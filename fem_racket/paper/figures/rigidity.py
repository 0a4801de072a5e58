"""Fig 13 of Kawazoe & Kanda (1997): COR against frame rigidity EI1 (EI2 = 0.88 EI1).

EI1 runs log-spaced from 50 to 3000 N m^2 at 20, 30 and 40 m/s, at three impact points, with
the ball/string damping (zeta = 0.0592) and without it. One assembled frame serves every EI1
through the batched engine's ``ei_factor`` (the modal frequencies scale as its square root; the
shapes do not): one :func:`fem_racket.impacts` call per curve.

Saturation is measured as the smallest EI1 beyond which the COR stays at or above 95 % of
COR_rigid, the value for the paper's rigid frame (EI1 = 9999 N m^2). With a linear ball/string
law and fixed zeta the COR depends on EI1 and K_CB only through EI1 / K_CB (frame frequencies
scale as EI1^(1/2), the ball/string frequency as K_CB^(1/2)), so this saturation rigidity grows
in proportion to K_CB(speed).
"""

from __future__ import annotations

import numpy as np

from fem_racket.contact.linear import PAPER_CLAMPED_COR, kcb_from_speed, zeta_from_cor
from fem_racket.frame.model import FrameModel
from fem_racket.frame.segments import PAPER_EI1, RIGID_EI1, standard_frame
from fem_racket.impact.engine import impacts
from fem_racket.paper.figures.data import FigureData, FigureSpec

__all__ = ["FIG_13", "SATURATION_FRACTION", "cor_rigidity", "saturation_ei"]

SPEEDS = (20.0, 30.0, 40.0)
POSITIONS = (0.60, 0.75, 0.90)
#: Share of the rigid frame's COR that counts as saturated.
SATURATION_FRACTION = 0.95


def saturation_ei(
    ei: np.ndarray, cor: np.ndarray, cor_rigid: float, fraction: float = SATURATION_FRACTION
) -> float:
    """Smallest ``ei`` from which ``cor`` stays at or above ``fraction * cor_rigid`` (NaN if it
    never does on the grid) [N m^2]."""
    level = fraction * cor_rigid
    below = np.flatnonzero(cor < level)
    if below.size == 0:
        return float(ei[0])
    if below[-1] == ei.size - 1:
        return float("nan")
    return float(ei[below[-1] + 1])


def cor_rigidity(quick: bool = False) -> FigureData:
    """COR against EI1 at three speeds, three positions, with and without damping."""
    base = FrameModel.build(standard_frame(PAPER_EI1), 20)
    ei = np.geomspace(50.0, 3000.0, 8 if quick else 40)
    factors = np.append(ei, RIGID_EI1) / PAPER_EI1  # the last: the paper's rigid frame
    cols: dict[str, list] = {}
    values: dict[str, float] = {"ei_points": float(ei.size)}
    for zeta, ztag in ((None, "damped"), (0.0, "undamped")):
        for p in POSITIONS:
            sat = {}
            end = []
            for v in SPEEDS:
                every = impacts(base, position=p, speed=v, zeta=zeta, ei_factor=factors).cor
                cor, c_rig = every[:-1], float(every[-1])
                for k, val in {
                    "zeta [-]": np.full(
                        ei.size, zeta_from_cor(PAPER_CLAMPED_COR) if zeta is None else zeta
                    ),
                    "position [x/L]": np.full(ei.size, p),
                    "speed [m/s]": np.full(ei.size, v),
                    "EI1 [N m^2]": ei,
                    "COR [-]": cor,
                    "COR rigid frame EI1 = 9999 N m^2 [-]": np.full(ei.size, c_rig),
                }.items():
                    cols.setdefault(k, []).append(val)
                tag = f"{ztag}_{round(p * 100)}_{round(v)}"
                sat[v] = saturation_ei(ei, cor, c_rig)
                values[f"ei_sat_{tag}"] = sat[v]
                values[f"cor_rigid_{tag}"] = c_rig
                values[f"cor_50_{tag}"] = float(cor[0])
                values[f"cor_3000_{tag}"] = float(cor[-1])
                values[f"overshoot_{tag}"] = float(np.max(cor - c_rig))
                values[f"max_drop_{tag}"] = float(np.max(np.maximum.accumulate(cor) - cor))
                end.append(c_rig)
            s = np.array([sat[v] for v in SPEEDS])
            ptag = f"{ztag}_{round(p * 100)}"
            values[f"ei_sat_rises_{ptag}"] = float(np.all(np.diff(s) > 0.0))
            values[f"ei_sat_ratio_40_20_{ptag}"] = float(s[-1] / s[0])
            values[f"cor_rigid_spread_{ptag}"] = float(np.ptp(end))
    values["kcb_ratio_40_20"] = kcb_from_speed(40.0) / kcb_from_speed(20.0)
    values["ei_ratio_step"] = float(ei[1] / ei[0])
    return FigureData(
        "fig13_cor_rigidity",
        "Fig. 13: coefficient of restitution against frame rigidity EI1 (EI2 = 0.88 EI1)",
        {"cor": {k: np.concatenate(v) for k, v in cols.items()}},
        values,
    )


FIG_13 = FigureSpec("fig13_cor_rigidity", ("cor",), cor_rigidity, "cor_rigidity")
