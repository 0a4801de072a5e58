"""Run files in Python = the CLI (issue 21.7): ``load_config(path).simulate()`` gives exactly
what ``fem-racket simulate --config path`` gives, for a file with every table, and refuses what
the command refuses."""

import json
import shutil
from pathlib import Path

import pytest
from clirun import run_json

from fem_racket import load_config
from fem_racket.cli import build_parser, main
from fem_racket.outputs.jsonable import json_ready
from fem_racket.validation import InputError

ROOT = Path(__file__).resolve().parents[2]

EVERY_TABLE = """
[frame]
ei1_n_m2 = 500.0
ei2_n_m2 = 420.0
elements = 24
[ball]
mass_kg = 0.058
[contact]
kcb_n_m = 31000.0
clamped_cor = 0.8
[impact]
position_x_over_l = 0.7
speed_m_s = 30.0
racket_speed_m_s = 12.0
reference_x_over_l = 0.7
pivot_m = 0.05
[solver]
name = "exact"
separation = "displacement"
basis = "modal"
modes = 40
tolerance = 1e-7
t_max_s = 0.05
[output]
out = "r.json"
overwrite = true
[simulate]
output_step = 2e-5
"""

FILES = {
    "every-table": EVERY_TABLE,
    # (without an output a [simulate] output_step and an overwrite are refused:
    # test_given_runfile.py, test_runfile_overwrite.py)
    "every-table-summary-only": EVERY_TABLE.replace(
        'out = "r.json"\noverwrite = true\n', ""
    ).replace("[simulate]\noutput_step = 2e-5\n", ""),
    # the case: EI1 = 500 gave COR 0.363950 in Python, 0.371760 on the command line
    "ei1-500": "[frame]\nei1_n_m2 = 500.0\n[impact]\nspeed_m_s = 30.0\n",
    "law-and-swing": (
        '[contact]\nlaw = "series"\nball_stiffness_n_m = 2.5e5\nstring_cubic_n_m3 = 4e8\n'
        "[impact]\nspeed_m_s = 25.0\nracket_speed_m_s = 10.0\n"
        '[solver]\nname = "cvode"\nrtol = 1e-9\natol = 1e-11\n'
        '[frame]\npreset = "rigid"\nelements = 12\n'
        "[output]\nout = 'r.json'\n"
    ),
    "hand": (
        '[hand]\ngrip = "firm"\nmass_kg = 0.42\ngrip_end_m = 0.11\nshock_window_s = 0.03\n'
        "[impact]\nspeed_m_s = 30.0\nposition_x_over_l = 0.8\n[ball]\nmass_kg = 0.056\n"
        "[solver]\ntolerance = 1e-8\n[contact]\nzeta = 0.05\n"
    ),
    "mesh": '[frame]\nmesh = "standard_racket.vtu"\n[impact]\nposition_x_over_l = 0.6\n',
    "segments": (
        "[frame]\nelements = 16\nsegments = [\n"
        "  { length_m = 0.2, ei_n_m2 = 150.0, rhoa_kg_m = 0.7 },\n"
        "  { length_m = 0.48, ei_n_m2 = 120.0, rhoa_kg_m = 0.46 },\n]\n"
    ),
}


