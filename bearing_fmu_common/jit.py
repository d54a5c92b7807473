"""The one jit policy of every numba kernel in the product.

``@kernel`` is ``numba.njit`` with:
- ``cache=True``: compiled code is kept on disk, so a later process (and a later FMU instance)
  starts without compiling;
- ``fastmath=False``: IEEE semantics, so NaN checks keep working and a kernel agrees with its
  plain-Python twin to rounding.

Kernels never read module globals that change at run time (numba freezes globals into the cache);
options reach them as integer codes.
"""

from numba import njit

JIT_OPTIONS = {"cache": True, "fastmath": False}


def kernel(function=None, **overrides):
    """Decorate a kernel with the product's jit policy (``@kernel`` or ``@kernel(inline="always")``)."""
    options = {**JIT_OPTIONS, **overrides}
    if function is None:
        return lambda f: njit(**options)(f)
    return njit(**options)(function)
