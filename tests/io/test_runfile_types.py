"""The keys of ``[vtk]``, ``[animate]``, ``[design]`` and ``[sensitivity]`` that the commands
convert by type (a flag true or false, an integer, a number, a text) are refused alike by the
run file's methods (issue 21.7): ``vtk.overwrite = 2`` was taken as true, ``design.seed = 1.5``
and ``design.shock_window = 'x'`` were accepted, ``vtk.out = 3`` raised a TypeError."""

from __future__ import annotations

import pytest
from clirun import file_refused_alike
from test_config_design import DESIGN

FRAME = "[frame]\nelements = 6\n"
METHODS = {"export-vtk": "export_vtk", "animate": "animate", "optimize": "optimize",
           "sensitivity": "sensitivity"}  # fmt: skip
TABLES = {"export-vtk": "vtk", "animate": "animate", "optimize": "design"}


@pytest.mark.parametrize(
    ("command", "key", "words"),
    [
        ("export-vtk", "overwrite = 2", "vtk.overwrite = 2 is not allowed: must be true or false"),
        ("export-vtk", "quiet = 2", "vtk.quiet = 2 is not allowed: must be true or false"),
        ("export-vtk", "out = true", "vtk.out = True is not allowed: must be a value like"),
        ("animate", "overwrite = 2", "animate.overwrite = 2 is not allowed: must be true or"),
        ("optimize", "overwrite = 2", "design.overwrite = 2 is not allowed: must be true or"),
        ("optimize", "restart = 2", "design.restart = 2 is not allowed: must be true or false"),
        ("optimize", "json = 2", "design.json = 2 is not allowed: must be true or false"),
        ("optimize", "seed = 1.5", "design.seed = 1.5 is not allowed: must be an integer"),
        ("optimize", "workers = 1.5", "design.workers = 1.5 is not allowed: must be an integer"),
        ("optimize", "generations = 1.5", "design.generations = 1.5 is not allowed: must be an"),
        ("optimize", 'shock_window = "x"', "design.shock_window = 'x' is not allowed"),
        ("optimize", 'zone_sigma = "x"', "design.zone_sigma = 'x' is not allowed"),
        ("optimize", "mass_start = true", "design.mass_start = True is not allowed"),
        ("sensitivity", "designs = 1.5", "sensitivity.designs = 1.5 is not allowed: must be an"),
        ("sensitivity", "quiet = 2", "sensitivity.quiet = 2 is not allowed: must be true or"),
    ],
)
def test_refused_alike(cwd, capsys, command, key, words):
    table = TABLES.get(command, command)
    if command in ("optimize", "sensitivity"):  # (sensitivity links no EI)
        text = DESIGN.format(table=table, extra=key).replace("link_ei = true\n", "")
        if command == "sensitivity":  # no constraint keys (tests/cli/test_sensitivity_no_...)
            text = text.replace('mass_range = "start"\n', "")
    else:
        text = FRAME + f"[{table}]\n{key}\n"
    argv = (command, "--config", "run.toml", "--quiet")

    def method(config):
        return getattr(config, METHODS[command])()

    file_refused_alike(capsys, text, argv, method, words, start=True)
