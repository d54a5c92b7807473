"""The compiled-kernel floor of a run: record every kernel call a run makes, then replay the calls alone.

`KernelRecorder(packages)` wraps each numba dispatcher in the namespace of every loaded module of the given packages
for the duration of a `with` block and records every call with copies of its array arguments taken before the call
(the warm-start state a kernel reads is part of its work). Facades call kernels through their module
(``jones_harris.solve_quasistatic``) or by a name imported into their own module (``lubricant_state``); wrapping
every module's attributes sees both, and the modules are looked up among those loaded, so an FMU's own copy of the
package (what it runs) is the one recorded. `replay_time(calls)` repeats exactly those calls, in order, on fresh
copies: what the run would cost with no Python between the kernels (no facade, no FMI, no master). Its default
clock is this process's CPU time, which other processes on shared cores do not lengthen.
"""

import collections
import statistics
import sys
import time

import numpy as np
from numba.core.dispatcher import Dispatcher

# packages whose kernels a co-simulation step calls: the bearing model's, and with the spindle's thermal model
BEARING_PACKAGES = ("bearing_fmu",)
PRODUCT_PACKAGES = (*BEARING_PACKAGES, "spindle")


def _snapshot(args):
    return tuple(a.copy() if isinstance(a, np.ndarray) else a for a in args)


class KernelRecorder:
    """Context manager recording (dispatcher, argument copies) of every call to a kernel reached through a loaded
    module of `packages` (names of top-level packages)."""

    def __init__(self, packages=PRODUCT_PACKAGES):
        self.calls, self._saved = [], []
        self.modules = [
            module
            for name, module in list(sys.modules.items())
            if module is not None and any(name == p or name.startswith(p + ".") for p in packages)
        ]
        if not self.modules:
            raise ValueError(f"no module of {packages} is loaded: nothing to record")

    def __enter__(self):
        calls = self.calls
        for module in self.modules:
            for name, fn in list(vars(module).items()):
                if isinstance(fn, Dispatcher):
                    self._saved.append((module, name, fn))
                    setattr(module, name, lambda *args, fn=fn: calls.append((fn, _snapshot(args))) or fn(*args))
        return self

    def __exit__(self, *exc):
        for module, name, fn in self._saved:
            setattr(module, name, fn)
        self._saved = []


def replay_time(calls, repeats=5, clock=time.process_time):
    """Median time (s, by `clock`) of replaying `calls` in order, each repeat on fresh argument copies."""
    samples = []
    for _ in range(repeats):
        work = [(fn, _snapshot(args)) for fn, args in calls]
        t0 = clock()
        for fn, args in work:
            fn(*args)
        samples.append(clock() - t0)
    return statistics.median(samples)


def kernel_names(calls):
    """Number of calls per kernel name."""
    return dict(collections.Counter(fn.py_func.__name__ for fn, _ in calls))
