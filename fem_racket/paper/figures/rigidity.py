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

Under another contact law every EI1 runs as one batch of the nine position/speed cases through
the general integrator (:mod:`.law_runs`), with the law and with its elastic counterpart in
place of zeta = 0; K_CB(40)/K_CB(20) is then the law's equivalent stiffness ratio.
"""

from __future__ import annotations

import numpy as np

from fem_racket.contact.law import ContactLaw
from fem_racket.contact.linear import PAPER_CLAMPED_COR, Ball, kcb_from_speed, zeta_from_cor
from fem_racket.frame.model import FrameModel
from fem_racket.frame.segments import PAPER_EI1, RIGID_EI1, standard_frame
from fem_racket.impact.exact.engine import impacts
from fem_racket.paper.figures.data import FigureData, FigureSpec
from fem_racket.paper.figures.law_runs import (
    free_impacts,
    law_figure,
)
from fem_racket.studies.calibrate import clamped_impacts

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


def _curves(base: FrameModel, factors: np.ndarray, law: ContactLaw | None) -> dict[str, np.ndarray]:
    """COR [-] at every EI1 factor, shape (positions, speeds, factors), per curve family:
    ``"damped"`` (the paper's zeta, or ``law``) and ``"undamped"`` (zeta = 0, or the law's
    elastic counterpart; left out when it has none)."""
    shape = (len(POSITIONS), len(SPEEDS), factors.size)
    if law is None:
        out = {}
        for zeta, tag in ((None, "damped"), (0.0, "undamped")):
            cor = np.empty(shape)
            for i, p in enumerate(POSITIONS):
                for j, v in enumerate(SPEEDS):
                    cor[i, j] = impacts(base, position=p, speed=v, zeta=zeta, ei_factor=factors).cor
            out[tag] = cor
        return out
    m_b = Ball().mass
    pos, speed = np.meshgrid(POSITIONS, SPEEDS, indexing="ij")
    laws = {"damped": law, "undamped": law.elastic()}
    out = {}
    for tag, used in laws.items():
        if used is None:
            continue
        cor = np.empty(shape)
        for k, f in enumerate(factors):  # the frequencies scale as f^(1/2): one model each
            cor[..., k] = free_impacts(used, base.scaled(f), pos, speed, m_b)[0]
        out[tag] = cor
    return out


def cor_rigidity(quick: bool = False, law: ContactLaw | None = None) -> FigureData:
    """COR against EI1 at three speeds, three positions, with and without damping (under
    ``law``: with the law and with its elastic counterpart)."""
    base = FrameModel.build(standard_frame(PAPER_EI1), 20)
    base.modes()  # computed once, reused by the scaled models
    ei = np.geomspace(50.0, 3000.0, 8 if quick else 40)
    factors = np.append(ei, RIGID_EI1) / PAPER_EI1  # the last: the paper's rigid frame
    curves = _curves(base, factors, law)
    cols: dict[str, list] = {}
    values: dict[str, float] = {"ei_points": float(ei.size)}
    for ztag, every_cor in curves.items():
        if law is None:
            label = {"zeta [-]": zeta_from_cor(PAPER_CLAMPED_COR) if ztag == "damped" else 0.0}
        else:
            label = {"elastic counterpart [-]": 0.0 if ztag == "damped" else 1.0}
        for i, p in enumerate(POSITIONS):
            sat = {}
            end = []
            for j, v in enumerate(SPEEDS):
                every = every_cor[i, j]
                cor, c_rig = every[:-1], float(every[-1])
                for k, val in {
                    **{name: np.full(ei.size, x) for name, x in label.items()},
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
    if law is None:
        values["kcb_ratio_40_20"] = kcb_from_speed(40.0) / kcb_from_speed(20.0)
    else:  # the law's equivalent K_CB (clamped half period, section 2.1.1)
        tc = clamped_impacts(law, np.array([20.0, 40.0]), Ball().mass)[1]
        values["kcb_ratio_40_20"] = float((tc[0] / tc[1]) ** 2)
    values["ei_ratio_step"] = float(ei[1] / ei[0])
    title = "Fig. 13: coefficient of restitution against frame rigidity EI1 (EI2 = 0.88 EI1)"
    tables = {"cor": {k: np.concatenate(v) for k, v in cols.items()}}
    return law_figure("fig13_cor_rigidity", title, tables, values, law)


FIG_13 = FigureSpec("fig13_cor_rigidity", ("cor",), cor_rigidity, "cor_rigidity")
