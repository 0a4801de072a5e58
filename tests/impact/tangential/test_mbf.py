"""Maw, Barber & Fawcett's oblique elastic impact (Wear 38, 1976) solved independently here, and
the project's tangential spring (Stronge's) against it (issue 26, item 3).

The independent solution: a sphere (mass m, radius R, I = K^2 m R^2) on a rigid half-space,
Hertz's normal contact and Mindlin-Deresiewicz tangential tractions with Coulomb friction mu,
normal and tangential problems uncoupled (Goodman's approximation, as MBF), by the method of
dimensionality reduction (Popov & Hess 2015, *Method of Dimensionality Reduction in Contact
Mechanics and Friction*, Springer, chapters 3 and 6; exact for Mindlin-Deresiewicz under any
normal and tangential loading history): the contact becomes a row of independent springs at
x in [0, a] on the 1-D profile g(x) = x^2 / R, normal stiffness E* dx and tangential G* dx,
E* = E / (1 - nu^2), G* = 4G / (2 - nu) (the half-space rigid). A spring in contact
(g(x) < d) sticks, its tangential stretch growing with the contact point's slip, until
G* |u| reaches mu E* (d - g(x)), where it slips; a spring leaving contact forgets its stretch.
The normal force is 2 int_0^a E* (d - g) dx = (4/3) E* sqrt(R) d^(3/2) (Hertz). Marched
here in fixed steps (velocity Verlet for the normal motion, the springs updated each step).

MBF's variables: psi = 2 (1 - nu) / (mu (2 - nu)) x (tangential over normal velocity of the
contact point; psi_2 with the outgoing tangential and incoming normal one), and
chi = (1 - nu) / (2 - nu) (1 + 1 / K^2). Their Fig. 1 (a thin diametral slice, nu = 0.28,
chi = 1.2558, K^2 = 1/2): "in contrast to the prediction of simple theory, psi_2 is negative for
low values of psi_1. Moreover, the range of psi_1 over which gross slip can be expected
throughout the cycle exceeds that from simple theory".
"""

import math

import numpy as np
import pytest

from fem_racket.impact.tangential.march import TangentialContact, march
from fem_racket.impact.tangential.normal import SampledNormal

NU, K2, MU = 0.28, 0.5, 0.3  # MBF's Fig. 1 slice; mu drops out of the normalised outcome
CHI = (1 - NU) / (2 - NU) * (1 + 1 / K2)
G_OVER_E = 2 * (1 - NU) / (2 - NU)  # G* / E* of an elastic sphere on a rigid plane
SCALE = 2 * (1 - NU) / (MU * (2 - NU))  # psi = SCALE x velocity ratio


def mdr_impact(psi1, n_x=400, n_t=4000):
    """MBF by the MDR in units m = R = E* = V_n = 1: psi_2 for each psi_1, and the normal
    history (t, P, F, d) at the steps."""
    psi1 = np.atleast_1d(np.asarray(psi1, dtype=float))
    beta = 1 + 1 / K2
    d_max = (15 / 16) ** 0.4  # Hertz: (15 m V^2 / (16 E* sqrt(R)))^(2/5)
    dt = 1.1 * 2.94 * d_max / n_t  # over 1.1 x Hertz's contact time (Johnson eq. 11.24)
    width = 1.02 * math.sqrt(d_max) / n_x
    x = (np.arange(n_x) + 0.5) * width
    g = x * x
    u = np.zeros((psi1.size, n_x))
    s = psi1 / SCALE
    d, v, acc = 0.0, 1.0, 0.0
    hist = [(0.0, 0.0, 0.0, 0.0)]
    while (d_new := d + dt * (v + 0.5 * dt * acc)) > 0.0:
        vh = v + 0.5 * dt * acc
        d = d_new
        f = 4.0 / 3.0 * d**1.5
        acc = -f
        v = vh + 0.5 * dt * acc
        hist.append((hist[-1][0] + dt, 1.0 - v, f, d))
        inside = g < d
        u += s[:, None] * dt
        u[:, ~inside] = 0.0
        limit = MU / G_OVER_E * np.where(inside, d - g, 0.0)
        np.clip(u, -limit, limit, out=u)
        s = s - dt * beta * 2.0 * G_OVER_E * u.sum(axis=1) * width
    return SCALE * s, np.array(hist).T


def stronge_on(hist, psi1, eta2):
    """The project's march (Stronge's spring, k_t = k_n / eta^2, k_n the secant at maximum
    compression as for any non-linear law, impact/result_peak.py) over the same history: here
    at the largest of the 4 000 steps, which on this undamped Hertz history differs from the
    peak located between them by O(h^2) only."""
    t, p, f, d = hist
    i = int(np.argmax(d))
    normal = SampledNormal(t, p, f, f[i] / d[i])
    c = TangentialContact(MU, normal.stiffness / eta2, 1 / (1 + 1 / K2))
    return np.array([SCALE * march(c, normal, q / SCALE).final_slip for q in psi1])


@pytest.fixture(scope="module")
def curves():
    psi1 = np.round(np.arange(0.05, 6.01, 0.05), 2)
    mdr, hist = mdr_impact(psi1)
    return psi1, mdr, hist


