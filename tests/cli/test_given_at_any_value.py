"""One rule for simulate (issue 21.3): an option given that the chosen solver or law does not
take is refused at any value, its default too (before, it passed as "neutral" when it equalled
the default or asked for what the solver does anyway); an option left out is never refused, and
leaving it out gives the same numbers, bit for bit. A swing's reference point given without a
swing is refused in one line, the same everywhere (simulate, sweep, map, a run file)."""

from pathlib import Path

import pytest

import fem_racket as fr
from fem_racket import load_config
from fem_racket.studies.map_options import MapPlay
from fem_racket.studies.sweep import sweep_result
from tests.clirun import library_error, one_error, refused_alike, run_json, run_ok

#: Combinations accepted as "neutral" before: (argv, simulate's keywords, the refusal's start).
NEUTRAL_BEFORE = {
    "law-basis": (
        ("--law", "hunt-crossley", "--basis", "modal"),
        {"law": "hunt-crossley", "basis": "modal"},
        "basis = 'modal' is not allowed with solver 'general': it takes tolerance",
    ),
    "exact-rtol": (
        ("--solver", "exact", "--rtol", "1e-10"),
        {"solver": "exact", "rtol": 1e-10},
        "rtol = 1e-10 is not allowed with solver 'exact': it takes tolerance",
    ),
    "exact-basis": (
        ("--solver", "exact", "--basis", "modal"),
        {"solver": "exact", "basis": "modal"},
        "basis = 'modal' is not allowed with solver 'exact': it solves in the free-free modes",
    ),
    "cvode-tolerance": (
        ("--solver", "cvode", "--tolerance", "0"),
        {"solver": "cvode", "tolerance": 0.0},
        "tolerance = 0.0 is not allowed with solver 'cvode': it takes rtol",
    ),
}
#: A swing's reference point given without a swing: the one line every path refuses it with.
AT_REST = "reference = 0.75 x/L is not allowed without a swing: give racket_speed (--racket-speed)"
SWEEP = ("sweep", "--speeds", "20", "--positions", "0.7", "--serial", "--quiet", "--out", "s.nc")
MAP = ("map", "--no-files", "--positions", "0.5:0.9:3")


def _said(line: str) -> str:
    return line.split(": error: ", 1)[1]


@pytest.mark.parametrize("name", list(NEUTRAL_BEFORE))
def test_an_option_the_solver_does_not_take_is_refused_at_its_default(capsys, cwd, name):
    argv, kwargs, words = NEUTRAL_BEFORE[name]
    line = _said(one_error(capsys, "simulate", *argv))
    assert line.startswith(words), line
    said = library_error(lambda: fr.simulate(output_step=None, **kwargs))
    assert said.startswith(words), said
    assert not any(Path().iterdir())


def test_left_out_the_numbers_are_those_of_the_options_taken_at_their_defaults(capsys):
    # bit for bit: an option left out is the solver's default, whatever the path
    law = run_json(capsys, "simulate", "--law", "hunt-crossley")
    taken = run_json(capsys, "simulate", "--law", "hunt-crossley", "--tolerance", "1e-6")
    one = fr.simulate(law="hunt-crossley", output_step=None).summary()
    assert law["cor"] == taken["cor"] == one["cor"]
    exact = run_json(capsys, "simulate", "--solver", "exact")
    taken = ("--modes", "80", "--tolerance", "1e-6")
    assert exact == run_json(capsys, "simulate", "--solver", "exact", *taken)
    assert exact["cor"] == fr.simulate(output_step=None).summary()["cor"]
    cvode = run_json(capsys, "simulate", "--solver", "cvode")
    taken = run_json(capsys, "simulate", "--solver", "cvode", "--rtol", "1e-10", "--basis", "modal")
    assert cvode == taken


def test_the_example_run_file_runs_as_is_with_the_default_numbers(capsys, cwd):
    # every key at its default: none given, so none refused (the reference point among them)
    Path("run.toml").write_text(run_ok(capsys, "config", "--example"))
    assert run_json(capsys, "simulate", "--config", "run.toml") == run_json(capsys, "simulate")
    assert load_config("run.toml").simulate().cor == fr.simulate(output_step=None).cor


@pytest.mark.parametrize(
    "argv",
    [("simulate",), SWEEP, MAP, ("compare", "standard", "rigid", "--positions", "0.5:0.9:3")],
    ids=["simulate", "sweep", "map", "compare"],
)
def test_a_reference_given_without_a_swing_is_refused_in_one_line(capsys, cwd, argv):
    assert _said(one_error(capsys, *argv, "--reference", "0.75")) == AT_REST
    assert not any(Path().iterdir())


def test_the_library_refuses_the_reference_without_a_swing_with_the_same_line():
    for call in (
        lambda: sweep_result(speed=[20.0], position=[0.7], reference=0.75),
        lambda: fr.racket_map(reference=0.75),
        lambda: fr.face_map(positions=[0.6, 0.7], offsets=[0.0, 0.02], reference=0.75),
        lambda: MapPlay(reference=0.75),
    ):
        assert library_error(call) == AT_REST


@pytest.mark.parametrize(
    ("command", "method"),
    [
        ("simulate", lambda cfg: cfg.simulate()),
        ("map", lambda cfg: cfg.map()),
        ("sweep", lambda cfg: cfg.sweep(backend="serial")),
    ],
)
def test_a_run_files_reference_without_a_swing_is_refused_as_the_command(
    capsys, cwd, command, method
):
    # the Python run file's simulate dropped it (and a pivot) without a word before
    Path("run.toml").write_text("[impact]\nreference_x_over_l = 0.6\n[sweep]\nout = 's.nc'\n")
    argv = [command, "--config", "run.toml", *(("--serial",) if command == "sweep" else ())]
    if command == "map":
        argv.append("--no-files")
    words = "run.toml: impact.reference_x_over_l = 0.6 x/L is not allowed without a swing"
    refused_alike(capsys, argv, lambda: method(load_config("run.toml")), words, start=True)


def test_the_run_files_pivot_without_a_swing_is_refused_in_python_too(cwd):
    Path("run.toml").write_text("[impact]\npivot_m = 0.1\n")
    said = library_error(lambda: load_config("run.toml").simulate())
    assert said.startswith("run.toml: impact.pivot_m = 0.1 m is not allowed without a swing")


def test_with_a_swing_the_reference_left_out_is_the_string_centre(capsys, cwd):
    swing = ("simulate", "--racket-speed", "10", "--pivot", "0.1")
    assert run_json(capsys, *swing) == run_json(capsys, *swing, "--reference", "0.75")
    assert fr.Swing.from_speed(10.0, 0.68, pivot=0.1) == fr.Swing.from_speed(
        10.0, 0.68, reference=0.75, pivot=0.1
    )
    Path("run.toml").write_text("[impact]\nracket_speed_m_s = 10.0\npivot_m = 0.1\n")
    left = load_config("run.toml").simulate().summary()
    assert left["cor"] == run_json(capsys, *swing)["cor"]
