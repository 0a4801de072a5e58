"""Do conclusions (1)-(4) of Kawazoe & Kanda (1997) hold, and are the contact times 6-3 ms?

Each conclusion (section 6, quoted in :data:`CONCLUSIONS`) is decided from the figures' scalar
values by the same checks as the linear-law report (:mod:`.results`), so that they can be
re-evaluated under any contact law (``fem-racket reproduce --law NAME``); every number of the
decision is shown beside the verdict. The contact times are set beside the paper's statement
for real impacts (section 1): "contact time is 6 - 3 ms, with shorter times at higher impact
speeds".

The thresholds, each the paper's word read as a number (as in :mod:`.results`):

- (1) "the contribution of second and higher modes is small": the COR with the rigid modes and
  frame mode 1 alone within :data:`MODE1_COR` of the full model over 0.55-0.95 L;
- (2) "increases ... saturates ... higher for faster impacts ... essentially simple": COR at the
  rigid frame above COR at EI1 = 50 N m^2 on every curve, every curve within 95 % of its
  rigid-frame COR below EI1 = 3000 N m^2, the saturation EI1 rising with speed at every point,
  and no fall along any curve larger than :data:`SIMPLE_DROP`;
- (3) "decreases away from the centre of rotation ... increases towards the nodes": the rigid
  frame's COR peaks within one grid step of the CG and falls over 0.55-0.95 L; the vibration loss
  (rigid minus standard COR) is smallest within two grid steps of the mode-1 node;
- (4) "affected little by frame rigidity ... changed little at different impact positions":
  standard vs rigid frame within :data:`RIGIDITY_TC` and a position spread under
  :data:`POSITION_TC`.
"""

from __future__ import annotations

import math
from typing import Any

from fem_racket.paper.claims.base import Claim, claim

__all__ = [
    "CONCLUSIONS",
    "PAPER_TC_RANGE_S",
    "conclusion_claims",
    "contact_time_claim",
    "contact_time_rows",
]

#: Section 6 of the paper, verbatim.
CONCLUSIONS = {
    "(1)": "Impact in a ball and racket system is controlled by the rigid body movement and the "
    "first order (2 node bending) mode vibration of the frame. The contribution of second order "
    "(3 node bending) and higher mode vibrations of the frame is small.",
    "(2)": "Although the coefficient of restitution increases with increases in frame rigidity, "
    "this increase saturates at a certain rigidity. The frame rigidity at which saturation is "
    "reached is higher for faster impact velocities and the changes are essentially simple.",
    "(3)": "The coefficient of restitution is greatly influenced by the rigid body movement of "
    "the ball and racket system. As impact positions move away from the center of rotation "
    "(nearly the center of gravity of the racket) the coefficient decreases. As impact "
    "approaches the positions of the nodes of the frame vibration the coefficient increases.",
    "(4)": "When the impact velocity of the ball and racket are fixed, the contact time is "
    "affected little by frame rigidity and is nearly the same as for a rigid body frame. In "
    "addition, contact time changed little at different impact positions.",
}
#: Contact time of real impacts, section 1: "6 - 3 ms, with shorter times at higher speeds" [s].
PAPER_TC_RANGE_S = (3e-3, 6e-3)
MODE1_COR = 0.02
SIMPLE_DROP = 0.01
SATURATION_EI_MAX = 3000.0
RIGIDITY_TC = 0.05
POSITION_TC = 0.25

POSITIONS = ("60", "75", "90")
SPEEDS = ("20", "30", "40")


def _families(r: dict[str, float]) -> list[str]:
    """The Fig. 13 curve families present: with losses, and without when computed."""
    return [z for z in ("damped", "undamped") if f"ei_sat_rises_{z}_60" in r]


def _ei(x: float) -> str:
    """A saturation EI1 [N m^2], or "-" where the curve does not reach 95 % on the grid."""
    return f"{x:.0f}" if math.isfinite(x) else "-"


def _ratio(xs: list[float]) -> str:
    finite = [x for x in xs if math.isfinite(x)]
    if not finite:
        return "- (no curve saturates at both 20 and 40 m/s)"
    return f"{min(finite):.2f}-{max(finite):.2f}"


def _sat_text(r: dict[str, float], z: str) -> str:
    return "; ".join(
        f"{int(p) / 100:.2f} L: " + " / ".join(_ei(r[f"ei_sat_{z}_{p}_{s}"]) for s in SPEEDS)
        for p in POSITIONS
    )


