"""Run files = CLI in what they accept and refuse (issue 21.3 and 21.7, audit item 9): a run
file's ``[solver] name`` takes what ``--solver`` takes; a mesh file on the command line is not
combined with the file's frame keys (as ``--ei1`` is not with the file's mesh); ``--config`` is
given once; a ``[solver]`` key, ``ball.mass_kg`` or an offset a command does not use is refused
in one line (exit 2), by the command and by its Python method alike."""

from __future__ import annotations

import json
from pathlib import Path

import pytest

from fem_racket import load_config
from fem_racket.validation import InputError
from tests.clirun import one_error, run, run_json

MESH = Path(__file__).resolve().parents[2] / "meshes" / "standard_racket.vtu"


@pytest.mark.parametrize("name", ["auto", "general"])
def test_solver_name_takes_what_the_option_takes(cwd, capsys, name):
    Path("run.toml").write_text(f'[solver]\nname = "{name}"\n')
    cli = run_json(capsys, "simulate", "--config", "run.toml")
    flag = run_json(capsys, "simulate", "--solver", name)
    assert cli["cor"] == flag["cor"]  # the file's name is the option's
    assert load_config("run.toml").simulate().cor == cli["cor"]


def test_solver_name_outside_the_registry_is_refused(cwd, capsys):
    Path("run.toml").write_text('[solver]\nname = "euler"\n')
    line = one_error(capsys, "simulate", "--config", "run.toml")
    assert "solver.name = 'euler' is not allowed: must be one of auto, exact, general" in line


@pytest.mark.parametrize(
    ("text", "key"),
    [
        ("[frame]\nei1_n_m2 = 500.0\n", "frame.ei1_n_m2 = 500.0"),
        ("[frame]\nei2_n_m2 = 100.0\n", "frame.ei2_n_m2 = 100.0"),
        ('[frame]\npreset = "rigid"\n', "frame.preset = 'rigid'"),
        ("[frame]\nelements = 10\n", "frame.elements = 10"),
        (
            "[frame]\nsegments = [{ length_m = 0.2, ei_n_m2 = 150.0, rhoa_kg_m = 0.7 }, "
            "{ length_m = 0.48, ei_n_m2 = 120.0, rhoa_kg_m = 0.46 }]\n",
            "frame.segments",
        ),
    ],
)
def test_a_mesh_on_the_command_line_with_the_files_frame_is_refused(cwd, capsys, text, key):
    Path("run.toml").write_text(text)
    line = one_error(capsys, "simulate", "--config", "run.toml", "--mesh", MESH)
    assert f"--mesh cannot be combined with {key} from run.toml" in line


def test_a_mesh_with_the_files_frame_at_its_defaults_runs(cwd, capsys):
    # the standard preset, EI1 146 and 20 elements change nothing: the mesh is the frame
    Path("run.toml").write_text('[frame]\npreset = "standard"\nei1_n_m2 = 146.0\nelements = 20\n')
    given = run_json(capsys, "simulate", "--config", "run.toml", "--mesh", MESH)
    assert given["cor"] == run_json(capsys, "simulate", "--mesh", MESH)["cor"]


def test_config_twice_is_refused(cwd, capsys):
    Path("a.toml").write_text("[frame]\nei1_n_m2 = 500.0\n")
    Path("b.toml").write_text("[impact]\nspeed_m_s = 30.0\n")
    line = one_error(capsys, "simulate", "--config", "a.toml", "--config", "b.toml")
    assert "--config is given twice ('a.toml' and 'b.toml')" in line


#: (command, operands, file text, the refused key): keys the command has no option for.
UNUSED = [
    ("sweep", ("--position", "0.5:0.9:2"), "[solver]\nt_max_s = 0.1\n", "solver.t_max_s = 0.1"),
    ("map", ("--no-files",), '[solver]\nname = "cvode"\n', "solver.name = 'cvode'"),
    ("map", ("--no-files",), "[solver]\nrtol = 1e-08\n", "solver.rtol = 1e-08"),
    ("map", ("--no-files",), "[solver]\nt_max_s = 0.05\n", "solver.t_max_s = 0.05"),
    ("refine", ("--no-files",), '[solver]\nname = "general"\n', "solver.name = 'general'"),
    ("refine", ("--no-files",), "[solver]\nrtol = 1e-08\n", "solver.rtol = 1e-08"),
    ("refine", ("--no-files",), "[solver]\nt_max_s = 0.05\n", "solver.t_max_s = 0.05"),
    ("compare", ("standard", "rigid"), '[solver]\nname = "bdf"\n', "solver.name = 'bdf'"),
    ("compare", ("standard", "rigid"), "[solver]\nrtol = 1e-08\n", "solver.rtol = 1e-08"),
    ("compare", ("standard", "rigid"), "[solver]\nt_max_s = 0.05\n", "solver.t_max_s = 0.05"),
    ("compare", ("standard", "rigid"), "[ball]\nmass_kg = 0.06\n", "ball.mass_kg = 0.06"),
]
METHODS = {
    "sweep": lambda c: c.sweep(),
    "map": lambda c: c.map(),
    "refine": lambda c: c.refine(),
    "compare": lambda c: c.compare(["standard", "rigid"]),
}


