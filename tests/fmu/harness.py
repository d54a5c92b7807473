"""Shared FMU test harness: open an initialised instance, run a scenario in a fresh process."""

import json
import shutil
import subprocess
import sys
from contextlib import contextmanager
from pathlib import Path

from fmpy import extract, read_model_description
from fmpy.fmi2 import FMU2Slave

from tests.fmu.fuzz import Host
from tests.fmu.probe import set_values

PROBE = Path(__file__).with_name("probe.py")


def probe(fmu_path, scenario):
    """Run tests/fmu/probe.py SCENARIO in a fresh process; its JSON report (the process must exit 0)."""
    proc = subprocess.run(
        [sys.executable, str(PROBE), str(fmu_path), scenario], capture_output=True, text=True, timeout=300
    )
    assert proc.returncode == 0, (proc.returncode, proc.stderr[-2000:])
    return json.loads(proc.stdout.strip().splitlines()[-1])


@contextmanager
def opened(fmu_path, name, parameters=None):
    """An initialised FMU2Slave instance (own extraction), with a name -> value reference map;
    terminated, freed and its extraction removed on exit. Parameters: set by their declared type
    (probe.set_values)."""
    md = read_model_description(str(fmu_path))
    vr = {v.name: v.valueReference for v in md.modelVariables}
    unzip = extract(str(fmu_path))
    fmu = FMU2Slave(
        guid=md.guid, unzipDirectory=unzip, modelIdentifier=md.coSimulation.modelIdentifier, instanceName=name
    )
    try:
        fmu.instantiate()
        fmu.setupExperiment(startTime=0.0)
        fmu.enterInitializationMode()
        set_values(fmu, md, parameters)
        fmu.exitInitializationMode()
        yield fmu, vr
        fmu.terminate()
    finally:
        fmu.freeInstance()
        shutil.rmtree(unzip, ignore_errors=True)


def init_refusal(fmu_path, parameters):
    """(status of fmi2ExitInitializationMode, its error messages) of a fresh instance with these parameters set (by
    their declared type)."""
    host = Host(str(fmu_path))
    fmu = host.instance()
    for name, value in parameters.items():
        if isinstance(value, str):
            host.set(fmu, host.variable[name], value)
        else:
            host.set_value(fmu, name, value)
    status = host.call(fmu.exitInitializationMode)
    fmu.freeInstance()
    return status, [text for level, text in host.messages if level >= 3]


def read_outputs(fmu, vr, names, integers):
    """{name: value} of the outputs `names` of an open instance: those in `integers` read with getInteger, the
    others with getReal."""
    reals = [n for n in names if n not in integers]
    ints = [n for n in names if n in integers]
    got = dict(zip(reals, fmu.getReal([vr[n] for n in reals])))
    got.update(zip(ints, fmu.getInteger([vr[n] for n in ints])))
    return got


def assert_variables_documented(md):
    """Every variable of a model description has a description, every Real a declared unit, and every output
    is computed at initialisation (initial="calculated", which ModelStructure declares)."""
    units = {u.name for u in md.unitDefinitions}
    for v in md.modelVariables:
        assert v.description, v.name
        if v.type == "Real":
            assert v.unit in units, v.name
        if v.causality == "output":
            assert v.initial == "calculated", v.name


def refused_steps(report, recovered_output):
    """{case: result} of the refused steps of a probe's bad-input report, each checked to be fmi2Discard (the
    step is refused, the instance lives on); its last step, "recovered", checked fmi2OK with output number
    `recovered_output` positive."""
    refused = {}
    for case, result in report["results"].items():
        if case == "recovered":
            assert result["status"] == 0 and result["outputs"][recovered_output] > 0.0
            continue
        assert result["status"] == 2, case
        refused[case] = result
    return refused


def probe_report(script):
    """The JSON report (last line of stdout) of a probe script run in a fresh process, which must exit 0."""
    proc = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=300)
    assert proc.returncode == 0, (proc.returncode, proc.stderr[-3000:])
    return json.loads(proc.stdout.strip().splitlines()[-1])


def bad_input_report(template, fmu_path, omega, start):
    """The report of a bad-input probe script (`template` formatted with the tests' folder, the FMU's path, the
    speed and the inputs' start values), whose first step, with good inputs, was accepted."""
    script = template.format(fmu_tests=str(Path(__file__).parent), path=str(fmu_path), omega=omega, start=start)
    report = probe_report(script)
    assert report["good"] == 0
    return report


def assert_refused_with(report, cases):
    """Each (case, text) of `cases` in a probe's report was refused with fmi2Discard (the instance lives on), kept
    the outputs it had before (report["before"]: the last accepted ones, never NaN) and logged an error holding
    `text`."""
    for case, text in cases:
        refused = report[case]
        assert refused["status"] == 2, case
        assert refused["outputs"] == report["before"], case
        errors = [m["message"] for m in refused["messages"] if m["status"] == 2]
        assert any(text in m for m in errors), (case, refused["messages"])


def close(a, b, rel=1e-12):
    return abs(a - b) <= rel * max(abs(a), abs(b)) or a == b


class PickleMarker:
    """Unpickling this creates the directory `path`: the proof that a pickle's code ran."""

    def __init__(self, path):
        self.path = str(path)

    def __reduce__(self):
        import os

        return (os.mkdir, (self.path,))
