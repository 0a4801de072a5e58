"""Every law parameter has documented physical bounds and conditions (issue 22, deliverable 2).

The library side: declarations are complete and self-consistent, values and combinations are
checked elementwise (a batch names its first bad case), the paper's law is one class whose
force is bit for bit the exact path's, and a ball's mass outside 1 g-1 kg names the likely slip.
"""

import math

import numpy as np
import pytest

from fem_racket import simulate
from fem_racket.contact.hunt_crossley import HuntCrossley
from fem_racket.contact.hysteretic import Hysteretic
from fem_racket.contact.law import DEFLECTION_RANGE
from fem_racket.contact.linear import Ball, LinearContact, check_ball_mass
from fem_racket.contact.presets import family_law, get_law
from fem_racket.contact.registry import FAMILIES, PRESETS
from fem_racket.contact.series import SeriesBallString
from fem_racket.io.config import parse_config
from fem_racket.studies.calibrate import FAMILIES as FITTED
from fem_racket.studies.calibrate import clamped_impacts, run_file_table
from fem_racket.studies.sweep import sweep_result
from fem_racket.validation import AccuracyError, InputError


@pytest.mark.parametrize("cls", [LinearContact, *FAMILIES.values()])
def test_every_parameter_is_declared_with_its_reasoning(cls):
    import dataclasses

    fields = {f.name for f in dataclasses.fields(cls)}
    for p in cls.declared:
        assert p.field in fields and p.unit and p.help and len(p.why) > 20
        assert p.low < p.high
        p.check(p.default)  # every default lies within its own bounds


@pytest.mark.parametrize("name", [*FAMILIES, *PRESETS])
def test_defaults_and_presets_meet_their_conditions(name):
    law = get_law(name)
    # rebuilt from its values, every condition checked again
    assert type(law).from_values(law.values()).values() == law.values()


@pytest.mark.parametrize(
    ("make", "words"),
    [
        (lambda: Hysteretic(5e15, 4e15, 8.913), ("k2 >= k1", "k1 = 5e+15", "k2 = 4e+15")),
        (lambda: Hysteretic(3.182e15, 1e40, 8.913), ("rigid COR",)),
        (lambda: Hysteretic(3.182e15, 1e300, 8.913), ("k2 = 1e+300", "[100, 1e+40]")),
        (lambda: HuntCrossley(1e7, 14.87, 0.01), ("deflection under 1000 N",)),
        (lambda: SeriesBallString(1e300, 17.0, 1559.0, 8.3e8), ("ball_stiffness = 1e+300",)),
        (lambda: SeriesBallString(1e-300, 17.0, 1559.0, 8.3e8), ("ball_stiffness = 1e-300",)),
        (lambda: SeriesBallString(9.8e4, 1e-300, 1559.0, 8.3e8), ("ball_damping = 1e-300",)),
        (lambda: SeriesBallString(9.8e4, 17.0, 1e300, 8.3e8), ("string_stiffness = 1e+300",)),
        (lambda: SeriesBallString(9.8e4, 17.0, 1e-300, 8.3e8), ("string_stiffness = 1e-300",)),
        (lambda: SeriesBallString(1e12, 1.0, 27400.0, 0.0), ("ball_stiffness = 1000000000000.0",)),
        (lambda: SeriesBallString(9.8e4, 17.0, 10.0, 0.0), ("deflection under 1000 N",)),
        (lambda: SeriesBallString(-1.0, 17.0, 1559.0, 0.0), ("ball_stiffness = -1.0", "> 0")),
        (lambda: LinearContact(2.74e4, 1.0), ("zeta = 1.0", "[0, 1)")),
        (lambda: LinearContact(0.0, 0.05), ("kcb = 0.0", "> 0")),
    ],
)
def test_out_of_bounds_laws_are_refused_in_one_line(make, words):
    with pytest.raises(InputError) as err:
        make()
    msg = str(err.value)
    assert "\n" not in msg and all(w in msg for w in words), msg


def test_a_batch_names_its_first_bad_case():
    # Arrays of one value per case (a sweep's batch): the first case breaking k2 >= k1 named.
    with pytest.raises(InputError, match=r"k1 = 5e\+15, k2 = 4e\+15.*and 1 more cases"):
        family_law(
            "hysteretic",
            {"k1": np.array([1e15, 5e15, 6e15]), "k2": 4e15, "hyst_exponent": 8.913},
        )


def test_deflection_condition_matches_the_static_deflection():
    # The condition's closed forms against Brent's root of F(delta) = 1 kN on each law.
    for law in (get_law("hunt-crossley"), get_law("hysteretic"), get_law("series")):
        d = law.static_deflection(1e3)
        assert DEFLECTION_RANGE[0] < d < DEFLECTION_RANGE[1]
        values = {k: np.asarray(v) for k, v in law.values().items()}
        cond = law.conditions[-1]
        assert "deflection" in cond.text and bool(cond.holds(values))
    hc = HuntCrossley(2.978e24, 14.87, 0.0)  # (F/k)^(1/n): the closed form
    assert hc.static_deflection(1e3) == pytest.approx((1e3 / 2.978e24) ** (1 / 14.87), rel=1e-9)


