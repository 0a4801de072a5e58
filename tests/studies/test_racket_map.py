"""racket_map against one simulate() per point, and its input checks."""

from __future__ import annotations

import numpy as np
import pytest

from fem_racket.impact.simulate import simulate
from fem_racket.impact.swing import Swing
from fem_racket.studies.racket_map import racket_map
from fem_racket.validation import InputError


def test_curves_are_simulate_at_each_point(standard_model):
    x = np.array([0.55, 0.7, 0.85, 0.95])
    m = racket_map(standard_model, speed=25.0, racket_speed=20.0, pivot=-0.4, positions=x)
    swing = Swing.from_speed(20.0, 0.68, pivot=-0.4)
    for k, p in enumerate(x):
        r = simulate(standard_model, position=p, speed=25.0, swing=swing, output_step=None)
        assert m.apparent_cor[k] == pytest.approx(r.apparent_cor, rel=1e-9)
        assert m.ball_speed_out[k] == pytest.approx(r.ball_speed_out, rel=1e-9)
        assert m.racket_speed[k] == pytest.approx(r.racket_speed_at_impact, rel=1e-12)


def test_the_refined_maximum_beats_every_grid_point(standard_model):
    x = np.linspace(0.5, 1.0, 11)
    m = racket_map(standard_model, racket_speed=15.0, pivot=0.1, positions=x)
    best = racket_map(
        standard_model, racket_speed=15.0, pivot=0.1, positions=[0.5, m.spots.max_ball_speed, 1.0]
    )
    assert best.ball_speed_out[1] >= m.ball_speed_out.max()
    lo, hi = m.spots.power_region
    assert lo < m.spots.max_ball_speed < hi


def test_the_linear_law_by_name_is_the_paper_s_map(standard_model):
    kwargs = dict(speed=25.0, racket_speed=20.0, pivot=0.1, positions=np.linspace(0.5, 1.0, 11))
    m, named = (
        racket_map(standard_model, **kwargs),
        racket_map(standard_model, **kwargs, law="linear"),
    )
    np.testing.assert_array_equal(m.apparent_cor, named.apparent_cor)
    np.testing.assert_array_equal(m.ball_speed_out, named.ball_speed_out)
    assert m.spots == named.spots and named.summary()["contact"] == {"law": "linear"}


def test_a_point_under_a_nonlinear_law_is_one_simulate(standard_model):
    x = np.array([0.55, 0.7, 0.85])
    m = racket_map(
        standard_model,
        speed=20.0,
        racket_speed=25.0,
        pivot=0.1,
        positions=x,
        law="kawazoe-1997-nonlinear",
    )
    assert m.summary(curves=False)["contact"]["law"] == "hysteretic"
    swing = Swing.from_speed(25.0, 0.68, pivot=0.1)
    for k, p in enumerate(x):
        # CVODE from the swing's velocity field; the map strikes the stationary racket at the
        # closing speed (exact for any law: studies/law_cases.py)
        r = simulate(
            standard_model,
            position=p,
            speed=20.0,
            swing=swing,
            law="kawazoe-1997-nonlinear",
            solver="cvode",
            output_step=None,
        )
        # the general integrator's COR error <= 1.2e-6 at its default tolerance 1e-6
        # (impact/general.py settings), a batch sharing the step of its shortest contact
        assert m.apparent_cor[k] == pytest.approx(r.apparent_cor, abs=2e-6)
        assert m.ball_speed_out[k] == pytest.approx(r.ball_speed_out, abs=1e-4)
    # max e_A refined between grid points by single-point runs
    assert 0.55 <= m.spots.max_apparent_cor <= 0.85


