"""The library's maps of the oblique ball refuse the tangential contact's parameters when no
case is oblique or spinning (no tangential force acts in any), as simulate, sweep and the
spin map refuse them: ``oblique_sweep`` over angles and spins all 0 (its frictions axis given
at any value, its base incidence's contact parameters away from their defaults) and
``oblique_map`` with a head-on, spinless incidence; with any angle or spin in the grid they
run."""

import pytest

from fem_racket.impact.incidence import Incidence
from fem_racket.studies.oblique_sweep import oblique_map, oblique_sweep
from tests.clirun import library_error

WHY = "is not allowed without an oblique or spinning ball: give angle, spin (or their side "


@pytest.mark.parametrize(
    ("kwargs", "words"),
    [
        (dict(angles=[0.0], frictions=[0.2, 0.8]), "frictions = [0.2, 0.8]"),
        (dict(angles=[0.0], spins=[0.0], frictions=[0.4]), "frictions = [0.4]"),
        (dict(angles=[0.0], base=Incidence(radius=0.03)), "radius = 0.03"),
        (dict(angles=[0.0], base=Incidence(compliance_ratio=1.0)), "compliance_ratio = 1.0"),
        (dict(angles=[0.0], side_spins=[0.0], base=Incidence(friction=0.6)), "friction = 0.6"),
    ],
)
def test_oblique_sweep_refuses_them_head_on(kwargs, words):
    line = library_error(lambda: oblique_sweep(clamped=True, **kwargs))
    assert line.startswith(f"{words} {WHY}"), line


def test_oblique_map_refuses_them_head_on():
    line = library_error(
        lambda: oblique_map(positions=[0.6, 0.7], incidence=Incidence(friction=0.8))
    )
    assert line.startswith(f"friction = 0.8 {WHY}"), line


@pytest.mark.parametrize(
    "kwargs",
    [
        dict(angles=[0.0, 10.0], frictions=[0.2, 0.8]),
        dict(angles=[0.0], spins=[0.0, 1000.0], frictions=[0.2]),
        dict(angles=[0.0], side_spins=[0.0, 500.0], base=Incidence(radius=0.03)),
        dict(angles=[0.0]),  # head-on, the contact at its defaults: nothing given, it runs
    ],
)
def test_they_run_with_an_angle_or_a_spin(kwargs):
    assert oblique_sweep(clamped=True, **kwargs)["spin_out_rpm"].size >= 1
