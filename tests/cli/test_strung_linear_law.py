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
