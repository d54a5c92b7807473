"""spindle.shaft.beam kernels against their twins (tests/reference/ref_beam.py: the Timoshenko element from its shape
functions by quadrature, the kernel from the printed closed-form matrices).

Elements: random steel-like and aluminium-like elements, solid and hollow, from slender (L / d = 20, Phi ~ 0.01) to
stubby (L / d = 0.2, Phi ~ 100), seeded. Tolerance: both sides evaluate polynomials of the same degree exactly (the
twin's 6-point Gauss rule integrates degree 11), so they differ by rounding: 1e-10 relative to the matrix's largest
entry (entries that cancel to zero in the closed form are ~1e-16 of it in the twin), far below any wrong coefficient.
"""

import numpy as np
import pytest

from spindle.shaft import beam
from tests.cases import shaft_beams as sb
from tests.reference import ref_beam as rb

RTOL = 1e-10


def random_elements(seed, n):
    rng = np.random.default_rng(seed)
    rows = []
    for _ in range(n):
        E = rng.uniform(60e9, 220e9)
        nu = rng.uniform(0.25, 0.35)
        d_o = rng.uniform(0.01, 0.2)
        d_i = d_o * rng.choice([0.0, rng.uniform(0.1, 0.9)])
        L = d_o * 10.0 ** rng.uniform(-0.7, 1.3)
        kappa = beam.shear_coefficient(nu, d_o, d_i)
        rows.append((E, E / (2.0 * (1.0 + nu)), rng.uniform(2500.0, 8000.0), kappa, L, d_o, d_i))
    return np.array(rows)


def assert_matrix_close(actual, expected, what):
    scale = np.max(np.abs(expected))
    assert np.max(np.abs(actual - expected)) <= RTOL * scale, what


def compare(kernel, twin, row, n, names):
    """Fill three n x n matrices with the kernel and with its twin for one element row; compare; the kernel's."""
    got = [np.empty((n, n)) for _ in range(3)]
    want = [np.empty((n, n)) for _ in range(3)]
    kernel(*row, *got)
    twin(*row, *want)
    for a, b, name in zip(got, want, names):
        assert_matrix_close(a, b, f"{name} of {row}")
    return got


@pytest.mark.parametrize("seed", range(4))
def test_shear_coefficient_and_plane_matrices_match_twin(seed):
    for row in random_elements(seed, 10):
        E, G, rho, kappa, L, d_o, d_i = row
        nu = E / (2.0 * G) - 1.0
        assert beam.shear_coefficient(nu, d_o, d_i) == pytest.approx(rb.shear_coefficient(nu, d_o, d_i), rel=1e-14)
        compare(beam.plane_matrices, rb.plane_matrices, row, 4, "KMP")


@pytest.mark.parametrize("seed", range(4))
def test_element_matrices_match_twin(seed):
    for row in random_elements(seed, 10):
        got = compare(beam.element_matrices, rb.element_matrices, row, 10, "KMG")
        assert np.array_equal(got[2], -got[2].T)  # the gyroscopic matrix is skew


def test_cowper_solid_section():
    """Cowper 1966: kappa = 6 (1 + nu) / (7 + 6 nu) for a solid circle (0.886 at nu = 0.3)."""
    assert beam.shear_coefficient(0.3, 0.05, 0.0) == pytest.approx(6.0 * 1.3 / 8.8, rel=1e-15)


def test_assembly_disks_and_seats_match_twin():
    elements = random_elements(7, 12)
    n = 5 * (elements.shape[0] + 1)
    got = [np.empty((n, n)) for _ in range(3)]
    want = [np.empty((n, n)) for _ in range(3)]
    beam.assemble_shaft(elements, *got)
    rb.assemble_shaft(elements, *want)
    disks = np.array([[0.0, 1.5, 7e-4, 1.6e-3], [5.0, 3.0, 2e-3, 1e-3], [12.0, 1.0, 8e-4, 6e-4]])
    beam.add_disks(disks, got[1], got[2])
    rb.add_disks(disks, want[1], want[2])
    seat_dofs = np.array([[10, 11, 12, 13, 14], [45, 46, 47, 48, 49]], dtype=np.int64)
    seat_K = np.array([sb.seat_matrix(2e8, 5e7, 1e5, 1e7), np.random.default_rng(3).normal(size=(5, 5)) * 1e8])
    beam.add_seats(seat_dofs, seat_K, got[0])
    rb.add_seats(seat_dofs, seat_K, want[0])
    for a, b, name in zip(got, want, "KMG"):
        assert_matrix_close(a, b, name)
