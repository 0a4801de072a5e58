"""Run files = CLI for map, refine, sweep's new axes and simulate's [oblique] table (issue 21
item 7): ``load_config(path).<command>()`` gives what ``fem-racket <command> --config path``
computes, for a run file with every table the command reads."""

from __future__ import annotations

import numpy as np
import pytest
from clirun import run_json
from runfile_helpers import REL, py_json, same

from fem_racket import load_config
from fem_racket.cli import build_parser, main
from fem_racket.io.config_studies import MAP_DEFAULTS, REFINE_DEFAULTS


@pytest.mark.parametrize(
    ("command", "defaults"), [("map", MAP_DEFAULTS), ("refine", REFINE_DEFAULTS)]
)
def test_the_library_states_the_commands_defaults(command, defaults):
    args = build_parser([command]).parse_args([command])
    for dest, value in defaults.items():
        assert getattr(args, dest) == value, dest


CORE = """
[frame]
elements = 16
[[frame.lead]]
place = "12"
mass_g = 3
[ball]
mass_kg = 0.058
[contact]
kcb_n_m = 40000
zeta = 0.05
[impact]
speed_m_s = 25
racket_speed_m_s = 10
pivot_m = 0.1
[solver]
separation = "force"
modes = 30
tolerance = 1e-7
"""


def test_map_equals_the_command(cwd, capsys):
    (cwd / "run.toml").write_text(
        CORE + '[map]\npreset = ["standard", "rigid"]\npositions = "0.6:0.9:7"\n'
        "power_fraction = 0.9\n"
    )
    maps = load_config(cwd / "run.toml").map()
    cli = run_json(capsys, "map", "--config", "run.toml", "--no-files")
    same(py_json({"rackets": [m.summary() for m in maps]}), cli)


def test_spin_map_equals_the_command(cwd, capsys):
    text = CORE.replace("racket_speed_m_s = 10\npivot_m = 0.1\n", "")
    text = text.replace('[[frame.lead]]\nplace = "12"\nmass_g = 3\n', "")  # sweep: no lead
    text += '[oblique]\nangle_deg = 40\nspin_rpm = -3820\n[map]\npositions = "0.6,0.8"\n'
    text += 'offsets = "-0.04,0.04"\n'
    (cwd / "run.toml").write_text(text)
    (m,) = load_config(cwd / "run.toml").map()
    cli = run_json(capsys, "map", "--config", "run.toml", "--no-files")
    same(py_json(m.summary()), cli)


def test_refine_equals_the_command(cwd, capsys):
    text = "[frame]\nei1_n_m2 = 200\n[ball]\nmass_kg = 0.058\n[contact]\nzeta = 0.05\n"
    text += '[impact]\nspeed_m_s = 30\n[solver]\nseparation = "force"\n'
    text += '[refine]\nelements = [5, 10]\nfamily = "uniform"\npositions = [0.6, 0.8]\ncount = 3\n'
    (cwd / "run.toml").write_text(text)
    studies = load_config(cwd / "run.toml").refine()
    cli = run_json(capsys, "refine", "--config", "run.toml", "--no-files")
    py = studies["uniform"].to_dict()
    for key in ("cor", "contact_time_s", "frequencies_hz", "elements"):
        np.testing.assert_allclose(np.asarray(py[key], float), cli[key], rtol=REL, err_msg=key)


def test_simulate_oblique_table_equals_the_command(cwd, capsys):
    text = CORE.replace("racket_speed_m_s = 10\npivot_m = 0.1\n", "")
    text += "[oblique]\nangle_deg = 30\nspin_rpm = 1500\nfriction = 0.3\nball_inertia = 0.6\n"
    text += "ball_radius_m = 0.034\ncompliance_ratio = 1.2\n"
    (cwd / "run.toml").write_text(text)
    r = load_config(cwd / "run.toml").simulate()
    cli = run_json(capsys, "simulate", "--config", "run.toml")
    py = py_json(r.summary())
    for key in (
        "spin_out_rpm",
        "angle_out_deg",
        "ball_speed_out_m_s",
        "cor",
        "ball_inertia_i_over_mr2",
    ):
        assert py[key] == pytest.approx(cli[key], rel=REL), key
    assert py["contact_regime"] == cli["contact_regime"]


def test_clamped_oblique_table_refuses_what_a_clamped_head_cannot_take(cwd):
    (cwd / "run.toml").write_text(
        "[frame]\nelements = 16\n[oblique]\nangle_deg = 30\nclamped = true\n"
    )
    from fem_racket.validation import InputError

    with pytest.raises(
        InputError, match=r"^frame.elements \(.*\) is not allowed with oblique.clamped"
    ):
        load_config(cwd / "run.toml").simulate()


def test_sweep_axes_from_a_run_file_equal_the_command(cwd, capsys):
    import xarray as xr

    text = CORE.replace("racket_speed_m_s = 10\npivot_m = 0.1\n", "")
    text = text.replace('[[frame.lead]]\nplace = "12"\nmass_g = 3\n', "")  # sweep: no lead
    text += '[oblique]\nfriction = 0.3\n[sweep]\nangle = "20,40"\nspin = [0, 2000]\nout = "s.nc"\n'
    (cwd / "run.toml").write_text(text)
    ds = load_config(cwd / "run.toml").sweep(backend="serial")
    assert main(["sweep", "--config", "run.toml", "--serial", "--quiet"]) == 0
    capsys.readouterr()
    with xr.open_dataset(cwd / "s.nc") as back:
        for name in ("cor", "spin_out_rpm", "angle_out_deg", "contact_regime"):
            np.testing.assert_array_equal(back[name].values, ds[name].values)
        assert back.attrs["friction"] == 0.3 == ds.attrs["friction"]


