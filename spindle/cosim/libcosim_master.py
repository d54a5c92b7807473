"""Second, independent co-simulation master: libcosim (Open Simulation Platform) via libcosimpy.

Used to cross-check the fmpy master (docs/architecture.md): the same FMUs, connections and step run under both
must agree. It talks FMI only (through libcosim) and imports no physics.

Algorithm: libcosim's fixed-step algorithm as bundled in libcosimpy 0.0.6 (libcosim 0.11.2). Source:
libcosim src/cosim/algorithm/fixed_step_algorithm.cpp (`initialize`, `do_step`,
`calculate_and_transfer`), src/cosim/slave_simulator.cpp (`do_iteration`, `start_simulation`,
`do_step`: set pending inputs -> call -> read outputs), src/cosim/execution.cpp (`step`: lazy
initialisation, observers), src/cosim/fmi/v2/fmu.cpp (`setup` = fmi2SetupExperiment +
fmi2EnterInitializationMode, `start_simulation` = fmi2ExitInitializationMode). Every point below was
confirmed with a probe FMU (y = u + 1 live, x += u*H, counters of fmi2SetReal calls per FMI state)
in chains and loops of 2-3 instances.

Initialisation (lazily, inside the first `step()`), N = number of instances:
  1. All instances: fmi2SetupExperiment(tStart = 0, no tolerance, no stop time),
     fmi2EnterInitializationMode, read outputs. Nothing is set in the *instantiated* state (newer
     libcosim sources set start values there; 0.11.2 does not: the probe saw 0 such calls).
  2. N rounds of: each instance gets its pending values set (round 1: the values given with
     `*_initial_value`, i.e. our parameters and inputs; later rounds: connected inputs), outputs read;
     then every connection is transferred (target input := source output just read).
  3. Pending connected inputs set, fmi2ExitInitializationMode, outputs read, every connection
     transferred again.
  So a connected input enters step 1 holding its source's output read *after*
  fmi2ExitInitializationMode; inside initialisation mode it holds the source's initialisation-mode
  output (the round-N value). Our pythonfmu FMUs compute outputs only at exit of initialisation and in
  doStep, so for them the N rounds only matter through the values present at exit.
  The t = 0 record is read after step 3's reads, before the transfer reaches the targets: a connected
  input recorded at t = 0 shows its initialisation-mode value.

Step n (t_n -> t_n + H), Jacobi: every instance is set the connected inputs transferred at the end of
step n-1 (or of initialisation), all instances call fmi2DoStep(t_n, H, noSetFMUStatePriorToCurrentPoint
= true) (on libcosim's worker threads; pythonfmu serialises them on the GIL), all outputs are read,
then every connection is transferred. No iteration, no rollback; fmi2Discard or worse from doStep fails
the step (LibcosimError). t_n = n * H is counted in integer nanoseconds (converted to seconds for
fmi2DoStep). A recorded *input* at t_{n+1} is the value the instance used during step n.

Input schedules (the run files' `schedules`, u(t) given as a function): libcosim 0.11.2 has no
piecewise-linear input of its own; its scenario files override or bias a variable with a constant at
listed times, so a ramp would need one scenario event per step. The same is done directly with
libcosim's override manipulator (what its scenario manager uses): a scheduled input is given u(0) as
its initial value; before each step n the manipulator overrides it with u(t_n) (u(t_n + H) for a
schedule with at = "end") and the execution advances one step (the override reaches the FMU with the
step's other pending inputs, before fmi2DoStep): the values spindle.cosim.master sets.

To run the fmpy master with the same algorithm: enterInitializationMode; set parameters and inputs;
N times {read every connected output, then set every connected input}; exitInitializationMode (all);
read every connected output and set every connected input; then per step: doStep all, read all
connected outputs, set all connected inputs. (tests/cosim/test_libcosim_master.py has this loop.)

Process safety: pythonfmu FMUs run inside this Python process. libcosimpy calls libcosim through
ctypes (which releases the GIL); libcosim calls fmi2DoStep from its worker thread and pythonfmu takes
the GIL there (PyGILState_Ensure), so it works in-process (30/30 fresh processes exited 0, also
without numba/scipy preloaded; no os._exit needed). `run_libcosim` destroys the execution before it
returns, so no FMU is freed during interpreter shutdown and libcosim removes its /tmp/libcosim_*
extraction directory; a script that ends with os._exit without that leaves one behind (~1 MB per FMU).
Cost: about 80 us per step for the execution plus 20 us per instance on top of the FMUs' own work
(2-core machine; the worker-thread handoff and GIL acquisition dominate).
"""

import ctypes
import math
from pathlib import Path

import numpy as np

NANOSECONDS = 1_000_000_000


class LibcosimError(RuntimeError):
    """A libcosim call failed; the message names the instance and variable and carries libcosim's."""


