"""The paper's linear law given with a string bed is refused, as kcb and zeta are: its K_CB is
the ball and strings together, which the bed replaces (the ball's own law then acts on the bed,
the ``kawazoe-1997-ball`` unless another law is given). Not given (the default, or a run file's
``contact.law`` at its default), the strung run is unchanged."""

import pytest

from fem_racket.impact.problem import ImpactProblem
from fem_racket.impact.simulate import simulate
from fem_racket.strings.bed import StringBed
from tests.clirun import library_error, one_error, run_json

WORDS = (
    "law = 'linear' is not allowed with a string bed: the bed replaces the lumped K_CB "
    "(give the ball's own law as law)"
)
BED = ("--string-tension", "250")


@pytest.mark.parametrize("extra", [(), ("--angle", "20")])
def test_linear_law_given_with_a_bed_is_refused(capsys, extra):
    line = one_error(capsys, "simulate", *BED, "--law", "linear", *extra)
    assert line.endswith(WORDS), line


def test_linear_law_in_the_library_with_a_bed_is_refused(standard_model):
    bed = StringBed(tension_n=250.0)
    line = library_error(lambda: simulate(standard_model, strings=bed, law="linear"))
    assert line == WORDS
    line = library_error(lambda: ImpactProblem.build(standard_model, strings=bed, law="linear"))
    assert line == WORDS


def test_linear_law_not_given_runs_unchanged(capsys, tmp_path):
    default = run_json(capsys, "simulate", *BED)
    assert default["ball_law"] == "kawazoe-1997-ball"
    cfg = tmp_path / "run.toml"
    cfg.write_text('[contact]\nlaw = "linear"\n')  # at its default: not given
    assert run_json(capsys, "simulate", *BED, "--config", cfg) == default
    ball = run_json(capsys, "simulate", *BED, "--law", "kawazoe-1997-ball")
    assert ball["cor"] == default["cor"] and ball["ball_law"] == "kawazoe-1997-ball"


def test_linear_law_given_to_a_strung_sweep_is_refused(capsys, tmp_path):
    out = tmp_path / "s.nc"
    sweep = ("sweep", "--string-tension", "246", "--position", "0.6", "--serial", "--out", out)
    line = one_error(capsys, *sweep, "--law", "linear")
    assert line.endswith(WORDS), line
    assert not out.exists()


def test_linear_law_in_a_library_sweep_with_a_bed_is_refused():
    from fem_racket.studies.sweep import sweep_result

    line = library_error(lambda: sweep_result(position=[0.6], law="linear", string_tension=246.0))
    assert line == WORDS


def test_strung_sweep_without_a_law_and_linear_sweep_without_a_bed_run(tmp_path):
    from fem_racket.studies.sweep import sweep_result

    strung = sweep_result(position=[0.6], string_tension=246.0).summary()
    paper = sweep_result(position=[0.6], law="linear").summary()
    assert strung["contact_law"] == "linear" and paper["contact_law"] == "linear"
    assert strung["cor_min"] != paper["cor_min"]  # the bed and the ball's own law, not K_CB