def conclusion_claims(v: dict[str, dict[str, float]]) -> list[Claim]:
    """Conclusions (1)-(4), each with its numbers and verdict.

    Parameters
    ----------
    v : dict
        Figure key -> scalar values, at least ``fig05``-``fig09`` and ``fig13``
        (:mod:`fem_racket.paper.figures`), computed with any contact law.
    """
    p8, p9, r = v["fig08"], v["fig09"], v["fig13"]
    ms = 1e3
    out: list[Claim] = []

    share = [v[k]["standard_final_mode1_share"] for k in ("fig05", "fig06", "fig07")]
    diff = p8["mode1_only_max_cor_diff"]
    out.append(
        claim(
            "Concl. (1)",
            CONCLUSIONS["(1)"],
            f"COR with the rigid modes + frame mode 1 only is within {diff:.4f} of the full "
            f"model over 0.55-0.95 L (20 m/s); frame mode 1 holds "
            + ", ".join(f"{s * 100:.0f} %" for s in share)
            + " of the elastic deformation left at separation (0.60, 0.75, 0.90 L)",
            diff < MODE1_COR,
            f"Holds: the COR changes by less than {MODE1_COR} without frame modes 2 and up.",
            "fig08",
            f"Does not hold: dropping frame modes 2 and up changes the COR by {diff:.4f} "
            f"(> {MODE1_COR}).",
        )
    )

    fams = _families(r)
    curves = [(z, p, s) for z in fams for p in POSITIONS for s in SPEEDS]

    def where(ok) -> list[str]:
        """The impact points (x/L) where ``ok(z, p)`` fails for some curve family."""
        return [f"0.{p} L" for p in POSITIONS if not all(ok(z, p) for z in fams)]

    falling = where(
        lambda z, p: all(r[f"cor_rigid_{z}_{p}_{s}"] > r[f"cor_50_{z}_{p}_{s}"] for s in SPEEDS)
    )
    unsaturated = where(
        lambda z, p: all(
            math.isfinite(x) and x < SATURATION_EI_MAX
            for x in (r[f"ei_sat_{z}_{p}_{s}"] for s in SPEEDS)
        )
    )
    not_later = where(lambda z, p: r[f"ei_sat_rises_{z}_{p}"] == 1.0)
    drop = max(r[f"max_drop_{z}_{p}_{s}"] for z, p, s in curves)
    ratios = [r[f"ei_sat_ratio_40_20_{z}_{p}"] for z in fams for p in POSITIONS]
    failed = [
        *([f"the COR does not rise with EI1 at {', '.join(falling)}"] if falling else []),
        *(
            [
                f"the COR is not within 95 % of the rigid frame's by EI1 = 3000 N m² at "
                f"{', '.join(unsaturated)} (no saturation)"
            ]
            if unsaturated
            else []
        ),
        *(
            [f"the saturation EI1 does not rise with speed at {', '.join(not_later)}"]
            if not_later
            else []
        ),
        *([f"a curve falls by {drop:.4f} (> {SIMPLE_DROP}: not simple)"] if drop >= SIMPLE_DROP
          else []),
    ]  # fmt: skip
    out.append(
        claim(
            "Concl. (2)",
            CONCLUSIONS["(2)"],
            "COR at EI1 = 50 N m² -> rigid frame, 20 m/s: "
            + ", ".join(
                f"{r[f'cor_50_damped_{p}_20']:.3f} -> {r[f'cor_rigid_damped_{p}_20']:.3f}"
                for p in POSITIONS
            )
            + " (0.60, 0.75, 0.90 L); 95 % of the rigid-frame COR reached at EI1 = "
            + _sat_text(r, "damped")
            + " N m² (20 / 30 / 40 m/s; -: not reached by EI1 = 3000 N m²); "
            + f"EI1_sat(40)/EI1_sat(20) = {_ratio(ratios)} (equivalent K_CB(40)/K_CB(20) = "
            + f"{r['kcb_ratio_40_20']:.2f}); largest fall along a curve {drop:.4f}",
            not failed,
            f"Holds: on all {len(curves)} curves of Fig. 13 the COR rises with EI1, comes within "
            f"95 % of the rigid frame's below EI1 = 3000 N m², later at higher speeds, and "
            f"falls nowhere by more than {SIMPLE_DROP}.",
            "fig13",
            "Does not hold: " + "; ".join(failed) + ".",
        )
    )

    off_cg = abs(p8["rigid_cor_argmax_x_over_l"] - p8["cg_x_over_l"])
    off_node = abs(p8["vibration_loss_argmin_x_over_l"] - p8["node_x_over_l"])
    parts3 = {
        "the rigid-frame COR peaks at the CG": off_cg <= p8["wide_step_x_over_l"],
        "falls outwards over 0.55-0.95 L": p8["rigid_decreasing"] == 1.0,
        "the vibration loss is smallest at the mode-1 node": off_node <= 2 * p8["step_x_over_l"],
    }
    misses = {
        "the rigid-frame COR peaks at the CG": f"the rigid-frame COR peaks {off_cg:.3f} L from "
        f"the CG (allowed {p8['wide_step_x_over_l']:.3f} L)",
        "falls outwards over 0.55-0.95 L": "the rigid-frame COR does not fall steadily over "
        "0.55-0.95 L",
        "the vibration loss is smallest at the mode-1 node": f"the vibration loss is smallest "
        f"{off_node:.3f} L from the mode-1 node (allowed {2 * p8['step_x_over_l']:.3f} L)",
    }
    failed3 = [misses[k] for k, ok in parts3.items() if not ok]
    out.append(
        claim(
            "Concl. (3)",
            CONCLUSIONS["(3)"],
            f"rigid-frame COR peaks at {p8['rigid_cor_argmax_x_over_l']:.3f} L (CG "
            f"{p8['cg_x_over_l']:.3f} L) and goes from {p8['rigid_cor_max']:.3f} to "
            f"{p8['rigid_cor_min']:.3f} over 0.55-0.95 L; vibration loss (rigid minus standard "
            f"COR) smallest, {p8['vibration_loss_min']:+.3f}, at "
            f"{p8['vibration_loss_argmin_x_over_l']:.3f} L (mode-1 node "
            f"{p8['node_x_over_l']:.3f} L); the standard frame's COR peaks at "
            f"{p8['standard_cor_argmax_x_over_l']:.3f} L",
            not failed3,
            "Holds: " + ", ".join(parts3) + " (within the position grid step).",
            "fig08",
            "Does not hold: " + "; ".join(failed3) + ".",
        )
    )

    rig, spread = p9["tc_rigidity_max_rel_diff"], p9["tc_standard_position_spread"]
    out.append(
        claim(
            "Concl. (4)",
            CONCLUSIONS["(4)"],
            f"standard vs rigid frame: at most {rig * 100:.1f} % apart (at "
            f"{p9['tc_rigidity_argmax_x_over_l']:.2f} L); over 0.55-0.95 L the "
            f"standard frame's contact time spans {p9['tc_standard_min_s'] * ms:.2f}-"
            f"{p9['tc_standard_max_s'] * ms:.2f} ms ({spread * 100:.0f} % spread; 20 m/s)",
            rig < RIGIDITY_TC and spread < POSITION_TC,
            f"Holds: rigidity within {RIGIDITY_TC * 100:.0f} %, position spread under "
            f"{POSITION_TC * 100:.0f} %.",
            "fig09",
            "Does not hold: "
            + "; ".join(
                text
                for text, bad in (
                    (
                        f"frame rigidity changes it by up to {rig * 100:.1f} % (allowed "
                        f"{RIGIDITY_TC * 100:.0f} %)",
                        rig >= RIGIDITY_TC,
                    ),
                    (
                        f"the impact position by {spread * 100:.0f} % (allowed "
                        f"{POSITION_TC * 100:.0f} %)",
                        spread >= POSITION_TC,
                    ),
                )
                if bad
            )
            + ".",
        )
    )
    return out