@pytest.mark.parametrize(("command", "operands", "text", "key"), UNUSED)
def test_keys_a_command_does_not_use_are_refused_alike(cwd, capsys, command, operands, text, key):
    Path("run.toml").write_text(text)
    line = one_error(capsys, command, *operands, "--config", "run.toml")
    assert f"{key} is not allowed with fem-racket {command}: it has no such option" in line
    with pytest.raises(InputError, match=key.replace(".", r"\.")):
        METHODS[command](load_config("run.toml"))
    assert sorted(p.name for p in Path().iterdir()) == ["run.toml"]  # nothing written


@pytest.mark.parametrize("command", ["map", "compare"])
def test_an_offset_without_offsets_is_refused_alike(cwd, capsys, command):
    # map and compare stay on the long axis without --offsets (one offset is no face: the
    # command line refuses --offsets 0.02), so the file's offset would be dropped
    Path("run.toml").write_text("[impact]\noffset_m = 0.02\n")
    operands = ("standard", "rigid") if command == "compare" else ("--no-files",)
    line = one_error(capsys, command, *operands, "--config", "run.toml")
    assert (
        f"impact.offset_m = 0.02 is not allowed with fem-racket {command} without --offsets" in line
    )
    with pytest.raises(InputError, match=r"impact\.offset_m = 0\.02 .* without --offsets"):
        METHODS[command](load_config("run.toml"))
    # a shared file: config --check notes it for the command and passes
    code, out, _ = run(capsys, "config", "--check", "run.toml")
    assert code == 0 and "[map] not for this command: impact.offset_m = 0.02" in out


def test_an_offset_with_offsets_spans_the_face(cwd, capsys):
    # the face map spans the offsets itself: the file's fixed offset is one of its axis's
    # values, on the command line and in [map] alike
    Path("run.toml").write_text('[impact]\noffset_m = 0.02\n[map]\npositions = "0.6:0.9:3"\n')
    grid = ("--offsets", "-0.02:0.02:3", "--no-files", "--json")
    code, out, err = run(capsys, "map", "--config", "run.toml", *grid)
    assert code == 0, err
    Path("run.toml").write_text(
        '[impact]\noffset_m = 0.02\n[map]\npositions = "0.6:0.9:3"\noffsets = "-0.02:0.02:3"\n'
    )
    (face,) = load_config("run.toml").map()
    assert "power_area_cm2" in json.loads(out)  # the face's summary
    assert list(face.offsets) == pytest.approx([-0.02, 0.0, 0.02])


def test_solver_keys_at_their_defaults_pass(cwd, capsys):
    # the example file's [solver] is simulate's defaults: every command takes the file
    assert run(capsys, "config", "--example", "--out", "run.toml")[0] == 0
    assert run(capsys, "config", "--check", "run.toml")[0] == 0
    Path("run.toml").write_text('[solver]\nname = "auto"\nrtol = 1e-10\n[ball]\nmass_kg = 0.057\n')
    code, _, err = run(capsys, "compare", "standard", "rigid", "--positions", "0.6:0.9:3",
                       "--config", "run.toml", "--json")  # fmt: skip
    assert code == 0, err


@pytest.mark.parametrize(
    ("law", "key", "why"),
    [
        ("linear", "hc_alpha_s_m = 0.02", "the paper's law is built from kcb and zeta"),
        ("kawazoe-1997-nonlinear", "k1_n_m_n = 3e15", "no law parameter (a preset)"),
        ("hysteretic", "hc_alpha_s_m = 0.02", "must be one of ['hyst_exponent', 'k1', 'k2']"),
    ],
)
def test_a_law_parameter_the_law_does_not_take_is_named_by_its_key(cwd, capsys, law, key, why):
    Path("run.toml").write_text(f'[contact]\nlaw = "{law}"\n{key}\n')
    name = key.split(" = ")[0]
    words = f"contact.{name} = "
    assert words in one_error(capsys, "simulate", "--config", "run.toml")
    err = run(capsys, "simulate", "--config", "run.toml")[2]
    assert f"(run.toml) is not allowed with law '{law}'" in err and why in err, err
