"""One BLAS thread while a small dense solve runs.

numpy's OpenBLAS splits a matrix operation over every core. On the shaft model's matrices (tens of unknowns) the
threads cost more than they bring, and when other work holds the cores a solve that takes 3 ms on one thread takes
10 to 40 ms on two (docs/shaft.md, "Cost"). `single_blas_thread()` sets OpenBLAS's thread count to 1 for the block
and puts the previous count back after it, as scikit-learn limits its BLAS threads around its own small solves
(threadpoolctl). The count is the process's: while a block runs, the host's other BLAS calls also run on one
thread; blocks entered from several threads at once keep 1 until the last one ends, then the count before the
first is restored. It goes through `openblas_set_num_threads_local` (OpenBLAS 0.3.27 and later: sets the count and
returns the one it replaces); where numpy carries no such OpenBLAS (another BLAS, an older OpenBLAS) the block runs
as it would have.
"""

import contextlib
import ctypes
import glob
import os
import threading


def _setter():
    """OpenBLAS's openblas_set_num_threads_local of the library numpy loaded, or None."""
    import numpy

    libs = os.path.join(os.path.dirname(os.path.dirname(numpy.__file__)), "numpy.libs")
    for path in sorted(glob.glob(os.path.join(libs, "*openblas*"))):
        try:
            setter = ctypes.CDLL(path).openblas_set_num_threads_local
        except (OSError, AttributeError):
            continue
        setter.restype, setter.argtypes = ctypes.c_int, [ctypes.c_int]
        return setter
    return None


_SETTER = _setter()
_LOCK = threading.Lock()
_state = {"depth": 0, "previous": None}  # blocks running now, and the count before the first of them


@contextlib.contextmanager
def single_blas_thread():
    """The block with one BLAS thread (where numpy's OpenBLAS allows it)."""
    if _SETTER is None:
        yield
        return
    with _LOCK:
        if _state["depth"] == 0:
            _state["previous"] = _SETTER(1)
        _state["depth"] += 1
    try:
        yield
    finally:
        with _LOCK:
            _state["depth"] -= 1
            if _state["depth"] == 0:
                _SETTER(_state["previous"])
