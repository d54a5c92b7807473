"""Fuzz one FMU over every input and parameter in a fresh process; one JSON line per case (tests/fmu/test_fuzz.py).

Usage: python fuzz.py FMU CASES    (CASES: fast | full)

The values are derived from the FMU's own modelDescription.xml (declared min/max, start values), so the
fuzz checks what the FMU declares. Each case uses a fresh instance, so one case cannot spoil the next:

- input: the bad value is set in initialisation mode (every other input at its start value), then
  fmi2DoStep; if refused, the input is set back to its start value and the step retried (recovery); then
  the same bad value is set again during the run and a step taken (refused again or accepted), and the
  input corrected once more;
- parameter: the bad value is set in initialisation mode; if fmi2ExitInitializationMode accepts it, a
  doStep follows.

Every line says whether the value was accepted, the statuses, the error messages logged during the case
and whether the outputs were all finite. The lines are flushed one by one: if the host crashes, the
cases before it are kept and the test names the case that was running.
"""

import json
import math
import shutil
import sys

from fmpy import extract, read_model_description
from fmpy.fmi1 import FMICallException
from fmpy.fmi2 import (
    FMU2Slave,
    calloc,
    fmi2CallbackAllocateMemoryTYPE,
    fmi2CallbackFreeMemoryTYPE,
    fmi2CallbackFunctions,
    fmi2CallbackLoggerTYPE,
    free,
)

# communication step per FMU kind: a thermal network steps in seconds, the DEM integrates every step
STEP = {"SpindleThermal": 1.0, "SpindleThermalFixed": 1.0, "BearingDEM": 1e-4}
STRING_CASES = ("", "no_such_name", "%s%n%d", "x" * 300)  # empty, unknown, printf format, too long for a file name
CHOICE_CASES = ("OUTER", " outer", "implicit euler")  # near-misses of a choice (wrong case, space, spelling)


def real_cases(low, high, fast):
    """(label, value) of a Real with declared range [low, high]."""
    margin = 1e-3 * max(abs(low), abs(high))
    cases = [("nan", math.nan), ("above", high + margin)]
    if fast:
        return cases
    return cases + [
        ("+inf", math.inf),
        ("-inf", -math.inf),
        ("below", low - margin),
        ("+1e30", 1e30),
        ("-1e30", -1e30),
        ("1e-300", 1e-300),
        ("-300", -300.0),
    ]


class Host:
    """fmpy host with a logger that keeps every message (status, text) of the current case."""

    def __init__(self, path):
        self.md = read_model_description(path)
        self.unzip = extract(path)
        self.vr = {v.name: v.valueReference for v in self.md.modelVariables}
        self.messages = []
        self.callbacks = fmi2CallbackFunctions()
        self.callbacks.logger = fmi2CallbackLoggerTYPE(self._log)
        self.callbacks.allocateMemory = fmi2CallbackAllocateMemoryTYPE(calloc)
        self.callbacks.freeMemory = fmi2CallbackFreeMemoryTYPE(free)
        self.name = self.md.coSimulation.modelIdentifier
        self.step = STEP.get(self.name, 1e-3)
        self.outputs = [v for v in self.md.modelVariables if v.causality == "output"]
        self.count = 0

    def _log(self, component, instance, status, category, message):
        self.messages.append((status, message.decode(errors="replace")))

    def instance(self):
        self.count += 1
        fmu = FMU2Slave(
            guid=self.md.guid,
            unzipDirectory=self.unzip,
            modelIdentifier=self.name,
            instanceName=f"fuzz{self.count}",
        )
        fmu.instantiate(loggingOn=False, callbacks=self.callbacks)
        fmu.setupExperiment(startTime=0.0)
        fmu.enterInitializationMode()
        return fmu

    def finite_outputs(self, fmu):
        """True if every Real and Integer output is finite."""
        reals = [v.valueReference for v in self.outputs if v.type == "Real"]
        integers = [v.valueReference for v in self.outputs if v.type == "Integer"]
        values = fmu.getReal(reals) + [float(i) for i in fmu.getInteger(integers)]
        return all(math.isfinite(x) for x in values)

    @staticmethod
    def call(function, *args):
        try:
            function(*args)
            return 0
        except FMICallException as exc:
            return exc.status

    def set(self, fmu, var, value):
        if var.type == "String":
            fmu.setString([var.valueReference], [value])
        else:
            fmu.setReal([var.valueReference], [value])

    def input_case(self, var, value):
        del self.messages[:]
        start = float(var.start)
        fmu = self.instance()
        self.set(fmu, var, value)
        report = {"exit_init": self.call(fmu.exitInitializationMode)}
        report["step"] = self.call(fmu.doStep, 0.0, self.step)
        report["finite"] = self.finite_outputs(fmu)
        t = 0.0
        if report["step"] != 0:  # refused at initialisation: correct the input, retry the step
            self.set(fmu, var, start)
            report["recovered"] = self.call(fmu.doStep, 0.0, self.step) == 0 and self.finite_outputs(fmu)
        t += self.step
        self.set(fmu, var, value)  # the same value during the run
        report["run_step"] = self.call(fmu.doStep, t, self.step)
        report["run_finite"] = self.finite_outputs(fmu)
        if report["run_step"] == 0:  # accepted: the time moved on
            t += self.step
        self.set(fmu, var, start)
        report["run_recovered"] = self.call(fmu.doStep, t, self.step) == 0 and self.finite_outputs(fmu)
        self.call(fmu.terminate)
        fmu.freeInstance()
        return report

    def parameter_case(self, var, value):
        del self.messages[:]
        fmu = self.instance()
        self.set(fmu, var, value)
        report = {"exit_init": self.call(fmu.exitInitializationMode)}
        report["step"] = self.call(fmu.doStep, 0.0, self.step)
        report["finite"] = self.finite_outputs(fmu)
        self.call(fmu.terminate)
        fmu.freeInstance()
        return report


def cases(host, fast):
    """(variable, label, value) of every case."""
    for var in host.md.modelVariables:
        if var.causality not in ("input", "parameter"):
            continue
        if var.type == "Real":
            for label, value in real_cases(float(var.min), float(var.max), fast):
                yield var, label, value
        elif var.type == "String":
            strings = STRING_CASES[:2] if fast else STRING_CASES + CHOICE_CASES
            for value in strings:
                yield var, repr(value)[:20], value


def main():
    path, which = sys.argv[1], sys.argv[2]
    host = Host(path)
    for var, label, value in cases(host, which == "fast"):
        print(json.dumps({"variable": var.name, "label": label, "running": True}), flush=True)
        run = host.input_case if var.causality == "input" else host.parameter_case
        report = run(var, value)
        errors = [text for status, text in host.messages if status >= 2]  # a refused step logs fmi2Discard
        shown = value if isinstance(value, str) else repr(value)  # as Python prints the float in a message
        line = {
            "variable": var.name,
            "causality": var.causality,
            "label": label,
            "value": shown,
            "min": None if var.type != "Real" else float(var.min),
            "max": None if var.type != "Real" else float(var.max),
            "errors": errors,
            **report,
        }
        print(json.dumps(line), flush=True)
    shutil.rmtree(host.unzip, ignore_errors=True)


if __name__ == "__main__":
    main()
