"""Run files = CLI for the design studies (issue 21.7): ``load_config(f).optimize()`` and
``.sensitivity()`` give what ``fem-racket optimize/sensitivity --config f`` compute, for a small
file with the core tables a design reads (frame, ball, contact, the swing) and a cheap budget."""

import json
import re

import pytest
from clirun import run_json

from fem_racket import load_config
from fem_racket.cli import main
from fem_racket.validation import InputError

DESIGN = """
[frame]
elements = 8
[ball]
mass_kg = 0.058
[contact]
zeta = 0.05
[impact]
racket_speed_m_s = 10.0
[{table}]
boundaries = [0.3]
vary = ["ei"]
link_ei = true
ei_bounds = ["100,2000"]
speeds = [30.0]
zone_points = 3
mass_range = "start"
backend = "serial"
{extra}
"""


def test_optimize_in_python_is_the_command(capsys, tmp_path):
    path = tmp_path / "run.toml"
    path.write_text(DESIGN.format(table="design", extra='method = "SLSQP"\nmaxiter = 2'))
    r = load_config(path).optimize(tmp_path / "py")
    cli = run_json(capsys, "optimize", "--config", path, "--out", tmp_path / "cli")
    assert r.objective == cli["objective"] and r.start_objective == cli["start_objective"]
    # (the command prints 15 significant digits: 145.99999999999997 as 146.0)
    assert float(r.x[0]) == pytest.approx(cli["variables"]["ei"], rel=1e-14)
    assert r.message == cli["message"] and (tmp_path / "py" / "result.json").is_file()
    assert json.loads(json.dumps(r.constraints())) == cli["constraints"]
    # the file's keys reach the problem: another ball gives another start
    path.write_text(path.read_text().replace("mass_kg = 0.058", "mass_kg = 0.05"))
    other = load_config(path).optimize(tmp_path / "py2")
    assert other.start_objective != r.start_objective


def test_sensitivity_in_python_is_the_command(capsys, tmp_path):
    pytest.importorskip("SALib")
    from fem_racket.io.design_study import sobol_json

    path = tmp_path / "run.toml"
    text = DESIGN.format(table="sensitivity", extra="designs = 16\nseed = 3")
    # no mass_range: a sensitivity analysis applies no constraint (refused, it was ignored)
    path.write_text(text.replace("link_ei = true\n", "").replace('mass_range = "start"\n', ""))
    s = load_config(path).sensitivity()
    cli = run_json(capsys, "sensitivity", "--config", path)
    assert json.loads(json.dumps(sobol_json(s))) == cli


def test_design_tables_refuse_as_the_command(capsys, tmp_path):
    path = tmp_path / "run.toml"
    for text, words in {
        '[design]\nvary = "ei"\n': "design.vary = 'ei' is not allowed: must be an array",
        "[design]\nmaxiterr = 3\n": "did you mean 'maxiter'",
        "[sensitivity]\nmaxiter = 3\n": "sensitivity.maxiter is not a known key",
        '[hand]\ngrip = "firm"\n': "hand.grip = 'firm' is not allowed with fem-racket",
    }.items():
        path.write_text(text)
        command = "sensitivity" if "sensitivity" in text else "optimize"
        assert main([command, "--config", str(path)]) == 2
        assert words.split(" is ")[0] in capsys.readouterr().err
        with pytest.raises(InputError, match=words.replace("(", r"\(").replace(".", r"\.")):
            getattr(load_config(path), command)(tmp_path / "x")


def test_sensitivity_overwrite_without_out(capsys, tmp_path):
    # overwrite where nothing is written is refused, the shared [output]'s (it was skipped:
    # silently ignored) and the table's own, by the command and by the method alike (issue 21.3)
    pytest.importorskip("SALib")
    path = tmp_path / "run.toml"
    text = DESIGN.format(table="sensitivity", extra="designs = 8").replace(
        'mass_range = "start"\n', ""
    )
    path.write_text("[output]\noverwrite = true\n" + text)
    assert main(["sensitivity", "--config", str(path), "--quiet"]) == 2
    words = f"output.overwrite = True ({path}) is not allowed without"
    assert words in capsys.readouterr().err
    with pytest.raises(InputError, match=re.escape(f"{words} out: nothing is written")):
        load_config(path).sensitivity()
    path.write_text(text + "overwrite = true\n")
    assert main(["sensitivity", "--config", str(path)]) == 2
    assert "sensitivity.overwrite = True" in capsys.readouterr().err
    with pytest.raises(InputError, match="overwrite = True is not allowed without out"):
        load_config(path).sensitivity()
