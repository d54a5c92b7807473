"""Small dense systems (kernels.elimination) against LAPACK (tests/reference/ref_elimination.py)."""

import numpy as np
import pytest

from bearing_fmu.kernels import elimination as ek
from tests.reference import ref_elimination as ref


@pytest.mark.parametrize("n, rhs", [(2, 1), (4, 1), (4, 4), (6, 1), (6, 3)])
def test_solutions_equal_lapacks(n, rhs):
    """Random systems, among them one whose first pivot is 0 (a row swap is needed) and one scaled over 12 orders of
    magnitude by rows (the mixed units of a ball's residuals): the solutions agree within 1e-10 of their largest
    entry (the condition numbers reach 1e4: rounding of either method)."""
    rng = np.random.default_rng(n * 10 + rhs)
    for trial in range(20):
        M = rng.normal(size=(n, n + rhs))
        if trial == 0:
            M[0, 0] = 0.0
        if trial == 1:
            M *= np.logspace(-6, 6, n)[:, None]
        mine = M.copy()
        assert ek.gauss_solve(mine, n, n + rhs)
        ok, twin = ref.gauss_solve(M, n, n + rhs)
        assert ok
        X, Y = mine[:, n:], twin[:, n:]
        assert X == pytest.approx(Y, abs=1e-10 * np.abs(Y).max())


def test_a_singular_or_nan_matrix_is_reported():
    """A zero column and a NaN entry: both the kernel and the twin say the system has no solution."""
    for bad in ("zero column", "nan"):
        M = np.eye(4, 5)
        M[:, 4] = 1.0
        if bad == "zero column":
            M[:, 2] = 0.0
        else:
            M[1, 1] = np.nan
        assert not ek.gauss_solve(M.copy(), 4, 5)
        assert not ref.gauss_solve(M, 4, 5)[0]
