"""The run file's methods replace and refuse existing outputs as their commands do (issue 21.7):
``export_vtk``, ``animate`` and ``optimize`` replace their command's own earlier output at its
default location (``output/impact_vtk``, ``output/impact.gif``, ``output/design``) without
``overwrite``, refuse anything else there or elsewhere with the command's one line, before the
work; ``[output] overwrite`` replaces as the command's ``--overwrite`` (also for
``sensitivity``). ``fit``: ``tests/io/test_runfile_fit.py``."""

from __future__ import annotations

from pathlib import Path

import pytest
from clirun import run
from test_config_design import DESIGN as STUDY

from fem_racket import load_config
from fem_racket.validation import InputError

FRAME = "[frame]\nelements = 6\n"
VTK = FRAME + "[vtk]\nframes = 3\n"
GIF = FRAME + '[animate]\nframes = 2\nsize = "160x160"\n'
#: A design study with the cheapest budget (tests/io/test_config_design.py's).
DESIGN = STUDY.format(table="design", extra="maxiter = 2")
#: command -> (run file, the method, its default output, the output's files to compare).
CASES = {
    "export-vtk": (VTK, "export_vtk", "output/impact_vtk", ("impact.pvd", "frame_0001.vtu")),
    "animate": (GIF, "animate", "output/impact.gif", ("",)),
    "optimize": (DESIGN, "optimize", "output/design", ("optimum.vtu",)),
}


def _needs(command: str) -> None:
    if command in ("export-vtk", "animate"):
        pytest.importorskip("pyvista")
    if command == "animate":
        pytest.importorskip("imageio")


def _cli(capsys, command: str, *argv) -> tuple[int, str]:
    code, _, err = run(capsys, command, "--config", "run.toml", *argv, "--quiet")
    return code, err


def _bytes(out: str, names) -> list[bytes]:
    return [Path(out, name).read_bytes() if name else Path(out).read_bytes() for name in names]


def _call(method: str, out=None):
    return getattr(load_config("run.toml"), method)(out)


@pytest.mark.parametrize("command", sorted(CASES))
def test_the_default_output_is_replaced_as_the_command_replaces_it(cwd, capsys, command):
    _needs(command)
    text, method, default, names = CASES[command]
    Path("run.toml").write_text(text)
    assert _cli(capsys, command) == (0, "")
    theirs = _bytes(default, names)
    _call(method)  # the command's own output at its default: replaced
    assert _bytes(default, names) == theirs  # by the same drawing / design
    assert _cli(capsys, command) == (0, "")  # and the command replaces the method's
    _call(method, default)  # the default named: the same
    assert _bytes(default, names) == theirs


def _snapshot(folder: Path) -> dict:
    return {p: p.read_bytes() for p in folder.rglob("*") if p.is_file() and p.name != "run.toml"}


@pytest.mark.parametrize("command", sorted(CASES))
@pytest.mark.parametrize("where", ["elsewhere", "foreign default"])
def test_what_the_command_refuses_the_method_refuses_alike(cwd, capsys, command, where):
    _needs(command)
    text, method, default, _ = CASES[command]
    Path("run.toml").write_text(text)
    if where == "elsewhere":  # an earlier output, at a path named: never replaced
        out = "mine.gif" if command == "animate" else "mine"
        assert _cli(capsys, command, "--out", out) == (0, "")
    else:  # at the default, something fem-racket did not write
        out = default
        target = Path(default) if command == "animate" else Path(default, "notes.txt")
        target.parent.mkdir(parents=True)
        target.write_text("not ours")
    before = _snapshot(cwd)
    code, err = _cli(capsys, command, "--out", out)
    assert code == 2 and err.count("\n") == 1 and "is not allowed" in err, err
    line = err.split(": error: ", 1)[1].rstrip("\n")
    with pytest.raises(InputError) as exc:
        _call(method, out)
    assert str(exc.value) == line
    table = {"export-vtk": "vtk", "optimize": "design"}.get(command, command)
    Path("run.toml").write_text(text.replace(f"[{table}]\n", f'[{table}]\nout = "{out}"\n'))
    with pytest.raises(InputError) as exc:
        _call(method)  # the table's out: the same
    assert str(exc.value) == line
    assert _snapshot(cwd) == before  # nothing written


@pytest.mark.parametrize("command", sorted(CASES))
def test_output_overwrite_replaces_as_the_command_does(cwd, capsys, command):
    _needs(command)
    text, method, _, names = CASES[command]
    out = "mine.gif" if command == "animate" else "mine"
    Path("run.toml").write_text(text)
    assert _cli(capsys, command, "--out", out) == (0, "")
    theirs = _bytes(out, names)
    Path("run.toml").write_text("[output]\noverwrite = true\n" + text)
    assert _cli(capsys, command, "--out", out) == (0, "")  # the command replaces it
    _call(method, out)  # and so does the method
    assert _bytes(out, names) == theirs


def test_sensitivity_takes_output_overwrite(cwd, capsys):
    pytest.importorskip("SALib")
    text = STUDY.format(table="sensitivity", extra="designs = 16\nseed = 3")
    # no mass_range: a sensitivity analysis applies no constraint (refused, it was ignored)
    text = text.replace("link_ei = true\n", "").replace('mass_range = "start"\n', "")
    Path("run.toml").write_text(text)
    assert _cli(capsys, "sensitivity", "--out", "s.png") == (0, "")
    code, err = _cli(capsys, "sensitivity", "--out", "s.png")
    line = err.split(": error: ", 1)[1].rstrip("\n")
    assert code == 2 and line.startswith("out = 's.png' is not allowed: it already exists")
    with pytest.raises(InputError) as exc:
        load_config("run.toml").sensitivity("s.png")
    assert str(exc.value) == line
    Path("run.toml").write_text("[output]\noverwrite = true\n" + text)
    assert _cli(capsys, "sensitivity", "--out", "s.png") == (0, "")
    load_config("run.toml").sensitivity("s.png")  # replaced, as the command replaces it
