"""A mistyped option gets one line with the closest name and the command's own help; an old
spelling names what replaced it (a mistyped run-file table: tests/cli/test_bad_input.py)."""

import pytest

from tests.clirun import run


@pytest.mark.parametrize(
    ("argv", "line"),
    [
        (
            ["simulate", "--positon", "0.7"],
            "fem-racket simulate: error: unrecognized option --positon: did you mean --position? "
            "(see fem-racket simulate --help)",
        ),
        (
            ["sweep", "--sped=30"],
            "fem-racket sweep: error: unrecognized option --sped: did you mean --speed? "
            "(see fem-racket sweep --help)",
        ),
        (
            ["optimize", "--no-progress"],
            "fem-racket optimize: error: unrecognized option --no-progress: did you mean --quiet? "
            "(see fem-racket optimize --help)",
        ),
        (
            ["sensitivity", "--progress"],
            "fem-racket sensitivity: error: unrecognized option --progress: the progress bar "
            "shows by itself when stderr is a terminal; --quiet hides it "
            "(see fem-racket sensitivity --help)",
        ),
        (
            ["modes", "--zzzz"],
            "fem-racket modes: error: unrecognized option --zzzz (see fem-racket modes --help)",
        ),
        (
            ["modes", "7"],
            "fem-racket modes: error: unrecognized arguments: 7 (see fem-racket modes --help)",
        ),
    ],
)
def test_a_mistyped_option_is_refused_with_a_suggestion(capsys, argv, line):
    code, out, err = run(capsys, *argv)
    assert (code, out, err) == (2, "", line + "\n")


def test_calibrate_takes_a_run_file(capsys, tmp_path):
    path = tmp_path / "run.toml"
    path.write_text('[ball]\nmass_kg = 0.058\n[calibrate]\nfamily = "linear"\n')
    code, out, _ = run(capsys, "calibrate", "--config", path, "--json")
    assert code == 0 and '"family": "linear"' in out
    code, out, _ = run(capsys, "config", "--check", path)
    assert code == 0 and '[calibrate] ball_mass = 0.058, family = "linear"' in out
