"""Run files (docs/architecture.md): a coupled co-simulation described in TOML, read into a RunSpec.

Format (every time in s; values SI in the units each FMU declares):

    [run]
    description = "..."
    start = 0.0                 # s
    stop = 3600.0               # s
    step = 1.0                  # s, communication step H
    algorithm = "gauss_seidel"  # or "jacobi"
    order = ["bearing_1", "bearing_2", "spindle"]   # Gauss-Seidel order (default: instance order)
    record = ["spindle.T_outer_ring_1"]             # extra variables to record (connected ones always are)
    rollback = false            # reject a refused step, restore every FMU's state, retry in halves
    max_halvings = 4            # how often a step may be halved
    [run.max_change]            # optional step rejection (needs rollback): largest change per step
    "spindle.T_inner_ring_1" = 2.0

    [fmus]                      # FMU files, relative to the run file (`spindle run --fmus DIR` overrides the folder)
    bearing = "../fmus/Bearing.fmu"

    [instances.bearing_1]
    fmu = "bearing"
    parameters = { race_control = "hybrid" }       # set in initialisation mode
    inputs = { F_z = 800.0 }                       # constant inputs (held for the whole run)
    schedules = { omega = [[0.0, 0.0], [2.0, 1047.2]] }   # inputs as functions of time, see below

    [[connections]]             # output -> input
    from = "spindle.T_oil_1"
    to = "bearing_1.T_oil"

    [[connections]]             # every element of an array: bearing_1.K[1,1] -> shaft.K_1[1,1], ..., [5,5]
    from = "bearing_1.K"
    to = "shaft.K_1"
    shape = [5, 5]

    [[limits]]                  # stop the run with a clear message when a variable leaves a range
    variable = "bearing_1.F_z"
    max = 4000.0
    message = "thermal runaway: the fixed preload keeps rising"

Input schedules: `schedules = { name = [[t_0, u_0], [t_1, u_1], ...] }` gives an unconnected input u(t)
as a piecewise-linear table (t in s, strictly increasing; u in the input's unit), held at u_0 before t_0
and at the last value after the last point: `[[0.0, 0.0], [2.0, 1047.2]]` is a ramp from rest to
1047.2 rad/s (10 000 rpm) over 2 s, held afterwards. The master sets u(start) in initialisation mode and,
before every communication step [t, t + h] (also the halves of a rejected step), a value through FMI:
u(t) by default (sample and hold at the start of the step, for an FMU that holds its inputs over the
step), or u(t + h) with `name = { table = [[t, u], ...], at = "end" }` (for an FMU that moves an input
linearly from its previous value to the new one over the step, as BearingDEM.fmu does with its speed:
it then follows the table exactly where the table is linear over the step).

`overrides` (sweeps, command line) replace values by dotted keys: "run.step", "bearing_1.F_z"
(an input or parameter of an instance, whichever it already is; a new key becomes an input). A table
[[t, u], ...] given for an input makes it scheduled; a number given for a scheduled input makes it
constant.
"""

import math
import tomllib
from bisect import bisect_right
from dataclasses import dataclass, field
from pathlib import Path

ALGORITHMS = ("gauss_seidel", "jacobi")
SCHEDULE_AT = ("start", "end")


class RunFileError(ValueError):
    """The run file is inconsistent (message names the key and what is allowed)."""


@dataclass
class InstanceSpec:
    name: str
    fmu: str  # absolute path of the FMU file
    parameters: dict = field(default_factory=dict)
    inputs: dict = field(default_factory=dict)
    schedules: dict = field(default_factory=dict)  # input name -> Schedule


