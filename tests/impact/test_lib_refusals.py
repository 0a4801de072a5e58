"""The library refuses what it would otherwise ignore or misreport (issue 21, deliverable 3):
kcb/zeta next to a law object, a law named as given, a LinearContact referred to the ball that
strikes, and numbers given as text or bools."""

from __future__ import annotations

import math

import pytest

import fem_racket as fr
from fem_racket.contact.bed_ball import KAWAZOE_BALL, kawazoe_ball
from fem_racket.contact.presets import check_linear_options, get_law
from fem_racket.impact.clamped_solve import law_key
from fem_racket.impact.problem import ImpactProblem
from fem_racket.impact.problem_batch import ProblemBatch
from fem_racket.validation import InputError, check_finite
from tests.clirun import library_error

MODEL = fr.FrameModel.build(None, 20)
LAW = fr.LinearContact(3e4, 0.1)


# -- H3: kcb/zeta with a law object, one shared line ------------------------------------------


@pytest.mark.parametrize(("key", "value"), [("zeta", 0.3), ("kcb", 5e4)])
def test_kcb_or_zeta_with_a_linear_law_object_is_refused_alike_everywhere(key, value):
    lines = {
        library_error(lambda: fr.simulate(MODEL, law=LAW, **{key: value})),
        library_error(lambda: fr.racket_map(MODEL, law=LAW, **{key: value})),
        library_error(lambda: fr.sweep(law=LAW, **{key: value})),
        library_error(lambda: ProblemBatch((MODEL,), 0.75, 20.0, law=LAW, **{key: value})),
    }
    assert len(lines) == 1, lines  # one shared check, one line
    (line,) = lines
    assert line.startswith(f"{key} = {value!r} is not allowed with contact law 'linear' (kcb = ")
    assert "the law object fixes K_CB and zeta" in line


def test_the_paper_law_by_name_or_none_still_takes_kcb_and_zeta():
    check_linear_options(None, kcb=3e4, zeta=0.1)
    check_linear_options("linear", kcb=3e4, zeta=0.1)
    check_linear_options(LAW, kcb=None, zeta=None)
    p = ImpactProblem.build(MODEL, kcb=3e4, zeta=0.1)
    assert p.contact().stiffness == 3e4 and p.contact().zeta == 0.1


# -- L4: the law named as given -----------------------------------------------------------------


@pytest.mark.parametrize("law", ["itf-ball", get_law("itf-ball")])
def test_a_preset_is_named_as_given_with_its_family(law):
    line = library_error(lambda: fr.simulate(MODEL, kcb=3e4, law=law))
    assert line.startswith(
        "kcb = 30000.0 is not allowed with contact law 'itf-ball' (hunt-crossley preset): "
    )
    assert "'hunt-crossley':" not in line


def test_racket_map_with_a_linear_law_object_no_longer_contradicts_itself():
    line = library_error(lambda: fr.racket_map(MODEL, law=LAW, zeta=0.3))
    assert "it sets the linear law's K_CB and zeta only" not in line
    assert "give them to LinearContact" in line


# -- M3: the law's zeta referred to the ball that strikes ---------------------------------------


def test_a_linear_law_keeps_its_spring_and_dashpot_for_another_ball():
    other = LAW.for_ball(0.1)
    assert LAW.for_ball(LAW.ball_mass) is LAW  # itself at its own mass
    assert law_key(LAW.for_ball(0.1)) == law_key(other)  # one law per mass, by value
    assert other.stiffness == LAW.stiffness and other.ball_mass == 0.1
    assert other.damping() == pytest.approx(LAW.damping(), rel=1e-15)
    # zeta = C_CB / (2 sqrt(m_B K_CB)) with the new ball
    assert other.zeta == pytest.approx(LAW.damping() / (2.0 * math.sqrt(0.1 * 3e4)), rel=1e-15)
    assert get_law("hysteretic").for_ball(0.1).name == "hysteretic"  # not stated per ball mass


def test_the_preset_ball_referred_to_a_ball_is_the_bed_ball_of_that_mass():
    for mass in (0.05, 0.057, 0.058, 0.1):  # bit for bit: the strung default path's law
        a, b = kawazoe_ball(mass), KAWAZOE_BALL.for_ball(mass)
        assert (a.stiffness, a.zeta, a.ball_mass) == (b.stiffness, b.zeta, b.ball_mass)


def test_settings_state_the_damping_ratio_of_the_ball_that_struck():
    run = fr.simulate(MODEL, law=LAW, ball_mass=0.1)
    used = run.settings()
    zeta = LAW.damping() / (2.0 * math.sqrt(0.1 * 3e4))  # 0.0755, not the law's 0.1 at 0.057 kg
    assert used["ball_mass_kg"] == 0.1 and used["kcb_n_m"] == 3e4
    assert used["zeta"] == pytest.approx(zeta, rel=1e-15)
    assert used["ccb_n_s_m"] == pytest.approx(LAW.damping(), rel=1e-15)
    # the same spring and dashpot as the paper's law given that zeta for that ball (exact
    # solver; the general integrator's default COR tolerance 1e-6)
    paper = fr.simulate(MODEL, kcb=3e4, zeta=zeta, ball_mass=0.1)
    assert run.cor == pytest.approx(paper.cor, abs=1e-6)
    assert paper.settings()["ccb_n_s_m"] == pytest.approx(used["ccb_n_s_m"], rel=1e-12)


def test_the_bed_ball_by_name_reports_as_the_default_bed_ball():
    bed = fr.StringBed()
    named = fr.simulate(MODEL, strings=bed, law="kawazoe-1997-ball", ball_mass=0.058)
    default = fr.simulate(MODEL, strings=bed, ball_mass=0.058)
    assert named.cor == default.cor
    assert named.summary()["zeta"] == default.summary()["zeta"] < KAWAZOE_BALL.zeta


def test_a_dashpot_damping_the_ball_critically_is_refused_naming_both_masses():
    line = library_error(
        lambda: ImpactProblem.build(MODEL, law=fr.LinearContact(3e4, 0.9), ball_mass=0.01)
    )
    assert line.startswith("ball mass = 0.01 kg is not allowed with contact law 'linear'")
    assert "zeta = 2.149" in line and "ball_mass 0.057 kg" in line


# -- L5: numbers as text or bools -----------------------------------------------------------------


@pytest.mark.parametrize(
    ("key", "value", "start"),
    [
        ("speed", "20", "speed = '20' m/s"),
        ("position", "0.7", "position = '0.7' x/L"),
        ("ball_mass", "0.057", "ball mass = '0.057' kg"),
        ("kcb", "3e4", "kcb = '3e4' N/m"),
        ("zeta", "0.1", "zeta = '0.1'"),
        ("offset", "0.0", "offset = '0.0' m"),
        ("speed", True, "speed = True m/s"),
        ("position", True, "position = True x/L"),
        ("ball_mass", True, "ball mass = True kg"),
        ("kcb", True, "kcb = True N/m"),
        ("zeta", False, "zeta = False"),
        ("offset", False, "offset = False m"),
    ],
)
def test_a_number_given_as_text_or_bool_is_refused(key, value, start):
    line = library_error(lambda: ImpactProblem.build(MODEL, **{key: value}))
    assert line == f"{start} is not allowed: must be a finite number"


def test_the_finite_check_refuses_text_bytes_and_bools():
    for value in ("20", b"20", True, "nan"):
        with pytest.raises(InputError, match="must be a finite number"):
            check_finite("speed", value, "m/s")
    assert check_finite("speed", 20) == 20.0
