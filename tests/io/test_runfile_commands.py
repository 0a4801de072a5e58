"""Run files = CLI for the commands that compute no impact (issue 21.7): ``load_config(f).modes()``,
``.fit()``, ``.customise()``, ``.closest()``, ``.compare()``, ``.calibrate()`` and
``reproduce_file(load_config(f))`` give the numbers ``fem-racket <command> --config f`` prints
(its JSON, to its printed digits) and write the same files (byte for byte where no provenance
is inside, the same contents beside it where it is), for one run file with every table these
commands read; and refuse what the commands refuse."""

from __future__ import annotations

import json
from pathlib import Path

import numpy as np
import pytest
from clirun import file_refused_alike, run, run_json
from runfile_helpers import py_json, same

from fem_racket import load_config
from fem_racket.paper.config_reproduce import reproduce_file
from fem_racket.validation import InputError

ROOT = Path(__file__).resolve().parents[2]
CSV = ROOT / "meshes" / "rackets.csv"

#: The core tables these commands read (frame with lead, the ball's speed and a swing for the
#: maps, the ball for calibrate, a law for reproduce), keys they skip (solver, hand), and their
#: own tables.
RUN = """
[frame]
elements = 12
[[frame.lead]]
place = "12"
mass_g = 3
[ball]
mass_kg = 0.058
[impact]
speed_m_s = 25.0
racket_speed_m_s = 5.0
pivot_m = 0.1
[solver]
modes = 30
[hand]
grip = "firm"
[modes]
count = 3
[fit]
length = 0.685
mass = 0.318
balance = "0.32"
swing_weight = 316
f1 = 150
elements = 30
[customise]
swing_weight = "328:332"
balance = "keep"
places = "12,handle"
maps = "py_maps.nc"
[closest]
swing_weight = 330
balance = "0.31:0.33"
count = 2
[compare]
positions = "0.6:0.9:7"
point = 0.7
grip = "loose"
[calibrate]
targets = "itf"
"""


