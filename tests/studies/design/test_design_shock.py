"""Handle shock as a design objective: minimised, averaged over the zone, usable with NSGA-II."""

import numpy as np
import pytest

from fem_racket.contact.presets import get_law
from fem_racket.frame.hand import FIRM_GRIP, LOOSE_GRIP
from fem_racket.frame.hermite import assemble_closed_form
from fem_racket.impact.held.basis import held_basis
from fem_racket.impact.held.modal import held_contact
from fem_racket.impact.held.shock import grip_peak, vibration_rms
from fem_racket.studies.design.build import design_problem
from fem_racket.studies.design.evaluate import Evaluator
from fem_racket.studies.design.objectives import evaluate_rows, output_names
from fem_racket.studies.design.options import VariableOptions
from fem_racket.studies.design.paper_problem import paper_problem
from fem_racket.studies.design.pareto import pareto_front
from fem_racket.studies.design.solvers import optimize
from fem_racket.studies.design.swing import SwingModel, mass_quantities
from fem_racket.studies.design.zone import uniform_zone
from fem_racket.validation import InputError

ZONE = uniform_zone(0.6, 0.9, 4)
SHOCK = ("handle_shock", "peak_grip_force")


def evaluate_design(p, x):
    """Every output of design ``x`` by name."""
    return dict(zip(output_names(p), evaluate_rows(p, x[None])[0], strict=True))


def test_objectives_are_the_zone_means_of_the_held_impacts():
    p = paper_problem(
        None,
        VariableOptions(boundaries=(0.3,)),
        speeds=(20.0,),
        zone=ZONE,
        swing=SwingModel(15.0, pivot=0.1),
        objectives=("ball_speed", *SHOCK),
        hand=FIRM_GRIP,
        shock_window=0.04,
    )
    out = evaluate_design(p, p.x_start)
    mesh = p.mesh(p.x_start)
    v_r = p.swing.impact_speed(ZONE.positions, mass_quantities(mesh, 0.1)["inertia_pivot"], 0.68)
    basis = held_basis(assemble_closed_form(mesh), FIRM_GRIP)
    cases = [
        held_contact(basis, position=x, speed=20.0 + v, zeta=p.zeta)
        for x, v in zip(ZONE.positions, v_r, strict=True)
    ]
    rms = np.mean([vibration_rms(c, 0.04) for c in cases])
    peak = np.mean([grip_peak(c, 0.04) for c in cases])
    # the same sums evaluated in another order: round-off only
    assert out["handle_shock"] == pytest.approx(rms, rel=1e-9)
    assert out["peak_grip_force"] == pytest.approx(peak, rel=1e-9)


@pytest.mark.parametrize("hand", [LOOSE_GRIP, FIRM_GRIP])
def test_stiffer_frames_shock_less(hand):
    # Kawazoe (DESIGN section 8): stiffer handles shock less.
    p = paper_problem(
        None,
        VariableOptions(boundaries=(0.3,), vary=("ei",), link_ei=True),
        speeds=(30.0,),
        zone=ZONE,
        objectives=SHOCK,
        hand=hand,
    )
    shock = [evaluate_design(p, np.array([ei]))["handle_shock"] for ei in (100.0, 300.0, 1000.0)]
    assert shock[0] > shock[1] > shock[2]


def test_a_single_objective_solver_lowers_the_shock():
    p = paper_problem(
        None,
        VariableOptions(boundaries=(0.3,), vary=("ei",)),
        speeds=(30.0,),
        zone=ZONE,
        objectives=("handle_shock",),
    )
    r = optimize(p, evaluator=Evaluator(p, backend="serial"), maxiter=5, progress=False)
    assert r.objective < 0.9 * r.start_objective


def test_pareto_front_of_power_against_shock_is_non_dominated():
    p = paper_problem(
        None,
        VariableOptions(boundaries=(0.3,), vary=("ei", "rhoa")),
        speeds=(20.0,),
        zone=uniform_zone(0.6, 0.9, 3),
        swing=SwingModel(20.0, pivot=0.1),
        objectives=("ball_speed", "handle_shock"),
    )
    r = pareto_front(
        p, evaluator=Evaluator(p, backend="serial"), pop_size=8, generations=3, progress=False
    )
    f = r.pareto_f
    assert np.all(np.diff(f[:, 0]) <= 0.0)  # fastest first
    # mean v_out maximised, shock minimised: no front design is better in both
    for i in range(len(f)):
        better = (f[:, 0] >= f[i, 0]) & (f[:, 1] <= f[i, 1])
        strictly = (f[:, 0] > f[i, 0]) | (f[:, 1] < f[i, 1])
        assert not np.any(better & strictly)
    assert r.outputs["ball_speed"] == pytest.approx(f[0, 0])


def test_shock_settings_and_their_errors():
    p = design_problem(objectives=("handle_shock",), grip="firm", shock_window=0.03)
    assert p.hand is FIRM_GRIP and p.describe()["shock_window_s"] == 0.03
    assert "hand" not in design_problem().describe()  # other problems' digests unchanged
    with pytest.raises(InputError, match="grip = 'tight'"):
        design_problem(objectives=("handle_shock",), grip="tight")
    with pytest.raises(InputError, match="shock window = -1"):
        design_problem(objectives=("handle_shock",), shock_window=-1.0)
    # The held racket's exact path is linear at the paper's K_CB(v): a string-bed variable or
    # another law would reach the power objectives only, so the pair is refused.
    with pytest.raises(InputError, match="variable kcb_factor is not allowed"):
        design_problem(objectives=("ball_speed", "handle_shock"), vary=("ei", "string"))
    with pytest.raises(InputError, match="law = 'series' is not allowed"):
        design_problem(objectives=("handle_shock",), law=get_law("series"))
