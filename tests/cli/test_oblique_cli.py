"""fem-racket simulate with an oblique, spinning ball (--angle, --spin, ..., --clamped)."""

import json
import math

import pytest

from fem_racket.impact.incidence import Incidence
from fem_racket.impact.oblique.stroke import Stroke
from fem_racket.impact.simulate_oblique import simulate_oblique
from fem_racket.impact.simulate_stroke import simulate_stroke
from fem_racket.impact.swing import Swing
from tests.clirun import run, run_json


def test_the_issues_stroke_on_a_clamped_head(capsys):
    # issue 26's done-when command prints the outgoing spin, angle and regime
    code, out, _ = run(capsys, "simulate", "--angle", "40", "--spin", "-3820", "--speed", "25",
                       "--clamped")  # fmt: skip
    assert code == 0
    lines = {line[:28].strip(): line[28:].split() for line in out.splitlines()}
    ref = simulate_oblique(incidence=Incidence(40.0, -3820.0), speed=25.0, clamped=True)
    s = ref.summary()
    assert float(lines["spin out"][0]) == pytest.approx(s["spin_out_rpm"], rel=1e-4)
    assert float(lines["angle out"][0]) == pytest.approx(s["angle_out_deg"], rel=1e-4)
    assert lines["contact regime"] == [s["contact_regime"]]
    assert lines["structure"] == ["clamped", "head"]


def test_json_is_the_library_call(capsys):
    argv = ("simulate", "--angle", "30", "--spin", "1000", "--friction", "0.3", "--ball-inertia",
            "0.55", "--compliance-ratio", "2", "--position", "0.7")  # fmt: skip
    data = run_json(capsys, *argv)
    inc = Incidence(angle=30.0, spin=1000.0, friction=0.3, ball_inertia=0.55, compliance_ratio=2.0)
    ref = simulate_oblique(incidence=inc, speed=20.0, position=0.7).summary()
    for key in ("ball_speed_out_m_s", "angle_out_deg", "spin_out_rpm", "contact_regime", "cor"):
        assert data[key] == ref[key]
    assert data["normal_speed_m_s"] == pytest.approx(20 * math.cos(math.radians(30)), rel=1e-15)


def test_a_stroke_is_the_library_call(capsys):
    argv = ("simulate", "--face-angle", "80", "--path-angle", "19", "--racket-speed", "15",
            "--pivot", "0.1", "--spin", "-1000")  # fmt: skip
    data = run_json(capsys, *argv)
    ref = simulate_stroke(
        incidence=Incidence(spin=-1000.0), stroke=Stroke(80.0, 19.0), speed=20.0,
        swing=Swing.from_speed(15.0, 0.68, pivot=0.1),
    ).summary()  # fmt: skip
    for key in ("launch_angle_deg", "spin_out_rpm", "ball_speed_out_m_s", "angle_deg"):
        assert data[key] == ref[key]


def test_out_writes_the_tangential_histories(capsys, tmp_path):
    f = tmp_path / "oblique.json"
    code, _, _ = run(capsys, "simulate", "--angle", "50", "--out", f)
    assert code == 0
    data = json.loads(f.read_text())
    h = data["history"]
    assert {"time [s]", "slip velocity [m/s]", "tangential force [N]", "contact force [N]"} <= set(
        h
    )
    assert data["summary"]["angle_deg"] == 50.0
    csv = tmp_path / "oblique.csv"
    assert run(capsys, "simulate", "--angle", "50", "--clamped", "--out", csv)[0] == 0
    assert csv.read_text().splitlines()[0].startswith("time [s],slip velocity [m/s]")


@pytest.mark.parametrize(
    "argv, message",
    [
        (("--angle", "90"), "angle = 90.0 deg is not allowed: must lie in [0, 90)"),
        (("--friction", "-1"), "friction = -1.0 is not allowed"),
        (("--clamped", "--position", "0.6"), "--position is not allowed with --clamped"),
        (("--clamped", "--output-step", "1e-6"), "--output-step is not allowed with --clamped"),
        (
            ("--angle", "30", "--grip", "firm", "--side-spin", "300"),
            "side_angle and side_spin are not allowed with a hand",
        ),
        (("--clamped", "--grip", "firm"), "a hand is not allowed with --clamped"),
        (("--ball-inertia", "0.9"), "ball_inertia = 0.9 is not allowed"),
        (("--path-angle", "19"), "path_angle = 19.0 deg is not allowed without a swing"),
        (("--face-angle", "80", "--angle", "5"), "angle = 5.0 deg is not allowed with a stroke"),
        (("--face-angle", "80", "--clamped", "--racket-speed", "5"), "--racket-speed is not"),
    ],
)
def test_bad_oblique_input_is_one_line_exit_2(capsys, argv, message):
    code, _, err = run(capsys, "simulate", *argv)
    assert code == 2
    assert message in err and len(err.strip().splitlines()) == 1
