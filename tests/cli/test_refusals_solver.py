"""Options the chosen solver or law cannot use are refused, not ignored (issue 21, D3 and D4:
studies ask the solver): a sweep refuses them with the very line simulate gives, because both
make the solver with the options given and ask it (``Solver.takes``, ``Solver.check``).

Every case: exit code 2, one line on stderr naming the option, its value and what is allowed,
no traceback, no file written (as ``tests/cli/test_bad_input.py``).
"""

from __future__ import annotations

import pytest

from fem_racket.cli import main
from tests.clirun import one_error, refused_before_any_file


def _message(capsys, *argv: str) -> str:
    """The refusal's message (after ``fem-racket COMMAND: error:``)."""
    return one_error(capsys, *argv).split(": error: ", 1)[1]


def _sweep(*argv: str) -> list[str]:
    return ["sweep", "--serial", "--quiet", "--speed", "20,30", *argv]


# (options, what the line must say); simulate and sweep must give the same line
SAME_LINE = [
    (["--solver", "exact", "--rtol", "1e-3"], "rtol = 0.001 is not allowed with solver 'exact'"),
    (
        ["--solver", "cvode", "--tolerance", "0.1"],
        "tolerance = 0.1 is not allowed with solver 'cvode'",
    ),
    (["--solver", "bdf", "--tolerance", "0.1"], "tolerance = 0.1 is not allowed with solver 'bdf'"),
    (
        ["--law", "hunt-crossley", "--separation", "force"],
        "separation = 'force' is not allowed with contact law 'hunt-crossley'",
    ),
    (
        ["--law", "hunt-crossley", "--solver", "cvode", "--modes", "10"],
        "modes = 10 is not allowed with solver 'cvode' under a contact law",
    ),
    (
        ["--solver", "bdf", "--basis", "physical", "--modes", "10"],
        "modes = 10 is not allowed with solver 'bdf' with basis 'physical'",
    ),
    (
        ["--solver", "cvode", "--basis", "physical", "--modes", "10"],
        "modes = 10 is not allowed with solver 'cvode' with basis 'physical'",
    ),
    (
        ["--solver", "exact", "--basis", "physical"],
        "basis = 'physical' is not allowed with solver 'exact'",
    ),
]


@pytest.mark.parametrize(("options", "says"), SAME_LINE, ids=[" ".join(c[0]) for c in SAME_LINE])
def test_sweep_refuses_what_simulate_refuses_with_its_line(
    capsys, tmp_path, monkeypatch, options, says
):
    monkeypatch.chdir(tmp_path)
    line = _message(capsys, *["simulate", *options, "--out", "r.json"])
    assert says in line
    assert _message(capsys, *_sweep(*options)) == line
    assert not any(tmp_path.iterdir()), "a file was written"


@pytest.mark.parametrize(
    ("argv", "says"),
    [
        (["--position", "0.5:0.9:1"], "position = '0.5:0.9:1' is not allowed: num 1 needs start"),
        (["--out", "s.txt"], "output = 's.txt' is not allowed: must end in .nc (netCDF) or .csv"),
    ],
)
def test_sweep_refuses_a_dropped_value(capsys, cwd, argv, says):
    assert says in refused_before_any_file(capsys, *_sweep(*argv))


def test_a_tolerance_with_histories_is_used_not_ignored(capsys, tmp_path, monkeypatch):
    """simulate --tolerance with --out: the file's COR is the one without histories (it used
    to be the every-mode COR, the tolerance recorded but ignored)."""
    import json

    monkeypatch.chdir(tmp_path)
    assert main(["simulate", "--tolerance", "0.1", "--out", "t.json"]) == 0
    assert main(["simulate", "--tolerance", "0.1", "--json"]) == 0
    out = capsys.readouterr().out
    printed = json.loads(out[out.index("{") :])
    written = json.loads((tmp_path / "t.json").read_text())
    assert written["summary"]["cor"] == printed["cor"] == 0.3765647691247458


def test_a_run_files_serial_and_workers_are_refused_not_one_dropped(capsys, tmp_path, monkeypatch):
    """``serial = true`` and ``workers = 2`` in one ``[sweep]`` table: the workers were dropped
    (serial won); now refused, by the command and by ``load_config(f).sweep()`` alike."""
    from fem_racket import load_config
    from fem_racket.validation import InputError

    monkeypatch.chdir(tmp_path)
    (tmp_path / "run.toml").write_text(
        '[sweep]\nposition = "0.6,0.7"\nserial = true\nworkers = 2\n'
    )
    line = _message(capsys, *["sweep", "--config", "run.toml", "--out", "s.nc", "--quiet"])
    assert (
        line == "workers = 2 is not allowed with backend 'serial': it is the 'processes' backend's"
    )
    with pytest.raises(InputError) as err:
        load_config("run.toml").sweep()
    assert str(err.value) == line
    assert sorted(p.name for p in tmp_path.iterdir()) == ["run.toml"]


# A grid value simulate refuses at once (the option's own bound, or the K_CB range its closing or
# normal speed leaves) is refused by the sweep before any case runs, named as the option: it was
# refused mid-sweep as the speed it derives ("speed = 1000020.0 m/s"), after solving a case and
# leaving a checkpoint that a rerun could never complete, or accepted (string tension 1e9 N).
GRID_VALUES = [
    (["--string-tension", "1e9"], "string_tension = 1000000000.0 N is not allowed"),
    (["--racket-speed", "0,1e6"], "racket_speed = 1000000.0 m/s is not allowed: must lie in"),
    (
        ["--racket-speed", "0,90"],
        "racket_speed = 90.0 m/s is not allowed with speed = 30.0 m/s: the closing speed",
    ),
    (["--angle", "0,89.999"], "angle = 89.999 deg is not allowed with speed = 20.0 m/s"),
    (["--side-angle", "89.99"], "side_angle = 89.99 deg is not allowed with speed = 20.0 m/s"),
]


@pytest.mark.parametrize(("options", "says"), GRID_VALUES, ids=[c[0][0] for c in GRID_VALUES])
def test_a_grid_value_is_refused_before_any_case_runs(capsys, cwd, options, says):
    line = refused_before_any_file(capsys, *_sweep(*options, "--out", "s.nc"))  # no checkpoint
    assert says in line, line


def test_the_grid_checks_let_a_law_or_kcb_take_what_the_paper_k_cb_cannot(capsys, tmp_path):
    # K_CB from the closing speed bounds it only under the paper's law without kcb
    for options in (["--kcb", "30000"], ["--law", "hunt-crossley"]):
        argv = _sweep("--racket-speed", "0,90", *options, "--out", str(tmp_path / "s.nc"))
        assert main(argv) == 0, capsys.readouterr().err
        (tmp_path / "s.nc").unlink()
