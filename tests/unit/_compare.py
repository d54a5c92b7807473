"""Comparison helpers for the kernel-versus-twin unit tests."""

import math

import numpy as np


def rel_err(actual, expected, atol=0.0):
    """Largest elementwise relative error |a - e| / |e| over scalars, tuples or arrays.

    Identical values (including both inf or both 0) count as 0, and so does a difference within the
    absolute allowance atol; otherwise a non-zero value against an exact 0, a mismatched infinity or
    any NaN counts as inf.
    """
    a = np.atleast_1d(np.asarray(actual, dtype=float)).ravel()
    e = np.atleast_1d(np.asarray(expected, dtype=float)).ravel()
    assert a.shape == e.shape, f"shape {a.shape} != {e.shape}"
    worst = 0.0
    for x, y in zip(a, e):
        if x == y:
            continue
        if math.isnan(x) or math.isnan(y) or math.isinf(x) or math.isinf(y):
            return math.inf
        if abs(x - y) <= atol:
            continue
        if y == 0.0:
            return math.inf
        worst = max(worst, abs(x - y) / abs(y))
    return worst


def assert_close(actual, expected, rtol, what="", atol=0.0):
    """Assert rel_err(actual, expected, atol) <= rtol with a message that shows both values."""
    err = rel_err(actual, expected, atol)
    assert err <= rtol, f"{what}: kernel {actual!r} vs twin {expected!r}: relative error {err:.3e} > {rtol:.1e}"
    return err
