"""An option that takes a value, given twice with two values, is refused (argparse keeps the last
and drops the first silently); the same value twice, options that collect (``map --mesh``) and
flags pass (issue 21.3: no option silently ignored)."""

from __future__ import annotations

import pytest

from fem_racket.cli import main
from tests.clirun import refused_before_any_file

MESHES = "meshes/standard_racket.vtu", "meshes/tapered_racket.vtu"


@pytest.mark.parametrize(
    ("argv", "says"),
    [
        (["simulate", "--speed", "10", "--speed", "30"], "--speed is given twice (10.0 and 30.0)"),
        (["sweep", "--speed", "10", "--speeds", "30"], "--speed is given twice ('10' and '30')"),
        (
            ["simulate", "--law", "hunt-crossley", "--law", "series"],
            "--law is given twice ('hunt-crossley' and 'series')",
        ),
        (
            ["map", "--positions", "0.5:1:5", "--positions", "0.6:1:5", "--no-files"],
            "--positions is given twice ('0.5:1:5' and '0.6:1:5')",
        ),
    ],
)
def test_a_value_given_twice_is_refused(capsys, cwd, argv, says):
    line = refused_before_any_file(capsys, *argv)
    assert says in line and "the last would replace the first" in line, line


def test_the_same_value_twice_and_collecting_options_pass(capsys, request):
    root = request.config.rootpath
    assert main(["simulate", "--speed", "20", "--speed", "20", "--json"]) == 0
    argv = ["map", "--no-files", "--json", "--positions", "0.6:0.9:3"]
    argv += [x for m in MESHES for x in ("--mesh", str(root / m))]
    assert main(argv) == 0, capsys.readouterr().err  # map overlays its rackets
