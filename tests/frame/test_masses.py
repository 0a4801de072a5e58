"""Added masses as strips: exact mass, balance and swing-weight changes (parallel-axis theorem)."""

import numpy as np
import pytest

from fem_racket import FrameModel, frame_mesh, standard_frame
from fem_racket.frame.masses import AddedMass, add_masses, strip_ends
from fem_racket.frame.modal import mass_properties
from fem_racket.validation import InputError


def props(mesh):
    return mass_properties(FrameModel.build(mesh).fe)


def test_strip_adds_its_mass_at_its_centre():
    mesh = frame_mesh(standard_frame(), 20)
    base = props(mesh)
    m, x = 0.03, 0.5
    out = props(add_masses(mesh, [AddedMass(x, m, 0.02)]))
    # exact: mass adds, first moment adds m * x_centre (strip symmetric about its centre)
    assert out.mass == pytest.approx(base.mass + m, rel=1e-13)
    xc = x * mesh.length
    assert out.cg == pytest.approx((base.mass * base.cg + m * xc) / (base.mass + m), rel=1e-13)
    # parallel axes: I_CG grows by the point-mass terms plus the strip's own m w^2 / 12
    i_new = base.inertia + base.mass * (base.cg - out.cg) ** 2 + m * (xc - out.cg) ** 2
    assert out.inertia == pytest.approx(i_new + m * 0.02**2 / 12, rel=1e-12)


def test_strip_at_the_tip_stays_on_the_frame():
    a, b = strip_ends(1.0, 0.02, 0.68)
    assert (a, b) == pytest.approx((0.66, 0.68), abs=1e-15)
    mesh = add_masses(frame_mesh(standard_frame(), 20), [AddedMass(1.0, 0.03)])
    assert mesh.length == pytest.approx(0.68, abs=1e-15)
    strip = mesh.points[1:] > 0.66 + 1e-12
    assert mesh.points[-1] - mesh.points[np.argmax(strip)] == pytest.approx(0.02, abs=1e-15)
    assert mesh.rhoA[-1] == pytest.approx(0.458 + 0.03 / 0.02)


@pytest.mark.parametrize(
    "kwargs",
    [
        {"position": 1.2, "mass": 0.01},
        {"position": 0.5, "mass": -0.01},
        {"position": 0.5, "mass": 0.01, "width": 0.0},
    ],
)
def test_bad_added_mass(kwargs):
    with pytest.raises(InputError):
        AddedMass(**kwargs)