def contact_time_rows(v: dict[str, dict[str, float]]) -> list[dict[str, Any]]:
    """Contact times [s] at 20, 30 and 40 m/s: the paper's linear K_CB on the clamped frame
    (eq 1), the law clamped and on the free standard frame at 0.60, 0.75 and 0.90 L."""
    f = v["fig02_03"]
    rows = []
    for s in SPEEDS:
        free = {p: f[f"tc_free_{p}_{s}_s"] for p in POSITIONS}
        rows.append(
            {
                "speed [m/s]": float(s),
                "paper's K_CB, clamped [s]": f.get(
                    f"tc_paper_clamped_{s}_s", f[f"tc_clamped_{s}_s"]
                ),
                "clamped [s]": f[f"tc_clamped_{s}_s"],
                **{f"free frame at 0.{p} L [s]": t for p, t in free.items()},
            }
        )
    return rows


def contact_time_claim(v: dict[str, dict[str, float]]) -> Claim:
    """The law's contact times (clamped and free, 20-40 m/s) against the paper's 6-3 ms."""
    rows = contact_time_rows(v)
    times = [t for row in rows for k, t in row.items() if k not in ("speed [m/s]",)
             and not k.startswith("paper")]  # fmt: skip
    low, high = PAPER_TC_RANGE_S
    inside = all(low <= t <= high for t in times)
    per_case = [[row[k] for row in rows] for k in rows[0] if k.startswith(("clamped", "free"))]
    shorter = all(a > b for case in per_case for a, b in zip(case[:-1], case[1:], strict=True))
    ms = 1e3
    parts = {"within 3-6 ms": inside, "shorter at higher speeds": shorter}
    failed = [k for k, ok in parts.items() if not ok]
    return claim(
        "1",
        "Contact time of real impacts is 6 - 3 ms, with shorter times at higher impact speeds.",
        f"{min(times) * ms:.2f}-{max(times) * ms:.2f} ms over 20-40 m/s (clamped and free "
        "frame at 0.60, 0.75, 0.90 L; table below)",
        not failed,
        "Holds: " + ", ".join(parts) + ".",
        "fig02_03",
        "Does not hold: "
        + ", ".join(f"not {k}" for k in failed)
        + f" (shortest {min(times) * ms:.2f} ms, longest {max(times) * ms:.2f} ms).",
    )
