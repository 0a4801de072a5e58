"""``oblique_sweep`` refuses, in one line naming both, a value of its base incidence that an
axis given replaces (the sweep would drop it silently): ``base.friction`` with ``frictions``,
``base.angle`` (``angles`` is always the axis), ``base.spin`` with ``spins``, the side angle and
side spin with theirs. Without the axis the base's value is the sweep's (the spin too)."""

from __future__ import annotations

import pytest

from fem_racket.impact.incidence import Incidence
from fem_racket.impact.simulate_oblique import simulate_oblique
from fem_racket.studies.oblique_sweep import oblique_sweep
from tests.clirun import library_error


@pytest.mark.parametrize(
    ("kwargs", "line"),
    [
        (dict(frictions=[0.2, 0.8], base=Incidence(friction=0.6)),
         "base.friction = 0.6 is not allowed with frictions = [0.2, 0.8]: the axis replaces the "
         "base incidence's friction (give one of them)"),
        (dict(base=Incidence(angle=20.0)),
         "base.angle = 20.0 is not allowed with angles = [30.0]: the axis replaces the base "
         "incidence's angle (give one of them)"),
        (dict(spins=[0.0, 100.0], base=Incidence(spin=500.0)),
         "base.spin = 500.0 is not allowed with spins = [0.0, 100.0]: the axis replaces the base "
         "incidence's spin (give one of them)"),
        (dict(side_angles=[5.0], base=Incidence(side_angle=10.0)),
         "base.side_angle = 10.0 is not allowed with side_angles = [5.0]: the axis replaces the "
         "base incidence's side_angle (give one of them)"),
        (dict(side_spins=[5.0], base=Incidence(side_spin=10.0)),
         "base.side_spin = 10.0 is not allowed with side_spins = [5.0]: the axis replaces the "
         "base incidence's side_spin (give one of them)"),
    ],
)  # fmt: skip
def test_a_base_value_an_axis_replaces_is_refused(kwargs, line):
    assert library_error(lambda: oblique_sweep(angles=[30.0], clamped=True, **kwargs)) == line


def test_the_base_at_its_defaults_or_without_the_axis_runs():
    both = oblique_sweep(angles=[30.0], frictions=[0.2], base=Incidence(friction=0.4),
                         clamped=True)  # fmt: skip
    assert list(both.friction) == [0.2]  # the base's friction at its default: nothing dropped
    spun = oblique_sweep(angles=[30.0], base=Incidence(spin=500.0), clamped=True)
    assert list(spun.spin_rpm) == [500.0]  # no spins axis: the base's spin, not 0
    ref = simulate_oblique(incidence=Incidence(angle=30.0, spin=500.0), clamped=True).summary()
    assert float(spun["spin_out_rpm"][0, 0, 0]) == pytest.approx(ref["spin_out_rpm"], rel=1e-12)
    plain = oblique_sweep(angles=[30.0], clamped=True)
    assert list(plain.spin_rpm) == [0.0]  # the default spin, as before