def test_the_sweep_grid_checks_every_combination_before_any_work(tmp_path):
    # Issue 22: k1 = 1e15, 5e15 against k2 = 4e15 computed the k2 < k1 case.
    out = tmp_path / "s.nc"
    with pytest.raises(InputError, match=r"k2 >= k1") as err:
        sweep_result(law="hysteretic", k1="1e15,5e15", k2=4e15, output=out)
    assert "k1 = 5e+15" in str(err.value)
    assert not out.exists() and list(tmp_path.iterdir()) == []


def test_paper_law_is_one_class_bit_for_bit():
    # The force the general integrators use is the exact path's C_CB = 2 zeta sqrt(m K).
    law = LinearContact.for_speed(30.0, ball_mass=0.058)
    c = 2.0 * law.zeta * math.sqrt(0.058 * law.stiffness)
    assert law.damping() == c and law.damping(0.058) == c
    assert law.force(0.01, 2.0, 0.0) == law.stiffness * 0.01 + c * 2.0
    assert law.elastic().damping() == 0.0
    # solver="general" runs the very object the exact path reads
    general = simulate(speed=30.0, solver="general", output_step=None)
    exact = simulate(speed=30.0, output_step=None, tolerance=None)
    assert (general.contact.stiffness, general.contact.zeta) == (
        exact.contact.stiffness,
        exact.contact.zeta,
    )
    assert general.cor == pytest.approx(exact.cor, abs=2e-6)


def test_linear_fit_writes_a_run_file_the_config_reads():
    # calibrate --family linear wrote ccb_n_s_m, which no run file accepts; now kcb and zeta.
    law = FITTED["linear"].build(np.array([5e4, 6.3]))
    text = run_file_table(law)
    kw = parse_config(text).simulate_kwargs()
    assert kw["kcb"] == law.stiffness and kw["zeta"] == law.zeta
    assert law.damping() == pytest.approx(6.3, rel=1e-15)
    cor, _ = clamped_impacts(law, [20.0])
    assert cor[0] < 1.0


@pytest.mark.parametrize(
    ("mass", "slip"), [(57.0, "57.0 g = 0.057 kg"), (0.0005, None), (2000.0, None)]
)
def test_ball_mass_outside_one_gram_to_one_kilogram_names_the_slip(mass, slip):
    with pytest.raises(InputError, match=r"ball mass = .* kg is not allowed: must lie in") as err:
        Ball(mass)
    assert (slip in str(err.value)) if slip else "grams" not in str(err.value)
    for m in (0.0027, 0.057, 0.145, 0.19):  # table tennis, tennis, baseball, softball
        assert check_ball_mass(m) == m


def test_library_simulate_refuses_kcb_and_zeta_with_another_law():
    with pytest.raises(
        InputError, match="kcb = 30000.0 is not allowed with contact law 'hysteretic'"
    ):
        simulate(law="hysteretic", kcb=3e4)
    with pytest.raises(InputError, match="zeta = 0.1 is not allowed with contact law 'series'"):
        simulate(law=get_law("series"), zeta=0.1)
    with pytest.raises(
        InputError, match="kcb = '3e4,4e4' is not allowed with contact law 'series'"
    ):
        sweep_result(law="series", kcb="3e4,4e4")


def test_a_failed_step_is_one_line_naming_the_case():
    # A steel-like ball (K_b 1e8 N/m, C_b 0.01 N s/m) within every bound: the general
    # integrator's Newton iteration diverges (CVODE computes it: COR 0.313 at 20 m/s).
    law = get_law("series", ball_stiffness=1e8, ball_damping=0.01)
    with pytest.raises(AccuracyError) as err:
        simulate(law=law, output_step=None)
    msg = str(err.value)
    assert "\n" not in msg and "ball_stiffness = 1e+08" in msg and "20 m/s" in msg
    assert "cvode" in msg


@pytest.mark.parametrize("family", list(FITTED))
def test_every_fit_starts_inside_its_bounds_with_a_valid_law(family):
    # calibrate --family series --targets itf started at k_s = 1e9 N/m, outside its own search
    # bounds (scipy refused with a traceback); every start now builds a law within its bounds.
    fit = FITTED[family]
    for start in fit.starts.values():
        assert all(lo <= x <= hi for lo, x, hi in zip(fit.low, start, fit.high, strict=True))
        fit.build(np.asarray(start, dtype=float))


def test_design_bounds_outside_the_law_are_refused_before_any_work():
    from fem_racket.studies.design.build import design_problem

    with pytest.raises(InputError, match=r"k_s bound = 1000000000.0 N/m .*\[1, 1e\+07\]"):
        design_problem(vary=("string",), law=get_law("series"), string_bounds=(1e3, 1e9))
    with pytest.raises(InputError, match=r"k_3 bound = 1e\+16 N/m\^3"):
        design_problem(vary=("string_cubic",), law=get_law("series"), cubic_bounds=(0.0, 1e16))


def test_the_batched_engine_refuses_a_ball_in_grams():
    from fem_racket import FrameModel, impacts

    model = FrameModel.build(None, 20)
    with pytest.raises(InputError, match=r"ball_mass = 57.0 kg .*57.0 g = 0.057 kg"):
        impacts(model, position=0.7, speed=20.0, ball_mass=[0.057, 57.0])
