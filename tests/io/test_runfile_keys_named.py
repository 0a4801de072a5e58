"""A run file's value the library refuses is named by its dotted key and the file, on the
command line (``simulate --config``, ``config --check``) and in Python (``load_config(f)
.simulate()``), as the README promises (they named the library's parameter: ``speed = 1000.0
m/s is not allowed``); the bound is the library's (no copy). Lead tape from a file has the
bounds ``--add-mass`` has (2000 g ran; 1e9 g failed in the mesh naming neither key nor limit).
A value from the command line is still named as its option. The key comes from the parameter
and value the library's refusal carries (``InputError.parameter``, ``.value``), not from its
words."""

from __future__ import annotations

from pathlib import Path

import pytest
from clirun import one_error, refused_alike

from fem_racket import load_config
from fem_racket.validation import InputError

MESH = Path(__file__).resolve().parents[2] / "meshes" / "tapered_racket.vtu"

#: (table, key, refused value, what the library allows)
REFUSED = [
    ("impact", "speed_m_s", 1000.0, "m/s is not allowed: must lie in [1, 100]"),
    ("oblique", "spin_rpm", 1e6, "rpm is not allowed: must lie in [-50000, 50000]"),
    ("strings", "tension_n", 1e6, "N is not allowed: must lie in [1, 2000]"),
    ("impact", "racket_speed_m_s", 1000.0, "m/s is not allowed: must lie in [-100, 100]"),
    ("oblique", "ball_radius_m", 5.0, "m is not allowed: must lie in (0, 0.1]"),
    ("frame", "ei1_n_m2", 1e9, "N m^2 is not allowed: must lie in [6.96e-07, 5.20455e+08]"),
    ("oblique", "face_angle_deg", 190.0, "deg is not allowed: must lie in (0, 180)"),
    ("strings", "head_area_cm2", 1e6, "cm^2 is not allowed: it makes the head"),
]


@pytest.mark.parametrize(("table", "key", "value", "allowed"), REFUSED)
def test_a_refused_value_names_its_key(tmp_path, capsys, table, key, value, allowed):
    path = tmp_path / "run.toml"
    path.write_text(f"[{table}]\n{key} = {value!r}\n")
    words = f"{path}: {table}.{key} = {value!r} {allowed}"
    refused_alike(capsys, ["simulate", "--config", path], load_config(path).simulate, words)
    line = one_error(capsys, "config", "--check", path)
    assert f"would refuse it: {table}.{key} = {value!r} {allowed}" in line


def test_the_same_value_on_the_command_line_is_named_as_its_option(tmp_path, capsys):
    path = tmp_path / "run.toml"
    path.write_text("[impact]\nspeed_m_s = 1000.0\n")
    line = one_error(capsys, "simulate", "--config", path, "--speed", 500)
    assert ": error: speed = 500.0 m/s is not allowed: must lie in [1, 100]" in line


def test_pivot_from_the_file_without_the_swing_names_its_key(tmp_path, capsys):
    path = tmp_path / "run.toml"
    path.write_text("[impact]\nracket_speed_m_s = 10.0\npivot_m = 0.1\n")
    line = one_error(capsys, "simulate", "--config", path, "--racket-speed", 0)
    assert f"{path}: impact.pivot_m = 0.1 m is not allowed without a swing" in line


def test_elements_with_the_files_mesh_names_its_key(tmp_path, capsys):
    path = tmp_path / "run.toml"
    path.write_text(f'[frame]\nmesh = "{MESH}"\n')
    line = one_error(capsys, "simulate", "--config", path, "--elements", 10)
    assert f"--elements is not allowed with frame.mesh ({path}): the mesh file" in line
    line = one_error(capsys, "simulate", "--mesh", MESH, "--elements", 10)
    assert "--elements is not allowed with --mesh: the mesh file" in line


@pytest.mark.parametrize("grams", [2000.0, 1e9])
def test_lead_from_a_file_has_the_add_mass_bounds(tmp_path, capsys, grams):
    path = tmp_path / "run.toml"
    path.write_text(f'[frame]\nlead = [{{ place = "3/9", mass_g = {grams!r} }}]\n')
    words = f"frame.lead[0].mass_g = {grams!r} is not allowed: must be at most 1000 g"
    refused_alike(capsys, ["simulate", "--config", path], lambda: load_config(path), words)
    assert words in one_error(capsys, "config", "--check", path)
    line = one_error(capsys, "simulate", "--add-mass", f"3/9:{grams:g}")
    assert "is not allowed: must be at most 1000 g" in line


