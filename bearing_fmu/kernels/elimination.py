"""Small dense linear systems in place: Gaussian elimination with partial pivoting (Golub & Van Loan 2013, Matrix
Computations, 4th ed., algorithm 3.4.1), for the few unknowns of a ball's Newton solves, where a LAPACK call would
cost more than the elimination."""

import math

from bearing_fmu_common.jit import kernel


@kernel
def gauss_solve(M, n, m):
    """Solve M[:n, :n] X = M[:n, n:m] in place: X replaces the right-hand sides, the matrix is destroyed. Returns
    False when a pivot is 0 or not finite (singular or NaN), M then partly eliminated."""
    for k in range(n):
        piv = k
        for i in range(k + 1, n):
            if abs(M[i, k]) > abs(M[piv, k]):
                piv = i
        if M[piv, k] == 0.0 or not math.isfinite(M[piv, k]):
            return False
        if piv != k:
            for c in range(k, m):
                M[k, c], M[piv, c] = M[piv, c], M[k, c]
        for i in range(k + 1, n):
            f = M[i, k] / M[k, k]
            for c in range(k, m):
                M[i, c] -= f * M[k, c]
    for c in range(n, m):
        for k in range(n - 1, -1, -1):
            s = M[k, c]
            for j in range(k + 1, n):
                s -= M[k, j] * M[j, c]
            M[k, c] = s / M[k, k]
    return True