@pytest.mark.parametrize(("command", "table"), [("export-vtk", "vtk"), ("animate", "animate")])
def test_the_drawing_defaults_are_the_commands(command, table):
    from fem_racket.io.config_drawings import ANIMATE_DEFAULTS, VTK_DEFAULTS

    defaults = VTK_DEFAULTS if table == "vtk" else ANIMATE_DEFAULTS
    args = build_parser([command]).parse_args([command])
    for dest, value in defaults.items():
        assert getattr(args, dest) == value, dest


def test_export_vtk_equals_the_command(cwd, capsys):
    pytest.importorskip("pyvista")
    import meshio

    text = CORE.replace("racket_speed_m_s = 10\npivot_m = 0.1\n", "")  # it takes no swing
    text += '[vtk]\nframes = 4\nsubdivide = 2\nscale = 3.0\noutput_step = 2e-5\nout = "a"\n'
    (cwd / "run.toml").write_text(text)
    assert main(["export-vtk", "--config", "run.toml", "--quiet"]) == 0
    capsys.readouterr()
    pvd = load_config(cwd / "run.toml").export_vtk(out=cwd / "b")
    cli_files = sorted((cwd / "a").glob("*.vtu"))
    assert [p.name for p in cli_files] == sorted(p.name for p in pvd.parent.glob("*.vtu"))
    assert len(cli_files) >= 4
    for path in cli_files:
        ours, theirs = meshio.read(cwd / "b" / path.name), meshio.read(path)
        # the same impact, to rounding (the command and the library sum the swing's and the
        # deflection's terms in another order)
        np.testing.assert_allclose(ours.points, theirs.points, rtol=1e-12, atol=1e-14)
        for key, values in theirs.point_data.items():
            np.testing.assert_allclose(ours.point_data[key], values, rtol=1e-9, atol=1e-14)


def test_a_table_the_drawing_does_not_take_is_refused(cwd):
    from fem_racket.validation import InputError

    (cwd / "run.toml").write_text("[oblique]\nangle_deg = 30\n")
    with pytest.raises(
        InputError, match=r"^\[oblique\] \(.*\) is not allowed with fem-racket export"
    ):
        load_config(cwd / "run.toml").export_vtk(out=cwd / "b")


def test_simulate_oblique_table_with_a_hand_equals_the_command(cwd, capsys):
    # [oblique] with [hand]: the held racket struck obliquely, as simulate --grip ... --angle ...
    # (it was refused in Python); every printed number and the hand's shock window applied
    text = (
        '[frame]\nelements = 10\n[hand]\ngrip = "firm"\nshock_window_s = 0.02\n'
        "[oblique]\nangle_deg = 30.0\nspin_rpm = 1500.0\n"
        "[impact]\nposition_x_over_l = 0.7\nspeed_m_s = 25.0\nracket_speed_m_s = 8.0\n"
    )
    (cwd / "run.toml").write_text(text)
    cli = run_json(capsys, "simulate", "--config", "run.toml")
    result = load_config(cwd / "run.toml").simulate()
    assert result.held and py_json(result.summary()) == cli
    assert cli["shock_window_s"] == 0.02 and cli["hand"]["grip"] == "firm"
    options = run_json(capsys, "simulate", "--grip", "firm", "--shock-window", "0.02",
                        "--angle", "30", "--spin", "1500", "--elements", "10", "--position",
                        "0.7", "--speed", "25", "--racket-speed", "8")  # fmt: skip
    assert options == cli


def test_clamped_oblique_table_refuses_alike_what_a_clamped_head_cannot_take(cwd, capsys):
    # the command dropped a run file's frame and swing with oblique.clamped (it refused them
    # on the command line only); it now refuses them as the method does
    from fem_racket.validation import InputError

    for text, key in [
        ("[frame]\nelements = 16\n", "frame.elements = 16"),
        ("[impact]\nracket_speed_m_s = 10.0\n", "impact.racket_speed_m_s = 10.0"),
        ('[solver]\nname = "cvode"\n', "solver.name = 'cvode'"),
    ]:
        (cwd / "run.toml").write_text(text + "[oblique]\nangle_deg = 30\nclamped = true\n")
        assert main(["simulate", "--config", "run.toml"]) == 2
        err = capsys.readouterr().err
        assert f"{key} (run.toml) is not allowed with --clamped" in err, err
        with pytest.raises(InputError, match=key.split(" =")[0].replace(".", r"\.")):
            load_config(cwd / "run.toml").simulate()
    (cwd / "run.toml").write_text(
        "[ball]\nmass_kg = 0.056\n[oblique]\nangle_deg = 30\nclamped = true\n"
    )
    cli = run_json(capsys, "simulate", "--config", "run.toml")
    assert py_json(load_config(cwd / "run.toml").simulate().summary()) == cli
