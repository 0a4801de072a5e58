"""Figs 2-4 of Kawazoe & Kanda (1997): the model's inputs.

- Figs 2-3: the compound ball/string stiffness K_CB against impact speed (the paper's three
  points, section 2.1.1, and the power-law interpolation of
  :func:`fem_racket.contact.linear.kcb_from_speed`), the clamped-frame COR of eqs 1-4 (0.83 at every
  speed, so zeta = 0.0592 and C_CB grows as K_CB^(1/2)) and the contact times: clamped frame
  (eq 1) and the free standard frame at three impact points.
- Fig 4: the first three free-free bending modes of the stepped beam with their nodes.

Under another contact law (:mod:`.law_runs`) Figs 2-3 show the law's clamped COR and contact
times, and its equivalent K_CB = m_B (pi / T_c)^2 beside the paper's three points; Fig 4 does not
depend on the law.
"""

from __future__ import annotations

import numpy as np

from fem_racket.contact.law import ContactLaw
from fem_racket.contact.linear import PAPER_KCB_POINTS, Ball, LinearContact, kcb_from_speed
from fem_racket.frame.modal import mode_nodes
from fem_racket.frame.model import FrameModel
from fem_racket.frame.segments import standard_frame
from fem_racket.impact.analytic.rigid import clamped_impact
from fem_racket.impact.simulate import simulate
from fem_racket.paper.figures.data import FigureData, FigureSpec
from fem_racket.paper.figures.law_runs import (
    equivalent_kcb,
    free_impacts,
    law_title,
)
from fem_racket.studies.calibrate import clamped_impacts

__all__ = ["FIG_02_03", "FIG_04", "ball_string", "frame_modes"]

#: Impact points [x/L] of Figs 5-7, used for the free-frame contact times.
POSITIONS = (0.60, 0.75, 0.90)


def _speed_values(curve: dict[str, np.ndarray], speeds: np.ndarray) -> dict[str, float]:
    """Contact times at 20, 30 and 40 m/s (clamped and free frame), for the reports."""
    at = {v: int(np.argmin(np.abs(speeds - v))) for v in (20.0, 30.0, 40.0)}
    out = {}
    for v, i in at.items():
        out[f"tc_clamped_{v:.0f}_s"] = float(curve["clamped contact time [s]"][i])
        for p in POSITIONS:
            col = curve[f"free frame contact time at {p:.2f} L [s]"]
            out[f"tc_free_{round(p * 100)}_{v:.0f}_s"] = float(col[i])
    return out


def ball_string(quick: bool = False, law: ContactLaw | None = None) -> FigureData:
    """K_CB, C_CB, clamped COR and contact times against impact speed (Figs 2-3 inputs); under
    ``law``, its clamped COR, contact times and equivalent K_CB beside the paper's."""
    if law is not None:
        return _ball_string_law(quick, law)
    m_b = Ball().mass
    speeds = np.linspace(10.0, 50.0, 9 if quick else 41)
    kcb = np.array([kcb_from_speed(v) for v in speeds])
    contacts = [LinearContact.for_speed(v) for v in speeds]
    zeta = contacts[0].zeta
    clamped = [
        clamped_impact(m_b, c.stiffness, c.zeta, v) for c, v in zip(contacts, speeds, strict=True)
    ]
    model = FrameModel.build(standard_frame(), 20)
    curve = {
        "speed [m/s]": speeds,
        "K_CB [N/m]": kcb,
        "C_CB [N s/m]": np.array([c.damping(m_b) for c in contacts]),
        "clamped COR [-]": np.array([c.cor for c in clamped]),
        "clamped contact time [s]": np.array([c.contact_time for c in clamped]),
    }
    for p in POSITIONS:
        curve[f"free frame contact time at {p:.2f} L [s]"] = np.array(
            [simulate(model, position=p, speed=v, output_step=None).contact_time for v in speeds]
        )
    points = {
        "speed [m/s]": np.array([v for v, _ in PAPER_KCB_POINTS]),
        "K_CB [N/m]": np.array([k for _, k in PAPER_KCB_POINTS]),
    }
    tc_free = np.array([curve[f"free frame contact time at {p:.2f} L [s]"] for p in POSITIONS])
    at = {v: int(np.argmin(np.abs(speeds - v))) for v in (20.0, 30.0, 40.0)}
    values = {
        "zeta": zeta,
        "clamped_cor_min": float(curve["clamped COR [-]"].min()),
        "clamped_cor_max": float(curve["clamped COR [-]"].max()),
        "ccb_ratio_40_20": float(curve["C_CB [N s/m]"][at[40.0]] / curve["C_CB [N s/m]"][at[20.0]]),
        "kcb_ratio_40_20": float(kcb[at[40.0]] / kcb[at[20.0]]),
        "tc_free_20_min_s": float(tc_free[:, at[20.0]].min()),
        "tc_free_20_max_s": float(tc_free[:, at[20.0]].max()),
        "tc_free_40_min_s": float(tc_free[:, at[40.0]].min()),
        "tc_free_40_max_s": float(tc_free[:, at[40.0]].max()),
        "tc_free_decreasing_with_speed": float(np.all(np.diff(tc_free, axis=1) < 0.0)),
        "tc_clamped_40_s": float(curve["clamped contact time [s]"][at[40.0]]),
        **_speed_values(curve, speeds),
    }
    return FigureData(
        "fig02_03_ball_string",
        "Figs 2-3 inputs: ball/string stiffness, clamped-frame COR and contact time",
        {"curve": curve, "paper_points": points},
        values,
    )


