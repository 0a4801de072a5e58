"""The spin map over the face strikes every point with one ball (one Incidence); head-on and
spinless (no angle, spin, side angle or side spin) it meets no tangential force, so its contact
parameters (``--friction`` on ``map``; friction, inertia, radius and eta^2 in the library) change
nothing: refused in one line, as ``simulate`` and ``sweep`` refuse them, by the command line (at
any value), the library and the run file (a key at its default is not given)."""

import pytest

from fem_racket import load_config
from fem_racket.impact.incidence import Incidence
from fem_racket.studies.spin_map import spin_map
from tests.clirun import library_error, one_error, refused_before_any_file, run_ok

WHY = "is not allowed without an oblique or spinning ball: give angle, spin (or their side "
GRID = ("--positions", "0.6,0.7", "--offsets", "0,0.01")


@pytest.mark.parametrize(
    ("argv", "words"),
    [
        (("--friction", "0.8"), "friction = 0.8"),
        (("--friction", "0.4"), "friction = 0.4"),  # at its default: given all the same
        (("--angle", "0", "--spin", "0", "--friction", "0.8"), "friction = 0.8"),
        (("--side-angle", "0", "--side-spin", "0", "--friction", "0.6"), "friction = 0.6"),
    ],
)
def test_map_refuses_friction_head_on(cwd, capsys, argv, words):
    line = refused_before_any_file(capsys, "map", *GRID, *argv)
    assert f"{words} {WHY}" in line, line


@pytest.mark.parametrize(
    ("field", "value"),
    [("friction", 0.8), ("ball_inertia", 0.4), ("radius", 0.03), ("compliance_ratio", 1.0)],
)
def test_the_library_refuses_them_head_on(standard_model, field, value):
    idle = Incidence(**{field: value})
    words = library_error(
        lambda: spin_map(standard_model, positions=[0.6, 0.7], offsets=[0.0, 0.01], incidence=idle)
    )
    assert words.startswith(f"{field} = {value} {WHY}"), words


def test_run_file(cwd, capsys):
    with open("run.toml", "w") as f:
        f.write("[oblique]\nfriction = 0.8\n")
    words = f"run.toml: oblique.friction = 0.8 {WHY}"
    assert words in one_error(capsys, "map", "--config", "run.toml", "--no-files")
    assert library_error(lambda: load_config("run.toml").map()).startswith(words)
    with open("run.toml", "w") as f:
        f.write("[oblique]\nfriction = 0.4\n")  # at its default: not given (as simulate's)
    assert "spin out max" in run_ok(capsys, "map", "--config", "run.toml", "--no-files", *GRID)


@pytest.mark.parametrize("extra", [("--angle", "20"), ("--spin", "1000"), ("--side-spin", "500")])
def test_they_run_with_an_angle_or_a_spin(capsys, extra):
    out = run_ok(capsys, "map", "--no-files", *GRID, *extra, "--friction", "0.8")
    assert "spin out max" in out