def libcosim_version():
    """'major.minor.patch' of the libcosim bundled with libcosimpy (None if libcosimpy is missing)."""
    try:
        from libcosimpy._internal import libcosimc
    except ImportError:
        return None

    class _Version(ctypes.Structure):
        _fields_ = [("major", ctypes.c_int), ("minor", ctypes.c_int), ("patch", ctypes.c_int)]

    fn = libcosimc().cosim_libcosim_version
    fn.restype = _Version
    v = fn()
    return f"{v.major}.{v.minor}.{v.patch}"


def _split(name):
    instance, sep, variable = name.partition(".")
    if not sep or not variable:
        raise LibcosimError(f"'{name}': expected 'instance.variable'")
    return instance, variable


def _ticks(seconds, what):
    """libcosim counts time in integer nanoseconds: the value must be a whole number of them."""
    ticks = round(seconds * NANOSECONDS)
    if ticks <= 0 or abs(ticks / NANOSECONDS - seconds) > 1e-12 * max(1.0, abs(seconds)):
        raise LibcosimError(f"{what} = {seconds!r} s is not a positive whole number of nanoseconds")
    return ticks


def _convert(kind, value, where):
    """The value as the FMI type wants it; refuses lossy or ambiguous conversions (bool('false'))."""
    if kind == "STRING":
        if not isinstance(value, str):
            raise LibcosimError(f"{where}: String value expected, got {value!r}")
        return value
    if kind == "BOOLEAN":
        if isinstance(value, bool) or value in (0, 1):
            return bool(value)
        raise LibcosimError(f"{where}: Boolean value expected (True/False), got {value!r}")
    if isinstance(value, (str, bytes)):
        raise LibcosimError(f"{where}: {kind.capitalize()} value expected, got {value!r}")
    try:
        number = float(value)
        if kind == "INTEGER" and number != int(number):
            raise ValueError
    except (TypeError, ValueError, OverflowError):
        raise LibcosimError(f"{where}: {kind.capitalize()} value expected, got {value!r}") from None
    return int(number) if kind == "INTEGER" else number


