"""The compiled-kernel floor of a run: record every kernel call a run makes, then replay the calls alone.

CPU time of this process (time.process_time) is the default clock: on cores shared with other
processes it is not lengthened by their work, so a ratio of two such times measured minutes apart
stays meaningful. `KernelRecorder(modules)` wraps each numba dispatcher found in the given modules for the duration of a
`with` block and records every call with copies of its array arguments taken before the call (the
warm-start state a kernel reads is part of its work). `replay_time(calls)` then repeats exactly those
calls, in order, on fresh copies and returns the median wall time: what the run would cost with no
Python between the kernels (no facade, no FMI, no master). Facades call kernels through their module
(``qk.solve_quasistatic``), so wrapping the module attribute sees every call they make.
"""

import statistics
import time

import numpy as np
from numba.core.dispatcher import Dispatcher

# modules whose kernels a co-simulation step calls (the facades' and the thermal model's entry points)
BEARING_KERNEL_MODULES = (
    "bearing_fmu.kernels.jones_harris",
    "bearing_fmu.kernels.contacts",
    "bearing_fmu.kernels.bearing_outputs",
    "bearing_fmu.kernels.radial_bearing",
)
KERNEL_MODULES = (*BEARING_KERNEL_MODULES, "spindle.thermal.network")


def _snapshot(args):
    return tuple(a.copy() if isinstance(a, np.ndarray) else a for a in args)


class KernelRecorder:
    """Context manager recording (dispatcher, argument copies) of every call to a kernel of `modules`
    (module names; those not imported yet are imported)."""

    def __init__(self, modules=KERNEL_MODULES):
        self.modules = [__import__(name, fromlist=["_"]) for name in modules]
        self.calls = []
        self._saved = []

    def __enter__(self):
        for module in self.modules:
            for name, obj in list(vars(module).items()):
                if isinstance(obj, Dispatcher):
                    self._saved.append((module, name, obj))
                    setattr(module, name, self._wrap(obj))
        return self

    def _wrap(self, dispatcher):
        calls = self.calls

        def recorded(*args):
            calls.append((dispatcher, _snapshot(args)))
            return dispatcher(*args)

        return recorded

    def __exit__(self, *exc):
        for module, name, obj in self._saved:
            setattr(module, name, obj)
        self._saved = []


def replay_time(calls, repeats=5, clock=time.process_time):
    """Median time (s, by `clock`: this process's CPU time unless told otherwise) of replaying `calls` in
    order, each repeat on fresh argument copies."""
    samples = []
    for _ in range(repeats):
        work = [(fn, _snapshot(args)) for fn, args in calls]
        t0 = clock()
        for fn, args in work:
            fn(*args)
        samples.append(clock() - t0)
    return statistics.median(samples)


def kernel_names(calls):
    """Number of calls per kernel name (for the report)."""
    counts = {}
    for fn, _ in calls:
        counts[fn.py_func.__name__] = counts.get(fn.py_func.__name__, 0) + 1
    return counts
