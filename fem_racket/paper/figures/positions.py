"""Figs 8-9 of Kawazoe & Kanda (1997): COR and contact time against impact position, 20 m/s.

One sweep over 0.55-0.95 L feeds both figures: the standard (EI1 = 146 N m^2) and rigid
(EI1 = 9999 N m^2) frames, with the ball/string damping (zeta = 0.0592) and without (zeta = 0),
the rigid-frame closed forms (eq 12 for the COR and eq 11 for the contact time, both without
damping), and the standard frame reduced to its rigid modes plus flexible mode 1 (conclusion 1).
Under another contact law the same cases run with that law and its elastic counterpart
(:mod:`.law_runs`).
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np

from fem_racket.contact.law import ContactLaw
from fem_racket.contact.linear import Ball
from fem_racket.frame.modal import mode_nodes
from fem_racket.frame.model import FrameModel
from fem_racket.frame.segments import PAPER_EI1, RIGID_EI1, standard_frame
from fem_racket.impact.analytic.rigid import rigid_impact_at
from fem_racket.impact.simulate import simulate
from fem_racket.paper.figures.data import FigureData, FigureSpec
from fem_racket.paper.figures.law_runs import (
    free_impacts,
    law_figure,
    rigid_contact_time,
)

__all__ = ["FIG_08", "FIG_09", "contact_time_position", "cor_position", "position_sweep"]

SPEED = 20.0
#: Values of the undamped cases (NaN under a law without an elastic counterpart): Fig 8, Fig 9.
UNDAMPED_COR = (
    "vibration_loss_undamped_argmin_x_over_l",
    "eq16_max_excess",
    "eq12_vs_rigid_fe_max_diff",
)
UNDAMPED_CONTACT_TIME = (
    "tc_damping_max_rel_diff",
    "tc_fe_vs_eq11_max_rel_diff",
    "tc_rigid_undamped_vs_eq11_max_rel_diff",
)


@lru_cache(maxsize=2)
def position_sweep(
    quick: bool = False, law: ContactLaw | None = None
) -> tuple[dict[str, np.ndarray], dict[str, float]]:
    """COR and contact time against position for every case; and the frame's reference points.

    Under ``law`` the "undamped" cases use its elastic counterpart (left out when it has none)
    and the eq 11 column the counterpart's rigid-frame contact time (:mod:`.law_runs`).
    """
    base = FrameModel.build(standard_frame(), 20)
    base.modes()  # computed once, reused by the scaled model
    rigid = base.scaled(RIGID_EI1 / PAPER_EI1)
    x = np.linspace(0.55, 0.95, 9 if quick else 41)
    out: dict[str, np.ndarray] = {"position [x/L]": x}
    props = base.props
    closed = [rigid_impact_at(props, p, SPEED) for p in x]
    xw = np.linspace(0.30, 0.95, 27 if quick else 66)
    if law is None:
        cases = {
            "standard": (base, None, None),
            "rigid": (rigid, None, None),
            "standard undamped": (base, 0.0, None),
            "rigid undamped": (rigid, 0.0, None),
            "standard rigid modes + mode 1": (base, None, 1),
        }
        for name, (model, zeta, modes) in cases.items():
            kw = {"zeta": zeta, "output_step": None}
            if modes is not None:
                kw["modes"] = modes
            rs = [simulate(model, position=p, speed=SPEED, **kw) for p in x]
            out[f"COR {name} [-]"] = np.array([r.cor for r in rs])
            out[f"contact time {name} [s]"] = np.array([r.contact_time for r in rs])
        out["COR eq 12 rigid undamped [-]"] = np.array([c.cor for c in closed])
        out["contact time eq 11 rigid undamped [s]"] = np.array([c.contact_time for c in closed])
        cor_wide = [simulate(rigid, position=p, speed=SPEED, output_step=None).cor for p in xw]
    else:
        m_b = Ball().mass
        elastic = law.elastic()
        runs = {
            "standard": (law, base, None),
            "rigid": (law, rigid, None),
            "standard undamped": (elastic, base, None),
            "rigid undamped": (elastic, rigid, None),
            "standard rigid modes + mode 1": (law, base, 1),
        }
        for name, (used, model, flexible) in runs.items():
            if used is None:
                continue
            cor, tc = free_impacts(used, model, x, SPEED, m_b, flexible=flexible)
            out[f"COR {name} [-]"], out[f"contact time {name} [s]"] = cor, tc
        if elastic is not None:
            out["COR eq 12 rigid undamped [-]"] = np.array([c.cor for c in closed])
            out["contact time eq 11 rigid undamped [s]"] = rigid_contact_time(
                elastic, base, x, SPEED, m_b
            )
        cor_wide = free_impacts(law, rigid, xw, SPEED, m_b)[0]
    refs = {
        "node_x_over_l": float(mode_nodes(base.fe, base.modes(1).shapes[:, 0])[-1]),
        "cg_x_over_l": props.cg_over_length,
        "rigid_cor_argmax_x_over_l": float(xw[int(np.argmax(cor_wide))]),
        "wide_step_x_over_l": float(xw[1] - xw[0]),
        "step_x_over_l": float(x[1] - x[0]),
    }
    return out, refs


def cor_position(quick: bool = False, law: ContactLaw | None = None) -> FigureData:
    """COR against impact position (Fig 8)."""
    data, refs = position_sweep(quick, law)
    x = data["position [x/L]"]
    cols = {k: v for k, v in data.items() if not k.startswith("contact time")}
    std, rig = data["COR standard [-]"], data["COR rigid [-]"]
    loss = rig - std
    fit = np.polyfit(x, rig, 1)
    values = dict(refs)
    values.update(
        {
            "rigid_cor_max": float(rig.max()),
            "rigid_cor_min": float(rig.min()),
            "rigid_decreasing": float(np.all(np.diff(rig) < 0.0)),
            "rigid_linear_slope_per_l": float(fit[0]),
            "rigid_linear_max_residual": float(np.max(np.abs(rig - np.polyval(fit, x)))),
            "standard_cor_max": float(std.max()),
            "standard_cor_min": float(std.min()),
            "standard_cor_argmax_x_over_l": float(x[np.argmax(std)]),
            "vibration_loss_argmin_x_over_l": float(x[np.argmin(loss)]),
            "vibration_loss_min": float(loss.min()),
            "vibration_loss_max": float(loss.max()),
            "mode1_only_max_cor_diff": float(
                np.max(np.abs(data["COR standard rigid modes + mode 1 [-]"] - std))
            ),
        }
    )
    values.update(dict.fromkeys(UNDAMPED_COR, float("nan")))  # a law with no elastic counterpart
    if "COR standard undamped [-]" in data:
        std0, rig0 = data["COR standard undamped [-]"], data["COR rigid undamped [-]"]
        eq12 = data["COR eq 12 rigid undamped [-]"]
        values["vibration_loss_undamped_argmin_x_over_l"] = float(x[np.argmin(rig0 - std0)])
        values["eq16_max_excess"] = float(np.max(std0 - eq12))
        values["eq12_vs_rigid_fe_max_diff"] = float(np.max(np.abs(eq12 - rig0)))
    title = "Fig. 8: coefficient of restitution against impact position, 20 m/s"
    return law_figure("fig08_cor_position", title, {"cor": cols}, values, law)


def contact_time_position(quick: bool = False, law: ContactLaw | None = None) -> FigureData:
    """Contact time against impact position (Fig 9)."""
    data, refs = position_sweep(quick, law)
    cols = {"position [x/L]": data["position [x/L]"]}
    cols.update({k: v for k, v in data.items() if k.startswith("contact time")})
    fe = {k: v for k, v in cols.items() if k.startswith("contact time") and "eq 11" not in k}
    std, rig = cols["contact time standard [s]"], cols["contact time rigid [s]"]
    allfe = np.array(list(fe.values()))
    rigids = [v for k, v in fe.items() if k.startswith("contact time rigid")]
    values = dict(refs)
    values.update(
        {
            "tc_min_s": float(allfe.min()),
            "tc_max_s": float(allfe.max()),
            "tc_standard_min_s": float(std.min()),
            "tc_standard_max_s": float(std.max()),
            "tc_rigid_decreasing": float(all(np.all(np.diff(v) < 0.0) for v in rigids)),
            "tc_max_rel_rise": float(
                max(np.max(np.maximum.accumulate(v[::-1])[::-1] / v - 1.0) for v in fe.values())
            ),
            "tc_end_below_start": float(all(v[-1] < v[0] for v in fe.values())),
            "tc_rigidity_max_rel_diff": float(np.max(np.abs(std / rig - 1.0))),
            "tc_rigidity_argmax_x_over_l": float(
                cols["position [x/L]"][np.argmax(np.abs(std / rig - 1.0))]
            ),
            "tc_standard_position_spread": float(std.max() / std.min() - 1.0),
        }
    )
    values.update(dict.fromkeys(UNDAMPED_CONTACT_TIME, float("nan")))  # as in cor_position
    if "contact time standard undamped [s]" in cols:
        eq11 = cols["contact time eq 11 rigid undamped [s]"]
        undamped = cols["contact time standard undamped [s]"]
        values["tc_damping_max_rel_diff"] = float(np.max(np.abs(std / undamped - 1.0)))
        values["tc_fe_vs_eq11_max_rel_diff"] = float(np.max(np.abs(allfe / eq11 - 1.0)))
        values["tc_rigid_undamped_vs_eq11_max_rel_diff"] = float(
            np.max(np.abs(cols["contact time rigid undamped [s]"] / eq11 - 1.0))
        )
    title = "Fig. 9: contact time against impact position, 20 m/s"
    return law_figure("fig09_contact_time_position", title, {"contact_time": cols}, values, law)


FIG_08 = FigureSpec("fig08_cor_position", ("cor",), cor_position, "cor_position")
FIG_09 = FigureSpec(
    "fig09_contact_time_position", ("contact_time",), contact_time_position, "contact_time_position"
)