class _Run:
    """One libcosim execution (fixed step) with a time-series observer; `close()` destroys it. With
    `ssp` (the path of an SSP package) the execution, its instances, connections and initial values
    come from the package; `step` is then its fixed step."""

    def __init__(self, step, samples, ssp=None):
        from libcosimpy._internal import get_last_error_message, libcosimc
        from libcosimpy.CosimExecution import CosimExecution
        from libcosimpy.CosimLogging import CosimLogLevel, log_output_level
        from libcosimpy.CosimObserver import CosimObserver

        self._last_error = get_last_error_message
        self._lib = libcosimc()
        self.slaves, self.index, self.variables = {}, {}, {}  # per instance: CosimLocalSlave, index, variables
        log_output_level(CosimLogLevel.WARNING)  # libcosim logs every FMU load at INFO; FMU errors still show
        if ssp is None:
            self.execution = CosimExecution.from_step_size(_ticks(step, "step"))
        else:
            try:
                self.execution = CosimExecution.from_ssp_file(str(ssp), _ticks(step, "step"))  # step in ns
            except AssertionError:  # libcosimpy asserts on a null execution
                raise LibcosimError(f"cannot load the SSP package {ssp}: {self._last_error()}") from None
        if not self.execution._CosimExecution__ptr:  # libcosimpy does not check this pointer
            raise LibcosimError(f"cannot create the execution: {self._last_error()}")
        if ssp is not None:  # the package's instances, by name
            for info in self.execution.slave_infos():
                name, index = info.name.decode(), info.index
                self.index[name] = index
                self.variables[name] = {v.name.decode(): v for v in self.execution.slave_variables(index)}
        # a sized buffer: the default one keeps only the last 10 000 samples
        self.observer = CosimObserver.create_time_series(buffer_size=samples)
        if not self.execution.add_observer(self.observer):
            raise LibcosimError(f"cannot add the observer: {self._last_error()}")

    def add_instance(self, instance, spec):
        from libcosimpy.CosimSlave import CosimLocalSlave

        if "." in instance or not instance:
            raise LibcosimError(f"instance name {instance!r}: must be non-empty, without '.'")
        path = Path(spec["fmu"]).resolve()
        if not path.is_file():
            raise LibcosimError(f"{instance}: FMU not found: {path}")
        slave = CosimLocalSlave(fmu_path=str(path), instance_name=instance)
        if not slave.ptr():
            raise LibcosimError(f"{instance}: cannot load {path}: {self._last_error()}")
        self.slaves[instance] = slave  # libcosimpy frees the C slave when this object dies
        index = self.execution.add_local_slave(slave)
        if index < 0:
            raise LibcosimError(f"{instance}: cannot add to the execution: {self._last_error()}")
        self.index[instance] = index
        self.variables[instance] = {v.name.decode(): v for v in self.execution.slave_variables(index)}
        for group in ("parameters", "inputs"):
            for name, value in spec.get(group, {}).items():
                self.set_initial(instance, name, value)

    def variable(self, instance, name):
        """(description, type name) of instance.name."""
        from libcosimpy.CosimEnums import CosimVariableType

        try:
            var = self.variables[instance][name]
        except KeyError:
            where = "instance" if instance not in self.variables else "variable"
            raise LibcosimError(f"{instance}.{name}: no such {where}") from None
        return var, CosimVariableType(var.type).name

    def set_initial(self, instance, name, value):
        """Set before initialisation; libcosim applies it in initialisation mode (see module docstring)."""
        var, kind = self.variable(instance, name)
        setter = getattr(self.execution, f"{kind.lower()}_initial_value")
        if not setter(self.index[instance], var.reference, _convert(kind, value, f"{instance}.{name}")):
            raise LibcosimError(f"{instance}.{name}: cannot set initial value {value!r}: {self._last_error()}")

    def connect(self, source, target):
        (s_inst, s_name), (t_inst, t_name) = _split(source), _split(target)
        (s_var, s_kind), (t_var, t_kind) = self.variable(s_inst, s_name), self.variable(t_inst, t_name)
        if s_kind != t_kind:
            raise LibcosimError(f"{source} -> {target}: types differ ({s_kind} -> {t_kind})")
        connect = getattr(self.execution, f"connect_{s_kind.lower()}_variables")
        if connect(self.index[s_inst], s_var.reference, self.index[t_inst], t_var.reference) != 0:
            raise LibcosimError(f"{source} -> {target}: cannot connect: {self._last_error()}")

    def observe(self, names):
        """Start recording `names` ('instance.variable', Real or Integer); samples from step 0 on."""
        from libcosimpy.CosimEnums import CosimVariableType

        columns = []
        for name in names:
            instance, variable = _split(name)
            var, kind = self.variable(instance, variable)
            if kind not in ("REAL", "INTEGER"):
                # libcosim's time-series observer records Real and Integer variables only
                raise LibcosimError(f"{name}: cannot record a {kind} variable (Real/Integer only)")
            if not self.observer.start_time_series(self.index[instance], var.reference, CosimVariableType[kind]):
                raise LibcosimError(f"{name}: cannot observe: {self._last_error()}")
            columns.append((name, self.index[instance], var.reference, kind))
        return columns

    def schedule(self, schedules):
        """Drive inputs as functions of time: schedules = {'instance.variable': u(t)} (Real inputs, t in
        s). Adds libcosim's override manipulator; apply() sets u(t) on all of them."""
        from libcosimpy.CosimManipulator import CosimManipulator

        self.manipulator = CosimManipulator.create_override()
        if not self.execution.add_manipulator(self.manipulator):
            raise LibcosimError(f"cannot add the override manipulator: {self._last_error()}")
        self.scheduled = []
        for name, u in schedules.items():
            instance, variable = _split(name)
            var, kind = self.variable(instance, variable)
            if kind != "REAL":
                raise LibcosimError(f"{name}: only Real inputs can be scheduled, this one is {kind}")
            self.set_initial(instance, variable, u(0.0))
            self.scheduled.append((name, self.index[instance], var.reference, u))

    def apply_schedules(self, t, h):
        """Override every scheduled input with its value for the next step, from t to t + h (s)."""
        for name, index, reference, u in self.scheduled:
            if not self.manipulator.slave_real_values(index, [reference], [u.for_step(t, h)]):
                raise LibcosimError(f"{name}: cannot override with u({t}): {self._last_error()}")

    def step(self, n_steps):
        if not self.execution.step(n_steps):
            t = self.execution.status().current_time / NANOSECONDS
            raise LibcosimError(
                f"step from t = {t} s failed: {self._last_error().strip()} "
                "(the FMU's own message is in libcosim's log on stderr)"
            )

    def samples(self, index, reference, kind, count):
        """`count` samples from step 0: values, step numbers, times (ns). Called through ctypes
        directly: libcosimpy's wrapper drops step 0 (it takes step number 0 for an empty slot)."""
        c_type, fname = {
            "REAL": (ctypes.c_double, "cosim_observer_slave_get_real_samples"),
            "INTEGER": (ctypes.c_int, "cosim_observer_slave_get_integer_samples"),
        }[kind]
        values, steps, times = (c_type * count)(), (ctypes.c_int64 * count)(), (ctypes.c_int64 * count)()
        fn = getattr(self._lib, fname)
        fn.restype = ctypes.c_int64
        fn.argtypes = [
            ctypes.c_void_p,
            ctypes.c_int,
            ctypes.c_uint32,
            ctypes.c_int64,
            ctypes.c_size_t,
            ctypes.POINTER(c_type),
            ctypes.POINTER(ctypes.c_int64),
            ctypes.POINTER(ctypes.c_int64),
        ]
        got = fn(ctypes.cast(self.observer.ptr(), ctypes.c_void_p), index, reference, 0, count, values, steps, times)
        if got != count:
            raise LibcosimError(f"observer returned {got} of {count} samples: {self._last_error()}")
        return np.array(values), np.array(steps), np.array(times)

    def close(self):
        """Destroy the execution now (fmi2Terminate + fmi2FreeInstance of every FMU, removal of
        libcosim's /tmp/libcosim_* extraction), while Python still runs: never at interpreter exit."""
        for attr in ("execution", "observer", "manipulator"):  # execution first: it owns the FMUs
            if hasattr(self, attr):
                delattr(self, attr)
        self.slaves.clear()


