"""The tangential contact's options (friction, ball inertia and radius, compliance ratio) change
nothing on a head-on, spinless ball: given without an angle or spin they are refused in one
line, alike by the command line, the run file, simulate and sweep (as --path-angle without
--racket-speed is). A run file's key at its default is not given; with an angle or a spin
they run."""

import pytest

import fem_racket as fr
from fem_racket.impact.incidence import Incidence
from fem_racket.impact.simulate_oblique import simulate_oblique
from tests.clirun import library_error, one_error, run_ok

WHY = "is not allowed without an oblique or spinning ball: give angle, spin (or their side "


@pytest.mark.parametrize(
    ("argv", "words"),
    [
        (("--friction", "0.8"), "friction = 0.8"),
        (("--friction", "0.4"), "friction = 0.4"),  # given at its default: refused alike
        (("--ball-radius", "0.03"), "ball_radius = 0.03"),
        (("--ball-inertia", "0.4"), "ball_inertia = 0.4"),
        (("--compliance-ratio", "1"), "compliance_ratio = 1.0"),
        (("--angle", "0", "--spin", "0", "--friction", "0.8"), "friction = 0.8"),
        (("--clamped", "--friction", "0.8"), "friction = 0.8"),
        (("--string-tension", "250", "--friction", "0.8"), "friction = 0.8"),
    ],
)
def test_simulate_refuses_them_head_on(capsys, argv, words):
    line = one_error(capsys, "simulate", *argv)
    assert f"{words} {WHY}" in line, line


def test_sweep_refuses_them_head_on(capsys):
    line = one_error(capsys, "sweep", "--positions", "0.6,0.7", "--friction", "0.8", "--quiet")
    assert f"friction = 0.8 {WHY}" in line, line
    words = library_error(lambda: fr.sweep(position=[0.6, 0.7], friction=0.8))
    assert words.startswith(f"friction = 0.8 {WHY}")


def test_the_library_refuses_them_head_on():
    idle = Incidence(friction=0.8)
    assert library_error(lambda: fr.simulate(incidence=idle)).startswith(f"friction = 0.8 {WHY}")
    words = library_error(lambda: simulate_oblique(incidence=idle, clamped=True))
    assert words.startswith(f"friction = 0.8 {WHY}")
    words = library_error(lambda: fr.simulate(incidence=Incidence(radius=0.03)))
    assert words.startswith(f"radius = 0.03 {WHY}")


def test_run_file(cwd, capsys):
    with open("run.toml", "w") as f:
        f.write("[oblique]\nfriction = 0.8\n")
    line = one_error(capsys, "simulate", "--config", "run.toml")
    assert f"oblique.friction = 0.8 {WHY}" in line, line
    with open("run.toml", "w") as f:
        f.write("[oblique]\nfriction = 0.4\n")  # at its default: not given
    assert "ball speed out" in run_ok(capsys, "simulate", "--config", "run.toml")


def test_the_example_run_file_runs_as_is(cwd, capsys):
    with open("run.toml", "w") as f:
        f.write(run_ok(capsys, "config", "--example"))
    assert "coefficient of restitution" in run_ok(capsys, "simulate", "--config", "run.toml")


@pytest.mark.parametrize("extra", [("--angle", "20"), ("--spin", "1000"), ("--side-spin", "500")])
def test_they_run_with_an_angle_or_a_spin(capsys, extra):
    assert "ball speed out" in run_ok(capsys, "simulate", *extra, "--friction", "0.8")