@pytest.fixture
def cfg(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    (tmp_path / "run.toml").write_text(RUN)
    return load_config(tmp_path / "run.toml")


#: A racket sidecar's keys that do not tell when and how the file was made.
SUMMARY = ("target", "fitted", "segments", "before", "after", "placement_g", "added_mass_g")


def _sidecar(path: Path) -> dict:
    """A sidecar's contents less its provenance."""
    data = json.loads(Path(f"{path}.json").read_text())
    return {k: data[k] for k in SUMMARY if k in data}


def _parameters(path: Path) -> dict:
    """The parameters a sidecar's provenance records."""
    return json.loads(Path(f"{path}.json").read_text())["parameters"]


def test_modes(cfg, capsys):
    cli = run_json(capsys, "modes", "--config", "run.toml")
    fm = cfg.modes()
    p = fm.props
    py = {"mass_kg": p.mass, "cg_m": p.cg, "cg_x_over_l": p.cg_over_length}
    py.update(inertia_cg_kg_m2=p.inertia, length_m=p.length, frequencies_hz=fm.frequencies.tolist())
    same(py_json(py), {k: cli[k] for k in py})
    assert len(cli["frequencies_hz"]) == 3  # [modes] count


def test_fit_writes_the_commands_files(cfg, capsys):
    cli = run_json(capsys, "fit", "--config", "run.toml", "--out", "cli.vtu")
    frame = cfg.fit(out="py.vtu")
    segments = [
        {"length_m": s.length, "ei_n_m2": s.EI, "rhoa_kg_m": s.rhoA} for s in frame.segments
    ]
    same(py_json(segments), cli["segments"])
    same(py_json(frame.summary()), {k: v for k, v in cli.items() if k != "mesh"})  # all of it
    assert frame.fitted["mass_kg"] == pytest.approx(0.318, rel=1e-9)  # the fit meets its target
    assert Path("py.vtu").read_bytes() == Path("cli.vtu").read_bytes()
    assert _sidecar(Path("py.vtu")) == _sidecar(Path("cli.vtu")) != {}
    assert _parameters(Path("py.vtu"))["out"] == "py.vtu"  # the method's out, not [fit]'s
    assert cfg.fit().segments == frame.segments  # without out: the same frame, no file
    assert sorted(p.name for p in Path().iterdir()) == sorted(
        ["run.toml", "cli.vtu", "cli.vtu.json", "py.vtu", "py.vtu.json"]
    )


def test_customise_writes_the_commands_files(cfg, capsys):
    argv = ("customise", "--config", "run.toml", "--out", "cli.vtu", "--maps", "cli_maps.nc")
    cli = run_json(capsys, *argv)
    result = cfg.customise(out="py.vtu")
    summary = py_json(result.summary())  # everything the command reports, maps included,
    assert set(summary) == set(cli) - {"mesh", "maps_file"}  # but the paths it wrote
    same(summary, {k: cli[k] for k in summary})
    assert [m.name for m in result.maps] == ["before", "customised"]
    assert result.mesh is result.customisation.mesh and result.total > 0
    assert Path("py.vtu").read_bytes() == Path("cli.vtu").read_bytes()
    assert _sidecar(Path("py.vtu")) == _sidecar(Path("cli.vtu"))
    assert _parameters(Path("py.vtu"))["out"] == "py.vtu"
    xr = pytest.importorskip("xarray")
    with xr.open_dataset("py_maps.nc") as a, xr.open_dataset("cli_maps.nc") as b:
        assert set(a.data_vars) == set(b.data_vars) != set()
        for name in a.data_vars:
            np.testing.assert_array_equal(a[name].values, b[name].values, err_msg=name)
    with pytest.raises(InputError, match=r"^customise\.maps = 'py_maps\.nc' is not allowed"):
        cfg.customise()  # maps without out: the command writes no maps without the mesh
    Path("no_maps.toml").write_text(RUN.replace('maps = "py_maps.nc"\n', ""))
    files = sorted(Path().iterdir())
    assert load_config("no_maps.toml").customise().summary() == result.summary()
    assert sorted(Path().iterdir()) == files  # without out: no file


def test_closest(cfg, capsys):
    cli = run_json(capsys, "closest", CSV, "--config", "run.toml")
    matches = cfg.closest(CSV)
    same(py_json([m.summary() for m in matches]), cli["rackets"])
    assert len(matches) == 2


def test_compare_writes_the_commands_files(cfg, capsys):
    from fem_racket.studies.compare import differences

    # compare has no option for the ball, the solver or a hand: it refuses them, as the command
    # does (tests/cli/test_refusals_runfile.py), so they leave its file
    text = RUN
    for table in ("[ball]\nmass_kg = 0.058\n", "[solver]\nmodes = 30\n", '[hand]\ngrip = "firm"\n'):
        text = text.replace(table, "")
    Path("run.toml").write_text(text)
    cfg = load_config("run.toml")
    cli = run_json(capsys, "compare", "standard", "rigid+3/9:6", "--config", "run.toml",
                   "--out", "cli.nc")  # fmt: skip
    reports = cfg.compare(["standard", "rigid+3/9:6"], out="py.nc")
    same(py_json([{"name": r.map.name, **r.values()} for r in reports]), cli["rackets"])
    ((name, theirs),) = cli["differences"].items()  # the second minus the first
    diffs = differences(reports)[name]
    same(py_json({k: diffs[k] for k in theirs}), theirs)
    xr = pytest.importorskip("xarray")
    with xr.open_dataset("py.nc") as a, xr.open_dataset("cli.nc") as b:
        assert json.loads(a.attrs["run_parameters"])["out"] == ["py.nc"]
        assert set(a.data_vars) == set(b.data_vars) != set()
        for name in a.data_vars:
            np.testing.assert_array_equal(a[name].values, b[name].values, err_msg=name)


@pytest.mark.parametrize("rackets", ["standard", Path("standard")])
def test_compare_refuses_one_set_up_for_a_list(cfg, rackets):
    with pytest.raises(InputError, match=r"^rackets = 'standard' is not allowed: must be a list"):
        cfg.compare(rackets)


def test_calibrate_writes_the_commands_files(cfg, capsys):
    from fem_racket.io.calibration_files import calibration_summary

    cli = run_json(capsys, "calibrate", "--config", "run.toml", "--out", "cli")
    cal = cfg.calibrate(out="py")
    same(py_json(calibration_summary(cal)), cli)
    assert cli["targets"] == "itf" and cli["family"] == "hysteretic"
    stem = "hysteretic-itf"
    assert Path(f"py/{stem}.toml").read_text() == Path(f"cli/{stem}.toml").read_text()
    py, theirs = (json.loads(Path(f"{d}/{stem}.json").read_text()) for d in ("py", "cli"))
    assert py.pop("provenance")["software"] == theirs.pop("provenance")["software"]
    assert py == theirs
    assert Path(f"py/{stem}.png").stat().st_size > 0


@pytest.mark.slow
def test_reproduce_writes_the_commands_files(cfg, capsys, monkeypatch):
    text = RUN + '[reproduce]\nquick = true\nout = "cli"\nreport = "cli.md"\n'
    Path("run.toml").write_text(text)
    code, out, err = run(capsys, "reproduce", "--config", "run.toml", "--quiet")
    assert code == 0, err
    result = reproduce_file(load_config("run.toml"), "py", "py.md")
    assert f"{result.counts()['agrees']} agree" in out
    ours = sorted(p.name for p in Path("py").iterdir())
    assert ours == sorted(p.name for p in Path("cli").iterdir())
    for name in ours:
        if name.endswith(".csv"):  # the figures' data: the same numbers
            assert Path("py", name).read_text() == Path("cli", name).read_text(), name


def test_the_methods_read_the_commands_tables():
    # every key of each command's table, with the command's default (but out: no file unless
    # given); json and quiet only say how the command prints, taken where its parser has them
    from fem_racket.cli.commands.config import _commands
    from fem_racket.cli.options.runfile import file_options
    from fem_racket.io import config_modes, config_racket, config_reports
    from fem_racket.io.config_tables import PRINT_KEYS
    from fem_racket.paper.config_reproduce import REPRODUCE_OPTIONS

    tables = {
        "modes": config_modes.MODES_OPTIONS,
        "fit": config_racket.FIT_OPTIONS,
        "customise": config_racket.CUSTOMISE_OPTIONS,
        "closest": config_racket.CLOSEST_OPTIONS,
        "compare": config_reports.COMPARE_OPTIONS,
        "calibrate": config_reports.CALIBRATE_OPTIONS,
        "reproduce": REPRODUCE_OPTIONS,
    }
    commands = _commands()
    for command, options in tables.items():
        cli = {d: a.default for d, a in file_options(commands[command]).items()}
        assert set(cli) == set(options) | set(PRINT_KEYS[command]), command
        for dest, (default, _) in options.items():
            assert default == (None if dest == "out" else cli[dest]), (command, dest)


def test_the_methods_play_with_the_commands_defaults():
    # the speed, swing and elements the methods take unless the core tables say: the parsers'
    from fem_racket.cli.commands.config import _commands
    from fem_racket.io.config_defaults import FRAME_ELEMENTS, PLAY_DEFAULTS
    from fem_racket.io.config_racket import CUSTOMISE_OPTIONS
    from fem_racket.io.customise_files import CUSTOMISE_OUTPUT, customise_maps

    commands = _commands()
    for command in ("customise", "compare", "modes"):
        cli = {a.dest: a.default for a in commands[command]._actions}
        assert cli["elements"] == FRAME_ELEMENTS, command
        if command != "modes":
            assert {k: cli[k] for k in PLAY_DEFAULTS} == PLAY_DEFAULTS, command
    # the maps: beside the mesh unless named, in the command and the method alike
    maps = next(a for a in commands["customise"]._actions if a.dest == "maps")
    out = next(a for a in commands["customise"]._actions if a.dest == "out")
    assert maps.default is None and CUSTOMISE_OPTIONS["maps"][0] is None
    assert Path(out.default) == CUSTOMISE_OUTPUT
    assert customise_maps(CUSTOMISE_OUTPUT) == Path("output") / "customised_map.png"


@pytest.mark.parametrize(
    ("command", "table", "words"),
    [
        ("modes", "[modes]\ncount = 0\n", "count = 0 is not allowed"),
        ("fit", "[fit]\nlength = 0.685\nelements = 2\n", "elements = 2 is not allowed"),
        ("fit", "[fit]\nmass = 0.3\n", "length is required"),
        ("customise", '[customise]\nswing_weight = "330:320"\n', "need 0 < LOW <= HIGH"),
        ("customise", "[customise]\nspeed = 30\n", "customise.speed"),
        ("closest", "[closest]\ncount = 1.5\n", "closest.count = 1.5 is not allowed"),
        ("compare", '[compare]\ngrip = "tight"\n', "compare.grip = 'tight' is not allowed"),
        ("compare", "[compare]\npoint = 1.5\n", "position = 1.5 x/L is not allowed"),
        ("calibrate", '[calibrate]\nfamily = "nope"\n', "calibrate.family = 'nope' is not"),
        ("reproduce", "[reproduce]\ndpi = 10\n", "dpi = 10"),
        ("fit", "[fit]\nlength = 0.685\nquiet = true\n", "fit.quiet is not a known key"),
        ("compare", "[compare]\nquiet = true\n", "compare.quiet is not a known key"),
        ("reproduce", "[reproduce]\njson = true\n", "reproduce.json is not a known key"),
    ],
)
def test_refused_alike(cwd, capsys, command, table, words):
    operands = {"closest": [CSV], "compare": ["standard", "rigid"]}.get(command, [])
    methods = {
        "closest": lambda c: c.closest(CSV),
        "compare": lambda c: c.compare(["standard", "rigid"]),
        "reproduce": lambda c: reproduce_file(c, "py", "py.md"),
    }
    method = methods.get(command, lambda c: getattr(c, command)())
    argv = (command, *operands, "--config", "run.toml")
    file_refused_alike(capsys, table, argv, method, words)
