"""The Python side of the FMUs' FMI layer (fmi2_python.c, docs/fmu_runtime.md).

The build puts this file into every FMU as resources/fmi2_layer.py (bearing_fmu_common.runtime.binaries); the
layer loads it from there at its first fmi2Instantiate, by file location, as a module of its own that is not
registered in sys.modules: each FMU's copy of the layer has its own copy of this module, and loading it adds
nothing to sys.path. Standard library only: it runs before the FMU's packages can be imported.
"""

import importlib
import inspect
import os
import pickle
import sys
import threading
import traceback
import types

# One set-up lock for every FMU of the product in the process. Each FMU brings its own copy of the layer and
# so its own copy of this module: the lock lives in a module registered once in sys.modules. Two FMUs set up
# by two threads at once (imports, numba loading kernels and filling its registries) are not safe: one of
# them can fail to instantiate.
_SHARED = "_bearing_fmu_runtime_shared"
_shared = sys.modules.setdefault(_SHARED, types.ModuleType(_SHARED))
_setup_lock = _shared.__dict__.setdefault("setup_lock", threading.RLock())


def begin_setup():
    _setup_lock.acquire()


def end_setup():
    _setup_lock.release()


def slave_class(resources):
    """The Fmi2Slave subclass of the module named in resources/slavemodule.txt (the one with the longest class
    hierarchy). resources/ is put on sys.path only if that module is not imported yet: later instances, from
    any extraction of the FMU, reuse it."""
    with open(os.path.join(resources, "slavemodule.txt"), encoding="utf-8") as fh:
        name = fh.readline().strip()
    if name not in sys.modules and resources not in sys.path:
        sys.path.insert(0, resources)
    module = importlib.import_module(name)
    found = [
        c
        for c in vars(module).values()
        if inspect.isclass(c) and not inspect.isabstract(c) and any(k.__name__ == "Fmi2Slave" for k in c.__mro__)
    ]
    if not found:
        raise ImportError(f"no Fmi2Slave subclass in module {name} ({module.__file__})")
    return max(found, key=lambda c: len(c.__mro__))


def describe(kind, value, tb):
    """An exception and its traceback as one text, the exception first: a host that shows only the start of
    a long message still shows the cause. An exception raised by the layer's own C code has no traceback: its
    text alone."""
    head = "".join(traceback.format_exception_only(kind, value)).rstrip()
    if tb is None:
        return head
    return head + "\n" + "".join(traceback.format_exception(kind, value, tb)).rstrip()


def variable_name(slave, vr):
    """The name of the slave's variable of value reference vr, with the reference, for a message."""
    var = slave.vars.get(vr)
    return f"value reference {vr}" if var is None else f"{var.name} (value reference {vr})"


def dumps(state):
    return pickle.dumps(state, protocol=pickle.HIGHEST_PROTOCOL)


loads = pickle.loads