@dataclass(frozen=True)
class Schedule:
    """An input as a piecewise-linear function of time: points (t_k, u_k), t in s strictly increasing,
    u in the input's unit; held at u_0 before t_0 and at the last value after the last point."""

    times: tuple
    values: tuple
    at: str = "start"  # value set for the step [t, t + h]: u(t) ("start") or u(t + h) ("end")

    def __call__(self, t):
        """u(t) (t in s): numpy.interp's formula and end rules, without its conversion of the tables to arrays
        at every call (a few microseconds per input and step in a co-simulation)."""
        times, values = self.times, self.values
        if not t > times[0]:  # before the first point (NaN passes on to the arithmetic below)
            return float(values[0]) if t <= times[0] else math.nan
        if t >= times[-1]:
            return float(values[-1])
        j = bisect_right(times, t) - 1
        slope = (values[j + 1] - values[j]) / (times[j + 1] - times[j])
        return float(slope * (t - times[j]) + values[j])

    def for_step(self, t, h):
        """The value to set before the step from t to t + h (s)."""
        return self(t + h) if self.at == "end" else self(t)

    @classmethod
    def from_entry(cls, entry, key):
        """From a run file's entry: a table [[t, u], ...] or { table = [[t, u], ...], at = "start"|"end" }."""
        if not isinstance(entry, dict):
            return cls.from_table(entry, key)
        _no_unknown_keys(key, entry, {"table", "at"})
        at = entry.get("at", "start")
        if at not in SCHEDULE_AT:
            raise RunFileError(f"{key}.at = {at!r}: allowed {list(SCHEDULE_AT)}")
        return cls.from_table(entry.get("table"), f"{key}.table", at)

    @classmethod
    def from_table(cls, table, key, at="start"):
        """From [[t, u], ...] as written in a run file; RunFileError naming `key` if it is not one."""
        form = f"{key}: write a table [[t, value], ...] (t in s, strictly increasing, finite numbers)"
        if not isinstance(table, (list, tuple)) or not table:
            raise RunFileError(f"{form}; got {table!r}")
        for k, point in enumerate(table):
            if not (
                isinstance(point, (list, tuple))
                and len(point) == 2
                and all(isinstance(x, (int, float)) and not isinstance(x, bool) and math.isfinite(x) for x in point)
            ):
                raise RunFileError(f"{form}; point {k} is {point!r}")
        times = tuple(float(t) for t, _ in table)
        for k in range(1, len(times)):
            if not times[k] > times[k - 1]:
                raise RunFileError(f"{form}; t = {times[k]} s at point {k} does not follow t = {times[k - 1]} s")
        return cls(times, tuple(float(u) for _, u in table), at)


@dataclass
class Limit:
    variable: str  # "instance.variable"
    min: float = -math.inf
    max: float = math.inf
    message: str = ""


@dataclass
class RunSpec:
    path: str
    description: str
    start: float
    stop: float
    step: float
    algorithm: str
    order: list
    instances: dict  # name -> InstanceSpec, in file order
    connections: list  # (source "inst.var", target "inst.var")
    record: list
    limits: list
    rollback: bool = False
    max_halvings: int = 4
    max_change: dict = field(default_factory=dict)

    @property
    def n_steps(self):
        """Number of communication steps (stop - start must be a whole number of steps)."""
        return int(round((self.stop - self.start) / self.step))


def split_name(qualified):
    """'bearing_1.T_oil' -> ('bearing_1', 'T_oil')."""
    inst, sep, var = qualified.partition(".")
    if not sep or not inst or not var:
        raise RunFileError(f"variable {qualified!r} must be written 'instance.variable'")
    return inst, var


def load_run(path, overrides=None, fmu_dir=None):
    """Read a run file; apply overrides {dotted key: value}; check it; return a RunSpec.

    fmu_dir: directory holding the FMUs the run file names (their file names are kept); None = the
    paths as written in [fmus], relative to the run file."""
    path = Path(path).resolve()
    try:
        with open(path, "rb") as fh:
            doc = tomllib.load(fh)
    except (OSError, tomllib.TOMLDecodeError) as exc:
        raise RunFileError(f"run file {path}: {exc}") from None
    return parse_run(doc, path, overrides, fmu_dir)


RUN_KEYS = {
    "description",
    "start",
    "stop",
    "step",
    "algorithm",
    "order",
    "record",
    "rollback",
    "max_halvings",
    "max_change",
}


