"""Run-file keys that had no table entry (issue 21.3/21.7): ``[strings] stretch`` =
``--string-stretch``; ``[oblique] side_angle_deg``/``side_spin_rpm`` = ``--side-angle``/
``--side-spin``, in Python (``load_config(f).simulate()``) as on the command line."""

import json

import pytest
from clirun import run_json

from fem_racket import load_config
from fem_racket.cli import main
from fem_racket.validation import InputError


def test_strings_stretch_key_is_the_option(capsys, tmp_path):
    # stretch = true gives the printed outcome of --string-stretch, bit for bit (both cvode,
    # which the library's "auto" picks for a stretching bed); stretch = false is the linear bed.
    path = tmp_path / "run.toml"
    path.write_text("[strings]\nstretch = true\n[impact]\nspeed_m_s = 40.0\n")
    file = run_json(capsys, "simulate", "--config", path, "--elements", 8)
    cli = run_json(capsys, "simulate", "--string-stretch", "--speed", 40, "--elements", 8)
    assert file == cli
    assert file["string_stretch"] is True and file["solver"] == "cvode"
    path.write_text("[strings]\nstretch = false\n[impact]\nspeed_m_s = 40.0\n")
    linear = run_json(capsys, "simulate", "--config", path, "--elements", 8)
    plain = run_json(capsys, "simulate", "--string-tension", 246, "--speed", 40, "--elements", 8)
    assert linear == plain and linear["string_stretch"] is False
    assert linear["solver"] == "exact" and linear["contact_time_s"] > file["contact_time_s"]
    path.write_text('[strings]\nstretch = "yes"\n')
    code = main(["simulate", "--config", str(path)])
    assert code == 2 and "strings.stretch = 'yes'" in capsys.readouterr().err


def test_auto_picks_cvode_for_a_stretching_bed():
    from fem_racket import FrameModel, standard_frame
    from fem_racket.impact.problem import ImpactProblem
    from fem_racket.impact.solvers import make_solver
    from fem_racket.strings.bed import StringBed

    model = FrameModel.build(standard_frame(), 8)
    stretch = ImpactProblem.build(model, strings=StringBed(stretch=True), speed=30.0)
    assert make_solver("auto").pick(stretch).name == "cvode"
    assert make_solver("auto").pick(ImpactProblem.build(model, strings=StringBed())).name == (
        "exact"
    )
    a, c = make_solver("auto").solve(stretch), make_solver("cvode").solve(stretch)
    assert (a.cor, a.contact_time) == (c.cor, c.contact_time)
    with pytest.raises(InputError, match="modes = 10 is not allowed .* solver 'cvode'"):
        make_solver("auto", modes=10).solve(stretch)  # cvode's own refusal, named


SIDE = """
[oblique]
angle_deg = 20.0
spin_rpm = 1500.0
side_angle_deg = 15.0
side_spin_rpm = -800.0
[impact]
position_x_over_l = 0.7
offset_m = 0.03
speed_m_s = 30.0
[frame]
elements = 10
"""


def test_side_keys_in_python_are_the_command(capsys, tmp_path):
    # load_config(f).simulate() = simulate --config f = the options, number for number
    from fem_racket.outputs.jsonable import json_ready

    path = tmp_path / "run.toml"
    path.write_text(SIDE)
    file = run_json(capsys, "simulate", "--config", path)
    cli = run_json(capsys, "simulate", "--angle", 20, "--spin", 1500, "--side-angle", 15,
                   "--side-spin", -800, "--position", 0.7, "--offset", 0.03, "--speed", 30,
                   "--elements", 10)  # fmt: skip
    assert file == cli
    assert file["side_angle_deg"] == 15.0 and file["side_spin_rpm"] == -800.0
    result = load_config(path).simulate()
    assert json.loads(json.dumps(json_ready(result.summary()), default=str)) == file
    path.write_text(SIDE.replace("side_angle_deg = 15.0\nside_spin_rpm = -800.0\n", ""))
    plain = load_config(path).simulate().summary()  # the keys change the outcome (not ignored)
    assert plain["side_spin_out_rpm"] != file["side_spin_out_rpm"]
    path.write_text(SIDE.replace("15.0", "90.0"))
    with pytest.raises(InputError, match=r"oblique\.side_angle_deg = 90"):
        load_config(path)


@pytest.mark.parametrize(
    ("text", "message"),
    [
        ("[frame]\nsegments = []\n", "frame.segments is not allowed: must be a non-empty array "
         "of tables with length_m, ei_n_m2 and rhoa_kg_m"),
        ("[frame]\nsegments = [3]\n", "frame.segments[0] = 3 is not allowed: must be a table "
         "with length_m, ei_n_m2 and rhoa_kg_m"),
        ("[frame]\nsegments = [{ length_m = 0.2, ei_n_m2 = 150.0, rhoa_kg_m = 0.7, rhoa = 1 }]\n",
         "frame.segments[0].rhoa is not a known key: did you mean 'rhoa_kg_m'?"),
        ("[frame]\nsegments = [{ length_m = 0.2 }]\n",
         "frame.segments[0] is missing ei_n_m2, rhoa_kg_m (each segment needs all 3)"),
        ("[frame]\nlead = []\n",
         "frame.lead is not allowed: must be a non-empty array of tables with place and mass_g"),
        ("[frame]\nlead = [3]\n",
         "frame.lead[0] = 3 is not allowed: must be a table with place and mass_g"),
        ('[[frame.lead]]\nplace = "12"\nmass_gram = 3\n', "frame.lead[0].mass_gram is not a "
         "known key: did you mean 'mass_g'? allowed: place, mass_g"),
        ('[[frame.lead]]\nplace = "12"\n',
         "frame.lead[0] is missing mass_g (each lead needs both)"),
    ],
)  # fmt: skip
def test_arrays_of_tables_are_refused_item_by_item(tmp_path, capsys, text, message):
    # [[frame.segments]] and [[frame.lead]]: one line naming the item and what it lacks, from
    # Python and from the command line alike
    path = tmp_path / "run.toml"
    path.write_text(text)
    with pytest.raises(InputError) as err:
        load_config(path)
    assert str(err.value) == f"{path}: {message}"
    assert main(["modes", "--config", str(path)]) == 2
    assert capsys.readouterr().err.count("\n") == 1
