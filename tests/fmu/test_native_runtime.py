"""The FMUs' own FMI 2.0 layer (bearing_fmu_common/runtime, docs/fmu_runtime.md) in native and Python hosts.

- a C importer (tests/fmu/native_importer.c, compiled here with the system gcc) loads the FMU
  binary with nothing preloaded and a bare environment, steps, round-trips a serialised state and
  reads the same outputs as fmpy, bit for bit (same interpreter, same kernels), in fresh processes
  that all exit 0 (no teardown abort);
- a refused parameter fails fmi2ExitInitializationMode with fmi2Error, so fmpy.simulate_fmu raises
  and prints the FMU's own message (with '%' shown as written);
- a bad input gives fmi2Discard without the terminate flag and a corrected input continues; the
  same step refused twice becomes fmi2Error (fmpy's simulate_fmu would otherwise retry forever);
- a Python exception in the slave is fmi2Error with its traceback logged (the exception first), never
  fmi2Fatal;
- FMUs set up by several host threads at once take turns: every copy of the layer in a process holds
  one set-up lock while it imports and constructs its slave.
"""

import json
import os
import shutil
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest
from fmpy import extract, read_model_description
from fmpy.fmi1 import FMICallException
from fmpy.fmi2 import fmi2Terminated

from bearing_fmu_common.runtime.build import fmi_headers
from tests.fmu import probe
from tests.fmu.harness import opened

IMPORTER = Path(__file__).with_name("native_importer.c")
STEP = 0.1  # s
N_STEPS = 5
# environment variables a native host may pass on (cache locations); nothing else, no LD_PRELOAD
KEPT = ("HOME", "BEARING_FMU_CACHE", "XDG_CACHE_HOME", "NUMBA_CACHE_DIR")

# FMU fixture -> (inputs and parameters set in initialisation mode, outputs compared)
CASES = {
    "analytic_fmu": ({"omega": 500.0, "F_y": 3000.0}, ["Lambda_outer", "p_max", "C_bearing", "omega_cage"]),
    "bearing_fmu": ({"omega": 1047.0, "F_z": 800.0, "F_x": 200.0}, ["z", "torque", "Lambda_inner", "K[3,3]"]),
    "spindle_thermal_fmu": ({"omega": 1047.0, "Q_inner_ring_1": 300.0}, ["T_inner_ring_1", "T_housing"]),
}


@pytest.fixture(scope="module")
def importer(tmp_path_factory):
    exe = tmp_path_factory.mktemp("native") / "native_importer"
    cmd = ["gcc", "-O1", "-Wall", "-Wextra", "-Werror", f"-I{fmi_headers()}", str(IMPORTER), "-o", str(exe), "-ldl"]
    proc = subprocess.run(cmd, capture_output=True, text=True)
    assert proc.returncode == 0, proc.stderr
    return exe


class Unpacked:
    """An FMU extracted for the C importer: binary, resource URI, GUID, value references."""

    def __init__(self, fmu_path):
        md = read_model_description(str(fmu_path))
        self.dir = Path(extract(str(fmu_path)))
        self.library = self.dir / "binaries" / "linux64" / f"{md.coSimulation.modelIdentifier}.so"
        self.resources = (self.dir / "resources").as_uri()
        self.guid = md.guid
        self.vr = {v.name: v.valueReference for v in md.modelVariables}
        self.types = {v.name: v.type for v in md.modelVariables}

    def run(self, importer, inputs, outputs, runs=1):
        """Run the importer in a fresh process with a bare environment; (returncode, outputs, stderr)."""
        args = [str(importer), str(self.library), self.resources, self.guid, str(runs), str(N_STEPS), repr(STEP)]
        for name, value in inputs.items():
            kind = "s" if isinstance(value, str) else "r"
            args.append(f"{kind}:{self.vr[name]}={value}")
        args += [f"o:{self.vr[name]}" for name in outputs]
        env = {k: os.environ[k] for k in KEPT if k in os.environ}
        proc = subprocess.run(args, capture_output=True, text=True, env=env, timeout=600)
        by_vr = dict(line.split("=") for line in proc.stdout.split())
        values = {name: float(by_vr[str(self.vr[name])]) for name in outputs if str(self.vr[name]) in by_vr}
        return proc.returncode, values, proc.stderr

    def remove(self):
        shutil.rmtree(self.dir, ignore_errors=True)


