"""Run one FMU scenario in a fresh process and print a JSON report (used by the FMU tests).

Run in a subprocess so that a crash of the host (the thing we test against) cannot take pytest
down, and so that each run starts with a fresh interpreter as a user's master would.
Usage: python probe.py FMU SCENARIO
"""

import json
import shutil
import sys

from fmpy import extract, read_model_description
from fmpy.fmi1 import FMICallException
from fmpy.fmi2 import FMU2Slave, fmi2CallbackFunctions, fmi2CallbackLoggerTYPE

messages = []
init_statuses = []  # status of each fmi2ExitInitializationMode (0 = OK, 3 = a refused parameter)


def _logger(component, instance, status, category, message):
    messages.append({"status": status, "message": message.decode(errors="replace")})


def set_values(fmu, md, values):
    """Set the variables of {name: value} `values` (None: none) of an instance of the FMU of model description
    `md`, each with the setter of its declared type (Real, Integer, Boolean, String)."""
    variables = {v.name: v for v in md.modelVariables}
    setters = {"Real": fmu.setReal, "Integer": fmu.setInteger, "Boolean": fmu.setBoolean, "String": fmu.setString}
    for name, value in (values or {}).items():
        setters[variables[name].type]([variables[name].valueReference], [value])


def open_fmu(path, parameters=None):
    md = read_model_description(path)
    unzip = extract(path)
    callbacks = fmi2CallbackFunctions()
    callbacks.logger = fmi2CallbackLoggerTYPE(_logger)
    from fmpy.fmi2 import calloc, fmi2CallbackAllocateMemoryTYPE, fmi2CallbackFreeMemoryTYPE, free

    callbacks.allocateMemory = fmi2CallbackAllocateMemoryTYPE(calloc)
    callbacks.freeMemory = fmi2CallbackFreeMemoryTYPE(free)
    fmu = FMU2Slave(
        guid=md.guid, unzipDirectory=unzip, modelIdentifier=md.coSimulation.modelIdentifier, instanceName="probe"
    )
    fmu.instantiate(loggingOn=True, callbacks=callbacks)
    fmu._keep = callbacks
    vr = {v.name: v.valueReference for v in md.modelVariables}
    fmu.setupExperiment(startTime=0.0)
    fmu.enterInitializationMode()
    set_values(fmu, md, parameters)
    try:
        fmu.exitInitializationMode()
        init_statuses.append(0)
    except FMICallException as exc:  # a refused parameter: fmi2Error with the reason logged
        init_statuses.append(exc.status)
    return fmu, vr, unzip


def step_status(fmu, t, dt=0.1):
    try:
        fmu.doStep(t, dt)
        return 0
    except FMICallException as exc:
        return exc.status


def reinitialised(fmu, vr, parameters):
    """fmi2Reset, then initialise with `parameters` (String) and step: the step's status."""
    fmu.reset()
    fmu.setupExperiment(startTime=0.0)
    fmu.enterInitializationMode()
    for name, value in parameters.items():
        fmu.setString([vr[name]], [value])
    fmu.exitInitializationMode()
    return step_status(fmu, 0.0)


def main():
    path, scenario = sys.argv[1], sys.argv[2]
    report = {"scenario": scenario}
    if scenario == "bad_inputs":
        fmu, vr, unzip = open_fmu(path)
        results = {}
        cases = [
            ("omega", float("nan")),
            ("omega", 1e9),
            ("T_oil", 0.0),
            ("T_oil", -10.0),
            ("F_y", float("inf")),
            ("F_y", 1e9),
        ]
        for n, (name, bad) in enumerate(cases):
            fmu.setReal([vr["omega"], vr["F_y"], vr["T_oil"]], [500.0, 3000.0, 313.15])
            fmu.setReal([vr[name]], [bad])
            status = step_status(fmu, 0.1 * n)
            results[f"{name}={bad}"] = {"status": status, "outputs": fmu.getReal([vr["Lambda_outer"], vr["p_max"]])}
        fmu.setReal([vr["omega"], vr["F_y"], vr["T_oil"]], [500.0, 3000.0, 313.15])
        results["recovered"] = {"status": step_status(fmu, 10.0), "outputs": fmu.getReal([vr["Lambda_outer"]])}
        report["results"] = results
    elif scenario in ("unknown_bearing", "percent_in_name"):
        name = "no_such_bearing" if scenario == "unknown_bearing" else "100%_bearing_%s_%d"
        fmu, vr, unzip = open_fmu(path, {"bearing": name})
        report["init_status"] = init_statuses[-1]
        report["status"] = step_status(fmu, 0.0)  # refused: the instance is in the error state
        report["recovered"] = reinitialised(fmu, vr, {"bearing": "6208"})  # reset, a corrected parameter
    elif scenario == "qs_bad_inputs":
        fmu, vr, unzip = open_fmu(path)
        good = {"omega": 1047.0, "F_z": 800.0, "F_x": 200.0, "T_oil": 313.15, "dPd_thermal": 0.0}
        results = {}
        cases = [
            ("omega", float("nan")),
            ("omega", 1e9),
            ("T_oil", 0.0),
            ("F_z", float("inf")),
            ("F_x", -float("inf")),
            ("F_z", 1e8),
            ("dPd_thermal", 1.0),
            ("F_z", -500.0),  # reverse thrust on the single-row angular-contact B7214C
        ]
        for n, (name, bad) in enumerate(cases):
            fmu.setReal([vr[k] for k in good], list(good.values()))
            fmu.setReal([vr[name]], [bad])
            status = step_status(fmu, 0.1 * n)
            results[f"{name}={bad}"] = {"status": status, "outputs": fmu.getReal([vr["z"], vr["torque"]])}
        fmu.setReal([vr[k] for k in good], list(good.values()))
        results["recovered"] = {"status": step_status(fmu, 10.0), "outputs": fmu.getReal([vr["z"], vr["torque"]])}
        report["results"] = results
    elif scenario == "qs_bad_race_control":
        fmu, vr, unzip = open_fmu(path, {"race_control": "sideways"})
        report["init_status"] = init_statuses[-1]
        report["status"] = step_status(fmu, 0.0)
        report["recovered"] = reinitialised(fmu, vr, {"race_control": "outer"})
    elif scenario == "simulate":
        fmu, vr, unzip = open_fmu(path)
        fmu.setReal([vr["omega"], vr["F_y"]], [500.0, 3000.0])
        report["status"] = step_status(fmu, 0.0)
        report["Lambda_outer"] = fmu.getReal([vr["Lambda_outer"]])[0]
    else:
        raise SystemExit(f"unknown scenario {scenario}")
    report["messages"] = messages
    fmu.terminate()
    fmu.freeInstance()
    shutil.rmtree(unzip, ignore_errors=True)
    print(json.dumps(report))


if __name__ == "__main__":
    main()
