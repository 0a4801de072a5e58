"""The strung racket's slack tail: friction acts only while the normal force presses (review H2).

At 100 N of string tension the bed's normal force history (801 samples, a cubic Hermite spline
of the impulse) keeps its samples positive while its force P' dips to -0.08 N between them, 8 us
before the first negative sample. The tangential contact was marched through that dip, where
mu F <= 0 leaves grip and slide undecided: it switched at one instant 200 times (a traceback,
"chattering") and the sweep gave NaN. The window of friction now ends where the force first
falls through zero. The oblique impact's history has OBLIQUE_SAMPLES (3 201) samples since;
the window ends there the same way (its dip is shallower)."""

from __future__ import annotations

import json
import math

import numpy as np
import pytest

import fem_racket.impact.strung.impact as strung_impact
import fem_racket.impact.tangential.normal as normal_module
from fem_racket.impact.incidence import Incidence
from fem_racket.impact.simulate import simulate
from fem_racket.impact.strung.impact import OBLIQUE_SAMPLES
from fem_racket.impact.tangential.release import first_release
from fem_racket.strings.bed import StringBed
from fem_racket.validation import InputError
from tests.clirun import one_error, run

REPRO = {"angle": 45.0, "spin": 5000.0, "friction": 1.0}


def _repro(model):
    return simulate(model, strings=StringBed(tension_n=100.0), incidence=Incidence(**REPRO))


@pytest.fixture(scope="module")
def repro(standard_model):
    return _repro(standard_model)


def test_reproducer_runs_and_its_phases_are_real(repro):
    sol = repro.tangential.solution
    line = getattr(sol, "line", sol)  # the 1-D march (a LineSolution wraps it on the face)
    normal, phases = line.normal, line.phases
    # friction acts until the force first stops pressing: it presses over the whole window
    # (round-off: 1e-12 of the peak) and the window ends at its first zero
    t = np.linspace(0.0, normal.end, 20001)
    peak = float(np.max(normal.force(t)))
    assert np.min(normal.force(t)) > -1e-12 * peak
    assert abs(float(normal.force(normal.end))) < 1e-9 * peak
    # contiguous phases over [0, end], none of zero length (shortest measured: 0.22 us of a
    # 5.3 ms contact; zero-length ones, 5e-15 s, were the chattering)
    assert phases[0].start == 0.0 and phases[-1].end == normal.end
    assert all(a.end == b.start for a, b in zip(phases, phases[1:], strict=False))
    assert min(p.end - p.start for p in phases) > 1e-5 * normal.end
    # the friction force never exceeds mu F (1e-9 of the peak: round-off at the switches)
    s, f = line.at(t)
    assert np.all(np.abs(f) <= REPRO["friction"] * np.maximum(normal.force(t), 0.0) + 1e-9 * peak)


def test_reproducer_creates_no_energy(repro):
    # the ball leaves with less kinetic energy (translation and spin) than it came with
    s = repro.summary()
    inc = repro.tangential.incidence
    m, R, V = repro.tangential.ball.mass, inc.radius, 20.0
    inertia = inc.ball_inertia * m * R * R
    w_in, w_out = (x * 2 * math.pi / 60 for x in (REPRO["spin"], s["spin_out_rpm"]))
    e_in = 0.5 * m * V * V + 0.5 * inertia * w_in**2
    e_out = 0.5 * m * s["ball_speed_out_m_s"] ** 2 + 0.5 * inertia * w_out**2
    assert e_out < e_in


#: The README's strung shot (246 N, 25 m/s, 40 deg, 3 820 rpm of backspin, mu 0.4).
SHOT = {"angle": 40.0, "spin": -3820.0}


def _shot(model):
    return simulate(model, strings=StringBed(), speed=25.0, incidence=Incidence(**SHOT))


# Spin out relative to 25 601 samples of the normal history, at 801 (the histories' own
# samples, the oblique's before), 3 201 (OBLIQUE_SAMPLES) and 12 801 (measured):
#   reproducer (100 N, 45 deg, 5 000 rpm, mu 1)   1.4e-5   1.6e-7   1.3e-9
#   the README's shot (246 N)                     6.3e-5   1.3e-7   2.0e-9
# 3 201 samples cost ~0.04 s more CPU per strung oblique impact than 801 (2 shared cores).
@pytest.mark.parametrize("case", [_repro, _shot], ids=["reproducer", "shot"])
def test_oblique_history_samples_are_converged(standard_model, monkeypatch, case):
    default = case(standard_model).summary()["spin_out_rpm"]
    spins = {}
    for n in (801, OBLIQUE_SAMPLES, 12801):
        monkeypatch.setattr(strung_impact, "OBLIQUE_SAMPLES", n)
        spins[n] = case(standard_model).summary()["spin_out_rpm"]
    assert spins[OBLIQUE_SAMPLES] == default
    err = {n: abs(s / spins[12801] - 1.0) for n, s in spins.items()}
    assert err[OBLIQUE_SAMPLES] < 1e-6, err
    assert err[801] > 10.0 * err[OBLIQUE_SAMPLES], err  # fourth order: 4x samples, ~100x less


