"""Twin of bearing_fmu.kernels.elimination: the same systems by LAPACK (numpy.linalg.solve, LU with partial
pivoting)."""

import numpy as np

KERNEL_MODULE = "bearing_fmu.kernels.elimination"


def gauss_solve(M, n, m):
    """(solved, M with X = M[:n, :n]^-1 M[:n, n:m] in its right-hand columns); a singular matrix gives (False, M)."""
    M = np.array(M, dtype=float)
    A = M[:n, :n]
    if not np.all(np.isfinite(A)) or np.linalg.matrix_rank(A) < n:
        return False, M
    M[:n, n:m] = np.linalg.solve(A, M[:n, n:m])
    return True, M


TWINS = {"gauss_solve": gauss_solve}
