"""fmpy co-simulation master (docs/architecture.md, master). Talks to FMUs only through FMI and imports no
physics for them: each FMU runs on the packages it carries (docs/fmu_runtime.md, "The master").

A run (spindle.cosim.runfile.RunSpec) couples FMU instances by connections output -> input and steps them
with a fixed communication step H:
- time is t_n = start + n H from an integer step counter (no drift);
- Gauss-Seidel (default): instances step one after the other in `order`, each with the newest
  outputs of those before it; Jacobi: every instance steps with the outputs of t_n, then all
  connections are transferred;
- input schedules (runfile.Schedule): a scheduled input gets u(start) in initialisation mode and u(t)
  (or u(t + h) if its schedule says at = "end") before every step [t, t + h] (also the halves of a
  rejected step), one setReal per instance;
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
- `limits` stop the run with the limit's message (e.g. thermal runaway) and keep the results so far;
- results are recorded every `record_interval` seconds (default: every communication point; the last
  point is always recorded) into arrays preallocated for the whole run, or streamed row by row to a
  CSV file (`csv_path`) and not kept in memory: the master's memory does not grow with run length.
Each FMU file is extracted once per master into a private temporary directory, removed at close().
Names are resolved once, when the run is wired: every step reads each instance's watched outputs with
one getReal (and one getInteger) call on precomputed value references and sets each instance's
connected inputs with one setReal call per type.
"""

import csv
import math
import shutil
import sys
import tempfile
import time as wallclock
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np
from fmpy import calloc, extract, free, read_model_description
from fmpy.fmi1 import FMICallException
from fmpy.fmi2 import (
    FMU2Slave,
    fmi2CallbackAllocateMemoryTYPE,
    fmi2CallbackFreeMemoryTYPE,
    fmi2CallbackFunctions,
    fmi2CallbackLoggerTYPE,
    fmi2Integer,
    fmi2Real,
    fmi2True,
    fmi2ValueReference,
)

from .runfile import split_name

STATUS_NAMES = {0: "OK", 1: "Warning", 2: "Discard", 3: "Error", 4: "Fatal", 5: "Pending"}
# FMI types read and written every step through the FMU's own functions with preallocated ctypes
# arrays (the values are the ones fmpy's getReal/setReal would pass: same C calls, same conversions)
BATCHED = {
    "Real": ("fmi2GetReal", "fmi2SetReal", fmi2Real),
    "Integer": ("fmi2GetInteger", "fmi2SetInteger", fmi2Integer),
    "Enumeration": ("fmi2GetInteger", "fmi2SetInteger", fmi2Integer),
}
# FMI type -> (FMU2Slave getter, setter, Python conversion); enumerations travel as integers
ACCESSORS = {
    "Real": ("getReal", "setReal", float),
    "Integer": ("getInteger", "setInteger", int),
    "Boolean": ("getBoolean", "setBoolean", bool),
    "String": ("getString", "setString", str),
    "Enumeration": ("getInteger", "setInteger", int),
}


class MasterError(RuntimeError):
    """An FMI call failed or a step could not be completed; the message carries the FMU's log."""


def csv_header(names, units):
    """Header cells 'name [unit]' of a result CSV (the unit '1' when dimensionless)."""
    return [f"{n} [{units.get(n, '1')}]" for n in names]


def csv_row(values):
    """Cells of one result row: repr of each float, which round-trips exactly."""
    return [repr(float(v)) for v in values]


def header_names(cells):
    """Column names of a CSV header row: a structured name such as K[1,2] that a writer left unquoted (split at
    its comma into 'K[1' and '2]') is joined again; the master itself quotes such names."""
    names = []
    for cell in cells:
        if names and names[-1].count("[") > names[-1].count("]"):
            names[-1] += "," + cell
        else:
            names.append(cell)
    return names


def read_csv(path):
    """Columns and units of a result CSV written by the master (or by another master that left names such as
    K[1,2] unquoted): ({name: numpy array}, {name: unit})."""
    with open(path, newline="") as fh:
        reader = csv.reader(fh)
        header = header_names(next(reader))
        values = np.array([[float(v) for v in row] for row in reader], dtype=float).reshape(-1, len(header))
    names, units = [], {}
    for cell in header:
        name, _, unit = cell.rpartition(" [")
        names.append(name)
        units[name] = unit.rstrip("]")
    return {n: values[:, k].copy() for k, n in enumerate(names)}, units


