"""Fuzz one FMU over every input and parameter in a fresh process; one JSON line per case (tests/fmu/test_fuzz.py).

Usage: python fuzz.py FMU CASES    (CASES: fast | full | inside)

The values are derived from the FMU's own modelDescription.xml (declared min/max, start values), so the
fuzz checks what the FMU declares. Each case uses a fresh instance, so one case cannot spoil the next:

- input: the bad value is set in initialisation mode (every other input at its start value), then
  fmi2DoStep; if refused, the input is set back to its start value and the step retried (recovery); then
  the same bad value is set again during the run and a step taken (refused again or accepted), and the
  input corrected once more;
- parameter: the bad value is set in initialisation mode; if fmi2ExitInitializationMode accepts it, a
  doStep follows.

- inside (a value within the declared range of a Real or Integer parameter): the parameter is set in
  initialisation mode with the switch that puts it in effect (bearing_from_file false for bearing_data.*, a
  lubricant law and its catalogue constants for the constants of a law the FMU does not start with, ...);
  if fmi2ExitInitializationMode accepts it, one doStep at the start inputs, then STEPS doSteps at the FMU's
  operating point (OPERATING: a speed and a load), each step's absurd outputs listed (ABSURD).

Every line says whether the value was accepted, the statuses, the error messages logged during the case
and whether the outputs were all finite. The lines are flushed one by one: if the host crashes, the
cases before it are kept and the test names the case that was running.
"""

import json
import math
import shutil
import sys
from pathlib import Path

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
STEP = {"SpindleThermal": 1.0, "SpindleThermalFixed": 1.0, "BearingDEM": 1e-4, "BearingDEMDisp": 1e-4,
        "SpindleShaftTransient": 1e-4}  # fmt: skip
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
        self.variable = {v.name: v for v in self.md.modelVariables}
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

    def values(self, fmu, names):
        """{name: value} of Real and Integer variables, Integers as floats."""
        variables = [self.variable[n] for n in names]
        reals = [v for v in variables if v.type == "Real"]
        integers = [v for v in variables if v.type == "Integer"]
        got = dict(zip([v.name for v in reals], fmu.getReal([v.valueReference for v in reals])))
        got |= {v.name: float(i) for v, i in zip(integers, fmu.getInteger([v.valueReference for v in integers]))}
        return {n: got[n] for n in names}

    def set_value(self, fmu, name, value):
        var = self.variable[name]
        setter = {"Real": fmu.setReal, "Integer": fmu.setInteger, "Boolean": fmu.setBoolean}[var.type]
        setter([var.valueReference], [value])

    def inside_case(self, var, value):
        """A value inside the declared range: accepted or refused at initialisation, then the steps."""
        del self.messages[:]
        fmu = self.instance()
        for name, x in {**inside_context(var), var.name: value}.items():
            self.set_value(fmu, name, x)
        report = {"exit_init": self.call(fmu.exitInitializationMode), "steps": [], "absurd": [], "finite": True}
        t = 0.0
        if report["exit_init"] <= 1:  # fmi2OK or fmi2Warning
            for k in range(1 + STEPS):
                if k == 1:
                    for name, x in OPERATING[self.name].items():
                        self.set_value(fmu, name, x)
                status = self.call(fmu.doStep, t, self.step)
                report["steps"].append(status)
                if status > 1:
                    break
                t += self.step
                report["finite"] = report["finite"] and self.finite_outputs(fmu)
                report["absurd"] += [f"step {k}: {text}" for text in absurd(self, fmu)]
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


# the inputs of a few steps at an operating point (a speed and a load the default bearings carry): the speed and the
# load reach the solvers, so a parameter that breaks them shows; the thermal FMUs take bearing heat
STEPS = 3
BEARING_POINT = {"omega": 200.0, "F_y": 500.0, "F_z": 500.0}
THERMAL_POINT = {"omega": 500.0, **{f"Q_{ring}_ring_{k}": 50.0 for ring in ("inner", "outer") for k in (1, 2)}}
OPERATING = {
    "BearingAnalytic": {"omega": 200.0, "F_y": 2000.0},
    "Bearing": BEARING_POINT,
    "BearingFixed": {"omega": 200.0, "F_y": 500.0},
    "BearingDisp": {"omega": 200.0, "y": 1e-5, "z": 4e-5},
    "BearingDEM": BEARING_POINT,
    "BearingDEMDisp": {"omega": 200.0, "y": 5e-6, "z": 1e-5},  # about BEARING_POINT's loads on the 6208
    "SpindleThermal": THERMAL_POINT,
    "SpindleThermalFixed": {**THERMAL_POINT, "K_axial_1": 1e8, "K_axial_2": 1e8},
    "SpindleShaft": {"omega": 1000.0},  # the seats keep their start values, a B7214C's K
    # the seats' reactions of a B7214C pair at rest under 500 N, its K at their start values, a tool-tip force
    "SpindleShaftTransient": {"omega": 1000.0, "F_x_1": 500.0, "F_x_2": -100.0, "F_x_tip": 400.0},
}
# outputs that cannot be negative (a film, a compressive contact load, a pressure, a count, a loss, a frequency, a
# life, an absolute temperature: T_* > 0 is checked as >= 0 and finite)
NON_NEGATIVE = ("h_min_", "h_c_", "Lambda_", "Q_max_", "p_max", "C_bearing", "n_loaded", "P_loss", "FTF", "BP", "BSF")
NON_NEGATIVE += ("L10", "T_", "monitor_status", "omega_ball_cage")
# a parameter in effect only with a switch: (prefix of its name, Boolean parameter, its value that puts it in effect)
SWITCHES = (
    ("bearing_data.", "bearing_from_file", False),
    ("lubricant_data.", "lubricant_from_file", False),
    ("bearing_1.", "network_from_file", False),
    ("bearing_2.", "network_from_file", False),
    ("expansion.", "network_from_file", False),
    ("axial.", "network_from_file", False),
    ("shaft_data.", "shaft_from_file", False),
    ("Pd", "Pd_from_file", False),
)