def fmpy_outputs(fmu_path, inputs, outputs):
    """The importer's sequence (inputs set in initialisation mode, N_STEPS steps) through fmpy."""
    with opened(fmu_path, "fmpy", inputs) as (fmu, vr):
        for n in range(N_STEPS):
            fmu.doStep(n * STEP, STEP)
        return dict(zip(outputs, fmu.getReal([vr[name] for name in outputs])))


@pytest.mark.parametrize("fixture", sorted(CASES))
def test_native_importer_matches_fmpy(fixture, importer, request):
    """Two instantiate/free cycles in one process (the interpreter outlives the last instance)."""
    path = request.getfixturevalue(fixture)
    inputs, outputs = CASES[fixture]
    fmu = Unpacked(path)
    try:
        rc, native, stderr = fmu.run(importer, inputs, outputs, runs=2)
    finally:
        fmu.remove()
    assert rc == 0, stderr[-3000:]
    assert native == fmpy_outputs(path, inputs, outputs)  # bit for bit: same interpreter and kernels


@pytest.mark.slow
def test_twenty_fresh_native_processes_exit_cleanly(analytic_fmu, importer):
    inputs, outputs = CASES["analytic_fmu"]
    fmu = Unpacked(analytic_fmu)
    try:
        results = [fmu.run(importer, inputs, outputs) for _ in range(20)]
    finally:
        fmu.remove()
    assert [rc for rc, _, _ in results] == [0] * 20, [stderr[-500:] for rc, _, stderr in results if rc]
    assert all(values == results[0][1] for _, values, _ in results)


def test_native_host_gets_the_refusal_with_its_message(analytic_fmu, importer):
    """A formatting (printf) C logger prints the FMU's message as written, '%' included."""
    fmu = Unpacked(analytic_fmu)
    try:
        rc, _, stderr = fmu.run(importer, {"bearing": "62O8%s%n"}, ["Lambda_outer"])
    finally:
        fmu.remove()
    assert rc == 3, stderr
    assert "unknown bearing '62O8%s%n'" in stderr
    assert "fmi2ExitInitializationMode(c) returned status 3" in stderr


SIMULATE = textwrap.dedent("""
    import sys
    import numpy as np
    from fmpy import simulate_fmu
    path, how = sys.argv[1], sys.argv[2]
    if how == "parameter":
        simulate_fmu(path, stop_time=0.3, output_interval=0.1, start_values={"bearing": "62O8 100%"})
    else:  # a bad input for the whole run
        signal = np.array([(0.0, float("nan"))], dtype=[("time", float), ("omega", float)])
        simulate_fmu(path, stop_time=0.3, output_interval=0.1, input=signal)
""")


@pytest.mark.parametrize(
    "how,function,message",
    [
        ("parameter", "fmi2ExitInitializationMode", "unknown bearing '62O8 100%'"),
        ("input", "fmi2DoStep", "omega = nan"),
    ],
)
def test_fmpy_simulate_fmu_raises_with_the_fmu_message(analytic_fmu, how, function, message):
    """Without debug logging: the message is printed by fmpy's default logger, the call raises."""
    proc = subprocess.run(
        [sys.executable, "-c", SIMULATE, str(analytic_fmu), how], capture_output=True, text=True, timeout=300
    )
    assert proc.returncode != 0
    assert f"{function} failed with status 3 (error)" in proc.stderr, proc.stderr[-2000:]
    assert message in proc.stdout, proc.stdout


