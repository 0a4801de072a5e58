"""A design problem's description states the swing's reference point only with a swing (a
racket speed other than 0), as a sweep's file does: at rest no point's speed is given."""

from __future__ import annotations

from fem_racket.studies.design.build import design_problem


def test_no_reference_at_rest():
    rest = design_problem(racket_speed=0.0, pivot=0.2).describe()["swing"]
    assert "reference_x_over_l" not in rest
    assert rest["head_speed_m_s"] == 0.0 and rest["pivot_m"] == 0.2  # the rest is kept
    assert design_problem().describe()["swing"] is None  # no swing model: as before


def test_the_reference_with_a_swing():
    swing = design_problem(racket_speed=10.0, reference=0.6).describe()["swing"]
    assert swing["reference_x_over_l"] == 0.6 and swing["head_speed_m_s"] == 10.0
    assert design_problem(racket_speed=10.0).describe()["swing"]["reference_x_over_l"] == 0.75
