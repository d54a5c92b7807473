"""A built FMU runs only the code it carries (docs/fmu_runtime.md, "Its own code"): a host that has imported
another `bearing_fmu` (here a copy of this one with another version marker, first on sys.path) and then
instantiates BearingAnalytic.fmu gets NULL from fmi2Instantiate and an error naming both places; a host that
imported the same code from elsewhere (an unchanged copy) runs the FMU. Each host is a fresh process."""

import json
import shutil
import subprocess
import sys

from bearing_fmu import __version__
from bearing_fmu.build import PACKAGE_DIR

HOST = r"""
import json, shutil, sys
sys.path.insert(0, sys.argv[2])
import bearing_fmu  # the host's own bearing_fmu, imported before the FMU
from fmpy import extract, fmi2, read_model_description

messages = []
callbacks = fmi2.fmi2CallbackFunctions()
callbacks.logger = fmi2.fmi2CallbackLoggerTYPE(lambda c, i, status, cat, text: messages.append(text.decode()))
callbacks.allocateMemory = fmi2.fmi2CallbackAllocateMemoryTYPE(fmi2.calloc)
callbacks.freeMemory = fmi2.fmi2CallbackFreeMemoryTYPE(fmi2.free)
md = read_model_description(sys.argv[1])
unzip = extract(sys.argv[1])
fmu = fmi2.FMU2Slave(guid=md.guid, unzipDirectory=unzip, modelIdentifier=md.coSimulation.modelIdentifier,
                     instanceName="host")
report = {"host_version": bearing_fmu.__version__, "unzip": str(unzip), "messages": messages}
try:
    fmu.instantiate(callbacks=callbacks)
except Exception as exc:  # fmpy raises when fmi2Instantiate returns NULL
    report["instantiated"] = False
else:
    report["instantiated"] = True
    fmu.setupExperiment(startTime=0.0)
    fmu.enterInitializationMode()
    fmu.exitInitializationMode()
    fmu.doStep(0.0, 1.0)
    report["ran_on"] = sys.modules["bearing_fmu"].__file__
    fmu.terminate()
    fmu.freeInstance()
print(json.dumps(report))
shutil.rmtree(unzip, ignore_errors=True)
"""


def host_run(fmu_path, site):
    proc = subprocess.run(
        [sys.executable, "-c", HOST, str(fmu_path), str(site)], capture_output=True, text=True, timeout=300
    )
    assert proc.returncode == 0, proc.stderr[-2000:]
    return json.loads(proc.stdout.strip().splitlines()[-1])


def copy_of_the_package(site, version):
    target = site / "bearing_fmu"
    shutil.copytree(PACKAGE_DIR, target, ignore=shutil.ignore_patterns("__pycache__", "*.pyc", "*.nbi", "*.nbc"))
    init = target / "__init__.py"
    text = init.read_text()
    assert f'__version__ = "{__version__}"' in text
    init.write_text(text.replace(f'__version__ = "{__version__}"', f'__version__ = "{version}"'))
    return target


def test_a_host_with_another_bearing_fmu_is_refused_naming_both(analytic_fmu, tmp_path):
    other = copy_of_the_package(tmp_path.resolve(), "9.9.9")
    report = host_run(analytic_fmu, tmp_path.resolve())
    assert report["host_version"] == "9.9.9"
    assert report["instantiated"] is False, report
    (message,) = [m for m in report["messages"] if "runs only the code it carries" in m]
    assert f"package bearing_fmu from {other} (1 of its files differ" in message
    assert "/resources/bearing_fmu, e.g. __init__.py" in message and report["unzip"] in message


def test_a_host_with_the_same_bearing_fmu_elsewhere_runs_the_fmu(analytic_fmu, tmp_path):
    other = copy_of_the_package(tmp_path.resolve(), __version__)
    report = host_run(analytic_fmu, tmp_path.resolve())
    assert report["instantiated"] is True, report["messages"]
    assert report["ran_on"] == str(other / "__init__.py")
