"""Implausible implements are refused naming the likely unit slip (issue 22, deliverable 2)."""

import math

import pytest

from fem_racket import Frame, FrameMesh, FrameModel, Segment, standard_frame
from fem_racket.frame.plausible import FREQUENCY_RANGE, check_implement
from fem_racket.validation import InputError


def test_the_frequency_estimate_is_the_uniform_beams_first_mode():
    # Independent path: the FE model's first flexible mode of a uniform free-free beam is
    # (4.7300 / L)^2 sqrt(EI / rhoA) / (2 pi) (Blevins, Formulas for natural frequency, table 8-1).
    # The check's estimate uses that closed form; 80 elements converge it to ~1e-7.
    length, ei, rhoa = 0.86, 3000.0, 1.05  # a bat-like beam: 0.9 kg
    model = FrameModel.build(Frame((Segment(length, ei, rhoa),)), 80)
    f_fe = model.modes(1).omega[0] / (2.0 * math.pi)
    f_closed = 4.730040744862704**2 / (2.0 * math.pi * length**2) * math.sqrt(ei / rhoa)
    assert f_fe == pytest.approx(f_closed, rel=1e-6)
    check_implement(model.mesh)
    factor = (1.01 * FREQUENCY_RANGE[1] / f_fe) ** 2  # just above the highest frequency
    too_stiff = FrameMesh(model.mesh.points, model.mesh.EI * factor, model.mesh.rhoA)
    with pytest.raises(InputError, match="N mm\\^2"):
        check_implement(too_stiff)


@pytest.mark.parametrize(
    "frame",
    [
        standard_frame(),  # the paper's racket, 0.36 kg, 0.68 m
        Frame((Segment(0.26, 30.0, 0.35),)),  # a table-tennis bat: 0.09 kg
        Frame((Segment(0.965, 5000.0, 1.3),)),  # a cricket bat: 1.25 kg
        Frame((Segment(0.68, 20.0, 0.12),)),  # a badminton racket: 0.08 kg
    ],
)
def test_bats_and_paddles_pass(frame):
    assert check_implement(frame) is frame


@pytest.mark.parametrize(
    ("scale", "words"),
    [
        ((1e3, 1.0, 1.0), ("length = 680 m", "a mesh in millimetres? 680 mm = 0.68 m")),
        ((1.0, 1.0, 1e3), ("mass = 360 kg", "rhoA in g/m? 360 g = 0.36 kg")),
        ((1.0, 1e6, 1.0), ("frequency", "N mm^2")),
        ((1.0, 1e-6, 1.0), ("frequency", "limp")),
        ((1e-3, 1.0, 1.0), ("length = 0.00068 m",)),
    ],
)
def test_unit_slips_are_named(scale, words):
    m = FrameModel.build(None, 20).mesh
    mesh = FrameMesh(m.points * scale[0], m.EI * scale[1], m.rhoA * scale[2])
    with pytest.raises(InputError) as err:
        check_implement(mesh, "mesh = 'r.vtu'")
    msg = str(err.value)
    assert msg.startswith("mesh = 'r.vtu'") and "\n" not in msg
    assert all(w in msg for w in words), msg
