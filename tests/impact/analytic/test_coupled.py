"""Coupled ball + frame modes (section 4.2, eqs 13-16) against closed forms and the simulation."""

import numpy as np
import pytest

from fem_racket import InputError, coupled_modes, mode_nodes, rigid_impact, simulate

V0 = 20.0


def rigid_closed_form(model, position, speed=V0):
    props = model.props
    kcb = coupled_modes(model, position, speed=speed).kcb
    d = position * props.length - props.cg
    return rigid_impact(0.057, props.mass, props.inertia, d, kcb, speed)


@pytest.mark.parametrize("position", [0.55, 0.60, 0.75, 0.90, 0.95])
def test_eq14_terms_add_up_to_the_impact_speed(standard_model, position):
    cm = coupled_modes(standard_model, position, speed=V0)
    total = cm.v_translation + cm.v_rotation + cm.velocity_terms.sum()
    # Exact identity sum_j psi_j psi_j^T = M^-1; eigh round-off only.
    assert total == pytest.approx(V0, rel=1e-12)
    assert cm.ball_velocity(0.0)[0] == pytest.approx(V0, rel=1e-12)
    assert np.all(cm.velocity_terms >= 0.0)


@pytest.mark.parametrize("position", [0.60, 0.75, 0.90])
def test_eqs_8_to_10_and_15_rigid_terms_match_the_rigid_frame(standard_model, position):
    cm = coupled_modes(standard_model, position, speed=V0)
    rig = rigid_closed_form(standard_model, position)
    # Same zero-frequency space as the rigid frame: equal to eigen-solver round-off (~1e-9 m/s).
    assert cm.v_translation == pytest.approx(rig.v_translation, abs=1e-8)
    assert cm.v_rotation == pytest.approx(rig.v_rotation, abs=1e-8)
    assert cm.v_vibration == pytest.approx(rig.v_vibration, abs=1e-8)  # eq 15


def test_rigid_terms_do_not_depend_on_frame_rigidity(standard_model, rigid_model):
    a = coupled_modes(standard_model, 0.65)
    b = coupled_modes(rigid_model, 0.65)
    # Section 4.2: the zero-frequency modes involve no frame stiffness (round-off ~1e-8 m/s).
    assert a.v_translation + a.v_rotation == pytest.approx(b.v_translation + b.v_rotation, abs=1e-6)
    assert a.frequencies[0] < b.frequencies[0]


@pytest.mark.parametrize("position", [0.60, 0.80])
def test_eq13_reproduces_the_simulated_undamped_impact(standard_model, position):
    r = simulate(standard_model, position=position, speed=V0, zeta=0.0, output_step=2e-5)
    cm = coupled_modes(standard_model, position, speed=V0)
    # Independent paths (exact reduced-state integrator vs undamped eigenmodes): agree to
    # round-off, observed ~1e-9 m/s and ~1e-12 m.
    np.testing.assert_allclose(cm.ball_velocity(r.t), r.ball_velocity, atol=1e-7)
    np.testing.assert_allclose(cm.deflection(r.t), r.deflection, atol=1e-10)


def test_at_the_mode1_node_the_frame_frequency_is_a_system_frequency(standard_model):
    fm = standard_model.modes(1)
    node = mode_nodes(standard_model.fe, fm.shapes[:, 0])[-1]
    cm = coupled_modes(standard_model, node, speed=V0)
    k = int(np.argmin(np.abs(cm.frequencies - fm.frequencies[0])))
    # Frame mode 1 is decoupled there (a_1 = 0 to brentq's 1e-14 m): exact up to round-off.
    assert cm.frequencies[k] == pytest.approx(fm.frequencies[0], rel=1e-9)
    assert cm.velocity_terms[k] < 1e-10 * V0
    # The paper's rounded node 0.769 L (0.0007 L away): nearly so (observed 0.14 % of V_I).
    cp = coupled_modes(standard_model, 0.769, speed=V0)
    k = int(np.argmin(np.abs(cp.frequencies - fm.frequencies[0])))
    assert cp.frequencies[k] == pytest.approx(fm.frequencies[0], abs=0.05)
    assert cp.velocity_terms[k] < 0.005 * cp.v_vibration


@pytest.mark.parametrize("position", [0.55, 0.65, 0.77, 0.85, 0.95])
def test_eq16_elastic_rebound_never_exceeds_the_rigid_one(standard_model, position):
    r = simulate(standard_model, position=position, speed=V0, zeta=0.0, output_step=None)
    rig = rigid_closed_form(standard_model, position)
    assert abs(r.rebound_velocity) <= abs(rig.rebound_velocity) + 1e-9


def test_higher_system_modes_carry_little(standard_model):
    # Section 4.2 / conclusion (1): system modes 3+ matter little (observed < 0.4 % of V_I).
    for position in (0.60, 0.769):
        cm = coupled_modes(standard_model, position)
        assert cm.velocity_terms[2:].sum() < 0.01 * cm.v_vibration


def test_frame_dofs_of_a_system_mode_satisfy_the_eigenproblem(standard_model):
    cm = coupled_modes(standard_model, 0.6)
    fe = standard_model.fe
    g = fe.point_vector(0.6 * fe.mesh.length)
    q, ub, om2 = cm.frame_dofs(0), cm.ball_amplitude(0), cm.omega[0] ** 2
    delta = ub - g @ q
    # Frame: K q - om^2 M q = kcb delta g; ball: -om^2 m_B u_B = -kcb delta.
    lhs = fe.K @ q - om2 * (fe.M @ q)
    np.testing.assert_allclose(lhs, cm.kcb * delta * g, atol=1e-6 * np.abs(fe.K @ q).max())
    assert om2 * cm.ball_mass * ub == pytest.approx(cm.kcb * delta, rel=1e-8)


@pytest.mark.parametrize(
    "kwargs, name",
    [
        ({"position": 1.5}, "position"),
        ({"position": 0.6, "kcb": -1.0}, "kcb"),
        ({"position": 0.6, "speed": 0.0}, "speed"),
        ({"position": 0.6, "ball_mass": -1}, "mass"),
    ],
)
def test_bad_input_is_named(standard_model, kwargs, name):
    with pytest.raises(InputError, match=name):
        coupled_modes(standard_model, **kwargs)