def test_reproducer_converges_at_fine_samples(standard_model, monkeypatch):
    # 1 601, 3 201 and 6 401 samples agree to 5e-6 relative in ball speed, angle and spin out,
    # with 18 phases each (measured spreads: 9.9e-7, 3.4e-7 and 1.9e-6; 12 801 samples moves
    # the spin by 7e-9 more): the march converges as the normal history does, fourth order.
    # With k_n the secant at the output time of largest compression (main before this) the
    # tangential spring moved with the samples, and the spreads were 6.2e-5, 2.2e-5 and
    # 1.2e-4 (the spin 4466.45 rpm at 3 201 samples, 4465.92 at 6 401, 4466.18 at 12 801).
    keys = ("ball_speed_out_m_s", "angle_out_deg", "spin_out_rpm")
    rows, phases = [], []
    for n in (1601, 3201, 6401):
        monkeypatch.setattr(strung_impact, "OBLIQUE_SAMPLES", n)
        out = _repro(standard_model)
        rows.append([out.summary()[k] for k in keys])
        phases.append(len(getattr(out.tangential.solution, "line", out.tangential.solution).phases))
    spread = np.ptp(rows, axis=0) / np.abs(rows[-1])
    assert np.all(spread < 5e-6), dict(zip(keys, spread, strict=True))
    assert phases == [18, 18, 18]


def test_reproducer_on_the_command_line(capsys):
    argv = ["simulate", "--string-tension", "100", "--angle", "45", "--spin", "5000"]
    code, out, err = run(capsys, *argv, "--friction", "1.0", "--json")
    assert code == 0 and "Traceback" not in err, err
    assert math.isfinite(json.loads(out)["spin_out_rpm"])


def test_chattering_is_refused_in_one_line(standard_model, capsys, monkeypatch):
    # without the release (the march through the dip, as before), the march still stops, now
    # with one line naming the friction instead of a traceback; on the 801 samples of the
    # history that chattered (at 3 201 the dip is shallower and marched through unswitched)
    monkeypatch.setattr(normal_module, "first_release", lambda spline, end: None)
    monkeypatch.setattr(strung_impact, "OBLIQUE_SAMPLES", 801)
    with pytest.raises(InputError, match=r"^friction = 1.0 is not allowed for this impact"):
        _repro(standard_model)
    line = one_error(
        capsys, "simulate", "--string-tension", "100", "--angle", "45", "--spin", "5000",
        "--friction", "1.0",
    )  # fmt: skip
    assert "chattering" in line


def test_release_leaves_a_pressing_history_unchanged():
    # a force that presses until its last sample: the window ends where the samples say, as
    # before (bit for bit), and no earlier
    t = np.linspace(0.0, 1e-3, 81)
    f = 300.0 * np.sin(np.pi * t / 1e-3)
    f[-1] = -1.0
    p = 300.0e-3 / np.pi * (1.0 - np.cos(np.pi * t / 1e-3))
    n = normal_module.SampledNormal(t, p, f, 1e5)
    assert n.end > t[-2] and n.grid.size == t.size
    assert first_release(n._spline, n.end) is None


def _phases(model, tension, **incidence):
    out = simulate(model, strings=StringBed(tension_n=tension), incidence=Incidence(**incidence))
    sol = out.tangential.solution
    return out, getattr(sol, "line", sol)


def test_grazing_switch_leaves_no_zero_length_phase(standard_model):
    # A slide stopping just as the spring reaches mu F starts a grip whose margin has zero value
    # and slope (its curvature mu (F'' + omega_t^2 F) decides): decided by round-off at
    # t0 + 1e-12 end, the march switched back and forth at one instant (this case: 26 phases of
    # 5e-15 s among 60). Probed where the curvature shows, the grip holds: 34 phases, none
    # shorter than 4e-8 s, and the outcome the same to round-off (measured 4e-15 relative).
    out, line = _phases(
        standard_model, 50.0, angle=25.7, spin=5126.0, friction=1.2, compliance_ratio=0.05
    )
    lengths = [p.end - p.start for p in line.phases]
    assert min(lengths) > 1e-9 * line.normal.end
    assert all(a.end == b.start for a, b in zip(line.phases, line.phases[1:], strict=False))
    assert out.summary()["contact_regime"].startswith("grip-slide")


def test_an_early_undershoot_does_not_end_the_window(standard_model):
    # On a 50 N bed the ball's dashpot presses 1 275 N at t = 0, the next sample 30 N, and P'
    # dips to -45 N between them: the contact presses on (every sample > 0 until the end), so
    # the window is the samples' (7.39 ms of the 7.86 ms contact), not the undershoot's 6.5 us.
    out, line = _phases(standard_model, 50.0, angle=26.0, spin=5000.0, friction=1.2)
    n = line.normal
    assert first_release(n._spline, n.end) is None
    assert n.end > 0.9 * out.summary()["contact_time_s"]
