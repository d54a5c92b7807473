"""The trust-region solve of the ring against its twin on points where the former line-search Newton failed.

Twin: tests/reference/ref_jones_harris.solve_loads, scipy.optimize.root ('hybr', then 'lm') on the same load
residual, with its own ball solves; an independent solver, not the kernel's algorithm. The points are of the
large-angle grid (tests/stability/test_large_free_angle_grid.py) with the twin's B7214C-like and 6208-like
bearings at speed, centrifugal and gyroscopic effects on; measured with the line-search Newton: "no
convergence in 100 iterations" at each of them. The twin starts 2 % (0.1 % for the third point) short of the
kernel's answer: from its own cold start, and from farther off, its ball solves fail at the trial positions
where a ball lies beyond the centre of curvature of its inner groove. Tolerance as in test_quasistatic.py:
the twin stops at a scaled residual of 1e-9, so displacements agree to 1e-6 of the largest.
"""

import numpy as np
import pytest

from bearing_fmu.kernels import jones_harris
from tests.reference import ref_jones_harris as ref
from tests.unit.test_quasistatic import kernel_solve, pack


def groove(p):
    """A = (f_i + f_o - 1) D (m) of a twin parameter set."""
    return (p["f_i"] + p["f_o"] - 1.0) * p["D"]


CASES = [  # (label, twin parameters, share of A, loads (N, N.m), speed (rad/s), start of the twin as a share of d)
    ("B7214C 0.59 A, 3 kN + 500 N, 500 rad/s", ref.params_b7214c, 0.59, (0.0, 3000.0, 500.0, 0.0, 0.0), 500.0, 0.98),
    ("6208 0.7 A, 3 kN + 500 N + 50 N.m, 50 rad/s", ref.params_6208, 0.7, (0.0, 3000.0, 500.0, 50.0, 0.0), 50.0, 0.98),
    ("6208 0.8 A, 3 kN + 500 N, 500 rad/s", ref.params_6208, 0.8, (0.0, 3000.0, 500.0, 0.0, 0.0), 500.0, 0.999),
]


@pytest.mark.parametrize("label, params, share, F_applied, omega, start", CASES, ids=[c[0] for c in CASES])
def test_formerly_failing_points_match_the_twin(label, params, share, F_applied, omega, start):
    p = params(centrifugal=True, gyroscopic=True, omega=omega)
    p = params(centrifugal=True, gyroscopic=True, omega=omega, Pd=share * groove(p))
    status, d, F, *_ = kernel_solve(pack(p, tol=1e-10), F_applied, omega)
    assert status == jones_harris.QS_OK
    d_ref = ref.solve_loads(F_applied, p, d0=start * d)
    scale = np.array([1, 1, 1, p["dm"] / 2, p["dm"] / 2])
    assert np.max(np.abs((d - d_ref) * scale)) <= 1e-6 * np.max(np.abs(d_ref * scale))