@pytest.mark.parametrize(
    ("kwargs", "message"),
    [
        ({"law": "hysteretic", "kcb": 5e4}, "kcb = 50000.0 is not allowed with contact law"),
        ({"law": "nonsense"}, "law = 'nonsense'"),
        ({"positions": [0.6, 0.7]}, "at least 3"),
        ({"positions": [0.6, 0.8, 0.7]}, "increasing"),
        ({"power_fraction": 1.5}, "power_fraction = 1.5"),
        ({"speed": -1.0}, "speed = -1"),
        ({"racket_speed": -50.0}, "must close"),
        # text is the command line's (as sweep's position): refused by its parser; other
        # values that are not numbers, and a label that is not text, in one line
        ({"positions": "abc"}, "position = 'abc' is not allowed: must be a number, a comma"),
        ({"positions": "0.5:0.9:2"}, "positions = 2 values"),
        ({"positions": ["a", "b", "c"]}, r"positions = \['a', 'b', 'c'\] is not allowed"),
        ({"name": 5}, "name = 5 is not allowed: must be a string"),
    ],
)
def test_bad_input(standard_model, kwargs, message):
    with pytest.raises(InputError, match=message):
        racket_map(standard_model, **kwargs)


@pytest.mark.parametrize(
    ("kwargs", "message"),
    [
        # what the law cannot use, refused by the general solver and the problem's own checks
        ({"law": "hunt-crossley", "modes": 10}, "modes = 10 is not allowed with solver 'general'"),
        ({"law": "hunt-crossley", "separation": "force"}, "separation = 'force' is not allowed"),
        ({"law": "hunt-crossley", "kcb_factor": 2.0}, "kcb_factor = 2.0 is not allowed"),
        # a model is meshed already (as ImpactProblem.build refuses it)
        ({"elements": 10}, "elements = 10 is not allowed with a FrameModel"),
        # a swing's point without a swing would be dropped; the pivot sets the COP at rest
        ({"reference": 0.6}, "reference = 0.6 x/L is not allowed without a swing"),
        # too many points, refused before the engine's arrays
        ({"positions": np.linspace(0.5, 0.9, 100_001)}, "positions = 100001 values"),
    ],
)
def test_what_the_map_would_drop_is_refused(standard_model, kwargs, message):
    with pytest.raises(InputError, match=message):
        racket_map(standard_model, **kwargs)


def test_apparent_cor_along_refuses_modes_under_a_law(standard_model):
    from fem_racket.contact.presets import get_law
    from fem_racket.studies.racket_map import apparent_cor_along

    law = get_law("hunt-crossley")
    with pytest.raises(InputError, match="modes = 10 is not allowed with solver 'general'"):
        apparent_cor_along(standard_model, [0.7], [20.0], law=law, modes=10)
    e = apparent_cor_along(standard_model, [0.7], [20.0], law=law)  # the law's own end condition
    assert e[0] == racket_map(standard_model, law=law, positions=[0.6, 0.7, 0.8]).apparent_cor[1]


def test_elements_mesh_a_frame_and_a_mesh_of_that_count_passes():
    from fem_racket.frame.mesh import frame_mesh
    from fem_racket.frame.segments import standard_frame

    x = [0.6, 0.7, 0.8]
    a = racket_map(standard_frame(), elements=20, positions=x).apparent_cor
    mesh = frame_mesh(standard_frame(), 20)
    assert np.array_equal(racket_map(mesh, elements=20, positions=x).apparent_cor, a)
    with pytest.raises(InputError, match="elements = 10 is not allowed with a mesh: it has 20"):
        racket_map(mesh, elements=10, positions=x)


def test_positions_as_the_command_line_gives_them(standard_model):
    # "0.5:0.9:5" is the CLI's start:stop:num, which fr.sweep(position=...) takes too
    a = racket_map(standard_model, positions="0.5:0.9:5")
    b = racket_map(standard_model, positions=np.linspace(0.5, 0.9, 5))
    assert np.array_equal(a.positions, b.positions)
    assert np.array_equal(a.apparent_cor, b.apparent_cor)
    assert racket_map(standard_model, positions="0.5,0.7,0.9").positions.tolist() == [0.5, 0.7, 0.9]
