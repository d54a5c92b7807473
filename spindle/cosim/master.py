"""fmpy co-simulation master (SPEC 6). Talks to FMUs only through FMI; imports no physics.

A run (spindle.cosim.runfile.RunSpec) couples FMU instances by connections output -> input and steps them
with a fixed communication step H:
- time is t_n = start + n H from an integer step counter (no drift);
- Gauss-Seidel (default): instances step one after the other in `order`, each with the newest
  outputs of those before it; Jacobi: every instance steps with the outputs of t_n, then all
  connections are transferred;
- initialisation: parameters and constant inputs are set in initialisation mode. Connected inputs
  start from the FMUs' own start values (never 0.0): Gauss-Seidel exits initialisation instance by
  instance in `order`, each after taking the outputs of those before it (computed at their exit)
  and the start values of those after it; Jacobi gives every connected input its source's start
  value, then all exit;
- every FMI status is checked (fmpy raises on Discard/Error/Fatal) and the FMU's own log lines go
  into the error message;
- optional step rejection (`rollback`): before a step every FMU's state is saved; if an FMU refuses
  the step, or a variable in `max_change` changes by more than allowed, all states are restored and
  the step is redone as two halves (up to `max_halvings` times);
- `limits` stop the run with the limit's message (e.g. thermal runaway) and keep the results so far.
Each FMU file is extracted once per master into a private temporary directory, removed at close().
"""

import csv
import math
import shutil
import sys
import tempfile
import time as wallclock
from dataclasses import dataclass, field

# pythonfmu FMUs run inside this interpreter. SPEC 3: loading scipy's compiled libraries (numba
# imports scipy) for the first time from inside an FMU can make the process abort at exit, so load
# both here, before any FMU. (Not sufficient on its own: see spindle.cli.run.)
import numba  # noqa: F401, E402
import numpy as np
import scipy.special  # noqa: F401, E402
from fmpy import calloc, extract, free, read_model_description
from fmpy.fmi1 import FMICallException
from fmpy.fmi2 import (
    FMU2Slave,
    fmi2CallbackAllocateMemoryTYPE,
    fmi2CallbackFreeMemoryTYPE,
    fmi2CallbackFunctions,
    fmi2CallbackLoggerTYPE,
)

from .runfile import split_name

STATUS_NAMES = {0: "OK", 1: "Warning", 2: "Discard", 3: "Error", 4: "Fatal", 5: "Pending"}


class MasterError(RuntimeError):
    """An FMI call failed or a step could not be completed; the message carries the FMU's log."""


@dataclass
class RunResult:
    """Recorded trajectories: columns[name] (numpy array, SI unit units[name]), one row per
    communication point from the start (after initialisation) to the end or the stop."""

    columns: dict
    units: dict
    status: str = "ok"  # ok | limit
    message: str = ""
    wall_time: float = 0.0  # s, stepping only (instantiation excluded)
    setup_time: float = 0.0  # s, extraction + instantiation + initialisation
    rejected_steps: int = 0
    log: list = field(default_factory=list)

    def write_csv(self, path):
        """CSV with a header 'name [unit]' and one row per communication point (repr floats)."""
        names = list(self.columns)
        with open(path, "w", newline="") as fh:
            writer = csv.writer(fh)  # quotes names like K[3,3]
            writer.writerow([f"{n} [{self.units.get(n, '1')}]" for n in names])
            for row in zip(*(self.columns[n] for n in names)):
                writer.writerow([repr(float(v)) for v in row])


