"""Figs 5-7 of Kawazoe & Kanda (1997): impact behaviour at 0.60, 0.75 and 0.90 L, 20 m/s.

For the standard (EI1 = 146 N m^2) and the 'rigid' (EI1 = 9999 N m^2) frames: displacement and
velocity of the ball, the impact point and both frame ends against time; the deformed frame at
six instants of its own contact (0, 20, ..., 100 % of its contact time, the last its end of
contact); and panel (c), standard minus rigid deformation at common times (0, 20, ..., 100 % of
the shorter of the two contact times), where both frames are still in contact.

The scalar values quantify the paper's remarks of section 3.1: the elastic part of the
deformation (the deflection minus its rigid-body part, removed by M-orthogonal projection), the
share of frame mode 1 in the elastic deformation left at separation, and the frame's angular
velocity about its centre of gravity at separation.
"""

from __future__ import annotations

from functools import partial

import numpy as np

from fem_racket.contact.law import ContactLaw
from fem_racket.frame.model import FrameModel
from fem_racket.frame.segments import PAPER_EI1, RIGID_EI1, standard_frame
from fem_racket.impact.simulate import ImpactResult, simulate
from fem_racket.paper.figures.data import FigureData, FigureSpec
from fem_racket.paper.figures.law_runs import law_figure

__all__ = ["FIG_05", "FIG_06", "FIG_07", "impact_behaviour"]

#: Fractions of the contact time at which deformed shapes are drawn.
INSTANTS = (0.0, 0.2, 0.4, 0.6, 0.8, 1.0)


def _instants(t: np.ndarray, tc: float, last: int) -> list[int]:
    """Indices of the output times ``t`` nearest to the :data:`INSTANTS` fractions of ``tc``,
    the fraction 1 at index ``last``."""
    idx = [int(np.argmin(np.abs(t[:last] - f * tc))) for f in INSTANTS[:-1]]
    return sorted({*idx, last})


def _elastic(model: FrameModel, q: np.ndarray) -> np.ndarray:
    """Frame DOFs (rows) minus their rigid-body part (M-orthogonal projection)."""
    rigid = model.modes().rigid
    return q - (q @ (model.fe.M @ rigid)) @ rigid.T


def _summary(model: FrameModel, r: ImpactResult, x: np.ndarray) -> dict[str, float]:
    fm = model.modes()
    q_el = _elastic(model, r.frame_displacement)
    w_el = np.asarray((model.fe.field_matrix(x, 0) @ q_el.T).T)
    eta = q_el[-1] @ (model.fe.M @ fm.shapes)
    rot = r.frame_velocity[-1] @ (model.fe.M @ fm.rigid[:, 1]) / np.sqrt(fm.props.inertia)
    return {
        "cor": r.cor,
        "contact_time_s": r.contact_time,
        "max_elastic_deflection_m": float(np.max(np.abs(w_el))),
        "final_elastic_deflection_m": float(np.max(np.abs(w_el[-1]))),
        "final_mode1_share": float(eta[0] ** 2 / np.sum(eta**2)),
        "final_angular_velocity_rad_s": float(rot),
    }


def impact_behaviour(
    position: float, quick: bool = False, law: ContactLaw | None = None
) -> FigureData:
    """Histories and deformed shapes of the standard and rigid frames struck at ``position``,
    with the paper's linear K_CB or, if given, ``law`` (general integrator)."""
    fig = {0.60: 5, 0.75: 6, 0.90: 7}.get(round(position, 2), 0)
    step = 5e-5 if quick else 1e-5
    base = FrameModel.build(standard_frame(PAPER_EI1), 20)
    base.modes()  # computed once, reused by the scaled model
    models = {PAPER_EI1: base, RIGID_EI1: base.scaled(RIGID_EI1 / PAPER_EI1)}
    L = base.mesh.length
    x = np.linspace(0.0, L, 35 if quick else 69)
    results = {
        ei: simulate(m, position=position, speed=20.0, output_step=step, law=law)
        for ei, m in models.items()
    }
    # Each frame at its own instants (the last its own end of contact); the difference (c) at
    # common times within the shorter contact (both runs share the output grid k * step).
    tc = min(r.contact_time for r in results.values())
    shorter = min(results.values(), key=lambda r: r.contact_time)
    common = _instants(shorter.t, tc, shorter.t.size - 2)
    hist: dict[str, list] = {}
    shapes: dict[str, list] = {}
    inst: dict[str, list] = {}
    fields = {}
    values: dict[str, float] = {"position_x_over_l": position, "speed_m_s": 20.0, "length_m": L}
    for ei, r in results.items():
        ends = r.frame_field(np.array([0.0, L]))
        vends = r.frame_field(np.array([0.0, L]), velocity=True)
        cols = {
            "EI1 [N m^2]": np.full(r.t.size, ei),
            "time [s]": r.t,
            "ball displacement [m]": r.ball_displacement,
            "impact point displacement [m]": r.impact_point_displacement,
            "grip end displacement [m]": ends[:, 0],
            "top end displacement [m]": ends[:, 1],
            "ball velocity [m/s]": r.ball_velocity,
            "impact point velocity [m/s]": r.impact_point_velocity,
            "grip end velocity [m/s]": vends[:, 0],
            "top end velocity [m/s]": vends[:, 1],
        }
        for k, v in cols.items():
            hist.setdefault(k, []).append(v)
        deflection = r.frame_field(x)
        idx = _instants(r.t, r.contact_time, r.t.size - 1)
        w = deflection[idx]
        fields[ei] = deflection[common]
        for j, i in enumerate(idx):
            for k, v in {
                "EI1 [N m^2]": np.full(x.size, ei),
                "time [s]": np.full(x.size, r.t[i]),
                "x [m]": x,
                "deflection [m]": w[j],
            }.items():
                shapes.setdefault(k, []).append(v)
            for k, v in {
                "EI1 [N m^2]": ei,
                "time [s]": r.t[i],
                "ball displacement [m]": r.ball_displacement[i],
                "impact point displacement [m]": r.impact_point_displacement[i],
            }.items():
                inst.setdefault(k, []).append(v)
        tag = "standard" if ei == PAPER_EI1 else "rigid"
        values.update({f"{tag}_{k}": v for k, v in _summary(models[ei], r, x).items()})
    t_idx = shorter.t[common]
    diff = fields[PAPER_EI1] - fields[RIGID_EI1]
    difference = {
        "time [s]": np.repeat(t_idx, x.size),
        "x [m]": np.tile(x, t_idx.size),
        "standard minus rigid deflection [m]": diff.ravel(),
    }
    values["max_difference_m"] = float(np.max(np.abs(diff)))
    return law_figure(
        f"fig{fig:02d}_impact_{round(position * 100):d}L",
        f"Fig. {fig}: impact behaviour at {position:.2f} L, 20 m/s",
        {
            "histories": {k: np.concatenate(v) for k, v in hist.items()},
            "shapes": {k: np.concatenate(v) for k, v in shapes.items()},
            "instants": {k: np.asarray(v) for k, v in inst.items()},
            "difference": difference,
        },
        values,
        law,
    )


_TABLES = ("histories", "shapes", "instants", "difference")
FIG_05 = FigureSpec(
    "fig05_impact_60L", _TABLES, partial(impact_behaviour, 0.60), "impact_behaviour"
)
FIG_06 = FigureSpec(
    "fig06_impact_75L", _TABLES, partial(impact_behaviour, 0.75), "impact_behaviour"
)
FIG_07 = FigureSpec(
    "fig07_impact_90L", _TABLES, partial(impact_behaviour, 0.90), "impact_behaviour"
)
