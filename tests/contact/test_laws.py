"""The contact laws: closed forms, derivatives, COR relations, names and presets."""

import math

import numpy as np
import pytest

from fem_racket.contact.hunt_crossley import HuntCrossley, damping_from_cor
from fem_racket.contact.hysteretic import Hysteretic
from fem_racket.contact.law import power_contact_time
from fem_racket.contact.linear import LinearContact
from fem_racket.contact.presets import LAW_NAMES, PRESETS, get_law
from fem_racket.contact.series import SeriesBallString
from fem_racket.validation import InputError

LAWS = {
    "linear": LinearContact.from_damping(5e4, 6.3),
    "hunt-crossley": HuntCrossley(1e17, 9.0, 0.01),
    "hysteretic": Hysteretic(3e15, 9e16, 8.9),
    "series": SeriesBallString(1e5, 17.0, 2e4, 8e8),
}
# (delta [m], rate [m/s], state [m]); for the hysteretic law one loading, one unloading point
POINTS = [(0.02, 3.0, 0.015), (0.02, -3.0, 0.025)]


@pytest.mark.parametrize("name", LAWS)
@pytest.mark.parametrize("point", POINTS)
def test_partials_match_finite_differences(name, point):
    # central differences, step 1e-7 relative: truncation ~1e-14, round-off ~1e-9 relative
    law = LAWS[name]
    d, v, z = point
    analytic = law.partials(d, v, z)
    args = [d, v, z]
    for i in range(3):
        step = 1e-7 * max(abs(args[i]), 1e-3)
        hi, lo = list(args), list(args)
        hi[i] += step
        lo[i] -= step
        fd = (law.force(*hi) - law.force(*lo)) / (2 * step)
        assert float(analytic[i]) == pytest.approx(float(fd), rel=1e-6, abs=1e-6)
    if law.state == "ode":
        for i, g in enumerate(law.rate_partials(d, v, z)):
            hi, lo = list(args), list(args)
            step = 1e-7 * max(abs(args[i]), 1e-3)
            hi[i] += step
            lo[i] -= step
            fd = (law.rate(*hi) - law.rate(*lo)) / (2 * step)
            assert float(g) == pytest.approx(float(fd), rel=1e-6, abs=1e-6)


def test_power_contact_time_closed_forms():
    # n = 1: pi sqrt(m/k) (eq 11); n = 3/2: Hertz, t = 2.943 delta_m / v with
    # delta_m = (5 m v^2 / (4 k))^(2/5) (Johnson 1985, Contact Mechanics, eq 11.24; 4 digits)
    assert power_contact_time(5e4, 1.0, 0.057, 30.0) == pytest.approx(
        math.pi * math.sqrt(0.057 / 5e4), rel=1e-14
    )
    hertz = 2.9432 * (5 * 0.057 * 10.0**2 / (4 * 1e6)) ** 0.4 / 10.0
    assert power_contact_time(1e6, 1.5, 0.057, 10.0) == pytest.approx(hertz, rel=1e-4)


def test_cor_relations_closed_forms():
    # Lankarani & Nikravesh 1990: 3 (1 - e^2) / (4 v0); Flores et al. 2011: 8 (1 - e) / (5 e v0)
    assert damping_from_cor(0.8, 2.0, "lankarani-nikravesh") == pytest.approx(0.135, rel=1e-14)
    assert damping_from_cor(0.8, 2.0, "flores") == pytest.approx(0.2, rel=1e-14)


def test_single_power_law_needs_exponent_near_nine():
    # DESIGN section 8: K_eq ~ V^(2(n-1)/(n+1)), so t_c ~ V^(-(n-1)/(n+1)); the paper's clamped
    # times 4.53 and 2.60 ms at 20 and 40 m/s (K_CB 2.74e4, 8.33e4 N/m) need n = 9.1
    ratio = math.sqrt(8.33e4 / 2.74e4)  # t_c(20) / t_c(40)
    q = math.log2(ratio)
    n = (1 + q) / (1 - q)
    assert n == pytest.approx(9.1, abs=0.05)
    law = HuntCrossley(1e17, n, 0.0)
    t20, t40 = power_contact_time(law.stiffness, n, 0.057, np.array([20.0, 40.0]))
    assert t20 / t40 == pytest.approx(ratio, rel=1e-12)


def test_hysteretic_rigid_cor_and_permanent_set():
    # Cross 2000: linear branches give e^2 = k1/k2; power branches (k1/k2)^(1/n)
    assert Hysteretic(2e4, 4e4, 1.0).rigid_cor == pytest.approx(math.sqrt(0.5), rel=1e-14)
    law = Hysteretic.from_cor(3e15, 0.83, 8.9)
    assert law.rigid_cor == pytest.approx(0.83, rel=1e-13)
    # force continuous at the turning point and zero at the permanent set
    z = 0.03
    assert law.force(z, -1.0, z) == pytest.approx(law.force(z - 1e-12, -1.0, z), rel=1e-8)
    assert law.force(law.end_deflection(z), -1.0, z) == 0.0


def test_get_law_names_and_errors():
    assert get_law("linear") is None
    assert get_law("kawazoe-1997-nonlinear") is PRESETS["kawazoe-1997-nonlinear"]
    hc = get_law("hunt-crossley", hc_exponent=1.5, hc_stiffness=1e6, hc_alpha=None)
    assert (hc.exponent, hc.stiffness) == (1.5, 1e6)
    assert set(LAW_NAMES) >= {"linear", "hunt-crossley", "hysteretic", "series"}
    with pytest.raises(InputError, match="k1"):
        get_law("hunt-crossley", k1=3.0)
    with pytest.raises(InputError, match="preset"):
        get_law("itf-ball", hc_alpha=0.1)
    with pytest.raises(InputError, match="law"):
        get_law("rubber")
    with pytest.raises(InputError, match="k2"):
        Hysteretic(2e4, 1e4)


def test_describe_records_law_and_units():
    d = LAWS["series"].describe()
    assert d["law"] == "series" and d["string_cubic_n_m3"] == 8e8