class Instance:
    """One instantiated co-simulation FMU with name -> variable maps and an output cache."""

    def __init__(self, name, md, unzip_dir):
        self.name = name
        self.md = md
        self.variables = {v.name: v for v in md.modelVariables}
        self.log = []
        self._callbacks = fmi2CallbackFunctions()
        self._callbacks.logger = fmi2CallbackLoggerTYPE(self._logger)
        self._callbacks.allocateMemory = fmi2CallbackAllocateMemoryTYPE(calloc)
        self._callbacks.freeMemory = fmi2CallbackFreeMemoryTYPE(free)
        # no fmpy.logging.addLoggerProxy: it keeps one global Python logger, so with several
        # instances every message would land in the last one's log; the FMI message is a printf
        # format, hence the '%%' -> '%' in _logger
        self.slave = FMU2Slave(
            guid=md.guid, unzipDirectory=unzip_dir, modelIdentifier=md.coSimulation.modelIdentifier, instanceName=name
        )
        self.slave.instantiate(callbacks=self._callbacks, loggingOn=True)
        self.cache = {}  # output name -> last value read
        self._reads = {}  # type -> (names, value references) read into the cache

    def _logger(self, env, instance, status, category, message):
        text = message.decode("utf-8", "replace") if isinstance(message, bytes) else str(message)
        text = text.replace("%%", "%")
        self.log.append(f"[{STATUS_NAMES.get(status, status)}] {text}")

    def var(self, name):
        if name not in self.variables:
            raise MasterError(
                f"{self.name}: no variable {name!r} (the FMU has {sorted(v for v in self.variables)[:40]} ...)"
            )
        return self.variables[name]

    def call(self, what, fn, *args):
        """Run an FMI call; on a non-OK status raise MasterError with the FMU's recent log lines."""
        n_log = len(self.log)
        try:
            return fn(*args)
        except FMICallException as exc:
            status = STATUS_NAMES.get(getattr(exc, "status", None), "failure")
            lines = "; ".join(self.log[n_log:]) or "no message logged"
            raise MasterError(f"{self.name}: {what} returned {status}: {lines}") from None

    def set(self, values):
        """Set variables by name (Real, Integer, Boolean, String)."""
        for name, value in values.items():
            v = self.var(name)
            setter = {
                "Real": (self.slave.setReal, float),
                "Integer": (self.slave.setInteger, int),
                "Boolean": (self.slave.setBoolean, bool),
                "String": (self.slave.setString, str),
                "Enumeration": (self.slave.setInteger, int),
            }[v.type]
            self.call(f"set {name} = {value!r}", setter[0], [v.valueReference], [setter[1](value)])

    def watch(self, names):
        """Read these outputs into the cache at every refresh()."""
        by_type = {}
        for name in sorted(set(names)):
            v = self.var(name)
            by_type.setdefault(v.type, []).append(name)
        self._reads = {t: (ns, [self.variables[n].valueReference for n in ns]) for t, ns in by_type.items()}

    def refresh(self):
        getters = {
            "Real": self.slave.getReal,
            "Integer": self.slave.getInteger,
            "Boolean": self.slave.getBoolean,
            "Enumeration": self.slave.getInteger,
        }
        for kind, (names, vrs) in self._reads.items():
            values = self.call("get outputs", getters[kind], vrs)
            self.cache.update(zip(names, values))

    def start_value(self, name):
        """The variable's current value read from the FMU (its start value before any step)."""
        v = self.var(name)
        getter = {
            "Real": self.slave.getReal,
            "Integer": self.slave.getInteger,
            "Boolean": self.slave.getBoolean,
            "Enumeration": self.slave.getInteger,
        }[v.type]
        return self.call(f"get {name}", getter, [v.valueReference])[0]

    def close(self):
        try:
            self.slave.terminate()
        except Exception:
            pass
        self.slave.freeInstance()


