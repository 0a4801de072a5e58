"""A frame without torsion data struck off its long axis: one line naming what the user gave
(the offset, offsets, side angle or side spin, or the spin map's default offsets when none was
given), the racket (in compare and map) and what is allowed (one home:
:func:`fem_racket.frame.torsion.check_off_axis`)."""

from __future__ import annotations

import pytest
from clirun import library_error, one_error, run_ok

from fem_racket.frame.model import FrameModel
from fem_racket.frame.segments import Frame, Segment
from fem_racket.studies.face_map import AXIS_ONLY, face_map

SPEC = ("--length", "0.685", "--mass", "0.318", "--balance", "0.32", "--swing-weight", "316")
WHY = (
    "it has no torsion data (GJ, rhoIp), so it is struck on its long axis only: {}; off the "
    "axis, give a frame with cell data GJ and rhoIp (torsion segments, or a mesh written by "
    "fem-racket fit --twist-weight)"
)

SPIN = WHY.format("the spin map's offsets cross the face (simulate --angle strikes on the axis)")


@pytest.fixture
def bare(capsys, cwd):
    """A fitted racket without torsion data, ``nt.vtu`` in the working folder."""
    run_ok(capsys, "fit", *SPEC, "--out", "nt.vtu")
    return "nt.vtu"


@pytest.mark.parametrize(
    ("argv", "given"),
    [
        (["--offset", "0.02"], "offset = 0.02 m"),
        (["--angle", "20", "--side-angle", "10"], "side_angle = 10.0 deg"),
        (["--angle", "20", "--side-spin", "100"], "side_spin = 100.0 rpm"),
        (["--offset", "0.02", "--string-tension", "250"], "offset = 0.02 m"),
    ],
)
def test_simulate_names_the_value(capsys, bare, argv, given):
    line = one_error(capsys, "simulate", "--mesh", bare, *argv)
    why = WHY.format("must be 0")
    assert line == f"fem-racket simulate: error: {given} is not allowed on this frame: {why}"


def test_compare_and_map_name_the_racket(capsys, bare):
    why = WHY.format("map it without offsets (along its axis)")
    line = one_error(
        capsys, "compare", "standard", bare, "--positions", "0.6:0.9:4", "--offsets",
        "-0.05,0,0.05", "--out", "cc.nc",
    )  # fmt: skip
    assert line.endswith(
        f"error: offsets = [-0.05, 0.0, 0.05] m is not allowed on racket 'nt': {why}"
    )
    line = one_error(
        capsys, "map", "--preset", "standard", "--mesh", bare, "--positions", "0.6,0.8",
        "--offsets=-0.05,0.05", "--no-files",
    )  # fmt: skip
    assert line.endswith(f"error: offsets = [-0.05, 0.05] m is not allowed on racket 'nt': {why}")
    line = one_error(
        capsys, "map", "--mesh", bare, "--positions", "0.6,0.8", "--angle", "30",
        "--offsets=-0.05,0.05", "--no-files",
    )  # fmt: skip
    assert line.endswith(f"error: offsets = -0.05,0.05 m is not allowed on racket 'nt': {SPIN}")


def test_spin_map_names_its_default_offsets(capsys, bare):
    line = one_error(
        capsys, "map", "--mesh", bare, "--positions", "0.6,0.8", "--angle", "30", "--no-files"
    )
    assert line == (
        "fem-racket map: error: offsets = -0.12:0.12:9 m (the spin map's default: no --offsets "
        f"given) is not allowed on racket 'nt': {SPIN}"
    )
    # on its long axis the same racket takes the oblique ball
    run_ok(capsys, "simulate", "--mesh", bare, "--angle", "30")


def test_face_map_library_names_the_racket():
    model = FrameModel.build(Frame((Segment(0.68, 146.0, 0.5),)))
    line = library_error(
        lambda: face_map(model, positions=[0.7, 0.8], offsets=[0.0, 0.05], name="bare")
    )
    assert (
        line == f"offsets = [0.0, 0.05] m is not allowed on racket 'bare': {WHY.format(AXIS_ONLY)}"
    )