def test_mdr_is_cattaneo_mindlin_and_hertz():
    # The springs at a fixed indentation d under a tangential displacement delta give
    # Cattaneo-Mindlin's F_t = mu F_N (1 - (1 - delta / delta*)^(3/2)),
    # delta* = mu (E*/G*) d (Johnson 1985, Contact Mechanics, eq. 7.42), to the grid's 1e-3
    d, n = 0.2, 2000
    width = 1.02 * math.sqrt(d) / n
    x = (np.arange(n) + 0.5) * width
    limit = MU / G_OVER_E * np.maximum(d - x * x, 0.0)
    f_n = 2 * np.sum(np.maximum(d - x * x, 0.0)) * width
    assert f_n == pytest.approx(4 / 3 * d**1.5, rel=1e-3)
    star = MU / G_OVER_E * d
    for frac in (0.1, 0.5, 0.9, 1.0):
        f_t = 2 * G_OVER_E * np.sum(np.minimum(frac * star, limit)) * width
        assert f_t == pytest.approx(MU * f_n * (1 - (1 - frac) ** 1.5), rel=1e-3)
    # the impact: elastic (e = 1 to 1e-6) over Hertz's contact time 2.94 delta_max / V
    # (Johnson eq. 11.24; 2 int_0^1 (1 - x^(5/2))^(-1/2) dx = 2.9432) to a step
    _, (t, p, _, _) = mdr_impact([0.0])
    d_max = (15 / 16) ** 0.4
    assert p[-1] == pytest.approx(2.0, rel=1e-6)
    assert t[-1] == pytest.approx(2.9432 * d_max, abs=1.1 * 2.94 * d_max / 4000 + 1e-4)


def test_mdr_converges(curves):
    # halving the springs' spacing and the step moves psi_2 by < 2e-4 (the tolerances below
    # are far wider)
    psi1, mdr, _ = curves
    fine, _ = mdr_impact(psi1[::10], n_x=800, n_t=8000)
    assert np.abs(fine - mdr[::10]).max() < 2e-4


def test_mdr_shows_mbfs_features(curves):
    # MBF's Fig. 1: psi_2 < 0 at low psi_1 (down to 0.3 here; it tends to 0 with psi_1), and
    # gross slip below the rigid theory's psi_1 = 4 chi: here from 4.05 (4 chi - 1 = 4.02),
    # on the line psi_2 = psi_1 - 4 chi
    psi1, mdr, _ = curves
    low = (psi1 >= 0.3) & (psi1 <= 4.0)
    assert (mdr[low] < 0).all()
    line = np.abs(mdr - (psi1 - 4 * CHI)) < 1e-6
    onset = psi1[np.flatnonzero(line)[0]]
    assert line[psi1 >= onset].all()
    assert onset == pytest.approx(4.05, abs=0.03) and onset < 4 * CHI


def test_the_projects_spring_against_mbf(curves):
    # Stronge's spring with MBF's stiffness ratio (k_n / k_t = (2 - nu) / (2 (1 - nu)),
    # Mindlin's initial ratio) over the same Hertz history:
    psi1, mdr, hist = curves
    eta2 = (2 - NU) / (2 * (1 - NU))
    lin = stronge_on(hist, psi1, eta2)
    # - the gross-slip line for large psi_1: both Coulomb throughout, psi_2 = psi_1 - 4 chi
    #   (to 1e-6: the stepped history stops within a step of separation, P short of 2 m V by
    #   < 1e-7)
    big = psi1 >= 5.0
    assert lin[big] == pytest.approx(mdr[big], abs=1e-6)
    assert lin[big] == pytest.approx(psi1[big] - 4 * CHI, abs=1e-6)
    # - the reversal region's minimum: -1.592 at psi_1 = 2.80 against MBF's -1.426 at 3.05
    #   (measured here: 12 % deeper, 8 % earlier). The linear spring keeps one stiffness (the
    #   secant at maximum compression over eta^2) where Mindlin's grows with the contact
    #   radius and softens by micro-slip in the annulus; no published bound on this difference
    #   was at hand, so the tolerance is the measured difference rounded up: 15 % and 10 %
    i, j = np.argmin(mdr), np.argmin(lin)
    assert mdr[i] == pytest.approx(-1.426, abs=1e-3) and psi1[i] == pytest.approx(3.05)
    assert lin[j] == pytest.approx(mdr[i], rel=0.15) and psi1[j] == pytest.approx(psi1[i], rel=0.1)
    assert lin[j] == pytest.approx(-1.592, abs=1e-3) and psi1[j] == pytest.approx(2.80)
    # - across the reversal region (1 <= psi_1 <= 4) the two curves stay within 0.25 (in psi_2
    #   units; the minimum's difference, 0.17, plus the shift of its location)
    mid = (psi1 >= 1.0) & (psi1 <= 4.0)
    assert np.abs(lin[mid] - mdr[mid]).max() < 0.25
    # - the known difference at low psi_1: the linear spring grips and gives the stretch back
    #   through cos(pi omega_t / omega_n) > 0 (test_tangential.py), so psi_2 > 0 where MBF's
    #   Hertzian contact leaves psi_2 <= 0
    low = (psi1 > 0.0) & (psi1 <= 0.35)
    assert (lin[low] > 0).all() and (mdr[low & (psi1 >= 0.3)] < 0).all()
