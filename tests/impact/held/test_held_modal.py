"""The held racket's exact path (impact/held_modal.py) and its shock measures (held_shock.py),
against CVODE in physical coordinates (impact/held.py) and closed forms."""

from __future__ import annotations

import numpy as np
import pytest

from fem_racket.frame.hand import FIRM_GRIP, LOOSE_GRIP, Hand
from fem_racket.impact.held.basis import held_basis
from fem_racket.impact.held.grip import simulate_held
from fem_racket.impact.held.modal import held_contact
from fem_racket.impact.held.shock import grip_peak, vibration_energy, vibration_rms
from fem_racket.impact.problem import ImpactProblem
from fem_racket.impact.simulate import simulate
from fem_racket.validation import AccuracyError, InputError

GRIPS = {"loose": LOOSE_GRIP, "firm": FIRM_GRIP}


@pytest.fixture(scope="module")
def bases(standard_model):
    return {name: held_basis(standard_model.fe, h) for name, h in GRIPS.items()}


def check_against_cvode(model, basis, hand, position, speed):
    ref = simulate_held(ImpactProblem.build(model, hand=hand, position=position, speed=speed))
    c = held_contact(basis, position=position, speed=speed, tolerance=None)
    # Both solve the same linear ODE (CVODE at rtol 1e-10; here exactly, every mode): the
    # measured differences are ~1e-11 in COR and t_c, ~1e-8 of the peak in F_h.
    assert c.cor == pytest.approx(ref.cor, abs=1e-8)
    assert c.contact_time == pytest.approx(ref.contact_time, rel=1e-8)
    # at the times before separation, then at each one's own t_c (the rigid part drops to 0
    # after it, with the contact force)
    t = np.append(ref.t[:-1], c.contact_time)
    total, rigid = c.grip_force(t)
    scale = np.max(np.abs(ref.grip_force))
    assert np.max(np.abs(total - ref.grip_force)) < 1e-6 * scale
    assert np.max(np.abs(rigid - ref.grip_force_rigid)) < 1e-6 * scale
    assert np.max(np.abs(total)) == pytest.approx(np.max(np.abs(ref.grip_force)), rel=1e-6)
    # CVODE's peak is root-found between its output times (audit A7), so it is the exact peak
    # over the contact (measured within 3e-9 here; the exact peak's grid and zoom alone give ~2e-9)
    peak = ref.summary()["peak_grip_force_n"]
    assert grip_peak(c, None) == pytest.approx(peak, rel=1e-8)
    # the exact peak over the contact is at least the peak at CVODE's output times
    assert grip_peak(c, None) >= np.max(np.abs(ref.grip_force)) * (1 - 1e-9)


def test_exact_path_matches_cvode(standard_model, bases):
    check_against_cvode(standard_model, bases["firm"], FIRM_GRIP, 0.8, 30.0)


@pytest.mark.slow
@pytest.mark.parametrize("grip", ["loose", "firm"])
@pytest.mark.parametrize(("position", "speed"), [(0.6, 20.0), (0.77, 40.0), (0.95, 30.0)])
def test_exact_path_matches_cvode_everywhere(standard_model, bases, grip, position, speed):
    check_against_cvode(standard_model, bases[grip], GRIPS[grip], position, speed)


@pytest.mark.parametrize("grip", ["loose", "firm"])
def test_truncation_converges(bases, grip):
    # The engine's rule (impact/reduction.py): COR within its tolerance; the shock's RMS
    # converges as fast (measured <= 2e-5 relative at tolerance 1e-6), its peak more slowly
    # (high-mode ripple, ~1e-3 at 1e-6), as the contact time does.
    b = bases[grip]
    for position in (0.6, 0.77, 0.9):
        full = held_contact(b, position=position, speed=30.0, tolerance=None)
        rms, peak = vibration_rms(full), grip_peak(full)
        errors = []
        for tol in (1e-4, 1e-6, 1e-8):
            c = held_contact(b, position=position, speed=30.0, tolerance=tol)
            assert c.modes < full.modes
            errors.append(
                (
                    abs(c.cor - full.cor),
                    abs(vibration_rms(c) / rms - 1),
                    abs(grip_peak(c) / peak - 1),
                )
            )
        cor, rel_rms, rel_peak = np.array(errors).T
        assert cor[1] < 2e-6 and cor[2] < 1e-7  # 1.5x the cutoff's calibrated tolerance
        assert rel_rms[1] < 1e-4 and rel_rms[2] < 1e-6
        assert rel_peak[2] < 1e-4 and rel_peak[2] < rel_peak[0]


def test_energy_closed_form_matches_quadrature(bases):
    c = held_contact(bases["loose"], position=0.9, speed=30.0, tolerance=1e-6)
    t = np.linspace(0.0, 0.05, 100_001)
    total, rigid = c.grip_force(t)
    v2 = (total - rigid) ** 2
    trapezoid = np.sum(v2[1:] + v2[:-1]) * 0.5 * (t[1] - t[0])
    # trapezoid error ~ dt^2 F''/12 relative ~1e-6 on 0.5 us steps
    assert vibration_energy(c, 0.05) == pytest.approx(trapezoid, rel=1e-5)
    assert vibration_rms(c, 0.05) == pytest.approx(np.sqrt(trapezoid / 0.05), rel=1e-5)
    assert grip_peak(c, 0.05) == pytest.approx(np.max(np.abs(total)), rel=1e-6)


def test_vibration_part_carries_no_net_impulse(bases):
    # Nothing but the grip acts on the hand, and every flexible mode is damped by the grip:
    # int_0^inf F_h dt = m_h v_h(inf) = the rigid part's impulse, so int_0^inf F_v dt = 0.
    for name, b in bases.items():
        c = held_contact(b, position=0.7, speed=25.0, tolerance=1e-6)
        contact = np.real(np.sum(c.vib * np.expm1(c.lam * c.contact_time) / c.lam))
        after = np.real(np.sum(-c.free / c.mu))
        rigid = np.real(np.sum(c.rigid * np.expm1(c.lam * c.contact_time) / c.lam))
        assert abs(contact + after) < 1e-8 * abs(rigid), name


def test_a_feather_hand_leaves_the_free_racket(standard_model):
    # A 1 mg hand on a 1 N/m^2 grip: the free racket's exact COR (impact/closed_form.py).
    b = held_basis(standard_model.fe, Hand(mass=1e-6, stiffness=1.0, damping=0.0))
    for position in (0.6, 0.8):
        held = held_contact(b, position=position, speed=30.0, tolerance=None)
        free = simulate(
            standard_model, position=position, speed=30.0, output_step=None, tolerance=None
        )
        assert held.cor == pytest.approx(free.cor, abs=1e-7)
        assert held.contact_time == pytest.approx(free.contact_time, rel=1e-6)


def test_bad_inputs(standard_model, bases):
    with pytest.raises(InputError, match="grip stiffness = 0.0"):
        held_basis(standard_model.fe, Hand(stiffness=0.0))
    with pytest.raises(AccuracyError, match="rigid-body modes are not separated"):
        held_basis(standard_model.fe, Hand(stiffness=1e-9))
    c = held_contact(bases["loose"], position=0.75, speed=20.0)
    with pytest.raises(InputError, match="window = 0.001 s"):
        vibration_rms(c, 0.001)
    with pytest.raises(InputError, match="position = 1.5"):
        held_contact(bases["loose"], position=1.5)
