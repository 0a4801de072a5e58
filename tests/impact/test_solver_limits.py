"""No silently wrong answer from a solver (issue 12): tolerances that cannot meet the stated
accuracy, the physical basis beyond its size, and output counts are refused in one line naming
the parameter the user gave."""

import pytest

from fem_racket import simulate
from fem_racket.impact.ode.integrators import ATOL_RANGE, PHYSICAL_MAX_ELEMENTS, RTOL_RANGE
from fem_racket.validation import InputError


@pytest.mark.parametrize("solver", ["cvode", "bdf"])
def test_loose_or_extreme_tolerances_refused(solver):
    # Issue 12: --solver cvode --rtol 1 returned COR -0.987 and t_c 0.24 ms.
    for rtol in (1.0, 1e-4, 1e-13):
        with pytest.raises(InputError, match=f"rtol = {rtol!r} is not allowed"):
            simulate(solver=solver, rtol=rtol)
    for atol in (1e-6, 1e-20):
        with pytest.raises(InputError, match=f"atol = {atol!r} is not allowed"):
            simulate(solver=solver, atol=atol)


def test_loosest_allowed_tolerances_meet_the_stated_accuracy():
    # The edge of the allowed range against the exact path (every mode, as CVODE keeps them):
    # COR within 1e-8, t_c within 1e-7.
    exact = simulate(output_step=None, tolerance=None)
    r = simulate(solver="cvode", rtol=RTOL_RANGE[1], atol=ATOL_RANGE[1], output_step=None)
    assert r.cor == pytest.approx(exact.cor, abs=1e-8)
    assert r.contact_time == pytest.approx(exact.contact_time, rel=1e-7)


def test_physical_basis_limited_in_size():
    n = PHYSICAL_MAX_ELEMENTS + 1
    with pytest.raises(InputError, match=f"basis = 'physical' is not allowed with {n} elements"):
        simulate(solver="cvode", basis="physical", elements=n)


def test_output_count_refusal_names_the_parameter_given():
    # Issue 12: --t-max 11 and --kcb 1e-6 were refused with an error about output_step.
    with pytest.raises(InputError, match=r"^t_max = 11\.0 s is not allowed"):
        simulate(t_max=11.0)
    with pytest.raises(InputError, match=r"^kcb = 1e-06 N/m is not allowed"):
        simulate(kcb=1e-6)  # now below kcb's range (audit F15): the softest allowed, 100 N/m
    with pytest.raises(InputError, match=r"^kcb = 100\.0 N/m is not allowed with at most 1e\+06"):
        simulate(kcb=100.0, output_step=1e-7)
    assert simulate(kcb=100.0, output_step=None).contact_time > 0.06


def test_ill_conditioned_exact_path_is_a_one_line_refusal(standard_model):
    # Modes scaled 1e16 (EI / rhoA ~ 2e18, far beyond EI_RANGE, reachable only by scaling the
    # modes directly): the closed form's self-check fails. It was a RuntimeError traceback.
    from fem_racket.impact.exact.closed_form import solve_exact
    from fem_racket.impact.system import modal_system
    from fem_racket.validation import AccuracyError

    fm = standard_model.modes().scaled(1e16)
    g = standard_model.fe.point_vector(0.75 * standard_model.mesh.length)
    system = modal_system(fm.all_omega, fm.all_shapes, g, 0.057, 2.74e4, 4.68, 20.0)
    with pytest.raises(AccuracyError, match="^solver = 'exact' cannot solve this case") as err:
        solve_exact(system)
    assert "\n" not in str(err.value)
