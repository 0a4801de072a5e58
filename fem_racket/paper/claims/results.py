"""Claims of sections 3.3-6 of Kawazoe & Kanda (1997): contact time and modal analysis here,
rigidity and conclusions (1)-(4) in :mod:`fem_racket.paper.claims.rigidity`."""

from __future__ import annotations

from fem_racket.paper.claims.base import Claim, below, claim
from fem_racket.paper.claims.rigidity import rigidity_claims

__all__ = ["result_claims"]


def result_claims(v: dict[str, dict[str, float]]) -> list[Claim]:
    """Statements of sections 3.3-6 (Figs 9-13 and the conclusions)."""
    p8, p9, s11, s12 = v["fig08"], v["fig09"], v["fig11"], v["fig12"]
    out: list[Claim] = []
    add = out.append
    ms = 1e3

    # -- 3.3 Fig 9 -------------------------------------------------------------------------
    add(
        claim(
            "3.3",
            "Contact time decreases as the impact point moves away from the centre of "
            "gravity (outwards).",
            f"{p9['tc_max_s'] * ms:.2f} ms at 0.55 L down to {p9['tc_min_s'] * ms:.2f} ms at "
            f"0.95 L; strictly decreasing for the rigid frame; the standard frame's curves "
            f"rise by at most {p9['tc_max_rel_rise'] * 100:.2f} % anywhere (flat top near 0.6 L "
            "without damping)",
            p9["tc_rigid_decreasing"] == 1.0
            and p9["tc_end_below_start"] == 1.0
            and p9["tc_max_rel_rise"] < 0.01,
            "Every curve of Fig. 9 falls from 0.55 L to 0.95 L; local rises are below 1 %.",
            "fig09",
        )
    )
    add(
        claim(
            "3.3",
            "Frame rigidity and ball/string damping make almost no difference to the contact time.",
            f"standard vs rigid: at most {p9['tc_rigidity_max_rel_diff'] * 100:.1f} %; with vs "
            f"without damping: at most {p9['tc_damping_max_rel_diff'] * 100:.1f} % "
            "(0.55-0.95 L)",
            max(p9["tc_rigidity_max_rel_diff"], p9["tc_damping_max_rel_diff"]) < 0.05,
            "'Almost no difference' read as within 5 %.",
            "fig09",
        )
    )

    # -- 4.1 rigid frame ---------------------------------------------------------------
    add(
        claim(
            "4.1 / Fig. 9",
            "The contact time is controlled primarily by eq 11 (rigid frame, "
            "no damping; the solid line of Fig. 9).",
            f"all four FE curves within {p9['tc_fe_vs_eq11_max_rel_diff'] * 100:.1f} % of eq 11; "
            f"the rigid frame without damping within "
            f"{p9['tc_rigid_undamped_vs_eq11_max_rel_diff'] * 100:.2f} %",
            p9["tc_fe_vs_eq11_max_rel_diff"] < 0.05,
            "Within 5 % everywhere.",
            "fig09",
        )
    )
    add(
        claim(
            "4.1",
            "Eqs 5-12: rigid frame without damping, rebound V_B = V_T + V_R - V_I.",
            f"EI1 = 9999 N m² FE model with zeta = 0 within {p8['eq12_vs_rigid_fe_max_diff']:.1e} "
            "of eq 12 in COR over 0.55-0.95 L",
            p8["eq12_vs_rigid_fe_max_diff"] < 1e-3,
            "The remaining gap is the 9999 frame's residual flexibility.",
            "fig08",
        )
    )

    # -- 4.2 modal analysis ------------------------------------------------------------
    vtvr = max(s11["rigid_frame_vt_vr_diff_060"], s11["rigid_frame_vt_vr_diff_node"])
    res14 = max(abs(s11[f"eq14_residual_{t}"]) for t in ("060", "node"))
    res15 = max(abs(s11[f"eq15_residual_{t}"]) for t in ("060", "node"))
    add(
        claim(
            "4.2",
            "Eq 14: V_B0 = V_T + V_R + V_1 + V_2 + ...; eq 15: V_I = V_1 + V_2 + ...",
            f"|eq 14 residual| {below(res14, 1e-12)} m/s; |sum of V_i - eq 10's V_I| "
            f"{below(res15, 1e-8)} m/s (0.60 L and node, V_B0 = 20 m/s)",
            max(res14, res15) < 1e-6,
            "Undamped ball + frame eigenmodes (fem_racket.impact.analytic.coupled); V_T, V_R "
            "equal eqs 8-9. "
            f"Eq 13 matches the simulated zeta = 0 ball velocity to "
            f"{below(s11['eq13_vs_simulation_max_diff_m_s'], 1e-8)} m/s.",
            "fig11",
        )
    )
    add(
        claim(
            "4.2",
            "Eq 16: an elastic frame cannot return the ball faster than the rigid one, "
            "|V_B| <= |V_T + V_R - V_I| (no damping).",
            f"max over 0.55-0.95 L of COR_standard(zeta = 0) - COR_eq12: "
            f"{p8['eq16_max_excess']:+.4f}",
            p8["eq16_max_excess"] <= 1e-9,
            "Holds at every position. With damping it need not: near the node the standard "
            f"frame beats the rigid one by up to {-p8['vibration_loss_min']:.4f} (Fig. 8), and "
            "Fig. 13's damped curves overshoot their rigid limit slightly.",
            "fig08",
        )
    )
    add(
        claim(
            "4.2 / Figs 11-12",
            "Third and higher system modes (second and higher frame modes) have little influence.",
            f"V_3 + V_4 + ... = {s11['higher_share_060'] * 100:.2f} % of V_I at 0.60 L, "
            f"{s11['higher_share_node'] * 100:.2f} % at the node",
            max(s11["higher_share_060"], s11["higher_share_node"]) < 0.05,
            "Share of the vibration velocity carried by system modes 3 and up.",
            "fig11",
        )
    )
    add(
        claim(
            "4.2 / Fig. 12",
            "At a node the frame's own frequency appears as a system frequency "
            "and that mode's V_i is 0 (V_1 = 0 at 0.769 L).",
            f"at our node {s11['x_node']:.4f} L: system mode at "
            f"{s12['nearest_system_f_to_frame_f1_node_hz']:.3f} Hz (frame: "
            f"{s12['frame_f1_hz']:.3f} Hz), V_1 {below(s12['v_at_frame_f1_node_m_s'], 1e-12)} "
            "m/s; at "
            f"0.769 L: {s12['nearest_system_f_to_frame_f1_0769_hz']:.3f} Hz and V_1 = "
            f"{s12['v_at_frame_f1_0769_m_s']:.3f} m/s",
            abs(s12["nearest_system_f_to_frame_f1_node_hz"] - s12["frame_f1_hz"]) < 1e-6
            and s12["v_at_frame_f1_node_m_s"] < 1e-9,
            "Exact at the node; at the paper's rounded 0.769 L, V_1 is 0.1 % of V_I.",
            "fig12",
        )
    )
    add(
        claim(
            "4.2",
            "At the node, ignoring V_3 and higher, 'V_1 ~ V_2'.",
            f"V_1 {below(s11['v_1_node'], 1e-12)}, V_2 = {s11['v_2_node']:.3f}, V_I = "
            f"{s11['v_i_node']:.3f} m/s",
            abs(s11["v_2_node"] / s11["v_i_node"] - 1.0) < 0.01,
            "Read as V_I ~ V_2 (eq 15 with V_1 = 0), apparently a misprint: V_2/V_I = "
            f"{s11['v_2_node'] / s11['v_i_node']:.4f}. Taken literally (V_1 ~ V_2) it would "
            "contradict V_1 = 0.",
            "fig11",
        )
    )
    add(
        claim(
            "4.2",
            "Rigid-body motion only removes momentum; it does not depend on frame "
            "rigidity, and translation does not depend on the impact position.",
            f"V_T = {s11['v_t_060']:.4f} m/s at 0.60 L and {s11['v_t_node']:.4f} m/s at the "
            f"node; change of V_T + V_R from EI1 = 146 to 9999 N m² {below(vtvr, 1e-6)} m/s",
            abs(s11["v_t_060"] - s11["v_t_node"]) < 1e-12
            and max(s11["rigid_frame_vt_vr_diff_060"], s11["rigid_frame_vt_vr_diff_node"]) < 1e-6,
            "The zero-frequency system modes do not involve the frame's stiffness.",
            "fig11",
        )
    )
    add(
        claim(
            "4.2 / eq 9",
            "Rotation lowers the rebound more as alpha (distance from the CG) grows.",
            f"V_R = {s11['v_r_060']:.3f} m/s at 0.60 L, {s11['v_r_node']:.3f} m/s at "
            f"{s11['x_node']:.3f} L",
            s11["v_r_node"] > s11["v_r_060"],
            "V_R grows with d; it is subtracted from the rebound (eq 12).",
            "fig11",
        )
    )

    return out + rigidity_claims(v)