def test_lead_at_the_bound_runs_from_both(tmp_path, capsys):
    from clirun import run_json

    path = tmp_path / "run.toml"
    path.write_text('[frame]\nlead = [{ place = "3/9", mass_g = 1000.0 }]\n')
    cli = run_json(capsys, "simulate", "--config", path)
    assert cli["cor"] == pytest.approx(load_config(path).simulate().cor, rel=1e-12)


#: keys named by the attribute path: dest -> the dotted key the file set it by
KEYS = {"speed": "impact.speed_m_s", "ball_radius": "oblique.ball_radius_m", "law": "contact.law"}
VALUES = {"speed": 1000.0, "ball_radius": 5.0, "law": "hertz"}


@pytest.mark.parametrize(
    ("parameter", "value", "line", "named"),
    [
        ("speed", 1000.0, "speed = 1000.0 m/s is not allowed: must lie in [1, 100]",
         "run.toml: impact.speed_m_s = 1000.0 m/s is not allowed: must lie in [1, 100]"),
        ("radius", 5, "radius = 5 m is not allowed: must lie in (0, 0.1]",  # an alias
         "run.toml: oblique.ball_radius_m = 5 m is not allowed: must lie in (0, 0.1]"),
        ("speed", 500.0, "speed = 500.0 m/s is not allowed: must lie in [1, 100]", None),
        ("law", "hertz", "law = 'hertz' is not allowed: must be one of linear", None),  # text
        (None, None, "speed = 1000.0 m/s is not allowed: must lie in [1, 100]", None),
    ],
)  # fmt: skip
def test_the_key_comes_from_the_parameter_and_value_the_error_carries(
    parameter, value, line, named
):
    from fem_racket.io.config_named import named_by_key
    from fem_racket.validation import InputError

    exc = InputError(line, parameter=parameter, value=value)
    out = named_by_key(exc, KEYS, VALUES, "run.toml")
    # a value the file did not give (500 from elsewhere), a text, or an error naming no
    # parameter (its words are not read) stays as the library wrote it
    assert str(out) == (named or line) and (out is exc) == (named is None)


#: A run file's key whose value check_mesh_suffix or check_grams refuses: (run file, method, the
#: parameter the refusal names = the key as the command's option or the file's dotted key, the
#: value refused, the key the run-file layer names it by).
PARAMETER_CARRIED = [
    (
        "[fit]\nlength = 0.685\nmass = 0.3\nbalance = 0.32\nswing_weight = 290\nout = 'r.stl'\n",
        lambda cfg: cfg.fit(),
        "out",
        Path("r.stl"),
        "fit.out",
    ),
    (
        "[customise]\nswing_weight = 330\nout = 'r.stl'\n",
        lambda cfg: cfg.customise(),
        "out",
        Path("r.stl"),
        "customise.out",
    ),
]


@pytest.mark.parametrize(
    ("text", "method", "parameter", "value", "key"), PARAMETER_CARRIED, ids=["fit", "customise"]
)
def test_a_mesh_suffix_refused_carries_its_key_and_value(cwd, text, method, parameter, value, key):
    # check_mesh_suffix's refusal carried neither parameter nor value: a run file's key could not
    # be named from them (a command table's key is named as the command's option, --out)
    Path("run.toml").write_text(text)
    with pytest.raises(InputError) as err:
        method(load_config("run.toml"))
    assert (err.value.parameter, err.value.value) == (parameter, value)
    assert str(err.value).startswith(f"{parameter} = 'r.stl' is not allowed: a mesh file must")
    named = str(err.value.named(key, "run.toml: "))
    assert named.startswith(f"run.toml: {key} = 'r.stl' is not allowed: a mesh file must end")


@pytest.mark.parametrize("grams", [0.0, 2000.0])
def test_a_lead_refused_carries_its_key_and_grams(grams):
    # check_grams' refusal carried neither: the file's key frame.lead[0].mass_g and --add-mass
    # now ride on it with the grams refused, as every check's refusal does
    from fem_racket.frame.lead import parse_lead
    from fem_racket.io.config_lead import lead_tables

    with pytest.raises(InputError) as err:
        lead_tables("frame.lead", [{"place": "3/9", "mass_g": grams}])
    assert (err.value.parameter, err.value.value) == ("frame.lead[0].mass_g", grams)
    assert str(err.value).startswith(f"frame.lead[0].mass_g = {grams!r} is not allowed: must be")
    with pytest.raises(InputError) as err:
        parse_lead(f"3/9:{grams:g}")
    assert (err.value.parameter, err.value.value) == ("add-mass", grams)
    assert str(err.value).startswith(f"add-mass = '3/9:{grams:g}' is not allowed: must be")