class Master:
    """Runs a RunSpec. Use as a context manager, or call close()."""

    def __init__(self, spec):
        self.spec = spec
        self._dirs = []
        self.instances = {}
        t0 = wallclock.perf_counter()
        try:
            self._instantiate()
            self._wire()
        except BaseException:
            self.close()
            raise
        self.setup_time = wallclock.perf_counter() - t0

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()

    # -- set-up ----------------------------------------------------------------------------------
    def _instantiate(self):
        extracted = {}
        for name in self.spec.order:
            path = self.spec.instances[name].fmu
            if path not in extracted:  # each FMU file once, whatever the number of its instances
                unzip = tempfile.mkdtemp(prefix="spindle_fmu_")
                self._dirs.append(unzip)
                extract(path, unzipdir=unzip)
                extracted[path] = (read_model_description(path), unzip)
            md, unzip = extracted[path]
            if md.coSimulation is None:
                raise MasterError(f"{name}: {path} is not a co-simulation FMU")
            self.instances[name] = Instance(name, md, unzip)

    def _wire(self):
        spec = self.spec
        self.links = {name: [] for name in spec.order}  # target -> [(source inst, output, input)]
        watched = {name: set() for name in spec.order}
        for source, target in spec.connections:
            s_inst, s_var = split_name(source)
            t_inst, t_var = split_name(target)
            sv = self.instances[s_inst].var(s_var)
            tv = self.instances[t_inst].var(t_var)
            if sv.causality not in ("output", "parameter", "calculatedParameter", "local"):
                raise MasterError(f"connection {source} -> {target}: {source} is a {sv.causality}, not an output")
            if tv.causality != "input":
                raise MasterError(f"connection {source} -> {target}: {target} is a {tv.causality}, not an input")
            self.links[t_inst].append((s_inst, s_var, t_var))
            watched[s_inst].add(s_var)
        self.recorded = []
        for qualified in (
            list(spec.record)
            + [f"{s}" for s, _ in spec.connections]
            + list(spec.max_change)
            + [lim.variable for lim in spec.limits]
        ):
            inst, var = split_name(qualified)
            self.instances[inst].var(var)
            watched[inst].add(var)
            if qualified not in self.recorded:
                self.recorded.append(qualified)
        for name, inst in self.instances.items():
            inst.watch(watched[name])

    def _initialise(self):
        spec = self.spec
        for name in spec.order:
            inst = self.instances[name]
            inst.call(
                "setupExperiment", lambda i=inst: i.slave.setupExperiment(startTime=spec.start, stopTime=spec.stop)
            )
            inst.call("enterInitializationMode", inst.slave.enterInitializationMode)
            inst.set(spec.instances[name].parameters)
            inst.set(spec.instances[name].inputs)
        if spec.algorithm == "jacobi":  # every connected input from its source's start value
            starts = {
                name: {t_var: self.instances[s].start_value(s_var) for s, s_var, t_var in self.links[name]}
                for name in spec.order
            }
            for name in spec.order:
                self.instances[name].set(starts[name])
        exited = set()
        for name in spec.order:
            inst = self.instances[name]
            if spec.algorithm == "gauss_seidel":  # outputs of those already initialised, else start values
                inst.set(
                    {
                        t_var: (self.instances[s].cache[s_var] if s in exited else self.instances[s].start_value(s_var))
                        for s, s_var, t_var in self.links[name]
                    }
                )
            self._exit_initialisation(inst)
            exited.add(name)

    @staticmethod
    def _exit_initialisation(inst):
        """fmi2ExitInitializationMode; it failed if it returned Error/Fatal or if the FMU logged an error
        there (an FMU built on pythonfmu's own binary returns OK whatever its slave says)."""
        n_log = len(inst.log)
        try:
            inst.slave.exitInitializationMode()
            refused = False
        except FMICallException:
            refused = True
        errors = [line for line in inst.log[n_log:] if line.startswith(("[Error]", "[Fatal]"))]
        if refused or errors:
            raise MasterError(f"{inst.name}: initialisation failed: {'; '.join(errors) or 'no message logged'}")
        inst.refresh()

    # -- stepping --------------------------------------------------------------------------------
    def _transfer(self, name):
        inst = self.instances[name]
        values = {t_var: self.instances[s].cache[s_var] for s, s_var, t_var in self.links[name]}
        if values:
            inst.set(values)

    def _macro_step(self, t, h):
        """One communication step of the coupled system from t to t + h."""
        if self.spec.algorithm == "jacobi":
            for name in self.spec.order:
                self._transfer(name)
            for name in self.spec.order:
                inst = self.instances[name]
                inst.call(f"doStep at t = {t:.9g} s, h = {h:.9g} s", inst.slave.doStep, t, h)
            for name in self.spec.order:
                self.instances[name].refresh()
        else:
            for name in self.spec.order:
                inst = self.instances[name]
                self._transfer(name)
                inst.call(f"doStep at t = {t:.9g} s, h = {h:.9g} s", inst.slave.doStep, t, h)
                inst.refresh()

    def _values(self):
        return {q: self.instances[split_name(q)[0]].cache[split_name(q)[1]] for q in self.recorded}

    def _too_big_change(self, before):
        for qualified, allowed in self.spec.max_change.items():
            inst, var = split_name(qualified)
            change = abs(self.instances[inst].cache[var] - before[qualified])
            if not change <= allowed:
                return f"{qualified} changed by {change:.4g} (allowed {allowed})"
        return None

    def _guarded_step(self, t, h, depth=0):
        """Step with rollback: returns the number of rejected (sub)steps."""
        states = {n: i.slave.getFMUstate() for n, i in self.instances.items()}
        caches = {n: dict(i.cache) for n, i in self.instances.items()}
        before = self._values()
        try:
            self._macro_step(t, h)
            reason = self._too_big_change(before)
        except MasterError as exc:
            reason = str(exc)
        try:
            if reason is None:
                return 0
            if depth >= self.spec.max_halvings:
                raise MasterError(f"step at t = {t:.9g} s rejected after {depth} halvings (h = {h:.4g} s): {reason}")
            for n, i in self.instances.items():
                i.slave.setFMUstate(states[n])
                i.cache = caches[n]
            half = 0.5 * h
            return 1 + self._guarded_step(t, half, depth + 1) + self._guarded_step(t + half, half, depth + 1)
        finally:
            for n, i in self.instances.items():
                i.slave.freeFMUstate(states[n])

    def _check_limits(self, t):
        for lim in self.spec.limits:
            inst, var = split_name(lim.variable)
            value = self.instances[inst].cache[var]
            if not (lim.min <= value <= lim.max) or math.isnan(value):
                return f"t = {t:.6g} s: {lim.variable} = {value:.6g} left [{lim.min:.6g}, {lim.max:.6g}]" + (
                    f": {lim.message}" if lim.message else ""
                )
        return None

    def run(self, progress=False):
        """Initialise, step to the stop time (or a limit) and return the RunResult."""
        spec = self.spec
        t_setup = wallclock.perf_counter()
        self._initialise()
        setup = self.setup_time + wallclock.perf_counter() - t_setup
        n_steps = spec.n_steps
        rows = [self._values()]
        times = [spec.start]
        status, message, rejected = "ok", self._check_limits(spec.start) or "", 0
        if message:
            status = "limit"
        bar = _Progress(n_steps, progress)
        t_wall = wallclock.perf_counter()
        for n in range(n_steps if status == "ok" else 0):
            t = spec.start + n * spec.step
            if spec.rollback:
                rejected += self._guarded_step(t, spec.step)
            else:
                self._macro_step(t, spec.step)
            t_next = spec.start + (n + 1) * spec.step
            rows.append(self._values())
            times.append(t_next)
            bar.update(n + 1)
            message = self._check_limits(t_next) or ""
            if message:
                status = "limit"
                break
        wall = wallclock.perf_counter() - t_wall
        bar.close()
        columns = {"time": np.array(times)}
        for q in self.recorded:
            columns[q] = np.array([r[q] for r in rows], dtype=float)
        units = {"time": "s"}
        for q in self.recorded:
            inst, var = split_name(q)
            units[q] = getattr(self.instances[inst].variables[var], "unit", None) or "1"
        log = [f"{n}: {line}" for n, i in self.instances.items() for line in i.log]
        return RunResult(columns, units, status, message, wall, setup, rejected, log)

    def close(self):
        for inst in self.instances.values():
            try:
                inst.close()
            except Exception:
                pass
        self.instances = {}
        for d in self._dirs:
            shutil.rmtree(d, ignore_errors=True)
        self._dirs = []


def run(spec, progress=False):
    """Run a RunSpec from start to end; always frees the FMUs and removes their extraction."""
    with Master(spec) as master:
        return master.run(progress=progress)


class _Progress:
    """A plain progress line on stderr (tqdm when installed); silent unless asked."""

    def __init__(self, total, enabled):
        self.total, self.enabled, self._bar, self._shown = total, enabled, None, -1
        if enabled:
            try:
                from tqdm import tqdm

                self._bar = tqdm(total=total, unit="step", file=sys.stderr)
            except ImportError:
                pass

    def update(self, n):
        if not self.enabled:
            return
        if self._bar is not None:
            self._bar.update(n - self._bar.n)
            return
        percent = 100 * n // max(self.total, 1)
        if percent // 10 != self._shown:
            self._shown = percent // 10
            sys.stderr.write(f"\r{percent:3d} % ({n}/{self.total} steps)")
            sys.stderr.flush()

    def close(self):
        if self._bar is not None:
            self._bar.close()
        elif self.enabled:
            sys.stderr.write("\n")