def run_libcosim(system, step, stop, record):
    """Run `system` under libcosim's fixed-step (Jacobi) algorithm from t = 0 to `stop`.

    system = {"instances": {name: {"fmu": path, "parameters": {...}, "inputs": {...},
                                   "schedules": {input: u}}},
              "connections": [("src.output", "dst.input"), ...]}
    A schedule u is a spindle.cosim.runfile.Schedule (u(t), u.for_step(t, h)): set to u.for_step(t_n, H)
    before each step n (see the module docstring).
    Parameters and inputs are given to libcosim as initial values; Real (float), Integer (int),
    Boolean (bool) and String (str) variables are accepted. An initial value on a connected input
    is overwritten during initialisation (see the module docstring). `record` lists
    'instance.variable' names (Real or Integer). step and stop in seconds (step a whole number of
    nanoseconds, stop a whole number of steps).
    Returns a numpy structured array: 'time' and one column per recorded name (float for Real,
    int64 for Integer), one row per communication point t = 0, H, ..., stop (row 0: after
    initialisation). Raises LibcosimError naming the instance and variable on any failure.
    """
    n_steps = round(stop / step)
    if n_steps < 1 or not math.isclose(n_steps * step, stop, rel_tol=1e-9):
        raise LibcosimError(f"stop = {stop!r} s is not a whole number of steps of {step!r} s")
    count = n_steps + 1
    run = _Run(step, samples=count)
    try:
        for instance, spec in system["instances"].items():
            run.add_instance(instance, spec)
        for source, target in system.get("connections", []):
            run.connect(source, target)
        schedules = {
            f"{instance}.{name}": u
            for instance, spec in system["instances"].items()
            for name, u in spec.get("schedules", {}).items()
        }
        columns = run.observe(record)
        if schedules:
            run.schedule(schedules)
            for n in range(n_steps):  # u at t_n = n H, as spindle.cosim.master computes it
                run.apply_schedules(n * step, step)
                run.step(1)
        else:
            run.step(n_steps)
        out = np.zeros(
            count,
            dtype=[("time", float)] + [(name, float if kind == "REAL" else np.int64) for name, _, _, kind in columns],
        )
        times = np.arange(count) * _ticks(step, "step")
        for name, index, reference, kind in columns:
            values, steps, sample_times = run.samples(index, reference, kind, count)
            if not (np.array_equal(steps, np.arange(count)) and np.array_equal(sample_times, times)):
                raise LibcosimError(f"{name}: observer samples are not at steps 0..{n_steps}")
            out[name] = values
        out["time"] = times / NANOSECONDS
        return out
    finally:
        run.close()


def cross_check(system, step, stop, record, reference, rtol=1e-6, atol=0.0):
    """Run `system` under libcosim and compare with `reference` (a structured array or dict of arrays
    with 'time' and the recorded names, one row per communication point including t = 0, e.g. from
    the fmpy master run with the same algorithm). Returns (libcosim result, {name: max relative
    difference}); raises AssertionError listing every column outside rtol/atol."""
    result = run_libcosim(system, step, stop, record)
    errors, bad = {}, []
    for name in ["time", *record]:
        a, b = np.asarray(result[name], float), np.asarray(reference[name], float)
        if a.shape != b.shape:
            raise AssertionError(f"{name}: {a.shape} rows under libcosim, {b.shape} in the reference")
        scale = np.maximum(np.abs(a), np.abs(b))
        errors[name] = float(np.max(np.abs(a - b) / np.where(scale > 0, scale, 1.0)))
        if not np.allclose(a, b, rtol=rtol, atol=atol):
            worst = int(np.argmax(np.abs(a - b)))
            bad.append(f"{name}: row {worst}, libcosim {a[worst]!r} vs reference {b[worst]!r}")
    if bad:
        raise AssertionError("libcosim and the reference differ:\n  " + "\n  ".join(bad))
    return result, errors
