"""Design studies find real optima: the paper's and the literature's findings, each with its
source beside the check."""

import numpy as np
import pytest

from fem_racket.studies.design.build import design_problem
from fem_racket.studies.design.evaluate import Evaluator
from fem_racket.studies.design.objectives import evaluate_rows
from fem_racket.studies.design.options import VariableOptions
from fem_racket.studies.design.paper_problem import paper_problem
from fem_racket.studies.design.report import racket_report
from fem_racket.studies.design.solvers import SETTLED, optimize
from fem_racket.studies.design.swing import SwingModel
from fem_racket.studies.design.variables import Constraint
from fem_racket.studies.design.zone import uniform_zone

ZONE = uniform_zone(0.6, 0.9, 7)


def test_every_constraint_holds_at_the_optimum():
    p = paper_problem(
        None,
        VariableOptions(boundaries=(0.3,)),
        speeds=(30.0,),
        zone=uniform_zone(0.6, 0.9, 5),
        constraints=(
            Constraint("mass_kg", 0.359992, 0.359992),
            Constraint("balance_m", 0.30, 0.32),
            Constraint("swing_weight_kg_cm2", 280.0, 320.0),
            Constraint("f1_hz", 100.0, 160.0),
        ),
    )
    r = optimize(p, evaluator=Evaluator(p, backend="serial"), maxiter=50, progress=False)
    for c in r.constraints():
        assert c["holds"], c
    assert r.objective > r.start_objective


def saturation_ei(speed, cost):
    """EI1* of the stiffness-priced optimum (EI2 = 0.88 EI1, as Fig 13) and the e_A gain of
    raising EI1 from there to the paper's 'rigid' 9999 N m^2."""
    v = VariableOptions(boundaries=(0.3,), vary=("ei",), link_ei=True, ei_bounds=(50.0, 9999.0))
    kw = dict(speeds=(speed,), zone=ZONE)
    priced = paper_problem(None, v, stiffness_cost=cost, **kw)
    r = optimize(priced, evaluator=Evaluator(priced, backend="serial"), progress=False)
    plain = paper_problem(None, v, **kw)
    cor = evaluate_rows(plain, np.array([r.x, [9999.0]]))[:, -1]
    return float(r.x[0]), float(cor[1] - cor[0])


def test_stiffness_saturates_and_the_priced_optimum_stops_there():
    """Kawazoe & Kanda 1997, conclusion (2) and Fig 13: the COR rises with EI1 and saturates, at
    a higher rigidity for faster impacts. With a price of 1e-6 per N m^2 on EI1 the optimiser
    stops below the 'rigid' 9999 N m^2, raising EI1 past its stop gains < 1e-3 in mean e_A, and
    the stop is stiffer at 40 m/s than at 20 m/s (measured: 1005 and 2887 N m^2, gains -2.9e-3
    and -2.1e-3: e_A even falls slightly past the stop, the paper's 'small maxima')."""
    ei20, gain20 = saturation_ei(20.0, 1e-6)
    ei40, gain40 = saturation_ei(40.0, 1e-6)
    assert ei20 < 9000.0 and ei40 < 9000.0
    assert gain20 < 1e-3 and gain40 < 1e-3
    assert ei40 > ei20


def test_tip_mass_raises_ball_speed_and_moves_max_power_tipward():
    """Cross 2001 (Sports Eng. 4): 30 g at the tip raises the ball speed off a swung racket and
    moves the point of maximum ball speed toward the tip; here with the swing slowing as
    I^-0.27 (Cross & Bower 2006)."""
    p = paper_problem(
        None,
        VariableOptions(boundaries=(0.3,), vary=("mass",), mass_positions=(1.0,)),
        speeds=(20.0,),
        swing=SwingModel(20.0),
        objectives=("ball_speed",),
        zone=ZONE,
    )
    v = evaluate_rows(p, np.array([[0.0], [0.03]]))[:, -1]
    assert v[1] > v[0]
    tip = [
        racket_report(p, np.array([m]))["sweet_spots"][0]["max_ball_speed_x_over_l"]
        for m in (0.0, 0.03)
    ]
    assert tip[1] > tip[0]


def test_best_total_mass_is_inside_its_bounds():
    """With swing speed ~ I^-0.27 (Cross & Bower 2006) a heavier racket hits with a larger e_A
    but a slower swing; for a rigid racket and a ball at rest, v_out ~ I^-0.27 / (1 + m_B/M_eff)
    peaks at m_B/M_eff = 0.27/0.73, a finite mass. Scaling the paper racket's mass (0.155-0.78 kg)
    for a serve-like impact (ball at 5 m/s, racket at 30 m/s) the optimum lies inside."""
    p = paper_problem(
        None,
        VariableOptions(boundaries=(0.3,), vary=("rhoa",), link_rhoa=True, rhoa_bounds=(0.3, 1.5)),
        speeds=(5.0,),
        swing=SwingModel(30.0),
        objectives=("ball_speed",),
        zone=ZONE,
    )
    r = optimize(p, evaluator=Evaluator(p, backend="serial"), progress=False)
    lo, hi = 0.3 * 0.359992 / 0.696, 1.5 * 0.359992 / 0.696
    assert lo * 1.05 < r.outputs["mass_kg"] < hi / 1.05


def test_slsqp_stops_once_settled_on_an_active_bound():
    # With f1 <= 200 Hz active at the optimum SLSQP met the bound to ~4e-6 Hz (2e-8 scaled,
    # within the 1e-3 Hz tolerance) but its own test wants 1e-9 scaled: it ran to maxiter
    # (100 iterations, 8 740 designs) for an objective that moved by 5e-10. The settle rule
    # stops it where the objective no longer changes and every constraint holds.
    cons = {
        "mass_kg": ("start",),
        "balance_m": (0.29, 0.33),
        "swing_weight_kg_cm2": (280.0, 330.0),
        "f1_hz": (100.0, 200.0),
    }
    p = design_problem(zone_points=4, speeds=(20.0, 40.0), constraints=cons)
    r = optimize(p, evaluator=Evaluator(p, backend="serial"), maxiter=100, progress=False)
    assert r.success and r.message == SETTLED and r.iterations < 30
    assert all(c["holds"] for c in r.constraints())
    assert r.outputs["f1_hz"] == pytest.approx(200.0, abs=1e-3)  # the active bound
