"""``[output] overwrite = true`` where a command writes nothing is refused, as ``--overwrite``
without an output is on the command line (it was skipped: silently ignored), in one line naming
the key and the file, by the command (exit 2, no traceback) and by the run file's Python method
alike; where the command writes, it is used; a command table's ``overwrite = false`` wins, as
on the command line; ``config --example`` (its keys at their defaults) runs as is."""

from __future__ import annotations

import re
from pathlib import Path

import pytest
from clirun import file_refused_alike, one_error, run_json, run_ok

from fem_racket import load_config
from fem_racket.validation import InputError

SHARED = "[output]\noverwrite = true\n"
UNWRITTEN = "is not allowed without out: it sets the histories or files written, and none are"
#: A cheap refine (its files written by default; none with --no-files).
REFINE = ("refine", "--elements", "5,10", "--positions", "0.7", "--count", "2", "--quiet")


@pytest.mark.parametrize(
    ("text", "key"),
    [(SHARED, "output.overwrite"), ("[simulate]\noverwrite = true\n", "simulate.overwrite")],
)
def test_simulate_refuses_overwrite_without_an_output(cwd, capsys, text, key):
    words = f"{key} = True (run.toml) {UNWRITTEN}"
    argv = ["simulate", "--config", "run.toml"]
    file_refused_alike(capsys, text, argv, lambda cfg: cfg.simulate(), words, start=True)
    line = one_error(capsys, "config", "--check", "run.toml")
    assert f"fem-racket simulate would refuse it: {words}" in line
    # the command line's words, where the option is given there
    line = one_error(capsys, "simulate", "--overwrite")
    assert "--overwrite is not allowed without --out: it sets the histories or files" in line


@pytest.mark.parametrize(
    ("argv", "why"),
    [
        (("map", "--positions", "0.6,0.8", "--no-files"),
         "is not allowed without files: --no-files or --json without --out writes none"),
        ((*REFINE, "--no-files"),
         "is not allowed without a file to write (--csv, --plot): nothing is written"),
        (("calibrate", "--family", "hunt-crossley"),
         "is not allowed without --out: nothing is written"),
    ],
)  # fmt: skip
def test_every_command_writing_nothing_refuses_it_as_the_option(cwd, capsys, argv, why):
    Path("run.toml").write_text(SHARED)
    line = one_error(capsys, *argv, "--config", "run.toml")
    assert line.endswith(f": error: output.overwrite = True (run.toml) {why}"), line
    assert f"--overwrite {why}" in one_error(capsys, *argv, "--overwrite")
    assert sorted(p.name for p in Path().iterdir()) == ["run.toml"]  # nothing written


def test_the_calibrate_method_refuses_it_as_the_command(cwd, capsys):
    Path("run.toml").write_text(SHARED + '[calibrate]\nfamily = "hunt-crossley"\n')
    words = "output.overwrite = True (run.toml) is not allowed without out: nothing is written"
    with pytest.raises(InputError, match=f"^{re.escape(words)}$"):
        load_config("run.toml").calibrate()


def test_where_the_command_writes_it_is_used(cwd, capsys):
    Path("run.toml").write_text(SHARED + '[simulate]\nout = "impact.json"\n')
    Path("impact.json").write_text("{}")  # replaced: the key is used
    cor = run_json(capsys, "simulate", "--config", "run.toml")["cor"]
    assert load_config("run.toml").simulate().cor == pytest.approx(cor, rel=1e-12)
    assert Path("impact.json").read_text() != "{}"
    run_ok(capsys, *REFINE, "--config", "run.toml")  # refine writes its own files
    assert Path("output/refine.csv").exists()


def test_a_command_tables_false_wins_as_on_the_command_line(cwd, capsys):
    Path("run.toml").write_text(SHARED + "[simulate]\noverwrite = false\n")
    cor = run_json(capsys, "simulate", "--config", "run.toml")["cor"]
    assert load_config("run.toml").simulate().cor == pytest.approx(cor, rel=1e-12)


def test_the_example_runs_as_is(cwd, capsys):
    Path("run.toml").write_text(run_ok(capsys, "config", "--example"))
    assert "overwrite = false" in Path("run.toml").read_text()
    cor = run_json(capsys, "simulate", "--config", "run.toml")["cor"]
    assert load_config("run.toml").simulate().cor == pytest.approx(cor, rel=1e-12)
