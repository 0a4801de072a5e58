"""Parts of the compiled march that issue 27's speed-ups changed.

- a power law's x^(n-1) from a nearby one by its Taylor series is pow's to round-off, and pow
  itself outside the series' range;
- each case starts from its own law exponent's step count and keeps its own histories: in a
  batch of laws with different exponents, every case's answer and histories are those it has
  alone, bit for bit.
"""

from __future__ import annotations

import numpy as np
import pytest

from fem_racket.contact.hunt_crossley import HuntCrossley
from fem_racket.impact.general.integrator import settings, solve_general
from fem_racket.impact.general.kernel_laws import power
from fem_racket.impact.general.vouch import first_steps
from fem_racket.impact.law_impact import receptance


@pytest.mark.parametrize("a", [0.0, 0.3, 1.0, 7.9, 13.9])
def test_power_from_a_nearby_power_is_pow_to_round_off(a):
    for b0 in (1e-7, 2.4e-3, 0.05):
        near = (b0, b0**a)
        limit = 1e-4 / (a + 4.0)
        for e in (1e-12, -3e-9, 2e-7, -0.999 * limit, 0.999 * limit):
            base = b0 * (1.0 + e)
            # the series' four terms: the rest is below 1e-18 relative
            assert power(base, a, near) == pytest.approx(base**a, rel=4e-16, abs=0.0)
        for e in (1.01 * limit, -0.5, 3.0):  # out of the series' range: pow itself
            base = b0 * (1.0 + e)
            assert power(base, a, near) == base**a
    assert power(0.0, a, (1e-3, 1e-3**a)) == 0.0**a  # contact lost: pow, not the series
    assert power(2e-3, a, (0.0, 0.0)) == 2e-3**a  # no earlier power


def test_first_steps_grow_with_the_exponent():
    steps = settings(1e-6)[0]
    first = first_steps(steps, np.array([0.5, 1.0, 8.913, 14.87]), 4)
    # n^(1/8): at most 1 (n <= 1), then 250 and 267 steps for the presets' exponents
    assert first.tolist() == [steps, steps, 250, 267]


def test_cases_of_different_exponents_are_each_as_alone(standard_model):
    exponents = np.array([1.0, 2.5, 9.0])
    stiffness = np.array([5e4, 2e7, 8e16])
    law = HuntCrossley(stiffness, exponents, np.array([0.0, 0.05, 0.01]))
    positions = [0.9, 0.6, 0.75]
    speeds = np.array([30.0, 20.0, 40.0])
    out = solve_general(law, receptance(standard_model, positions, 0.057), speeds)
    for i in range(3):
        one = solve_general(
            HuntCrossley(stiffness[i], exponents[i], law.alpha[i]),
            receptance(standard_model, positions[i], 0.057),
            speeds[i],
        )
        assert out.ball_velocity[i] == one.ball_velocity[0]
        assert out.step[i] == one.step[0]
        n = int(one.last[0]) + 1
        assert out.last[i] == one.last[0]
        for key in ("force", "deflection", "rate", "state"):
            assert np.array_equal(getattr(out, key)[i, :n], getattr(one, key)[0, :n]), key


@pytest.mark.parametrize("name", ["kawazoe-1997-nonlinear", "hunt-crossley", "series"])
def test_zero_modes_the_kernel_pads_with_change_nothing(standard_model, name):
    # march_cases pads a case's modes with zero modes (a^2 = 0) up to a multiple of 4 where its
    # rows have room (compiled._modes gives them room): every case's answer and histories are
    # those of its own modes alone (rows exactly as wide: nothing padded), bit for bit
    from fem_racket.contact.presets import PRESETS, get_law
    from fem_racket.impact.general import jit
    from fem_racket.impact.general.compiled import kernel_law
    from fem_racket.impact.general.cubic_force import STENCILS

    jit.prepare(2 * jit.INTERPRETED_NODES)  # the compiled kernels
    from fem_racket.impact.general.kernel import march_cases

    rec = receptance(standard_model, [0.6, 0.75, 0.9], 0.057)
    law = kernel_law(PRESETS[name] if name in PRESETS else get_law(name), 3)
    kind = (law.law, law.state, law.end, 1)
    nmode = np.array([5, 7, 8])  # 3, 1 and 0 zero modes padded
    W, A2 = np.ones((3, 8)), np.zeros((3, 8))
    for c, k in enumerate(nmode):
        W[c, :k], A2[c, :k] = rec.omega[:k], rec.a[c, :k] ** 2
    speed = np.array([30.0, 20.0, 40.0])
    mu0, h, nsteps = rec.compliance, np.full(3, 2e-5), np.full(3, 600)
    cases = (mu0, h, nsteps, speed, speed / (mu0 * 5e-3))
    none = np.zeros((0, 2, 0))
    store, start, res = march_cases(kind, law.params, (W, A2, nmode), cases, none, STENCILS, True)
    assert np.all(res[:, 2] == 0.0)  # every case separated
    for c, k in enumerate(nmode):
        one = (W[c : c + 1, :k].copy(), A2[c : c + 1, :k].copy(), nmode[c : c + 1])
        alone = tuple(x[c : c + 1] for x in cases)
        s1, _, r1 = march_cases(kind, law.params[c : c + 1], one, alone, none, STENCILS, True)
        assert np.array_equal(res[c], r1[0])
        assert np.array_equal(store[:, start[c] : start[c + 1]], s1)
