"""Exact free-free frequencies of piecewise-uniform beams (fem_racket.frame.continuous)."""

import numpy as np
import pytest

from fem_racket import FrameModel, Segment, standard_frame
from fem_racket.frame.continuous import free_free_determinant, free_free_frequencies, uniform_roots
from fem_racket.frame.hermite import assemble_closed_form, rayleigh_frequencies
from fem_racket.frame.mesh import frame_mesh
from fem_racket.frame.modal import free_modes
from fem_racket.frame.segments import Frame
from fem_racket.validation import InputError

#: Roots of cos(x) cosh(x) = 1 (uniform free-free beam), 16 digits: Blevins, "Formulas for
#: natural frequency and mode shape" (1979), table 8-1, and the asymptote (2k + 1) pi / 2.
BETA_L = (4.730040744862704, 7.853204624095838, 10.99560783800167, 14.13716549125746)


def test_uniform_beam_textbook_roots():
    # The four-digit values every textbook prints (the acceptance check).
    assert uniform_roots(4) == pytest.approx([4.7300, 7.8532, 10.9956, 14.1372], abs=5e-5)


def test_uniform_beam_roots_to_round_off():
    # 16-digit reference; the root finder's xtol is 1e-15 relative, so a few ulps are allowed.
    assert uniform_roots(4) == pytest.approx(BETA_L, rel=1e-14)
    # Higher roots approach (2k + 1) pi / 2 (their difference ~ 2 e^-x is below round-off).
    assert uniform_roots(12)[-1] == pytest.approx(25 * np.pi / 2, rel=1e-14)


def test_uniform_beam_frequency_units():
    # omega = (beta L)^2 sqrt(EI / (rhoA L^4)) for L = 0.68 m, EI = 146 N m^2, rhoA = 0.5 kg/m.
    seg = Segment(0.68, 146.0, 0.5)
    f = free_free_frequencies([seg], 3)
    expected = np.array(BETA_L[:3]) ** 2 * np.sqrt(146.0 / (0.5 * 0.68**4)) / (2 * np.pi)
    assert f == pytest.approx(expected, rel=1e-14)


def test_determinant_is_scaled_and_signed():
    # Roots at the frequencies, O(1) values elsewhere (no overflow even at beta L ~ 400).
    frame = standard_frame()
    f = free_free_frequencies(frame, 2)
    assert abs(free_free_determinant(frame, 2 * np.pi * f[0])) < 1e-13
    big = free_free_determinant(frame, 2 * np.pi * 2e6)
    assert np.isfinite(big) and abs(big) <= 1.0
    a = free_free_determinant(frame, 2 * np.pi * f[0] * (1 - 1e-6))
    b = free_free_determinant(frame, 2 * np.pi * f[0] * (1 + 1e-6))
    assert a * b < 0


def test_standard_racket_against_high_precision_transfer_matrix():
    # Independent check: the plain 4x4 transfer-matrix product in 40-digit arithmetic (no
    # compound matrices, no scaling), its determinant's roots found by mpmath.
    mp = pytest.importorskip("mpmath")
    mp.mp.dps = 40
    segs = standard_frame().segments

    def det(om):
        tt = mp.eye(4)
        for s in segs:
            ei, ra, ln = mp.mpf(s.EI), mp.mpf(s.rhoA), mp.mpf(s.length)
            b = (ra * om**2 / ei) ** mp.mpf(0.25)
            z = b * ln
            S = (mp.cosh(z) + mp.cos(z)) / 2
            T = (mp.sinh(z) + mp.sin(z)) / 2
            U = (mp.cosh(z) - mp.cos(z)) / 2
            V = (mp.sinh(z) - mp.sin(z)) / 2
            k = mp.matrix([[S, T, U, V], [V, S, T, U], [U, V, S, T], [T, U, V, S]])
            scale = [1, b, ei * b**2, ei * b**3]
            tt = mp.diag(scale) * k * mp.diag([1 / x for x in scale]) * tt
        return tt[2, 0] * tt[3, 1] - tt[2, 1] * tt[3, 0]

    f = free_free_frequencies(standard_frame(), 4)
    ref = [float(mp.findroot(det, 2 * mp.pi * mp.mpf(x)) / (2 * mp.pi)) for x in f]
    assert f == pytest.approx(ref, rel=1e-14)  # a few ulps


def test_stepped_racket_against_fe_model():
    # Consistent-mass Hermite FE is a Rayleigh-Ritz method: its frequencies bound the exact ones
    # from above and approach them as h^4 (error ratio 16 per halving).
    exact = free_free_frequencies(standard_frame(), 4)
    errs = []
    for n in (20, 40):
        fe = FrameModel.build(standard_frame(), n).fe
        f = free_modes(fe, 4).frequencies
        assert np.all(f > exact)
        errs.append(f / exact - 1)
    assert errs[0] == pytest.approx([2.117e-6, 1.642e-5, 6.242e-5, 1.685e-4], rel=2e-3)
    assert np.log2(errs[0] / errs[1]) == pytest.approx(4.0, abs=0.1)
    # The paper's numbers (section 2.2): 122 Hz and 337 Hz.
    assert exact[:2] == pytest.approx([122.0, 337.0], abs=0.5)


def test_close_roots_are_not_missed():
    # Two identical stiff halves joined by a short, light and very flexible link: nearly
    # decoupled, so most frequencies come in close pairs (relative gaps 2e-4 and 5e-4). A fine
    # FE model (nodes at the steps, ~1 mm cells) must find the same count and values.
    half = Segment(0.3, 100.0, 0.5)
    link = Segment(0.02, 1e-4, 1e-3)
    segs = (half, link, half)
    exact = free_free_frequencies(segs, 10)
    fe = assemble_closed_form(frame_mesh(Frame(segs), 650))
    fem = np.sort(rayleigh_frequencies(fe, free_modes(fe, 12).shapes))[:10]
    assert np.min(np.diff(exact) / exact[1:]) < 1e-3  # there are close pairs
    # FE error of these modes at this mesh is below 2e-6 (measured, h^4 convergence); a missed
    # root would shift every later pairing by a whole mode (errors of order 1).
    assert fem == pytest.approx(exact, rel=1e-5)


def test_bad_input():
    with pytest.raises(InputError, match="modes"):
        free_free_frequencies(standard_frame(), 0)
    with pytest.raises(InputError, match="segments"):
        free_free_frequencies([], 2)
