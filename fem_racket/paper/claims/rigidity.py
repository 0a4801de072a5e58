"""Claims of sections 5 and 6 of Kawazoe & Kanda (1997): the frame's rigidity (Fig 13) and the
conclusions (1)-(4)."""

from __future__ import annotations

from fem_racket.paper.claims.base import Claim, claim

__all__ = ["POSITIONS", "SPEEDS", "rigidity_claims"]

#: Impact points (x/L in %) and speeds [m/s] of the paper's figures.
POSITIONS = ("60", "75", "90")
SPEEDS = ("20", "30", "40")


def rigidity_claims(v: dict[str, dict[str, float]]) -> list[Claim]:
    """Statements of sections 5 (Fig 13) and 6 (the conclusions)."""
    p8, p9, s11, r = v["fig08"], v["fig09"], v["fig11"], v["fig13"]
    out: list[Claim] = []
    add = out.append
    ms = 1e3

    # -- 5 Fig 13 ------------------------------------------------------------------------
    sat = {
        (z, p, s): r[f"ei_sat_{z}_{p}_{s}"]
        for z in ("damped", "undamped")
        for p in POSITIONS
        for s in SPEEDS
    }
    rises = all(
        r[f"ei_sat_rises_{z}_{p}"] == 1.0 for z in ("damped", "undamped") for p in POSITIONS
    )
    sat_txt = "; ".join(
        f"{int(p) / 100:.2f} L: " + " / ".join(f"{sat[('damped', p, s)]:.0f}" for s in SPEEDS)
        for p in POSITIONS
    )
    ratios = [r[f"ei_sat_ratio_40_20_{z}_{p}"] for z in ("damped", "undamped") for p in POSITIONS]
    add(
        claim(
            "5 / Fig. 13",
            "The COR first rises quickly with EI1, then saturates.",
            "COR at EI1 = 50 -> rigid frame, 20 m/s, damped: "
            + ", ".join(
                f"{r[f'cor_50_damped_{p}_20']:.3f} -> {r[f'cor_rigid_damped_{p}_20']:.3f}"
                for p in POSITIONS
            )
            + " (0.60, 0.75, 0.90 L); 95 % of the rigid COR reached at "
            "EI1 = " + sat_txt + " N m² (20 / 30 / 40 m/s)",
            all(
                r[f"cor_rigid_{z}_{p}_{s}"] > r[f"cor_50_{z}_{p}_{s}"]
                for z in ("damped", "undamped")
                for p in POSITIONS
                for s in SPEEDS
            )
            and all(sat[k] < 3000.0 for k in sat),
            "Saturation EI1 = smallest EI1 beyond which the COR stays at or above 95 % of the "
            f"rigid frame's (EI1 = 9999 N m²); {r['ei_points']:.0f} log-spaced EI1 values "
            "from 50 to 3000 N m².",
            "fig13",
        )
    )
    add(
        claim(
            "5 / Concl. (2)",
            "The rigidity at which the COR saturates is higher at greater impact speeds.",
            f"saturation EI1 rises with speed at every position, with and without damping: "
            f"{'yes' if rises else 'no'}; EI1_sat(40)/EI1_sat(20) = {min(ratios):.2f}-"
            f"{max(ratios):.2f} vs K_CB(40)/K_CB(20) = {r['kcb_ratio_40_20']:.2f}",
            rises,
            "With a linear ball/string law and fixed zeta the COR depends on EI1 and K_CB only "
            "through EI1/K_CB, so the saturation rigidity scales with K_CB(speed); the ratio "
            f"is resolved to the EI1 grid step (x{r['ei_ratio_step']:.3f}).",
            "fig13",
        )
    )
    over = max(r[f"overshoot_damped_{p}_{s}"] for p in POSITIONS for s in SPEEDS)
    drop = max(
        r[f"max_drop_{z}_{p}_{s}"]
        for z in ("damped", "undamped")
        for p in POSITIONS
        for s in SPEEDS
    )
    add(
        claim(
            "5 / Concl. (2)",
            "The curves are essentially simple, with small maxima and minima and no unevenness.",
            f"largest fall along any curve {drop:.4f}; largest overshoot above the rigid-frame "
            f"COR {over:.4f}",
            drop < 0.01,
            "Wiggles below 0.01 in COR near saturation; otherwise monotonic.",
            "fig13",
        )
    )
    spread0 = max(r[f"cor_rigid_spread_undamped_{p}"] for p in POSITIONS)
    spread1 = max(r[f"cor_rigid_spread_damped_{p}"] for p in POSITIONS)
    add(
        claim(
            "5",
            "Without ball/string damping, the saturated COR at each impact point is the "
            "same at every impact speed.",
            f"rigid-frame COR spread over 20/30/40 m/s: <= {spread0:.1e} (zeta = 0); with "
            f"damping <= {spread1:.1e}",
            spread0 < 0.005,
            "Eq 12 does not involve K_CB. With damping the saturated COR is also speed-"
            "independent here, because zeta is the same at every speed (section 2.1.2); the "
            "paper does not say otherwise.",
            "fig13",
        )
    )

    # -- 6 conclusions ---------------------------------------------------------------------
    add(
        claim(
            "Concl. (1)",
            "The impact is governed by the rigid-body motion and the first "
            "(2-node) frame mode; the second and higher modes contribute little.",
            f"COR with rigid modes + frame mode 1 only is within "
            f"{p8['mode1_only_max_cor_diff']:.3f} of the full model over 0.55-0.95 L; system "
            f"modes 3+ carry < {max(s11['higher_share_060'], s11['higher_share_node']) * 100:.1f}"
            " % of V_I",
            p8["mode1_only_max_cor_diff"] < 0.02,
            "Compare the dotted and solid blue curves of Fig. 8.",
            "fig08",
        )
    )
    add(
        claim(
            "Concl. (2)",
            "The COR increases with frame rigidity and saturates; the saturation "
            "rigidity is higher for faster impacts; the changes are simple.",
            "see section 5 rows above",
            rises and drop < 0.01,
            "Fig. 13.",
            "fig13",
        )
    )
    add(
        claim(
            "Concl. (3)",
            "The COR is dominated by rigid-body motion: it falls as the impact "
            "point moves away from the centre of rotation (about the CG) and rises as it "
            "approaches a node of the frame vibration.",
            f"rigid-frame COR peaks at {p8['rigid_cor_argmax_x_over_l']:.3f} L (CG "
            f"{p8['cg_x_over_l']:.3f} L); vibration loss smallest at "
            f"{p8['vibration_loss_argmin_x_over_l']:.3f} L (node {p8['node_x_over_l']:.3f} L)",
            abs(p8["rigid_cor_argmax_x_over_l"] - p8["cg_x_over_l"]) <= p8["wide_step_x_over_l"]
            and abs(p8["vibration_loss_argmin_x_over_l"] - p8["node_x_over_l"])
            <= 2 * p8["step_x_over_l"],
            "Both extrema within the position grid step of the CG and the node.",
            "fig08",
        )
    )
    add(
        claim(
            "Concl. (4)",
            "At a given speed the contact time is affected little by frame "
            "rigidity, nearly as for a rigid frame, and changes little with impact position.",
            f"standard vs rigid <= {p9['tc_rigidity_max_rel_diff'] * 100:.1f} %; over "
            f"0.55-0.95 L the standard frame's contact time varies by "
            f"{p9['tc_standard_position_spread'] * 100:.0f} % "
            f"({p9['tc_standard_min_s'] * ms:.2f}-{p9['tc_standard_max_s'] * ms:.2f} ms)",
            p9["tc_rigidity_max_rel_diff"] < 0.05 and p9["tc_standard_position_spread"] < 0.25,
            f"Rigidity: within 5 %. Position: a {p9['tc_standard_position_spread'] * 100:.0f} % "
            "spread, small beside the factor ~1.8 between 20 and 40 m/s (Figs 2-3 (c)); "
            "'little' read as under 25 %.",
            "fig09",
        )
    )
    return out