def test_bad_input_is_discarded_without_terminate_and_a_corrected_input_continues(analytic_fmu):
    with opened(analytic_fmu, "discard", {"omega": 500.0, "F_y": 3000.0}) as (fmu, vr):
        fmu.doStep(0.0, STEP)
        good = fmu.getReal([vr["Lambda_outer"]])
        fmu.setReal([vr["omega"]], [float("nan")])
        with pytest.raises(FMICallException) as refused:
            fmu.doStep(STEP, STEP)
        assert refused.value.status == 2  # fmi2Discard
        assert fmu.getBooleanStatus(fmi2Terminated) is False or fmu.getBooleanStatus(fmi2Terminated) == 0
        assert fmu.getReal([vr["Lambda_outer"]]) == good  # outputs keep their last valid values
        with pytest.raises(FMICallException) as again:  # the same step refused twice: fmi2Error
            fmu.doStep(STEP, STEP)
        assert again.value.status == 3
        fmu.setReal([vr["omega"]], [500.0])
        fmu.doStep(STEP, STEP)
        assert fmu.getReal([vr["Lambda_outer"]]) == good  # same inputs as the first step: same outputs


def test_python_exception_is_an_error_with_its_traceback(analytic_fmu):
    fmu, vr, unzip = probe.open_fmu(str(analytic_fmu))
    try:
        del probe.messages[:]
        with pytest.raises(FMICallException) as failed:
            fmu.getString([vr["omega"]])  # a Real: the slave raises TypeError
        assert failed.value.status == 3  # fmi2Error, not fmi2Fatal
        texts = [m["message"] for m in probe.messages if m["status"] == 3]
        assert any("Traceback" in t and "TypeError" in t and "is not of type String" in t for t in texts), texts
        # the exception before its traceback: a host that shows only a message's start still shows the cause
        assert all(t.index("TypeError") < t.index("Traceback") for t in texts if "Traceback" in t), texts
        assert fmu.getReal([vr["omega"]]) == [0.0]  # the instance is still usable
        fmu.terminate()
    finally:
        fmu.freeInstance()
        shutil.rmtree(unzip, ignore_errors=True)


SETUP_TURNS = textwrap.dedent("""
    import json, sys, threading, time, types
    from fmpy import extract, read_model_description
    from fmpy.fmi2 import FMU2Slave

    # the layer's process-wide set-up lock, registered here first so that this host can hold it
    shared = types.ModuleType("_bearing_fmu_runtime_shared")
    shared.setup_lock = lock = threading.RLock()
    sys.modules["_bearing_fmu_runtime_shared"] = shared
    path = sys.argv[1]
    md = read_model_description(path)
    report, done = {}, {}

    def instantiate(fmu, key):
        fmu.instantiate()
        done[key] = time.monotonic()

    for key in ("first", "second"):  # two extractions: two copies of the layer, as two FMUs bring
        fmu = FMU2Slave(guid=md.guid, unzipDirectory=extract(path), modelIdentifier=md.coSimulation.modelIdentifier,
                        instanceName=key)
        lock.acquire()  # another FMU's set-up in progress
        thread = threading.Thread(target=instantiate, args=(fmu, key))
        thread.start()
        thread.join(1.0)
        report[key + "_waited"] = key not in done
        lock.release()
        thread.join(120.0)
        report[key + "_instantiated"] = key in done
        fmu.freeInstance()
    print(json.dumps(report))
""")


def test_fmus_set_up_by_several_threads_take_turns(analytic_fmu):
    """Two threads setting up FMUs at once (imports, numba loading kernels and filling its registries) are
    not safe. While another set-up holds the process-wide lock, fmi2Instantiate of each copy of the layer
    waits, and goes on when it is released."""
    proc = subprocess.run(
        [sys.executable, "-c", SETUP_TURNS, str(analytic_fmu)], capture_output=True, text=True, timeout=300
    )
    assert proc.returncode == 0, proc.stderr[-2000:]
    report = json.loads(proc.stdout.strip().splitlines()[-1])
    assert report == {
        "first_waited": True,
        "first_instantiated": True,
        "second_waited": True,
        "second_instantiated": True,
    }
