"""Run files refuse what the command line refuses (issue 21.3): ``[simulate] output_step`` with
no output (as ``--output-step`` without ``--out``), a swing's reference point without a swing
for ``customise`` under ``config --check`` (its check ran after the work began), and a sweep's
solver key the law cannot use."""

from pathlib import Path

import pytest

from fem_racket import load_config
from fem_racket.validation import InputError
from tests.clirun import one_error, refused_alike, run


def _file(text: str) -> Path:
    path = Path("run.toml")
    path.write_text(text)
    return path


def test_an_output_step_without_output_is_refused_naming_the_key(capsys, cwd):
    path = _file("[simulate]\noutput_step = 2e-5\n")
    words = (
        "simulate.output_step = 2e-05 (run.toml) is not allowed without out: it sets the "
        "histories or files written, and none are"
    )
    refused_alike(capsys, ["simulate", "--config", path], load_config(path).simulate, words)
    line = one_error(capsys, "config", "--check", path)
    assert words in line
    # used: with an output, or histories asked of the Python method; a key at its default
    assert load_config(path).simulate(histories=True).t.size > 2
    _file("[simulate]\noutput_step = 2e-5\n[output]\nout = 'r.json'\n")
    assert run(capsys, "simulate", "--config", path)[0] == 0 and Path("r.json").exists()
    _file("[simulate]\noutput_step = 1e-5\n")
    assert run(capsys, "simulate", "--config", path)[0] == 0
    assert load_config(path).simulate().cor > 0


def test_customise_checks_the_swing_before_its_work(capsys, cwd):
    path = _file("[impact]\nreference_x_over_l = 0.7\n[customise]\nswing_weight = 330\n")
    line = one_error(capsys, "config", "--check", path)
    assert (
        "fem-racket customise would refuse it: impact.reference_x_over_l = 0.7 x/L is not allowed"
        in line
    )
    with pytest.raises(
        InputError,
        match=f"^{path}: impact.reference_x_over_l = 0.7 x/L is not allowed without a swing",
    ):
        load_config(path).customise("c.vtu")
    assert not Path("c.vtu").exists()


@pytest.mark.parametrize(
    ("text", "words"),
    [
        (
            '[contact]\nlaw = "hunt-crossley"\n[solver]\nseparation = "force"\n',
            "separation = 'force' is not allowed with contact law 'hunt-crossley'",
        ),
        (
            '[contact]\nlaw = "hunt-crossley"\n[solver]\nname = "cvode"\nbasis = "physical"\n',
            "basis = 'physical' is not allowed with solver 'cvode' under a contact law",
        ),
    ],
)
def test_a_sweep_file_refuses_what_the_law_cannot_use(capsys, cwd, text, words):
    path = _file(text + "[sweep]\nspeed = [20.0]\nposition = [0.7]\nout = 's.nc'\n")
    argv = ["sweep", "--config", path, "--serial", "--quiet"]
    refused_alike(capsys, argv, lambda: load_config(path).sweep(backend="serial"), words)
