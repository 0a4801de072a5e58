"""Where ``customise`` and ``compare`` write, and how they replace (audit A2).

``customise`` puts its maps beside ``--out`` (``a/x.vtu`` -> ``a/x_map.png``) unless ``--maps``
names them, from the command line and from a run file's method alike; the mesh, its sidecar and
the maps are one set (all or none), as are compare's files. At their default locations both
replace their own earlier output (recognised by its provenance) and refuse anything else,
naming the option that gave the path refused.
"""

from __future__ import annotations

import errno
import os
from pathlib import Path

import pytest
from clirun import one_error, run, run_ok

from fem_racket import load_config
from fem_racket.validation import InputError

CUSTOMISE = ("customise", "--swing-weight", "320", "--places", "12", "--elements", "6")
COMPARE = ("compare", "standard", "rigid", "--positions", "0.5:1:5", "--elements", "6")
RUN = '[frame]\nelements = 6\n[customise]\nswing_weight = 320\nplaces = "12"\n'


def _files(folder: Path = Path()) -> list[str]:
    return sorted(str(p) for p in folder.rglob("*") if p.is_file() and p.name != "run.toml")


def test_the_maps_go_beside_out_and_a_second_out_is_not_refused(cwd, capsys):
    text = run_ok(capsys, *CUSTOMISE, "--out", "a/x.vtu")
    assert text.endswith("wrote a/x.vtu\nwrote a/x.vtu.json\nwrote a/x_map.png\n")
    run_ok(capsys, *CUSTOMISE, "--out", "b/y.vtu")  # was refused: output/customised_map.png
    assert _files() == [
        "a/x.vtu", "a/x.vtu.json", "a/x_map.png", "b/y.vtu", "b/y.vtu.json", "b/y_map.png",
    ]  # fmt: skip
    # the derived path refused names the option that gave it, --out; a named one --maps
    os.remove("b/y.vtu")
    os.remove("b/y.vtu.json")
    line = one_error(capsys, *CUSTOMISE, "--out", "b/y.vtu")
    assert line.endswith("error: out = 'b/y_map.png' is not allowed: it already exists: pass "
                         "--overwrite to replace it")  # fmt: skip
    line = one_error(capsys, *CUSTOMISE, "--out", "c.vtu", "--maps", "a/x_map.png")
    assert "error: maps = 'a/x_map.png' is not allowed: it already exists" in line
    line = one_error(capsys, *CUSTOMISE, "--out", "c.vtu", "--maps", "c.txt")
    assert "error: maps = 'c.txt' is not allowed: must end in .nc, .csv, .png" in line
    assert not Path("output").exists() and not Path("c.vtu").exists()


def test_the_run_files_method_puts_the_maps_beside_its_out_as_the_command(cwd, capsys):
    Path("run.toml").write_text(RUN)
    load_config("run.toml").customise("sub/x.vtu")  # wrote the maps into ./output/ before
    assert _files() == ["sub/x.vtu", "sub/x.vtu.json", "sub/x_map.png"]
    run_ok(capsys, "customise", "--config", "run.toml", "--out", "cli/x.vtu")
    assert Path("cli/x_map.png").is_file()
    os.remove("sub/x.vtu")
    os.remove("sub/x.vtu.json")
    with pytest.raises(InputError, match=r"^out = 'sub/x_map\.png' is not allowed: it already"):
        load_config("run.toml").customise("sub/x.vtu")


@pytest.mark.parametrize("command", ["customise", "compare"])
def test_the_default_output_is_replaced_and_a_foreign_one_refused(cwd, capsys, command):
    argv = CUSTOMISE if command == "customise" else COMPARE
    default = (
        ["output/customised.vtu", "output/customised.vtu.json", "output/customised_map.png"]
        if command == "customise"
        else ["output/compare.png"]
    )
    run_ok(capsys, *argv)
    assert _files() == default
    first = Path(default[-1]).stat().st_mtime_ns
    text = run_ok(capsys, *argv)  # its own earlier output: replaced (was refused)
    assert text.endswith("".join(f"wrote {p}\n" for p in default))
    assert Path(default[-1]).stat().st_mtime_ns >= first and _files() == default
    Path(default[-1]).write_text("not ours")  # something fem-racket did not write
    line = one_error(capsys, *argv)
    assert "is not allowed: it already exists: pass --overwrite to replace it" in line
    assert Path(default[-1]).read_text() == "not ours"
    run_ok(capsys, *argv, "--overwrite")
    # a path named elsewhere: never replaced without --overwrite
    named = ["--out", "mine.vtu"] if command == "customise" else ["--out", "mine.png"]
    run_ok(capsys, *argv, *named)
    assert "it already exists" in one_error(capsys, *argv, *named)


@pytest.mark.parametrize("command", ["customise", "compare"])
def test_the_run_files_method_replaces_the_default_as_the_command(cwd, capsys, command):
    Path("run.toml").write_text(RUN)
    if command == "customise":
        argv, out = ("customise", "--config", "run.toml"), "output/customised.vtu"

        def method(out):
            return load_config("run.toml").customise(out)
    else:
        argv = ("compare", "standard", "rigid", "--config", "run.toml", "--positions", "0.5:1:5")
        out = "output/compare.png"
        Path("run.toml").write_text('[frame]\nelements = 6\n[compare]\npositions = "0.5:1:5"\n')

        def method(out):
            return load_config("run.toml").compare(["standard", "rigid"], out)

    run_ok(capsys, *argv)
    method(out)  # the command's own output at its default: replaced (was refused)
    run_ok(capsys, *argv)  # and the command replaces the method's
    foreign = Path("output/customised_map.png" if command == "customise" else out)
    foreign.write_text("not ours")
    line = one_error(capsys, *argv).split(": error: ", 1)[1]
    with pytest.raises(InputError) as exc:
        method(out)
    assert str(exc.value) == line and foreign.read_text() == "not ours"


def _no_space(*_args, **_kwargs):
    raise OSError(errno.ENOSPC, os.strerror(errno.ENOSPC))


def test_customise_writes_mesh_sidecar_and_maps_as_one_set(cwd, capsys, monkeypatch):
    # a fault while writing the maps: no mesh, no sidecar (the mesh was left before)
    monkeypatch.setattr("fem_racket.io.map_files.save_map_png", _no_space)
    code, _, err = run(capsys, *CUSTOMISE, "--out", "a/x.vtu")
    assert code == 1 and "No space left on device" in err, err
    assert _files() == [] and not Path("a").exists()


def test_compare_writes_its_files_as_one_set(cwd, capsys, monkeypatch):
    # a fault while writing the netCDF: no figure either (the figure was left before)
    monkeypatch.setattr("fem_racket.io.compare_files._dataset", _no_space)
    code, _, err = run(capsys, *COMPARE, "--out", "c.png", "c.nc")
    assert code == 1 and "No space left on device" in err, err
    assert _files() == []
    # one path named twice: refused before the work (the second write was refused after it)
    line = one_error(capsys, *COMPARE, "--out", "c.png", "c.png")
    assert "out = 'c.png' is not allowed: the same path is given for two outputs" in line
