"""``load_config(f).simulate()`` reads ``[simulate]`` as ``fem-racket simulate --config f`` reads
it (issue 21.7): its keys were not checked at all (an unknown key, ``overwrite = 2``, an output
``a.txt`` or a core table's option there were accepted), and ``output_step = "2e-5"``, which the
command takes, was refused when histories were computed. The method writes no file: the output's
name is checked (its suffix), not what is there."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
from clirun import file_refused_alike, run

from fem_racket import load_config

FRAME = "[frame]\nelements = 6\n"


@pytest.mark.parametrize(
    ("table", "words"),
    [
        ("[simulate]\noverwrite = 2\n", "simulate.overwrite = 2 is not allowed: must be true or"),
        ("[simulate]\njson = 2\n", "simulate.json = 2 is not allowed: must be true or false"),
        ("[simulate]\nout = true\n", "simulate.out = True is not allowed: must be a value like"),
        ('[simulate]\nout = "a.txt"\n', "out = 'a.txt' is not allowed: must end in .json or .csv"),
        ('[output]\nout = "a.txt"\n', "out = 'a.txt' is not allowed: must end in .json or .csv"),
        ("[simulate]\nquiet = true\n", "simulate.quiet is not a known key"),
        ("[simulate]\nspeed = 30\n", "simulate.speed is not allowed here: set impact.speed_m_s"),
        ("[simulate]\noutput_step = true\n", "simulate.output_step = True is not allowed: must"),
        ("[simulate]\noutput_step = -1\n", "output_step = -1"),
    ],
)
def test_refused_alike(cwd, capsys, table, words):
    argv = ("simulate", "--config", "run.toml")
    file_refused_alike(capsys, FRAME + table, argv, lambda c: c.simulate(), words)


def test_a_step_written_as_text_is_taken_as_the_command_takes_it(cwd, capsys):
    Path("run.toml").write_text(FRAME + '[simulate]\noutput_step = "2e-5"\nout = "o.json"\n')
    code, _, err = run(capsys, "simulate", "--config", "run.toml")
    assert code == 0, err
    result = load_config("run.toml").simulate()
    theirs = json.loads(Path("o.json").read_text())["history"]["time [s]"]
    np.testing.assert_allclose(result.t, theirs, rtol=1e-12, atol=0)
    assert result.t[1] == pytest.approx(2e-5, rel=1e-12)
