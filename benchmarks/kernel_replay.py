"""The compiled-kernel floor of a run: record every kernel call a run makes, then replay the calls alone.

`KernelRecorder(modules)` wraps each numba dispatcher of the given modules for the duration of a `with` block and
records every call with copies of its array arguments taken before the call (the warm-start state a kernel reads
is part of its work); facades call kernels through their module (``jones_harris.solve_quasistatic``), so wrapping the
module attribute sees every call they make. `replay_time(calls)` repeats exactly those calls, in order, on fresh
copies: what the run would cost with no Python between the kernels (no facade, no FMI, no master). Its default
clock is this process's CPU time, which other processes on shared cores do not lengthen.
"""

import collections
import importlib
import statistics
import time

import numpy as np
from numba.core.dispatcher import Dispatcher

# modules whose kernels a co-simulation step calls (the facades' and the thermal model's entry points)
BEARING_KERNEL_MODULES = tuple(
    f"bearing_fmu.kernels.{m}" for m in ("jones_harris", "contacts", "bearing_outputs", "radial_bearing")
)
KERNEL_MODULES = (*BEARING_KERNEL_MODULES, "spindle.thermal.network")


def _snapshot(args):
    return tuple(a.copy() if isinstance(a, np.ndarray) else a for a in args)


class KernelRecorder:
    """Context manager recording (dispatcher, argument copies) of every call to a kernel of `modules`."""

    def __init__(self, modules=KERNEL_MODULES):
        self.modules, self.calls, self._saved = [importlib.import_module(name) for name in modules], [], []

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
