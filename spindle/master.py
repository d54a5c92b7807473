"""fmpy co-simulation master (SPEC 6). Talks to FMUs only through FMI; imports no physics.

For now: one FMU driven by tabulated inputs (the demo of the analytic bearing FMU). The coupled
closed-loop master of issue 4 builds on `FmuInstance`.
"""
import shutil
from dataclasses import dataclass, field

import numpy as np
# pythonfmu FMUs run inside this interpreter. SPEC 3: loading scipy's compiled libraries (numba
# imports scipy) for the first time from inside an FMU can make the process abort at exit, so load
# both here, before any FMU. (Not sufficient on its own: see spindle.cli.run.)
import numba  # noqa: F401, E402
import scipy.special  # noqa: F401, E402
from fmpy import extract, read_model_description
from fmpy.fmi2 import FMU2Slave


class MasterError(RuntimeError):
    """An FMI call failed; the message carries the FMU's own log lines."""


@dataclass
class FmuInstance:
    """One instantiated co-simulation FMU, extracted once, with name -> value-reference maps."""
    path: str
    instance_name: str
    messages: list = field(default_factory=list)

    def __post_init__(self):
        self.md = read_model_description(self.path)
        self.unzip_dir = extract(self.path)
        self.variables = {v.name: v for v in self.md.modelVariables}
        self.slave = FMU2Slave(guid=self.md.guid, unzipDirectory=self.unzip_dir,
                               modelIdentifier=self.md.coSimulation.modelIdentifier,
                               instanceName=self.instance_name)
        self.slave.instantiate(loggingOn=True)

    def _call(self, what, fn, *args):
        try:
            return fn(*args)
        except Exception as exc:
            raise MasterError(f"{self.instance_name}: {what} failed ({exc})") from None

    def initialize(self, start_time=0.0, parameters=None, inputs=None):
        self._call("setupExperiment", lambda: self.slave.setupExperiment(startTime=start_time))
        self._call("enterInitializationMode", self.slave.enterInitializationMode)
        self.set(parameters or {})
        self.set(inputs or {})
        self._call("exitInitializationMode", self.slave.exitInitializationMode)

    def set(self, values):
        for name, value in values.items():
            var = self.variables[name]
            if var.type == "Real":
                self._call(f"set {name}", self.slave.setReal, [var.valueReference], [float(value)])
            elif var.type == "Integer":
                self._call(f"set {name}", self.slave.setInteger, [var.valueReference], [int(value)])
            elif var.type == "String":
                self._call(f"set {name}", self.slave.setString, [var.valueReference], [str(value)])
            else:
                raise MasterError(f"{self.instance_name}: unsupported type {var.type} of {name}")

    def get(self, names):
        out = {}
        for name in names:
            var = self.variables[name]
            getter = self.slave.getInteger if var.type == "Integer" else self.slave.getReal
            out[name] = self._call(f"get {name}", getter, [var.valueReference])[0]
        return out

    def do_step(self, time, step):
        self._call(f"doStep at t = {time} s", self.slave.doStep, time, step)

    def close(self):
        try:
            self.slave.terminate()
            self.slave.freeInstance()
        finally:
            shutil.rmtree(self.unzip_dir, ignore_errors=True)


def run_with_inputs(path, times, inputs, outputs, parameters=None):
    """Step one FMU over `times` (s, uniform) with inputs given per time (dict name -> array).

    The time is an integer step count times the step (no drift). Returns a structured array
    with 'time', the inputs and the outputs.
    """
    times = np.asarray(times, dtype=float)
    step = float(times[1] - times[0])
    fmu = FmuInstance(path, "bearing")
    try:
        first = {name: values[0] for name, values in inputs.items()}
        fmu.initialize(start_time=float(times[0]), parameters=parameters, inputs=first)
        rows = []
        for n, t in enumerate(times):
            fmu.set({name: values[n] for name, values in inputs.items()})
            if n > 0:
                fmu.do_step(float(times[0] + (n - 1) * step), step)
            rows.append((t, *[inputs[k][n] for k in inputs], *fmu.get(outputs).values()))
    finally:
        fmu.close()
    dtype = [("time", float)] + [(k, float) for k in inputs] + [(k, float) for k in outputs]
    return np.array(rows, dtype=dtype)