def _ball_string_law(quick: bool, law: ContactLaw) -> FigureData:
    """Figs 2-3 under ``law``: its equivalent K_CB, clamped COR and contact times."""
    m_b = Ball().mass
    speeds = np.linspace(10.0, 50.0, 9 if quick else 41)
    cor, tc = clamped_impacts(law, speeds, m_b)
    paper = [LinearContact.for_speed(v) for v in speeds]
    model = FrameModel.build(standard_frame(), 20)
    curve = {
        "speed [m/s]": speeds,
        "equivalent K_CB [N/m]": equivalent_kcb(tc, m_b),
        "paper K_CB [N/m]": np.array([c.stiffness for c in paper]),
        "clamped COR [-]": cor,
        "clamped contact time [s]": tc,
        "paper clamped contact time [s]": np.array(
            [clamped_impact(m_b, c.stiffness, c.zeta, v).contact_time for c, v in
             zip(paper, speeds, strict=True)]
        ),
    }  # fmt: skip
    _, free = free_impacts(law, model, np.array(POSITIONS)[:, None], speeds[None, :], m_b)
    for p, row in zip(POSITIONS, free, strict=True):
        curve[f"free frame contact time at {p:.2f} L [s]"] = row
    points = {
        "speed [m/s]": np.array([v for v, _ in PAPER_KCB_POINTS]),
        "K_CB [N/m]": np.array([k for _, k in PAPER_KCB_POINTS]),
    }
    at = {v: int(np.argmin(np.abs(speeds - v))) for v in (20.0, 30.0, 40.0)}
    kcb = curve["equivalent K_CB [N/m]"]
    values = {
        "clamped_cor_min": float(cor.min()),
        "clamped_cor_max": float(cor.max()),
        "kcb_ratio_40_20": float(kcb[at[40.0]] / kcb[at[20.0]]),
        "tc_free_decreasing_with_speed": float(np.all(np.diff(free, axis=1) < 0.0)),
        **_speed_values(curve, speeds),
    }
    for v, i in at.items():
        values[f"kcb_equivalent_{v:.0f}_n_m"] = float(kcb[i])
        values[f"tc_paper_clamped_{v:.0f}_s"] = float(curve["paper clamped contact time [s]"][i])
    name = law_title(law)
    return FigureData(
        "fig02_03_ball_string",
        f"Figs 2-3 inputs under the {name} law: equivalent K_CB, clamped COR and contact time",
        {"curve": curve, "paper_points": points},
        values,
        law=name,
    )


def frame_modes(quick: bool = False, law: ContactLaw | None = None) -> FigureData:
    """Free-free modes 1-3 of the stepped beam, normalised to unit peak deflection (Fig 4); the
    same under every contact law (the frame alone)."""
    model = FrameModel.build(standard_frame(), 20)
    fm = model.modes(3)
    L = model.mesh.length
    x = np.linspace(0.0, L, 69 if quick else 681)
    R = model.fe.field_matrix(x, 0)
    shapes = {"x [m]": x, "x/L [-]": x / L}
    nodes = {"mode [-]": [], "frequency [Hz]": [], "node x/L [-]": []}
    for k in range(3):
        w = R @ fm.shapes[:, k]
        shapes[f"mode {k + 1} deflection [-]"] = w / np.max(np.abs(w))
        for xn in mode_nodes(model.fe, fm.shapes[:, k]):
            nodes["mode [-]"].append(k + 1)
            nodes["frequency [Hz]"].append(fm.frequencies[k])
            nodes["node x/L [-]"].append(xn)
    nodes = {k: np.asarray(v) for k, v in nodes.items()}
    props = model.props
    values = {
        "mass_kg": props.mass,
        "cg_m": props.cg,
        "cg_x_over_l": props.cg_over_length,
        "inertia_kg_m2": props.inertia,
        "length_m": L,
        "elements": float(model.mesh.n_elements),
        "system_dofs": float(model.fe.ndof + 1),
    }
    for k in range(3):
        values[f"f{k + 1}_hz"] = float(fm.frequencies[k])
        sel = nodes["mode [-]"] == k + 1
        for j, xn in enumerate(nodes["node x/L [-]"][sel]):
            values[f"mode{k + 1}_node{j + 1}_x_over_l"] = float(xn)
    return FigureData(
        "fig04_frame_modes",
        "Fig. 4: free-free bending modes of the stepped beam (EI1 = 146 N m², 20 elements)",
        {"shapes": shapes, "nodes": nodes},
        values,
    )


FIG_02_03 = FigureSpec(
    "fig02_03_ball_string", ("curve", "paper_points"), ball_string, "ball_string"
)
FIG_04 = FigureSpec("fig04_frame_modes", ("shapes", "nodes"), frame_modes, "frame_modes")
