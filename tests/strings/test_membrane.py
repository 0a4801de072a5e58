"""The string-bed membrane against closed forms: circular membrane statics and modes, the
orthotropic ellipse that maps to a circle, convergence under refinement and the modal sum rules."""

import math

import numpy as np
import pytest
from scipy.special import jn_zeros

from fem_racket.strings.bed import StringBed, parse_pattern
from fem_racket.strings.membrane import bed_mesh, disk_load, unit_modes
from fem_racket.strings.point import bed_point_data
from fem_racket.validation import InputError

R = 0.14  # radius of the circular test head [m]
A = 0.02  # load radius [m]


def circular_bed(tension: float = 250.0) -> StringBed:
    # mains / W = crosses / L: isotropic tension N = 16 T / 0.28
    return StringBed(
        tension_n=tension, mains=16, crosses=16, head_length_m=2 * R, head_width_m=2 * R
    )


def heard(values: np.ndarray) -> np.ndarray:
    """Modes with a value at the point: on a circle's centre the axisymmetric ones (the others
    vanish there but for discretisation noise)."""
    return np.abs(values) > 3e-2 * np.max(np.abs(values))


def test_static_stiffness_circular_closed_form():
    # Uniform pressure on a disk of radius a at the centre of a circular membrane (radius R,
    # tension N): the exact axisymmetric solution's mean over the disk gives
    # k = 2 pi N / (ln(R/a) + 1/4). P2 triangles on the polygonal circle plus the disk
    # quadrature: measured errors 3.3e-3, 5.5e-4, 1.2e-4 at refine 3, 4, 5.
    bed = circular_bed()
    k_exact = 2 * math.pi * bed.n_x / (math.log(R / A) + 0.25)
    err = [
        bed_point_data(bed, [0.0, 0.0], modes=4, refine=r).stiffness[0] / k_exact - 1
        for r in (3, 4, 5)
    ]
    assert abs(err[0]) < 4e-3 and abs(err[1]) < 7e-4 and abs(err[2]) < 1.5e-4
    assert abs(err[0]) > 4 * abs(err[1]) > 16 * abs(err[2]) / 1.5  # order >= ~2


def test_circular_frequencies_and_convergence():
    # Fixed-edge circular membrane: omega_0n = j_0n sqrt(N / rho_s) / R (the modes heard at the
    # centre are the axisymmetric ones). The polygonal boundary makes the error second order:
    # errors fall ~4x per refinement (measured 3.4e-3, 8.3e-4, 2.0e-4 for the first).
    bed = circular_bed()
    exact = jn_zeros(0, 3) * math.sqrt(bed.n_x / bed.rho_s) / R
    errs = []
    for r in (3, 4, 5):
        d = bed_point_data(bed, [0.0, 0.0], modes=40, refine=r)
        w = d.omega[heard(d.values[0])][:3]
        errs.append(w / exact - 1)
    errs = np.array(errs)
    assert np.all(errs > 0)  # conforming FE: from above
    assert np.all(errs[1] < 4e-3) and errs[2, 0] < 3e-4
    order = np.log2(errs[:-1] / errs[1:])
    assert np.all((order > 1.7) & (order < 2.6)), order


def test_orthotropic_ellipse_maps_to_circle():
    # x = sqrt(N_x) xi, y = sqrt(N_y) zeta turn N_x w_xx + N_y w_yy into a Laplacian; with
    # N_x / N_y = (L/W)^2 the ellipse becomes a circle of radius R' = (L/2)/sqrt(N_x), so
    # omega_01 = j_01 / (R' sqrt(rho_s)) exactly (16 mains on W = 0.30, 20 crosses on L = 0.24).
    bed = StringBed(tension_n=230.0, mains=16, crosses=20, head_length_m=0.24, head_width_m=0.30)
    assert bed.n_x / bed.n_y == pytest.approx((0.24 / 0.30) ** 2, rel=1e-14)
    d = bed_point_data(bed, [0.01, 0.02], modes=3, refine=5)
    exact = jn_zeros(0, 1)[0] / (0.12 / math.sqrt(bed.n_x) * math.sqrt(bed.rho_s))
    assert d.omega[0] / exact - 1 == pytest.approx(0.0, abs=3e-4)  # as the circle: 2.0e-4


def test_modal_sums_match_the_static_solves():
    # Independent paths: a dense eigen-decomposition of every mode gives sum psi^2/omega^2 =
    # q^T K^-1 q (the compliance) and sum psi^2 = q^T M^-1 q (residuals with no modes kept).
    from scipy.linalg import eigh

    bed = StringBed(tension_n=240.0, mains=18, crosses=20)
    point = np.array([[0.05, -0.03]])
    d0 = bed_point_data(bed, point, modes=1, refine=2)
    mesh = bed_mesh(bed.head_length_m, bed.head_width_m, 2)
    K = (bed.n_x * mesh.Kxx + bed.n_y * mesh.Kyy).toarray()
    M = bed.rho_s * mesh.M1.toarray()
    lam, phi = eigh(K, M)
    psi = disk_load(mesh, point, bed.load_radius_m)[:, 0] @ phi
    flex = d0.residual_flexibility[0] + d0.values[0, 0] ** 2 / d0.omega[0] ** 2
    mass = d0.residual_mass[0] + d0.values[0, 0] ** 2
    assert np.sum(psi**2 / lam) == pytest.approx(d0.compliance[0], rel=1e-10)
    assert np.sum(psi**2 / lam) == pytest.approx(flex, rel=1e-10)
    assert np.sum(psi**2) == pytest.approx(mass, rel=1e-9)
    assert np.sqrt(lam[0]) == pytest.approx(d0.omega[0], rel=1e-9)


