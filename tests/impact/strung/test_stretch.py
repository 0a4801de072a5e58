"""The strings' stretch in the dynamics: reduction to the linear bed, energy, the refit."""

import numpy as np
import pytest

from fem_racket.contact.hysteretic import Hysteretic
from fem_racket.contact.linear import LinearContact
from fem_racket.impact.strung.impact import strung_impact
from fem_racket.impact.strung.point import clamped_point
from fem_racket.impact.strung.stretch import bed_stretch, solve_stretch
from fem_racket.strings.bed import StringBed
from fem_racket.validation import InputError

MB = 0.057


@pytest.fixture(scope="module")
def point():
    return clamped_point(StringBed())


def _outcome(point, law, speed):
    t, y = solve_stretch(point, law, MB, speed)
    n = point.omega.size + 1
    return t, y, n


def test_unit_matrices_are_the_linear_bed(point):
    # N_x Gx + N_y Gy is the bed's modal stiffness diag(omega^2): the modes (and the pseudo-mode,
    # K- and M-orthogonal to them) diagonalise it (measured 4e-14 of the largest).
    st = bed_stretch(point)
    bed = point.strings
    K = bed.n_x * st.Gx + bed.n_y * st.Gy
    w2 = point.omega[st.index] ** 2
    assert np.max(np.abs(K - np.diag(w2))) < 1e-12 * w2.max()


def test_small_deflection_is_the_linear_bed(point):
    # The stretch is of order (deflection)^2: at 0.01 and 0.1 m/s the COR differs from the exact
    # linear path by 2.9e-9 and 2.6e-7 (measured): the difference scales as V^2.
    law = LinearContact(1.37e5, 0.4, MB)
    diff = []
    for V in (0.01, 0.1):
        t, y, n = _outcome(point, law, V)
        exact = strung_impact(point, law, MB, V, solver="exact")
        diff.append(abs(-y[-1, n] / V - exact.cor))
        assert t[-1] == pytest.approx(exact.contact_time, rel=1e-6)
    assert diff[0] < 1e-8
    assert diff[1] / diff[0] == pytest.approx(100.0, rel=0.2)


def test_elastic_ball_conserves_energy(point):
    # No damping: the ball's kinetic energy at the end plus the bed's (modes and the stretch
    # potential) is the energy it came with (CVODE rtol 1e-10: measured 2e-10).
    st = bed_stretch(point)
    for V in (20.0, 40.0):
        t, y, n = _outcome(point, LinearContact(1.37e5, 0.0, MB), V)
        x, v = y[-1, 1:n], y[-1, n + 1 :]
        bed = 0.5 * np.sum(v**2 + (point.omega * x) ** 2) + st.energy(x[st.index])[0]
        total = 0.5 * MB * y[-1, n] ** 2 + bed
        assert total == pytest.approx(0.5 * MB * V * V, rel=1e-8)
        assert st.energy(x[st.index])[0] > 0.0


def test_refit_linear_ball_of_the_docstring(point):
    # fem_racket.contact.bed_ball: a linear ball refitted with the stretch (nylon) to the 20 m/s
    # pair (4.53 ms, 0.83; paper sec. 2.1.1) gives 4.53 / 4.44 / 4.35 ms and COR 0.830 / 0.820 /
    # 0.809 at 20 / 30 / 40 m/s (the digits printed there).
    law = LinearContact(101235.2852, 0.2966864675, MB)
    got = []
    for V in (20.0, 30.0, 40.0):
        t, y, n = _outcome(point, law, V)
        got.append((t[-1] * 1e3, -y[-1, n] / V))
    assert np.allclose([g[0] for g in got], [4.53, 4.44, 4.35], atol=0.006)
    assert np.allclose([g[1] for g in got], [0.830, 0.820, 0.809], atol=0.0006)


def test_state_laws_refused(point):
    with pytest.raises(InputError, match="without an internal state"):
        solve_stretch(point, Hysteretic(3.182e15, 8.816e16, 8.913), MB, 20.0)


def test_stretching_bed_through_simulate():
    # StringBed(stretch=True): simulate's cvode path is solve_stretch's impact; the energy the
    # ball loses with an elastic ball is all in the racket (modes and stretch potential: 1e-7);
    # exact and general are refused in one line, as is a law with a state. (A coarse frame, 8
    # elements: CVODE's dense Jacobian grows with the modes.)
    from fem_racket import FrameModel, standard_frame
    from fem_racket.impact.simulate import simulate
    from fem_racket.impact.strung.point import strung_point

    standard_model = FrameModel.build(standard_frame(), 8)
    bed = StringBed(stretch=True)
    out = simulate(standard_model, strings=bed, position=0.75, speed=30.0, solver="cvode")
    p = strung_point(standard_model, bed, 0.75)
    t, y, n = _outcome(p, out.law, 30.0)
    assert out.cor == pytest.approx(-y[-1, n] / 30.0, abs=1e-14)
    assert out.contact_time == t[-1] and out.summary()["string_stretch"] is True
    linear = simulate(standard_model, strings=StringBed(), position=0.75, speed=30.0)
    assert out.contact_time < linear.contact_time  # the stiffer bed
    elastic = LinearContact(1.37e5, 0.0, MB)
    e = simulate(standard_model, strings=bed, law=elastic, position=0.75, speed=30.0,
                 solver="cvode")  # fmt: skip
    assert e.racket_energy == pytest.approx(e.ball_loss, rel=1e-7)
    for solver in ("exact", "general"):
        with pytest.raises(InputError, match="integrated by 'cvode'"):
            simulate(standard_model, strings=bed, solver=solver)
    auto = simulate(standard_model, strings=bed, position=0.75, speed=30.0)  # auto: cvode
    assert (auto.cor, auto.contact_time) == (out.cor, out.contact_time)
    with pytest.raises(InputError, match="without an internal state"):
        simulate(standard_model, strings=bed, law="hysteretic", solver="cvode")


def test_cli_string_stretch(capsys):
    from tests.clirun import run

    code, out, err = run(capsys, "simulate", "--string-stretch", "--speed", "40", "--elements", 8)
    assert code == 0, err
    assert "string stretch" in out and "cvode" in out
    code, plain, _ = run(capsys, "simulate", "--string-tension", "246", "--speed", "40",
                         "--elements", 8)  # fmt: skip
    assert "string stretch" not in plain

    def tc(text):
        line = next(ln for ln in text.splitlines() if ln.startswith("contact time"))
        return float(line.split()[2])

    assert tc(out) < tc(plain)
