"""Figs 11-12 of Kawazoe & Kanda (1997): the modal split of the ball velocity (eqs 13-16).

Without damping the ball velocity is V_T + V_R + sum_i V_i cos Omega_i t over the natural modes of
the coupled ball + frame system (:mod:`~fem_racket.impact.analytic.coupled`). Fig 11 draws the
terms against time at 0.60 L and at the node of frame mode 1; Fig 12 the system's frequencies and
mode shapes
there. The paper's node is 0.769 L; ours (20 elements) is 0.7697 L, used for the figures so that
V_1 vanishes exactly; the values at 0.769 L itself are reported too.
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np

from fem_racket.contact.law import ContactLaw
from fem_racket.frame.modal import mode_nodes
from fem_racket.frame.model import FrameModel
from fem_racket.frame.segments import PAPER_EI1, RIGID_EI1, standard_frame
from fem_racket.impact.analytic.coupled import CoupledModes, coupled_modes
from fem_racket.impact.analytic.rigid import rigid_impact_at
from fem_racket.impact.simulate import simulate
from fem_racket.paper.figures.data import FigureData, FigureSpec
from fem_racket.validation import InputError

__all__ = ["FIG_11", "FIG_12", "LINEAR_ONLY", "modal_terms", "system_modes"]

SPEED = 20.0
#: System modes drawn individually; the rest are summed.
SHOWN = 4


@lru_cache(maxsize=1)
def _cases() -> tuple[FrameModel, dict[float, CoupledModes]]:
    model = FrameModel.build(standard_frame(), 20)
    node = float(mode_nodes(model.fe, model.modes(1).shapes[:, 0])[-1])
    return model, {p: coupled_modes(model, p, speed=SPEED) for p in (0.60, node, 0.769)}


#: Why Figs 11-12 are not drawn under another contact law than the paper's linear one.
LINEAR_ONLY = (
    "eqs 13-16 split the ball velocity into the natural modes of the linear ball + frame "
    "system; a nonlinear or hysteretic ball/string law has no such modes (its stiffness changes "
    "during the contact), so there is nothing to draw"
)


def _linear_only(law: ContactLaw | None) -> None:
    if law is not None:
        raise InputError(f"law = {law.name!r} is not allowed for Figs 11-12: {LINEAR_ONLY}")


def modal_terms(quick: bool = False, law: ContactLaw | None = None) -> FigureData:
    """The terms of eq 13 against time at 0.60 L and at the mode-1 node (Fig 11); the paper's
    linear law only (:data:`LINEAR_ONLY`)."""
    _linear_only(law)
    model, cases = _cases()
    cols: dict[str, list] = {}
    values: dict[str, float] = {}
    props = model.props
    rigid = model.scaled(RIGID_EI1 / PAPER_EI1)
    for p, cm in list(cases.items())[:2]:
        r = simulate(model, position=p, speed=SPEED, zeta=0.0, output_step=5e-5 if quick else 1e-5)
        terms = cm.terms(r.t)
        table = {
            "position [x/L]": np.full(r.t.size, p),
            "time [s]": r.t,
            "V_T [m/s]": terms[:, 0],
            "V_R [m/s]": terms[:, 1],
        }
        for i in range(SHOWN):
            table[f"V_{i + 1} cos(Omega_{i + 1} t) [m/s]"] = terms[:, 2 + i]
        table[f"V_{SHOWN + 1}+ terms [m/s]"] = terms[:, 2 + SHOWN :].sum(axis=1)
        table["eq 13 sum [m/s]"] = terms.sum(axis=1)
        table["simulated ball velocity, zeta = 0 [m/s]"] = r.ball_velocity
        for k, v in table.items():
            cols.setdefault(k, []).append(v)
    for p, cm in cases.items():
        tag = {0.60: "060"}.get(p, "0769" if p == 0.769 else "node")
        closed = rigid_impact_at(props, p, SPEED)
        vj = cm.velocity_terms
        values.update(
            {
                f"x_{tag}": p,
                f"v_t_{tag}": cm.v_translation,
                f"v_r_{tag}": cm.v_rotation,
                f"v_i_{tag}": cm.v_vibration,
                f"v_1_{tag}": float(vj[0]),
                f"v_2_{tag}": float(vj[1]),
                f"v_3_{tag}": float(vj[2]),
                f"higher_share_{tag}": float(vj[2:].sum() / vj.sum()),
                f"eq14_residual_{tag}": cm.v_translation + cm.v_rotation + vj.sum() - SPEED,
                f"eq15_residual_{tag}": vj.sum() - closed.v_vibration,
                f"eq8_9_residual_{tag}": max(
                    abs(cm.v_translation - closed.v_translation),
                    abs(cm.v_rotation - closed.v_rotation),
                ),
            }
        )
        cr = coupled_modes(rigid, p, speed=SPEED)
        values[f"rigid_frame_vt_vr_diff_{tag}"] = abs(
            cr.v_translation + cr.v_rotation - cm.v_translation - cm.v_rotation
        )
    t_all = np.concatenate(cols["time [s]"])
    err = np.abs(
        np.concatenate(cols["eq 13 sum [m/s]"])
        - np.concatenate(cols["simulated ball velocity, zeta = 0 [m/s]"])
    )
    values["eq13_vs_simulation_max_diff_m_s"] = float(err.max())
    values["time_points"] = float(t_all.size)
    return FigureData(
        "fig11_modal_terms",
        "Fig. 11: terms of eq 13 (ball velocity split into system modes), 20 m/s, no damping",
        {"terms": {k: np.concatenate(v) for k, v in cols.items()}},
        values,
    )


def system_modes(quick: bool = False, law: ContactLaw | None = None) -> FigureData:
    """Frequencies and shapes of the first system modes at 0.60 L and the node (Fig 12); the
    paper's linear law only (:data:`LINEAR_ONLY`)."""
    _linear_only(law)
    model, cases = _cases()
    L = model.mesh.length
    x = np.linspace(0.0, L, 35 if quick else 137)
    R = model.fe.field_matrix(x, 0)
    modes: dict[str, list] = {}
    shapes: dict[str, list] = {}
    values: dict[str, float] = {
        "frame_f1_hz": float(model.modes(1).frequencies[0]),
        "length_m": L,
    }
    for p, cm in list(cases.items())[:2]:
        for j in range(SHOWN):
            w = R @ cm.frame_dofs(j)
            ball = cm.ball_amplitude(j)
            scale = max(np.max(np.abs(w)), abs(ball))
            row = {
                "position [x/L]": p,
                "system mode [-]": j + 1,
                "frequency [Hz]": cm.frequencies[j],
                "V_i [m/s]": cm.velocity_terms[j],
                "ball amplitude [-]": ball / scale,
            }
            for k, v in row.items():
                modes.setdefault(k, []).append(v)
            for k, v in {
                "position [x/L]": np.full(x.size, p),
                "system mode [-]": np.full(x.size, j + 1),
                "x [m]": x,
                "frame deflection [-]": w / scale,
            }.items():
                shapes.setdefault(k, []).append(v)
    for p, cm in cases.items():
        tag = {0.60: "060"}.get(p, "0769" if p == 0.769 else "node")
        k = int(np.argmin(np.abs(cm.frequencies - values["frame_f1_hz"])))
        values[f"nearest_system_f_to_frame_f1_{tag}_hz"] = float(cm.frequencies[k])
        values[f"v_at_frame_f1_{tag}_m_s"] = float(cm.velocity_terms[k])
        for j in range(3):
            values[f"system_f{j + 1}_{tag}_hz"] = float(cm.frequencies[j])
    return FigureData(
        "fig12_system_modes",
        "Fig. 12: natural frequencies and mode shapes of the ball + frame system",
        {
            "modes": {k: np.asarray(v) for k, v in modes.items()},
            "shapes": {k: np.concatenate(v) for k, v in shapes.items()},
        },
        values,
    )


FIG_11 = FigureSpec(
    "fig11_modal_terms", ("terms",), modal_terms, "modal_terms", law_skip=LINEAR_ONLY
)
FIG_12 = FigureSpec(
    "fig12_system_modes", ("modes", "shapes"), system_modes, "system_modes", law_skip=LINEAR_ONLY
)