def parse_run(doc, path, overrides=None, fmu_dir=None):
    base = Path(path).parent
    run = dict(doc.get("run", {}))
    if fmu_dir is None:
        fmus = {k: str((base / v).resolve()) for k, v in doc.get("fmus", {}).items()}
    else:
        fmus = {k: str((Path(fmu_dir) / Path(v).name).resolve()) for k, v in doc.get("fmus", {}).items()}
    _no_unknown_keys("the run file", doc, {"run", "fmus", "instances", "connections", "limits"})
    _no_unknown_keys("[run]", run, RUN_KEYS)
    instances = {}
    for name, inst in doc.get("instances", {}).items():
        _no_unknown_keys(f"[instances.{name}]", inst, {"fmu", "parameters", "inputs", "schedules"})
        if inst.get("fmu") not in fmus:
            raise RunFileError(f"instance {name}: fmu = {inst.get('fmu')!r} is not in [fmus] ({sorted(fmus)})")
        schedules = inst.get("schedules", {})
        if not isinstance(schedules, dict):
            raise RunFileError(f"instances.{name}.schedules: write schedules = {{ input = [[t, value], ...] }}")
        instances[name] = InstanceSpec(
            name,
            fmus[inst["fmu"]],
            dict(inst.get("parameters", {})),
            dict(inst.get("inputs", {})),
            {k: Schedule.from_entry(v, f"instances.{name}.schedules.{k}") for k, v in schedules.items()},
        )
    for key, value in (overrides or {}).items():
        _apply_override(run, instances, key, value)
    connections = [pair for c in doc.get("connections", []) for pair in _connection_pairs(c)]
    sources = {target: source for source, target in connections}
    for key in overrides or {}:
        if key in sources:  # the connection sets this input at every step: the override would be dropped
            raise RunFileError(
                f"override {key!r}: {key} is a connected input (from {sources[key]}), set at every step by the "
                f"connection; override an unconnected input, a parameter or the source's inputs instead"
            )
    limits = [Limit(**lim) for lim in doc.get("limits", [])]
    spec = RunSpec(
        path=str(path),
        description=run.get("description", ""),
        start=float(run.get("start", 0.0)),
        stop=float(run.get("stop", 0.0)),
        step=float(run.get("step", 0.0)),
        algorithm=run.get("algorithm", "gauss_seidel"),
        order=list(run.get("order", instances)),
        instances=instances,
        connections=connections,
        record=list(run.get("record", [])),
        limits=limits,
        rollback=bool(run.get("rollback", False)),
        max_halvings=int(run.get("max_halvings", 4)),
        max_change=dict(run.get("max_change", {})),
    )
    check(spec)
    return spec


def _connection_pairs(c):
    """The (source, target) pairs of one [[connections]] entry: one pair, or with `shape = [n]` or `[n, m]` one
    per element of an array variable, `from = "bearing_1.K"`, `to = "shaft.K_1"`, `shape = [5, 5]` standing for
    bearing_1.K[1,1] -> shaft.K_1[1,1] ... K[5,5] -> K_1[5,5] (FMI's structured names, indices from 1)."""
    if not (isinstance(c, dict) and {"from", "to"} <= set(c) <= {"from", "to", "shape"}):
        raise RunFileError(
            f'connection {c}: write [[connections]] with from = "source.output" and to = "target.input" (and '
            "shape = [n] or [n, m] to connect every element of an array)"
        )
    if "shape" not in c:
        return [(c["from"], c["to"])]
    shape = c["shape"]
    if not (
        isinstance(shape, list) and len(shape) in (1, 2) and all(isinstance(n, int) and 1 <= n <= 100 for n in shape)
    ):
        raise RunFileError(f"connection {c['from']} -> {c['to']}: shape = {shape!r}; allowed [n] or [n, m], 1..100")
    indices = [(i,) for i in range(1, shape[0] + 1)]
    if len(shape) == 2:
        indices = [(i, j) for i in range(1, shape[0] + 1) for j in range(1, shape[1] + 1)]
    return [(f"{c['from']}[{','.join(map(str, k))}]", f"{c['to']}[{','.join(map(str, k))}]") for k in indices]