@dataclass
class RunResult:
    """Recorded trajectories: columns[name] (numpy array, SI unit units[name]), one row per recorded
    communication point from the start (after initialisation) to the end or the stop. A run streamed
    to a CSV file keeps no columns in memory (columns is empty, csv_path names the file: read_csv)."""

    columns: dict
    units: dict
    status: str = "ok"  # ok | limit
    message: str = ""
    wall_time: float = 0.0  # s, stepping only (instantiation excluded)
    setup_time: float = 0.0  # s, extraction + instantiation + initialisation
    rejected_steps: int = 0
    log: list = field(default_factory=list)
    cpu_time: float = 0.0  # s, this process's CPU time for the stepping (not lengthened by other processes)
    csv_path: str = None  # the CSV the rows were streamed to, or None (rows in columns)
    n_rows: int = 0  # recorded rows (communication points)
    n_steps: int = 0  # communication steps done (the run reached start + n_steps * step)

    def write_csv(self, path):
        """CSV with a header 'name [unit]' and one row per recorded communication point (repr floats);
        a streamed result copies its file."""
        if self.csv_path is not None:
            if Path(path).resolve() != Path(self.csv_path).resolve():
                shutil.copyfile(self.csv_path, path)
            return
        names = list(self.columns)
        with open(path, "w", newline="") as fh:
            writer = csv.writer(fh)  # quotes names like K[3,3]
            writer.writerow(csv_header(names, self.units))
            for row in zip(*(self.columns[n] for n in names)):
                writer.writerow(csv_row(row))


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
        try:
            self.slave.instantiate(callbacks=self._callbacks, loggingOn=True)
        except Exception as exc:  # fmpy raises a bare Exception: name the instance and what it logged
            lines = "; ".join(self.log) or "no message logged"
            raise MasterError(f"{name}: fmi2Instantiate failed ({exc}): {lines}") from None
        self._do_step = self._checked("fmi2DoStep")
        self.cache = {}  # output name -> last value read
        self._reads = []  # (getter, names, value references) read into the cache at each refresh
        self.failed = False  # a call returned fmi2Error or worse: only fmi2FreeInstance (or fmi2Reset) is allowed

    def _logger(self, env, instance, status, category, message):
        text = message.decode("utf-8", "replace") if isinstance(message, bytes) else str(message)
        text = text.replace("%%", "%")
        self.log.append(f"[{STATUS_NAMES.get(status, status)}] {text}")

    def var(self, name):
        if name not in self.variables:
            raise MasterError(
                f"{self.name}: no variable {name!r}; the FMU's variables: {', '.join(sorted(self.variables))}"
            )
        return self.variables[name]

    def call(self, what, fn, *args):
        """Run an FMI call; on a non-OK status raise MasterError with the FMU's recent log lines.
        `what` (str, or a function returning it: formatted only on failure) names the call."""
        n_log = len(self.log)
        try:
            return fn(*args)
        except FMICallException as exc:
            self.failed = self.failed or getattr(exc, "status", 3) >= 3
            status = STATUS_NAMES.get(getattr(exc, "status", None), "failure")
            lines = "; ".join(self.log[n_log:]) or "no message logged"
            what = what() if callable(what) else what
            raise MasterError(f"{self.name}: {what} returned {status}: {lines}") from None

    def _accessor(self, kind, which):
        getter, setter, convert = ACCESSORS[kind]
        return getattr(self.slave, getter if which == "get" else setter), convert

    def set(self, values):
        """Set variables by name (Real, Integer, Boolean, String), one call each (set-up only)."""
        for name, value in values.items():
            v = self.var(name)
            setter, convert = self._accessor(v.type, "set")
            self.call(f"set {name} = {value!r}", setter, [v.valueReference], [convert(value)])

    def _checked(self, function):
        """The FMU's C function `function` (fmi2...), raising FMICallException on Discard or worse
        as fmpy's wrappers do (a Warning passes)."""
        raw = self.slave._functions[function]
        component = self.slave.component

        def call(*args):
            status = raw(component, *args)
            if status > 1:
                self.failed = self.failed or status >= 3
                raise FMICallException(function=function, status=status)

        return call

    def batch_reader(self, kind, vrs):
        """A function returning the current values of the variables vrs (all of FMI type `kind`)."""
        if kind not in BATCHED:
            getter = self._accessor(kind, "get")[0]
            return lambda: getter(vrs)
        function, _, ctype = BATCHED[kind]
        call, n = self._checked(function), len(vrs)
        refs, buffer = (fmi2ValueReference * n)(*vrs), (ctype * n)()

        def read():
            call(refs, n, buffer)
            return buffer[:]

        return read

    def batch_writer(self, kind, vrs):
        """A function setting the variables vrs (all of FMI type `kind`) to a list of values."""
        if kind not in BATCHED:
            setter = self._accessor(kind, "set")[0]
            return lambda values: setter(vrs, values)
        function, ctype = BATCHED[kind][1], BATCHED[kind][2]
        call, n = self._checked(function), len(vrs)
        refs, array = (fmi2ValueReference * n)(*vrs), ctype * n
        return lambda values: call(refs, n, array(*values))

    def setter_plan(self, names):
        """Batches that set these variables, resolved once: [(writer, convert, positions in `names`)],
        one batch per FMI type."""
        by_type = {}
        for k, name in enumerate(names):
            v = self.var(name)
            by_type.setdefault(v.type, ([], []))
            by_type[v.type][0].append(v.valueReference)
            by_type[v.type][1].append(k)
        return [
            (self.batch_writer(kind, vrs), ACCESSORS[kind][2], positions) for kind, (vrs, positions) in by_type.items()
        ]

    def watch(self, names):
        """Read these outputs into the cache at every refresh(): one call per FMI type, value
        references resolved here."""
        by_type = {}
        for name in sorted(set(names)):
            v = self.var(name)
            by_type.setdefault(v.type, []).append(name)
        self._reads = [
            (self.batch_reader(kind, [self.variables[n].valueReference for n in ns]), ns)
            for kind, ns in by_type.items()
        ]

    def refresh(self):
        cache = self.cache
        for read, names in self._reads:
            cache.update(zip(names, self.call("get outputs", read)))

    def do_step(self, t, h):
        """fmi2DoStep(t, h) (raises FMICallException on Discard or worse)."""
        self._do_step(t, h, fmi2True)

    def start_value(self, name):
        """The variable's current value read from the FMU (its start value before any step)."""
        v = self.var(name)
        getter, _ = self._accessor(v.type, "get")
        return self.call(f"get {name}", getter, [v.valueReference])[0]

    def close(self):
        if not self.failed:  # after fmi2Error the FMI 2.0 call sequence allows no fmi2Terminate
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
        # resolved once: per target, its connected inputs in batches and where each value comes from
        self._transfers = {}
        for name, links in self.links.items():
            sources = [(self.instances[s], s_var) for s, s_var, _ in links]
            self._transfers[name] = [
                (writer, convert, [sources[k] for k in positions])
                for writer, convert, positions in self.instances[name].setter_plan([t for _, _, t in links])
            ]
        # per instance with schedules: its scheduled inputs in batches, with the schedule of each value
        self._scheduled = []
        for name in spec.order:
            schedules = list(spec.instances[name].schedules.items())
            for writer, convert, positions in self.instances[name].setter_plan([var for var, _ in schedules]):
                self._scheduled.append((self.instances[name], writer, convert, [schedules[k][1] for k in positions]))
        self._record = [(q, self.instances[split_name(q)[0]], split_name(q)[1]) for q in self.recorded]
        self._limits = [
            (lim, self.instances[split_name(lim.variable)[0]], split_name(lim.variable)[1]) for lim in spec.limits
        ]
        self._max_change = [
            (q, allowed, self.instances[split_name(q)[0]], split_name(q)[1]) for q, allowed in spec.max_change.items()
        ]

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
        for inst, writer, convert, schedules in self._scheduled:
            inst.call("set scheduled inputs at the start", writer, [convert(u(spec.start)) for u in schedules])
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
        except FMICallException as exc:
            refused = True
            inst.failed = getattr(exc, "status", 3) >= 3
        errors = [line for line in inst.log[n_log:] if line.startswith(("[Error]", "[Fatal]"))]
        if refused or errors:
            raise MasterError(f"{inst.name}: initialisation failed: {'; '.join(errors) or 'no message logged'}")
        inst.refresh()

    # -- stepping --------------------------------------------------------------------------------
    def _transfer(self, name):
        inst = self.instances[name]
        for writer, convert, sources in self._transfers[name]:
            inst.call("set connected inputs", writer, [convert(src.cache[var]) for src, var in sources])

    def _apply_schedules(self, t, h):
        """Set every scheduled input to its value for the step from t to t + h (s)."""
        for inst, writer, convert, schedules in self._scheduled:
            values = [convert(u.for_step(t, h)) for u in schedules]
            inst.call(lambda: f"set scheduled inputs at t = {t:.9g} s", writer, values)

    def _do_step(self, inst, t, h):
        inst.call(lambda: f"doStep at t = {t:.9g} s, h = {h:.9g} s", inst.do_step, t, h)

    def _macro_step(self, t, h):
        """One communication step of the coupled system from t to t + h."""
        self._apply_schedules(t, h)
        if self.spec.algorithm == "jacobi":
            for name in self.spec.order:
                self._transfer(name)
            for name in self.spec.order:
                self._do_step(self.instances[name], t, h)
            for name in self.spec.order:
                self.instances[name].refresh()
        else:
            for name in self.spec.order:
                inst = self.instances[name]
                self._transfer(name)
                self._do_step(inst, t, h)
                inst.refresh()

    def _values(self):
        return {q: inst.cache[var] for q, inst, var in self._record}

    def _too_big_change(self, before):
        for qualified, allowed, inst, var in self._max_change:
            change = abs(inst.cache[var] - before[qualified])
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
        for lim, inst, var in self._limits:
            value = inst.cache[var]
            if not (lim.min <= value <= lim.max) or math.isnan(value):
                return f"t = {t:.6g} s: {lim.variable} = {value:.6g} left [{lim.min:.6g}, {lim.max:.6g}]" + (
                    f": {lim.message}" if lim.message else ""
                )
        return None

    def run(self, progress=False, record_interval=None, csv_path=None):
        """Initialise, step to the stop time (or a limit) and return the RunResult.

        record_interval (s): record every this many seconds, a whole multiple of the step (default:
        every communication point); the last point reached is always recorded. csv_path: stream the
        rows to this CSV file as the run goes instead of keeping them in memory."""
        spec = self.spec
        every = self._record_every(record_interval)
        t_setup = wallclock.perf_counter()
        self._initialise()
        setup = self.setup_time + wallclock.perf_counter() - t_setup
        n_steps = spec.n_steps
        units = {"time": "s"}
        for q in self.recorded:
            inst, var = split_name(q)
            units[q] = getattr(self.instances[inst].variables[var], "unit", None) or "1"
        rows = n_steps // every + 2  # every `every`-th point from 0, plus the last one
        recorder = _CsvRecorder(csv_path, units) if csv_path is not None else _ArrayRecorder(rows, units)
        with recorder:
            recorder.add(spec.start, self._record)
            status, message, rejected = "ok", self._check_limits(spec.start) or "", 0
            if message:
                status = "limit"
            bar = _Progress(n_steps, progress)
            t_wall, t_cpu = wallclock.perf_counter(), wallclock.process_time()
            done = 0
            for n in range(n_steps if status == "ok" else 0):
                t = spec.start + n * spec.step
                if spec.rollback:
                    rejected += self._guarded_step(t, spec.step)
                else:
                    self._macro_step(t, spec.step)
                t_next = spec.start + (n + 1) * spec.step
                done = n + 1
                bar.update(done)
                message = self._check_limits(t_next) or ""
                if message:
                    status = "limit"
                if (n + 1) % every == 0 or n + 1 == n_steps or message:
                    recorder.add(t_next, self._record)
                if message:
                    break
            wall, cpu = wallclock.perf_counter() - t_wall, wallclock.process_time() - t_cpu
            bar.close()
        log = [f"{n}: {line}" for n, i in self.instances.items() for line in i.log]
        return RunResult(
            recorder.columns(), units, status, message, wall, setup, rejected, log, cpu, csv_path, recorder.n_rows, done
        )

    def _record_every(self, record_interval):
        """Steps between recorded points for a record interval in seconds (None: 1)."""
        if record_interval is None:
            return 1
        every = round(record_interval / self.spec.step)
        if every < 1 or not math.isclose(every * self.spec.step, record_interval, rel_tol=1e-9):
            raise MasterError(
                f"record interval {record_interval!r} s is not a whole multiple of the step {self.spec.step!r} s"
            )
        return every

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


