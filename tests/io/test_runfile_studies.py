"""``load_config(f).map()`` and ``.refine()`` read their tables as ``fem-racket map/refine
--config f`` read them (issue 21.7): ``[map] mesh`` (the command's list of mesh files, which the
method refused) maps those rackets; the keys that say where the command writes and how it prints
are the command's own (``[refine] format`` was refused, ``[refine] out`` and ``[map] quiet``
accepted) and are checked as the command checks them (bad values were accepted), though the
methods write nothing."""

from __future__ import annotations

from pathlib import Path

import pytest
from clirun import file_refused_alike, run_json
from runfile_helpers import py_json, same

from fem_racket import load_config
from fem_racket.io.config_run_keys import RUN_KEYS
from fem_racket.io.config_tables import flag, integer, number, text, texts

MESH = Path(__file__).resolve().parents[2] / "meshes" / "tapered_racket.vtu"
MAP = '[frame]\nelements = 6\n[map]\npositions = "0.6,0.7,0.8"\n'
REFINE = "[refine]\nelements = [4, 6]\ncount = 2\npositions = [0.7]\n"


@pytest.mark.parametrize("command", sorted(RUN_KEYS))
def test_the_run_keys_are_the_commands_options(command):
    from fem_racket.cli.commands.config import _commands
    from fem_racket.cli.options.runfile import file_options
    from fem_racket.io.config_studies import MAP_DEFAULTS, REFINE_DEFAULTS

    options = file_options(_commands()[{"vtk": "export-vtk"}.get(command, command)])
    computed = {"map": MAP_DEFAULTS, "refine": REFINE_DEFAULTS}.get(command)
    assert set(RUN_KEYS[command]) <= set(options)  # no key the command refuses
    if computed is not None:  # every key of the command's table is the method's too
        assert set(options) <= set(RUN_KEYS[command]) | set(computed)
    for key, conv in RUN_KEYS[command].items():  # converted as the parser converts it
        action = options[key]
        kind = {
            flag: action.nargs == 0,
            texts: action.nargs == "+",
            integer: action.type is int,
            number: action.type is float,
            text: action.type in (None, str, Path) and not action.nargs,
        }
        assert kind.get(conv, action.choices is not None), (command, key)


def test_map_maps_the_mesh_files_of_its_table(cwd, capsys):
    text = MAP.replace("[map]", '[[frame.lead]]\nplace = "12"\nmass_g = 3\n[map]')
    Path("run.toml").write_text(text + f'preset = ["rigid"]\nmesh = [{str(MESH)!r}]\n')
    maps = load_config("run.toml").map()
    cli = run_json(capsys, "map", "--config", "run.toml", "--no-files")
    assert [m.name for m in maps] == ["rigid", "tapered_racket"]  # presets first, as the command
    same(py_json({"rackets": [m.summary() for m in maps]}), cli)


@pytest.mark.parametrize(
    ("command", "keys", "words"),
    [
        ("map", "overwrite = 2\n", "map.overwrite = 2 is not allowed: must be true or false"),
        ("map", "json = 2\n", "map.json = 2 is not allowed: must be true or false"),
        ("map", "out = 3\n", "map.out = 3 is not allowed: must be an array"),
        ("map", 'out = ["a.txt"]\n', "output = 'a.txt' is not allowed: must end in .nc"),
        ("map", 'no_files = true\nout = ["a.nc"]\n', "no_files = True is not allowed with --out"),
        ("map", "quiet = true\n", "map.quiet is not a known key"),
        ("map", 'preset = "rigid"\n', "map.preset = 'rigid' is not allowed: must be an array"),
        (
            "map",
            'preset = ["stiff"]\n',
            "map.preset = 'stiff' is not allowed: must be one of rigid, standard",
        ),  # noqa: E501
        ("refine", 'format = "bmp"\n', "refine.format = 'bmp' is not allowed: must be one of png"),
        ("refine", "dpi = 10\n", "dpi = 10.0 is not allowed: must be a number in [50, 1200]"),
        ("refine", 'plot = "a.txt"\n', "output = 'a.txt' is not allowed: a figure file must end"),
        (
            "refine",
            'plot = "a.png"\nformat = "svg"\n',
            "format = 'svg' is not allowed with --plot 'a.png'",
        ),  # noqa: E501
        ("refine", "no_files = 2\n", "refine.no_files = 2 is not allowed: must be true or false"),
        ("refine", 'out = "x"\n', "refine.out is not a known key"),
        ("refine", "no_plot = true\n", "refine.no_plot is not a known key"),
    ],
)
def test_refused_alike(cwd, capsys, command, keys, words):
    text = (MAP if command == "map" else REFINE) + keys
    argv = (command, "--config", "run.toml", "--json")
    file_refused_alike(capsys, text, argv, lambda c: getattr(c, command)(), words)


def test_refine_takes_the_format_of_its_plot(cwd, capsys):
    # was refused; a csv to write (with no_files the format would be ignored: refused now)
    Path("run.toml").write_text(REFINE + 'format = "svg"\ncsv = "r.csv"\n')
    cli = run_json(capsys, "refine", "--config", "run.toml")
    studies = load_config("run.toml").refine()
    assert cli["family"] == "uniform" and set(studies) == {"uniform", "graded"}
    assert studies["uniform"].to_dict()["elements"] == cli["elements"] == [4, 6]