def _no_unknown_keys(where, table, allowed):
    unknown = sorted(set(table) - allowed)
    if unknown:
        raise RunFileError(f"{where}: unknown key(s) {unknown}; allowed {sorted(allowed)}")


def _apply_override(run, instances, key, value):
    head, _, tail = key.partition(".")
    if head == "run" and tail:
        if tail not in RUN_KEYS:
            raise RunFileError(f"override {key!r}: unknown run key {tail!r}; allowed {sorted(RUN_KEYS)}")
        run[tail] = value
    elif head in instances and tail:
        inst = instances[head]
        if isinstance(value, (list, tuple, dict)):  # a table: the input becomes scheduled
            inst.inputs.pop(tail, None)
            inst.schedules[tail] = Schedule.from_entry(value, f"override {key!r}")
        elif tail in inst.parameters:
            inst.parameters[tail] = value
        else:
            inst.schedules.pop(tail, None)
            inst.inputs[tail] = value
    else:
        raise RunFileError(
            f"override {key!r}: use 'run.<key>' or '<instance>.<variable>' (instances: {sorted(instances)})"
        )


def check(spec):
    """Raise RunFileError listing every problem of the run description at once."""
    problems = []
    if not spec.instances:
        problems.append("no [instances]")
    if spec.algorithm not in ALGORITHMS:
        problems.append(f"run.algorithm = {spec.algorithm!r}: allowed {list(ALGORITHMS)}")
    if not (math.isfinite(spec.step) and spec.step > 0.0):
        problems.append(f"run.step = {spec.step} s: must be > 0")
    elif not (math.isfinite(spec.stop) and spec.stop > spec.start):
        problems.append(f"run.stop = {spec.stop} s: must be > run.start = {spec.start} s")
    elif abs(spec.n_steps * spec.step - (spec.stop - spec.start)) > 1e-9 * max(1.0, spec.stop - spec.start):
        problems.append(
            f"run.stop - run.start = {spec.stop - spec.start} s is not a whole number of steps of {spec.step} s"
        )
    if sorted(spec.order) != sorted(spec.instances):
        problems.append(f"run.order = {spec.order} must list every instance once ({list(spec.instances)})")
    targets = set()
    for pair in spec.connections:
        for qualified in pair:
            try:
                inst, _ = split_name(qualified)
                if inst not in spec.instances:
                    problems.append(f"connection {pair}: unknown instance {inst!r}")
            except RunFileError as exc:
                problems.append(str(exc))
        if pair[1] in targets:
            problems.append(f"input {pair[1]} is connected twice")
        targets.add(pair[1])
    for name, inst in spec.instances.items():
        for var in sorted(set(inst.schedules) & (set(inst.inputs) | set(inst.parameters))):
            problems.append(f"instances.{name}: {var} is both scheduled and in inputs/parameters (give it once)")
        for var in sorted(inst.schedules):
            if f"{name}.{var}" in targets:
                problems.append(
                    f"instances.{name}.schedules.{var}: the input is connected (schedules are for free inputs)"
                )
    for name in spec.record + list(spec.max_change) + [lim.variable for lim in spec.limits]:
        try:
            if split_name(name)[0] not in spec.instances:
                problems.append(f"{name}: unknown instance")
        except RunFileError as exc:
            problems.append(str(exc))
    if spec.max_change and not spec.rollback:
        problems.append("run.max_change needs run.rollback = true (a rejected step is redone from saved states)")
    if not 0 <= spec.max_halvings <= 20:
        problems.append(f"run.max_halvings = {spec.max_halvings}: allowed [0, 20]")
    if problems:
        raise RunFileError(f"run file {spec.path}: " + "; ".join(problems))