def run(spec, progress=False, record_interval=None, csv_path=None):
    """Run a RunSpec from start to end (Master.run for the arguments); always frees the FMUs and
    removes their extraction."""
    with Master(spec) as master:
        return master.run(progress=progress, record_interval=record_interval, csv_path=csv_path)


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


class _ArrayRecorder:
    """Rows into numpy arrays preallocated for the whole run (`capacity` rows); columns() trims them."""

    def __init__(self, capacity, units):
        self.names = list(units)
        self.values = np.empty((capacity, len(self.names)))
        self.n_rows = 0

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        pass

    def add(self, t, record):
        row = self.values[self.n_rows]
        row[0] = t
        for k, (_, inst, var) in enumerate(record, start=1):
            row[k] = inst.cache[var]
        self.n_rows += 1

    def columns(self):
        return {n: self.values[: self.n_rows, k].copy() for k, n in enumerate(self.names)}


class _CsvRecorder:
    """Rows streamed to a CSV file (header 'name [unit]', repr floats) as the run goes; nothing kept."""

    def __init__(self, path, units):
        self.path, self.units, self.n_rows = path, units, 0

    def __enter__(self):
        self._fh = open(self.path, "w", newline="")
        self._writer = csv.writer(self._fh)  # quotes names like K[3,3]
        self._writer.writerow(csv_header(list(self.units), self.units))
        return self

    def __exit__(self, *exc):
        self._fh.close()

    def add(self, t, record):
        self._writer.writerow(csv_row([t] + [inst.cache[var] for _, inst, var in record]))
        self.n_rows += 1

    def columns(self):
        return {}