@pytest.fixture
def cwd(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    shutil.copy(ROOT / "meshes" / "standard_racket.vtu", tmp_path)
    return tmp_path


@pytest.mark.parametrize("name", list(FILES))
def test_python_gives_the_clis_result_for_every_table(capsys, cwd, name):
    path = cwd / "run.toml"
    path.write_text(FILES[name])
    cli = run_json(capsys, "simulate", "--config", path)
    (cwd / "r.json").unlink(missing_ok=True)
    result = load_config(path).simulate()
    # the same computation: every number bit for bit, once printed by the command's rule
    # (a short decimal plus float noise, 50000.00000000001, printed as the decimal)
    python = json.loads(json.dumps(json_ready(result.summary()), default=str))
    assert python == cli
    assert result.summary()["cor"] == cli["cor"]
    # histories as the command computes them: when the file names an output
    if name != "hand":
        assert (len(result.t) > 2) == ("r.json" in FILES[name])
    if name == "ei1-500":
        assert cli["cor"] == pytest.approx(0.371760, abs=5e-7)


def test_python_refuses_what_the_command_refuses(capsys, cwd):
    cases = {
        '[hand]\ngrip = "firm"\n[solver]\nmodes = 10\n': "solver.modes = 10",
        '[hand]\ngrip = "firm"\n[solver]\nseparation = "force"\n': "solver.separation",
        '[contact]\nlaw = "series"\nkcb_n_m = 3e4\n': "contact.kcb_n_m = 30000.0",
        '[contact]\nlaw = "hysteretic"\nclamped_cor = 0.8\n': "contact.clamped_cor = 0.8",
        '[contact]\nlaw = "series"\n[hand]\ngrip = "loose"\n': "not allowed with a hand",
        "[hand]\ngrip_end_m = 5.0\n": "beyond the frame",
        "[impact]\npivot_m = 0.51\nracket_speed_m_s = 10\n": "reference point",
        "[hand]\nshock_window_s = 0.03\n": "not allowed without a hand",
        "[hand]\nmass_kg = 0.4\n": None,  # any hand parameter holds the racket
    }
    for text, words in cases.items():
        path = cwd / "run.toml"
        path.write_text(text)
        code = main(["simulate", "--config", str(path)])
        err = capsys.readouterr().err
        if words is None:
            assert code == 0, err
            load_config(path).simulate()
            continue
        assert code == 2 and words in err, (text, err)
        with pytest.raises(InputError, match=words.replace(".", r"\.")):
            load_config(path).simulate()


def test_the_run_files_defaults_are_the_commands():
    # One table of defaults serves the run file and the command line: the parser's own
    # defaults must be those.
    from fem_racket.io.config_defaults import DEFAULT_STEP, DEFAULTS, SIMULATE_DEFAULTS

    args = build_parser(["simulate"]).parse_args(["simulate"])
    assert {k: getattr(args, k) for k in DEFAULTS} == DEFAULTS
    assert {k: getattr(args, k) for k in SIMULATE_DEFAULTS} == SIMULATE_DEFAULTS
    assert args.output_step == DEFAULT_STEP


def test_the_command_line_defaults_are_the_librarys():
    # simulate_file leaves unset keys to the library: its defaults must be the command's.
    from fem_racket.impact.problem import ImpactProblem
    from fem_racket.impact.settings import Settings

    args = build_parser(["simulate"]).parse_args(["simulate"])
    p = ImpactProblem.build()
    assert (args.position, args.speed) == (p.impact.position, p.impact.speed)
    assert args.elements == p.model.mesh.n_elements
    assert args.output_step == Settings().output_step


SWEEPS = {
    "core-and-grids": (
        "[frame]\nei1_n_m2 = 300.0\nelements = 16\n[ball]\nmass_kg = 0.058\n"
        "[impact]\nspeed_m_s = 25.0\nracket_speed_m_s = 5.0\n[solver]\nmodes = 30\n"
        "[sweep]\nposition = [0.6, 0.7, 0.8]\nkcb = '2e4:4e4:3'\npeak_force = true\n"
        "serial = true\nquiet = true\nout = 's.nc'\n"
    ),
    "law-axis": (
        '[contact]\nlaw = "hunt-crossley"\nhc_stiffness_n_m_n = 1e7\n'
        "[sweep]\nhc_exponent = [1.5, 2.0]\nposition = '0.6,0.8'\nserial = true\nquiet = true\n"
        "out = 's.nc'\n"
    ),
    "segments-ei-factor": (
        "[frame]\nelements = 12\nsegments = [\n"
        "  { length_m = 0.2, ei_n_m2 = 150.0, rhoa_kg_m = 0.7 },\n"
        "  { length_m = 0.48, ei_n_m2 = 120.0, rhoa_kg_m = 0.46 },\n]\n"
        "[sweep]\nei_factor = [0.5, 1.0]\nserial = true\nquiet = true\nout = 's.nc'\n"
    ),
}


@pytest.mark.parametrize("name", list(SWEEPS))
def test_python_sweep_gives_the_clis_dataset(capsys, cwd, name):
    import xarray as xr

    path = cwd / "run.toml"
    path.write_text(SWEEPS[name])
    assert main(["sweep", "--config", str(path)]) == 0, capsys.readouterr().err
    python = load_config(path).sweep(backend="serial")
    skip = {"created_utc", "run_parameters", "backend"}
    with xr.open_dataset(cwd / "s.nc") as cli:
        xr.testing.assert_identical(cli.drop_attrs(), python.drop_attrs())
        assert {k: v for k, v in cli.attrs.items() if k not in skip} == {
            k: v for k, v in python.attrs.items() if k not in skip
        }
