"""``load_config(f).fit(out)`` replaces and refuses outputs as ``fem-racket fit --config f``
does (issue 21.7): the command's default ``output/racket.vtu`` is replaced when what is there is
an earlier fit's (its sidecar holds fem_racket's provenance), without ``--overwrite``; any other
existing file (another path, a file fem-racket did not write, a stray sidecar) is refused unless
the file says ``overwrite``, with the same one line, and nothing is written."""

from __future__ import annotations

import json
from pathlib import Path

import pytest
from clirun import run

from fem_racket import load_config
from fem_racket.validation import InputError

RUN = "[fit]\nlength = 0.685\nmass = 0.318\nbalance = 0.32\nswing_weight = 316\nelements = 12\n"
DEFAULT = Path("output") / "racket.vtu"
SIDECAR = Path("output") / "racket.vtu.json"


def _summary(path: Path) -> dict:
    """A sidecar less its provenance (when and how the file was made)."""
    data = json.loads(Path(f"{path}.json").read_text())
    return {k: data[k] for k in ("target", "fitted", "segments", "mesh")}


def _cli(capsys, *argv) -> tuple[int, str]:
    code, _, err = run(capsys, "fit", "--config", "run.toml", *argv, "--json")
    return code, err


def test_the_default_output_is_replaced_as_the_command_replaces_it(cwd, capsys):
    Path("run.toml").write_text(RUN)
    assert _cli(capsys) == (0, "")  # the command's default: output/racket.vtu
    mesh, summary = DEFAULT.read_bytes(), _summary(DEFAULT)
    frame = load_config("run.toml").fit(out=DEFAULT)  # replaces the command's own fit
    assert DEFAULT.read_bytes() == mesh and _summary(DEFAULT) == summary
    assert len(frame.segments) == 3
    assert _cli(capsys) == (0, "")  # and the command replaces the method's
    Path("run.toml").write_text(RUN + 'out = "output/racket.vtu"\n')
    load_config("run.toml").fit()  # [fit] out at the default: the same
    assert DEFAULT.read_bytes() == mesh and _summary(DEFAULT) == summary
    assert sorted(p.name for p in Path("output").iterdir()) == ["racket.vtu", "racket.vtu.json"]


def _files(folder: Path) -> dict:
    """Every file under ``folder`` but the run file, with its bytes."""
    return {p: p.read_bytes() for p in folder.rglob("*") if p.is_file() and p.name != "run.toml"}


def _foreign_mesh():
    Path("output").mkdir()
    DEFAULT.write_text("not ours")


def _foreign_sidecar():
    _foreign_mesh()
    SIDECAR.write_text('{"software": "another"}')


def _stray_sidecar():
    Path("output").mkdir()
    SIDECAR.write_text("{}")


def _earlier_fit_elsewhere(capsys, where: Path):
    Path("run.toml").write_text(RUN)
    assert _cli(capsys, "--out", where) == (0, "")


@pytest.mark.parametrize(
    ("setup", "out", "refused"),
    [
        ("earlier fit elsewhere", "mine.vtu", "mine.vtu"),  # a path named: never replaced
        ("earlier fit at default, named absolute", "ABS", "ABS"),  # not the default's spelling
        ("mesh not ours", str(DEFAULT), str(DEFAULT)),  # no sidecar: not an earlier fit
        ("sidecar not ours", str(DEFAULT), str(DEFAULT)),
        ("stray sidecar", str(DEFAULT), str(SIDECAR)),  # the mesh is new, its sidecar is not
    ],
)
def test_what_the_command_refuses_the_method_refuses_alike(cwd, capsys, setup, out, refused):
    if out == "ABS":
        out = refused = str(cwd / DEFAULT)
    if setup.startswith("earlier fit"):
        _earlier_fit_elsewhere(capsys, Path(out))
    else:
        {"mesh not ours": _foreign_mesh, "sidecar not ours": _foreign_sidecar,
         "stray sidecar": _stray_sidecar}[setup]()  # fmt: skip
    before = _files(cwd)
    Path("run.toml").write_text(RUN)
    code, err = _cli(capsys, "--out", out)
    line = f"out = '{refused}' is not allowed: it already exists: pass --overwrite to replace it"
    assert code == 2 and err == f"fem-racket fit: error: {line}\n"
    with pytest.raises(InputError) as exc:
        load_config("run.toml").fit(out=out)
    assert str(exc.value) == line
    Path("run.toml").write_text(RUN + f"out = {out!r}\n")
    with pytest.raises(InputError) as exc:
        load_config("run.toml").fit()  # [fit] out: the same
    assert str(exc.value) == line
    Path("run.toml").write_text(RUN)
    assert _files(cwd) == before  # nothing written


@pytest.mark.parametrize("key", ["fit", "output"])
def test_overwrite_in_the_file_replaces_as_the_command_does(cwd, capsys, key):
    _foreign_sidecar()
    text = RUN + "overwrite = true\n" if key == "fit" else "[output]\noverwrite = true\n" + RUN
    Path("run.toml").write_text(text)
    assert _cli(capsys, "--out", "cli.vtu") == (0, "")
    Path("mine.vtu").write_text("not ours")
    load_config("run.toml").fit(out="mine.vtu")  # another file replaced, as with --overwrite
    load_config("run.toml").fit(out=DEFAULT)
    for path in ("mine.vtu", DEFAULT):
        assert Path(path).read_bytes() == Path("cli.vtu").read_bytes()
        assert _summary(Path(path))["segments"] == _summary(Path("cli.vtu"))["segments"]


def test_the_default_is_the_commands():
    from fem_racket.cli.commands import fit
    from fem_racket.io.racket_files import FIT_OUTPUT

    assert FIT_OUTPUT == fit.DEFAULT_OUTPUT