def inside_values(low, high, integer):
    """(label, value) within [low, high]: both ends, just inside each end and interior points (log-spaced where the
    range spans decades from a positive end or from 0, linear otherwise)."""
    if integer:
        points = {"min": low, "min+1": low + 1, "mid": (low + high) // 2, "max-1": high - 1, "max": high}
        return [(label, int(v)) for label, v in points.items() if low <= v <= high]
    inner = 1e-6 * (high - low)
    cases = [("min", low), ("min+", low + inner), ("max-", high - inner), ("max", high)]
    if low > 0.0 and high / low >= 100.0:
        cases += [(f"log{k}/4", low * (high / low) ** (k / 4)) for k in (1, 2, 3)]
    elif low == 0.0:
        cases += [(f"{f:g}max", f * high) for f in (1e-4, 1e-2, 0.5)]
    else:
        cases += [(f"lin{k}/4", low + k / 4 * (high - low)) for k in (1, 2, 3)]
    return cases


def law_context(name):
    """{parameter: value} that puts the lubricant law constant `name` in effect: its law chosen and the law's other
    constants those of a catalogue lubricant with that law (empty for any other parameter)."""
    from bearing_fmu.models.file_parameters import LUBRICANT_QUANTITIES, lubricant_values
    from bearing_fmu.params import catalogue

    quantity = next((q for q in LUBRICANT_QUANTITIES if q.variable.name == name), None)
    if quantity is None or not quantity.used_when:
        return {}
    choice, code = quantity.used_when
    for lubricant in catalogue("lubricants"):
        values = lubricant_values(lubricant)
        if values[choice] == code:
            law = [q.variable.name for q in LUBRICANT_QUANTITIES if q.used_when == (choice, code)]
            return {choice: code, **{key: values[key] for key in law}}
    return {choice: code}


def inside_context(var):
    """{parameter: value} set with `var` so that its value is in effect."""
    context = {switch: on for prefix, switch, on in SWITCHES if var.name.startswith(prefix)}
    return {**context, **law_context(var.name)}


def absurd(host, fmu):
    """'name = value' of the outputs no physical state gives: a negative film, load, pressure, count, loss,
    frequency, life or absolute temperature; a thermal growth of a clearance beyond the ball diameter or of the
    pair's axial interference beyond the bearings' spacing."""
    values = host.values(fmu, [v.name for v in host.outputs])
    out = [f"{n} = {x!r}" for n, x in values.items() if n.startswith(NON_NEGATIVE) and not x >= 0.0]
    for k in (1, 2):
        if f"dPd_thermal_{k}" in values:
            (D,) = host.values(fmu, [f"bearing_{k}.D"]).values()
            if not abs(values[f"dPd_thermal_{k}"]) < D:
                out.append(f"dPd_thermal_{k} = {values[f'dPd_thermal_{k}']!r} beyond bearing_{k}.D = {D!r}")
    if "dz_thermal" in values:
        (spacing,) = host.values(fmu, ["axial.spacing"]).values()
        moved = {n: x for n, x in values.items() if n.startswith("dz_thermal") and not abs(x) < spacing}
        out += [f"{n} = {x!r} beyond axial.spacing = {spacing!r}" for n, x in moved.items()]
    return out


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


def inside_cases(host):
    """(variable, label, value) of every value inside the declared range of a Real or Integer parameter."""
    for var in host.md.modelVariables:
        if var.causality == "parameter" and var.type in ("Real", "Integer"):
            kind = float if var.type == "Real" else int
            for label, value in inside_values(kind(var.min), kind(var.max), var.type == "Integer"):
                yield var, label, value


def main():
    path, which = sys.argv[1], sys.argv[2]
    host = Host(path)
    inside = which == "inside"
    if inside:  # the lubricant catalogue (law_context) is the product's
        sys.path.insert(0, str(Path(__file__).resolve().parents[2]))
    only = sys.argv[3] if len(sys.argv) > 3 else None  # a variable name: its cases alone
    for var, label, value in inside_cases(host) if inside else cases(host, which == "fast"):
        if only is not None and var.name != only:
            continue
        print(json.dumps({"variable": var.name, "label": label, "running": True}), flush=True)
        run = host.inside_case if inside else host.input_case if var.causality == "input" else host.parameter_case
        report = run(var, value)
        errors = [text for status, text in host.messages if status >= 2]  # a refused step logs fmi2Discard
        report["warnings"] = [text for status, text in host.messages if status == 1] if inside else []
        shown = value if isinstance(value, str) else repr(value)  # as Python prints the float in a message
        ranged = var.type == "Real" or inside and var.type == "Integer"
        line = {
            "variable": var.name,
            "causality": var.causality,
            "label": label,
            "value": shown,
            "min": float(var.min) if ranged else None,
            "max": float(var.max) if ranged else None,
            "errors": errors,
            **report,
        }
        print(json.dumps(line), flush=True)
    shutil.rmtree(host.unzip, ignore_errors=True)


if __name__ == "__main__":
    main()
