"""Property-based tests (hypothesis) over random valid frames, impact points and speeds.

Frames: 1-5 uniform segments, total length 0.5-0.8 m (the paper's is 0.68 m), EI 50-3000 N m^2
(the range of the paper's Fig 13), rhoA 0.2-1.2 kg/m (the paper's 0.458 and 0.696 inside it);
impact anywhere from the grip end to the tip; speeds 5-50 m/s (K_CB from the paper's law).

Properties: linear and angular momentum of ball + free frame conserved during contact; energy
conserved without damping and balanced by the dashpot's work with it; -1 <= COR <= 1; a positive,
finite contact time; the exact and CVODE integrators agree to 1e-6.

The default profile is derandomized (the same examples every run, so CI is reproducible); run
``HYPOTHESIS_PROFILE=explore python -m pytest tests/impact/test_properties.py`` to search new ones.
"""

from __future__ import annotations

import math

import numpy as np
from hypothesis import given, settings
from hypothesis import strategies as st
from strategies import PROFILE, frames

from fem_racket import FrameModel, simulate


def budget(n: int) -> settings:
    """``n`` examples in CI (keeps this file under ~60 s); the profile's count when exploring."""
    return settings(max_examples=n if PROFILE == "ci" else settings.default.max_examples)


ELEMENTS = 20  # the paper's mesh


positions = st.floats(0.0, 1.0)
speeds = st.floats(5.0, 50.0)


def _impact(frame, position, speed, **kw):
    return simulate(FrameModel.build(frame, ELEMENTS), position=position, speed=speed, **kw)


@budget(25)
@given(frame=frames(), position=positions, speed=speeds)
def test_momentum_conserved_during_contact(frame, position, speed):
    r = _impact(frame, position, speed)
    p, h = r.momentum()
    p0 = r.ball.mass * speed
    # No external force acts on ball + free frame: both are constant. The closed-form path
    # builds them from eigenvectors of a well-conditioned modal system: round-off ~1e-13
    # measured; 1e-9 leaves room for conditioning.
    assert np.max(np.abs(p - p0)) <= 1e-9 * p0
    # Angular momentum about the grip end, scaled by p0 * L (x_i may be 0).
    h0 = r.x_impact * p0
    assert np.max(np.abs(h - h0)) <= 1e-9 * p0 * frame.length


@budget(25)
@given(frame=frames(), position=positions, speed=speeds)
def test_energy_conserved_without_damping(frame, position, speed):
    r = _impact(frame, position, speed, zeta=0.0)
    e = r.energies()
    e0 = 0.5 * r.ball.mass * speed**2
    assert np.all(e["dissipated"] == 0.0)
    # Kinetic + strain + spring energy of the undamped system is exact in the closed form:
    # only round-off (measured up to 2e-11 relative; before the modal frequencies were taken as
    # Rayleigh quotients, eigh's eps * omega_max^2 / omega_1^2 error gave 1e-9 here).
    assert np.max(np.abs(e["total"] - e0)) <= 1e-9 * e0


@budget(25)
@given(frame=frames(), position=positions, speed=speeds)
def test_energy_balanced_by_dashpot_work(frame, position, speed):
    # The dashpot's work is the one quadrature here (cumulative Simpson on the output times), so
    # the output step must resolve the fastest frame mode kept: 20 points per period of the
    # 20th mode (a consistent truncated system; all 40 modes would need steps of ~0.05 us).
    model = FrameModel.build(frame, ELEMENTS)
    step = min(1e-6, 1.0 / (20.0 * model.modes(20).frequencies[-1]))
    r = simulate(model, position=position, speed=speed, modes=20, output_step=step)
    e = r.energies()
    e0 = 0.5 * r.ball.mass * speed**2
    assert 0.0 < e["dissipated"][-1] < e0
    # Simpson's error on a sinusoid sampled 20 times a period is (2 pi / 20)^4 / 180 = 5e-5 of
    # its share of the dissipated energy, and the fastest modes carry a small share:
    # measured up to 2e-9 of e0 over 200 random frames. 1e-7 bounds that.
    assert np.max(np.abs(e["total"] - e0)) <= 1e-7 * e0


@budget(40)
@given(frame=frames(), position=positions, speed=speeds)
def test_cor_and_contact_time_are_physical(frame, position, speed):
    r = _impact(frame, position, speed, output_step=None)
    assert -1.0 <= r.cor <= 1.0
    assert math.isfinite(r.contact_time) and r.contact_time > 0.0
    # The ball leaves no faster than it came (COR <= 1 above) and the contact is no longer
    # than the default time limit, 20 x the eq 11 estimate pi sqrt(m_B / K_CB) (which is the
    # contact time of a clamped frame).
    assert r.contact_time < 20.0 * math.pi * math.sqrt(r.ball.mass / r.contact.stiffness)


@budget(12)
@given(frame=frames(), position=positions, speed=speeds)
def test_exact_and_cvode_agree(frame, position, speed):
    model = FrameModel.build(frame, ELEMENTS)
    # 20 modes keep CVODE fast (~50 ms; the highest kept frequency sets its step) and the
    # comparison is between integrators of the same system. The issue asks for 1e-6.
    kw = {"position": position, "speed": speed, "modes": 20, "output_step": None}
    # Every one of those modes in the exact path too (tolerance None): the engine's default
    # tolerance bounds the COR, not the contact time, which converges more slowly.
    exact = simulate(model, tolerance=None, **kw)
    cvode = simulate(model, solver="cvode", **kw)
    assert abs(exact.cor - cvode.cor) <= 1e-6
    assert abs(exact.contact_time - cvode.contact_time) <= 1e-6 * exact.contact_time


@budget(3)
@given(frame=frames(), position=positions, speed=speeds)
def test_exact_and_cvode_agree_with_all_modes(frame, position, speed):
    model = FrameModel.build(frame, ELEMENTS)
    kw = {"position": position, "speed": speed, "modes": None, "output_step": None}
    exact = simulate(model, tolerance=None, **kw)
    cvode = simulate(model, solver="cvode", **kw)  # ~0.5-1.5 s: every FE mode kept
    assert abs(exact.cor - cvode.cor) <= 1e-6  # the bound
    assert abs(exact.contact_time - cvode.contact_time) <= 1e-6 * exact.contact_time