def test_stiffness_scales_with_tension_and_typical_values():
    # k and omega^2 proportional to T (linear membrane); DESIGN.md section 10: bed stiffness of
    # order 50 kN/m and first bed mode of order 500-800 Hz (typical, so a factor-2 window).
    low = bed_point_data(StringBed(tension_n=220.0), [0.0, 0.0])
    high = bed_point_data(StringBed(tension_n=270.0), [0.0, 0.0])
    assert high.stiffness[0] / low.stiffness[0] == pytest.approx(270 / 220, rel=1e-12)
    assert high.omega[0] / low.omega[0] == pytest.approx(math.sqrt(270 / 220), rel=1e-12)
    assert 25e3 < low.stiffness[0] < 100e3
    assert 400 < low.frequencies_hz[0] < 1600


def test_bad_input():
    assert parse_pattern("18X20") == (18, 20)
    for text in ("16", "16x", "x19", "16x100", "a16x19"):
        with pytest.raises(InputError, match="pattern"):
            parse_pattern(text)
    with pytest.raises(InputError, match="string tension"):
        StringBed(tension_n=-5.0)
    with pytest.raises(InputError, match="string = 'gut'"):
        StringBed(string="gut")
    with pytest.raises(InputError, match="load radius"):
        StringBed(load_radius_m=0.07)


def test_geometric_stiffening():
    # The strings' stretch raises the tension by EA eps with eps ~ w^2: at small deflection the
    # stiffening k(w)/k(0) - 1 grows as w^2 and in proportion to EA (nylon vs polyester).
    # Measured at the centre, 246 N, 16x19: nylon +2.4 % at 10 mm, +9.7 % at 20 mm; polyester
    # +4.5 % and +17.8 % (DESIGN.md section 10: modest, 5-30 % at 10-20 mm, typical).
    from fem_racket.strings.stiffening import stiffening, stiffening_ratio

    nylon, poly = StringBed(string="nylon"), StringBed(string="polyester")
    assert stiffening(nylon, 0.0)[0] == pytest.approx(bed_point_data(nylon, [0, 0]).stiffness[0])
    small = [stiffening_ratio(nylon, w) - 1 for w in (0.001, 0.002)]
    assert small[1] / small[0] == pytest.approx(4.0, rel=1e-2)
    ea = poly.material.axial_rigidity_n / nylon.material.axial_rigidity_n
    assert (stiffening_ratio(poly, 0.001) - 1) / small[0] == pytest.approx(ea, rel=1e-2)
    assert 0.05 < stiffening_ratio(nylon, 0.02) - 1 < 0.3


def test_edge_transmission_closed_forms():
    # T: the bed's mean over the ball's disk under a static edge displacement. Constants and
    # linear functions solve N_x w_xx + N_y w_yy = 0, so T reproduces them (to round-off); for
    # the edge data x^2 the solution is alpha x^2 + beta y^2 + gamma with N_x alpha + N_y beta
    # = 0 and alpha - beta b^2/a^2 = 1, gamma = -beta b^2 (a, b the semi-axes), and the disk
    # mean adds rho^2/4 to x0^2 and y0^2. Discretisation error (the P2 edge DOFs on the
    # polygon's chords): measured -7.0e-5, -1.7e-5, -4.3e-6 at refine 3, 4, 5 (second order).
    from fem_racket.strings.point import edge_transmission

    bed = StringBed(tension_n=250.0, mains=16, crosses=19)
    pts = np.array([[0.0, 0.0], [0.09, -0.04], [-0.05, 0.07]])
    xy, T = edge_transmission(bed, pts)
    assert np.allclose(T.sum(axis=1), 1.0, atol=1e-12) and np.all(T > -1e-12)
    assert np.allclose(T @ xy, pts, atol=1e-12)
    a, b = bed.head_length_m / 2, bed.head_width_m / 2
    r = bed.n_x / bed.n_y
    alpha = 1.0 / (1.0 + r * b * b / (a * a))
    beta = -r * alpha
    rho2 = bed.load_radius_m**2 / 4
    exact = alpha * (pts[:, 0] ** 2 + rho2) + beta * (pts[:, 1] ** 2 + rho2) - beta * b * b
    errs = [T @ xy[:, 0] ** 2 - exact]  # refine 4, the default
    xy3, T3 = edge_transmission(bed, pts, 3)
    errs.insert(0, T3 @ xy3[:, 0] ** 2 - exact)
    assert np.all(np.abs(errs[1]) < 2e-5)
    assert np.all((errs[0] / errs[1] > 3.5) & (errs[0] / errs[1] < 4.6))


def test_modes_repeat_to_the_last_bit():
    # ARPACK's random start vector made the bed's modes (and a strung impact's COR, by 1.2e-12)
    # differ run to run; a fixed start vector (fem_racket.lanczos) makes them repeat exactly.
    first = unit_modes(0.3, 0.24, 1.2, 3, 12)
    unit_modes.cache_clear()
    second = unit_modes(0.3, 0.24, 1.2, 3, 12)
    assert first is not second
    assert np.array_equal(first[0], second[0]) and np.array_equal(first[1], second[1])
