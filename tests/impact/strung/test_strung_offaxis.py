"""The string bed struck off the racket's axis: the point (x, y) on the membrane, the ring's
twist, symmetry, momentum and angular momentum, exact against CVODE."""

import numpy as np
import pytest

from fem_racket.contact.bed_ball import BALL_STIFFNESS, BALL_ZETA, kawazoe_ball
from fem_racket.impact.exact.engine import EngineOptions, modal_impacts
from fem_racket.impact.offaxis import combined_modes, combined_point_vector
from fem_racket.impact.strung.exact import strung_exact
from fem_racket.impact.strung.impact import strung_engine, strung_impact
from fem_racket.impact.strung.point import strung_point
from fem_racket.strings.bed import StringBed
from fem_racket.validation import InputError

MB = 0.057
V = 30.0
X = 0.74  # the head's centre (x/L)
Y = 0.05  # [m] across the axis


def _engine(p):
    out = strung_engine(p, BALL_STIFFNESS, BALL_ZETA, MB, V, tolerance=None)
    return float(out.cor), float(out.contact_time)


@pytest.mark.parametrize("edge", ["point", "hoop"])
def test_mirror_symmetric_and_off_axis_differs(standard_model, edge):
    # y -> -y: the same impact (the disk mesh is mirror symmetric: measured 3e-13 in COR); off
    # the axis the bed is stiffer (nearer its edge) and the roll takes energy: lower COR
    # (Brody 2005; measured at 30 m/s, y = 5 cm: 0.377 -> 0.282 with edge "point").
    bed = StringBed(edge=edge)
    on = strung_point(standard_model, bed, X)
    plus, minus = (strung_point(standard_model, bed, X, y) for y in (Y, -Y))
    assert plus.rigid_count == 3 and on.rigid_count == 2
    a, b = _engine(plus), _engine(minus)
    assert a[0] == pytest.approx(b[0], abs=1e-11) and a[1] == pytest.approx(b[1], rel=1e-11)
    assert plus.bed_stiffness > on.bed_stiffness
    assert a[0] < _engine(on)[0] - 0.05


def test_twist_basis_at_zero_offset_is_the_bending_one(standard_model):
    # The off-axis basis (bending + torsion, roll) at y = 0 gives the on-axis impact: the torsion
    # values vanish, so the structure is today's to round-off (1e-12).
    p = strung_point(standard_model, StringBed(), X)
    cm = combined_modes(standard_model, None)
    L = standard_model.mesh.length
    a = cm.all_shapes.T @ combined_point_vector(standard_model, X * L, 0.0)
    assert np.all(a[cm.is_torsion] == 0.0)
    w = np.concatenate([cm.omega, p.omega[p.bed]])
    order = np.argsort(w, kind="stable")
    values = np.concatenate([a[3:], p.a[p.bed]])[order]
    ref = modal_impacts(w[order], values, float(np.sum(a[:3] ** 2)), speed=V, kcb=BALL_STIFFNESS,
                        zeta=BALL_ZETA, ball_mass=MB,
                        options=EngineOptions(tolerance=None))  # fmt: skip
    cor, tc = _engine(p)
    assert float(ref.cor) == pytest.approx(cor, abs=1e-12)
    assert float(ref.contact_time) == pytest.approx(tc, rel=1e-12)
    # and a tiny offset is continuous with it (the disk quadrature's kinks: measured 2.6e-10)
    assert _engine(strung_point(standard_model, StringBed(), X, 1e-7))[0] == pytest.approx(
        cor, abs=1e-9
    )


@pytest.mark.parametrize("edge", ["point", "hoop"])
def test_momentum_and_roll(standard_model, edge):
    # The frame's momentum is the ball's impulse J = m_B V (1 + e); its roll's angular momentum
    # about the long axis is y J (the force acts at y; I_p theta' = sqrt(I_p) eta_roll').
    p = strung_point(standard_model, StringBed(edge=edge), X, Y)
    law = kawazoe_ball(MB)
    tc, states = strung_exact(p, law, MB, V)
    x, v = states(np.linspace(0.0, tc, 5))
    e = -v[-1, 0] / V
    J = MB * V * (1.0 + e)
    I_p = standard_model.torsion.modes().polar_moment
    assert v[-1, 1] / p.a[0] == pytest.approx(J, rel=1e-12)
    assert np.sqrt(I_p) * v[-1, 3] == pytest.approx(Y * J, rel=1e-12)
    assert p.a[2] == pytest.approx(Y / np.sqrt(I_p), rel=1e-12)  # the roll: y / sqrt(I_p)
    # exact against CVODE (rtol 1e-10) on a coarser frame and fewer bed modes (every mode of the
    # structure either way; CVODE's dense Jacobian grows with them): measured 7e-14 in COR
    from fem_racket import FrameModel, standard_frame

    small = strung_point(FrameModel.build(standard_frame(), 8), StringBed(edge=edge), X, Y,
                         bed_modes=12)  # fmt: skip
    exact = strung_impact(small, law, MB, V, solver="exact")
    cv = strung_impact(small, law, MB, V, solver="cvode")
    assert cv.cor == pytest.approx(exact.cor, abs=1e-10)
    assert cv.contact_time == pytest.approx(exact.contact_time, abs=1e-11)


def test_offset_through_simulate_and_off_the_head(standard_model):
    from fem_racket.impact.simulate import simulate

    out = simulate(standard_model, strings=StringBed(), position=X, offset=Y, speed=V)
    assert out.point.lateral_m == Y and out.summary()["offset_m"] == Y
    J = MB * V * (1.0 + out.cor)  # the roll rate: I_p Omega = y J
    I_p = standard_model.torsion.modes().polar_moment
    assert out.summary()["roll_rate_rad_s"] == pytest.approx(Y * J / I_p, rel=1e-12)
    assert out.cor == pytest.approx(_engine(strung_point(standard_model, StringBed(), X, Y))[0],
                                    abs=1e-10)  # fmt: skip
    with pytest.raises(InputError, match="must lie on the head"):
        simulate(standard_model, strings=StringBed(), position=X, offset=0.13)


def test_vtk_off_axis_ring_twists(standard_model):
    # The drawn bed's edge (edge "point") moves with the ring at the impact point, w + y theta;
    # the frame carries its twist (the roll is y J / I_p per unit time after the impact).
    from fem_racket.impact.strung.impact import simulate_strung
    from fem_racket.io.strung_vtk import frame_twist, strung_fields
    from fem_racket.strings.membrane import bed_mesh

    r = simulate_strung(standard_model, StringBed(), position=X, offset=Y, speed=V)
    p = r.point
    nodes, bed = strung_fields(r, standard_model)
    twist = frame_twist(r, standard_model)
    mesh = bed_mesh(p.strings.head_length_m, p.strings.head_width_m, p.refine)
    L = standard_model.mesh.length
    g = combined_point_vector(standard_model, X * L, Y)
    ring = (r.coordinates[:, 1:][:, ~p.bed] @ p.frame_shapes.T) @ g
    edge = bed[:, mesh.basis.mesh.boundary_nodes()]
    assert np.allclose(edge, ring[:, None], rtol=0, atol=1e-15)
    assert twist.shape == nodes.shape and np.abs(twist[-1]).max() > 0.0
    on_axis = simulate_strung(standard_model, StringBed(), position=X)
    assert frame_twist(on_axis, standard_model) is None
