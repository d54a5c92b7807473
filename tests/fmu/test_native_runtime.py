"""The FMUs' own FMI 2.0 layer (bearing_fmu_common/runtime, docs/fmu_runtime.md) in native and Python hosts.

- a C importer (tests/fmu/native_importer.c, compiled here with the system gcc) loads the FMU
  binary with nothing preloaded and a bare environment, steps, round-trips a serialised state and
  reads the same outputs as fmpy, bit for bit (same interpreter, same kernels), in fresh processes
  that all exit 0 (no teardown abort);
- a native host's interpreter search: a BEARING_FMU_PYTHON that does not exist is refused with its name
  and nothing else is tried; without it, every candidate tried (python3/python on PATH, the build's
  interpreter) is listed with what it lacks; a python on PATH with numpy and numba is found and runs;
- a refused parameter fails fmi2ExitInitializationMode with fmi2Error, so fmpy.simulate_fmu raises
  and prints the FMU's own message (with '%' shown as written);
- a bad input gives fmi2Discard without the terminate flag and a corrected input continues; the
  same step refused twice becomes fmi2Error (fmpy's simulate_fmu would otherwise retry forever);
- a Python exception in the slave is fmi2Error with its traceback logged (the exception first), never
  fmi2Fatal;
- FMUs set up by several host threads at once take turns: every copy of the layer in a process holds
  one set-up lock while it imports and constructs its slave, and a native host that starts two FMUs on
  two threads at once (both copies of the layer starting the interpreter) exits 0;
- no entry point crashes the host: a NULL instance, a NULL argument, a call out of the FMI 2.0 call
  sequence, a wrong GUID and calls after a failed fmi2Reset get fmi2Error (with a message naming the
  call and the state where an instance has a logger), and a slave constructor's exception reaches the
  host's logger with its text;
- a getter stops at the first value it cannot convert and names its value reference; nvr = 0 with NULL
  arrays is fmi2OK;
- fmi2SetBoolean with a value other than fmi2True or fmi2False is fmi2Error naming the variable and the value,
  and sets no variable of the call;
- the host's logger runs without the GIL (a logger waiting for a lock another host thread holds while it
  calls into an FMU does not deadlock);
- the layer's Python code is the resources/fmi2_layer.py the FMU carries;
- the interpreter search fits a host thread with a 64 kB stack, a whole run one with 128 kB;
- the interpreter a native host starts reads PYTHONPATH, is not isolated and leaves the signals as the host
  set them.
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

from bearing_fmu_common.runtime.binaries import RUNTIME_DIR, fmi_headers, install_runtime
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
    cmd = ["gcc", "-O1", "-Wall", "-Wextra", "-Werror", f"-I{fmi_headers()}", f"-I{RUNTIME_DIR}", str(IMPORTER)]
    cmd += ["-o", str(exe)]
    cmd += ["-ldl", "-lpthread"]
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

    def run(self, importer, inputs, outputs, runs=1, extra=None):
        """Run the importer in a fresh process with a bare environment (and the variables of `extra`);
        (returncode, outputs, stderr)."""
        args = [str(importer), str(self.library), self.resources, self.guid, str(runs), str(N_STEPS), repr(STEP)]
        for name, value in inputs.items():
            kind = "s" if isinstance(value, str) else "r"
            args.append(f"{kind}:{self.vr[name]}={value}")
        args += [f"o:{self.vr[name]}" for name in outputs]
        env = {k: os.environ[k] for k in KEPT if k in os.environ} | (extra or {})
        proc = subprocess.run(args, capture_output=True, text=True, env=env, timeout=600)
        by_vr = dict(line.split("=") for line in proc.stdout.split())
        values = {name: float(by_vr[str(self.vr[name])]) for name in outputs if str(self.vr[name]) in by_vr}
        return proc.returncode, values, proc.stderr

    def calls(self, importer, calls, extra=None):
        """The importer's --calls mode in a fresh process with a bare environment (and the variables of
        `extra`): (returncode, [(call, status)], stderr); status is the fmi2Status number, or "ok"/"null"
        for instantiate."""
        args = [str(importer), "--calls", str(self.library), self.resources, self.guid, *calls]
        env = {k: os.environ[k] for k in KEPT if k in os.environ} | (extra or {})
        proc = subprocess.run(args, capture_output=True, text=True, env=env, timeout=600)
        lines = [line.split(" ", 1) for line in proc.stdout.splitlines()]
        return proc.returncode, [(call, int(s) if s.isdigit() else s) for call, s in lines], proc.stderr

    def remove(self):
        shutil.rmtree(self.dir, ignore_errors=True)


@pytest.fixture
def unpacked(request):
    """Unpacked(fmu) for the FMU fixture named by the test's parameter, removed afterwards."""
    fmu = Unpacked(request.getfixturevalue(request.param))
    yield fmu
    fmu.remove()


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


@pytest.mark.parametrize("raw", [2, -1, 255])
def test_a_boolean_neither_true_nor_false_is_refused_naming_the_variable(analytic_fmu, raw):
    """fmi2SetBoolean with a raw value other than fmi2True (1) or fmi2False (0): fmi2Error, one message naming
    the FMU variable, the value and the allowed values, and no variable of the call changes (the other one
    set to false in the same call stays true)."""
    probe.messages.clear()
    fmu, vr, unzip = probe.open_fmu(str(analytic_fmu))
    refs = [vr["bearing_from_file"], vr["Pd_from_file"]]
    with pytest.raises(FMICallException) as refused:
        fmu.setBoolean(refs, [0, raw])  # fmpy hands the ints to fmi2SetBoolean as they are
    assert refused.value.status == 3
    errors = [m["message"] for m in probe.messages if m["status"] == 3]
    assert any(
        f"fmi2SetBoolean: Pd_from_file (value reference {vr['Pd_from_file']}) = {raw} is not allowed: allowed values "
        "fmi2False (0) and fmi2True (1)" in text
        for text in errors
    ), errors
    assert fmu.getBoolean(refs) == [True, True]  # the start values, kept
    fmu.freeInstance()
    shutil.rmtree(unzip, ignore_errors=True)


def test_bad_input_is_discarded_without_terminate_and_a_corrected_input_continues(analytic_fmu):
    """fmi2Discard leaves the instance stepping (a corrected input continues); the same step refused twice
    is fmi2Error, after which the instance is in the error state until a state saved before is restored."""
    with opened(analytic_fmu, "discard", {"omega": 500.0, "F_y": 3000.0}) as (fmu, vr):
        fmu.doStep(0.0, STEP)
        good = fmu.getReal([vr["Lambda_outer"]])
        saved = fmu.getFMUstate()
        fmu.setReal([vr["omega"]], [float("nan")])
        with pytest.raises(FMICallException) as refused:
            fmu.doStep(STEP, STEP)
        assert refused.value.status == 2  # fmi2Discard
        assert fmu.getBooleanStatus(fmi2Terminated) is False or fmu.getBooleanStatus(fmi2Terminated) == 0
        assert fmu.getReal([vr["Lambda_outer"]]) == good  # outputs keep their last valid values
        fmu.setReal([vr["omega"]], [500.0])
        fmu.doStep(STEP, STEP)
        assert fmu.getReal([vr["Lambda_outer"]]) == good  # same inputs as the first step: same outputs
        fmu.setReal([vr["omega"]], [float("nan")])
        with pytest.raises(FMICallException):
            fmu.doStep(2 * STEP, STEP)
        with pytest.raises(FMICallException) as again:  # the same step refused twice: fmi2Error
            fmu.doStep(2 * STEP, STEP)
        assert again.value.status == 3
        with pytest.raises(FMICallException) as stopped:  # the error state: no step before a restore
            fmu.doStep(2 * STEP, STEP)
        assert stopped.value.status == 3
        fmu.setFMUstate(saved)
        fmu.freeFMUstate(saved)
        fmu.setReal([vr["omega"]], [500.0])
        fmu.doStep(STEP, STEP)
        assert fmu.getReal([vr["Lambda_outer"]]) == good


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
        assert fmu.getReal([vr["omega"]]) == [0.0]  # values can still be read (diagnostics)
        fmu.reset()  # and the instance runs again after fmi2Reset
        fmu.setupExperiment(startTime=0.0)
        fmu.enterInitializationMode()
        fmu.exitInitializationMode()
        fmu.doStep(0.0, STEP)
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


# -- the layer cannot crash its host ------------------------------------------------------------------

TYPES = ("Real", "Integer", "Boolean", "String")
FUNCTIONS = """SetDebugLogging SetupExperiment EnterInitializationMode ExitInitializationMode Terminate Reset GetReal
    GetInteger GetBoolean GetString SetReal SetInteger SetBoolean SetString GetFMUstate SetFMUstate FreeFMUstate
    SerializedFMUstateSize SerializeFMUstate DeSerializeFMUstate GetDirectionalDerivative SetRealInputDerivatives
    GetRealOutputDerivatives DoStep CancelStep GetStatus GetRealStatus GetIntegerStatus GetBooleanStatus
    GetStringStatus""".split()


@pytest.mark.parametrize("unpacked", ["analytic_fmu"], indirect=True)
def test_every_entry_point_refuses_a_null_instance(unpacked, importer):
    """fmi2Error (3) from each of the 30 functions that take an instance, fmi2FreeInstance(NULL) returns."""
    rc, statuses, stderr = unpacked.calls(importer, ["null"])
    assert rc == 0, stderr[-2000:]
    assert statuses == [(f"null:fmi2{name}", 3) for name in FUNCTIONS]


@pytest.mark.parametrize("unpacked", ["analytic_fmu"], indirect=True)
def test_calls_out_of_the_fmi_call_sequence_are_refused(unpacked, importer):
    """fmi2DoStep before fmi2ExitInitializationMode (in state instantiated, then in initialization mode)
    and after fmi2Terminate returns fmi2Error with a message naming the call and the state; the instance
    is then in the error state (fmi2Terminate refused) and fmi2Reset makes it run again."""
    calls = ["instantiate", "step", "reset", "setup", "enter", "step", "terminate", "reset"]
    calls += ["setup", "enter", "exit", "step", "terminate", "step", "free"]
    rc, statuses, stderr = unpacked.calls(importer, calls)
    assert rc == 0, stderr[-2000:]
    assert [s for _, s in statuses] == ["ok", 3, 0, 0, 0, 3, 3, 0, 0, 0, 0, 0, 0, 3, "done"]
    assert "fmi2DoStep is not allowed in state instantiated" in stderr
    assert "fmi2DoStep is not allowed in state initialization mode" in stderr
    assert "fmi2Terminate is not allowed in state error" in stderr
    assert "fmi2DoStep is not allowed in state terminated" in stderr


@pytest.mark.parametrize("unpacked", ["analytic_fmu"], indirect=True)
def test_null_arguments_are_refused(unpacked, importer):
    """A NULL value-reference or value array with nvr > 0 gets fmi2Error and a message from every getter and
    setter, and a NULL state or size pointer likewise: no crash. Each getter and setter is called in
    initialization mode after fmi2Reset (a refusal leaves the error state, where setters are not allowed)."""
    rc, statuses, stderr = unpacked.calls(importer, ["instantiate", "setup", "enter", "exit", "nullargs", "free"])
    assert rc == 0, stderr[-2000:]
    assert [status for call, status in statuses if call.startswith("nullargs:")] == [3] * 20, statuses
    labels = [f"fmi2{d}{kind}({arg})" for d in ("Get", "Set") for kind in TYPES for arg in ("vr", "value")]
    calls = ["instantiate"] + [c for label in labels for c in ("reset", "setup", "enter", f"nullargs:{label}")]
    rc, statuses, stderr = unpacked.calls(importer, calls + ["free"])
    assert rc == 0, stderr[-2000:]
    assert [(call, status) for call, status in statuses if call.startswith("nullargs:")] == [
        (f"nullargs:{label}", 3) for label in labels
    ]
    for label in labels:
        call, argument = label.rstrip(")").split("(")
        assert f"native: {call}: argument {argument} is NULL" in stderr


@pytest.mark.parametrize("unpacked", ["analytic_fmu"], indirect=True)
def test_empty_arrays_may_be_null(unpacked, importer):
    """nvr = 0 with NULL arrays is a valid call (FMI 2.0): fmi2OK from every getter and setter."""
    rc, statuses, stderr = unpacked.calls(importer, ["instantiate", "setup", "enter", "exit", "empty", "free"])
    assert rc == 0, stderr[-2000:]
    assert [s for c, s in statuses if c.startswith("empty:")] == [0] * 8, statuses


@pytest.mark.parametrize("unpacked", ["analytic_fmu"], indirect=True)
def test_a_wrong_guid_is_refused(unpacked, importer):
    rc, statuses, stderr = unpacked.calls(importer, ["guid:{not-this-fmu}", "instantiate"])
    assert rc == 0, stderr[-2000:]
    assert statuses == [("instantiate", "null")]
    assert f"GUID '{{not-this-fmu}}' is not this FMU's ('{unpacked.guid}' in its modelDescription.xml)" in stderr


@pytest.mark.parametrize("unpacked", ["analytic_fmu"], indirect=True)
def test_a_host_logger_waiting_for_a_lock_of_the_host_does_not_block_other_threads(unpacked, importer):
    """The host's logger runs without the GIL: thread 2's refused call logs, and its logger waits for a lock that
    thread 1 holds while it reads an output of another instance (which needs the GIL); both calls return."""
    env = {k: os.environ[k] for k in KEPT if k in os.environ}
    args = [str(importer), "--logger-lock", str(unpacked.library), unpacked.resources, unpacked.guid]
    args.append(str(unpacked.vr["Lambda_outer"]))
    proc = subprocess.run(args, capture_output=True, text=True, env=env, timeout=600)
    assert proc.returncode == 0, (proc.stdout, proc.stderr[-2000:])
    assert proc.stdout.split() == ["logger-lock", "0", "3"]  # the read is OK, the refused step fmi2Error
    assert "refused (logStatusError): refused: fmi2DoStep is not allowed in state instantiated" in proc.stderr


@pytest.mark.parametrize("where", ["loader", "set-up"])
def test_a_host_logger_waiting_for_a_lock_of_the_host_does_not_block_another_instantiation(
    where, analytic_fmu, failing_fmu, importer
):
    """Thread 2 makes the process's first fmi2Instantiate and its messages wait for a lock of the host; thread 1
    holds that lock and calls fmi2Instantiate too. The messages are passed on once the FMU holds none of its
    locks: the loader's (with logging on, "started Python ..."; the loader holds its own locks while it starts
    Python) and the layer's (a constructor's exception; the layer holds the set-up lock while it constructs)."""
    fmu = Unpacked(analytic_fmu) if where == "loader" else failing_from(failing_fmu, 1)
    env = {k: os.environ[k] for k in KEPT if k in os.environ}
    args = [str(importer), "--logger-lock-instantiate", str(fmu.library), fmu.resources, fmu.guid]
    args.append("1" if where == "loader" else "0")
    try:
        proc = subprocess.run(args, capture_output=True, text=True, env=env, timeout=600)
    finally:
        fmu.remove()
    assert proc.returncode == 0, (proc.stdout, proc.stderr[-2000:])
    got = "ok ok" if where == "loader" else "null null"  # the failing FMU's constructor always refuses here
    assert proc.stdout.split() == ["logger-lock-instantiate", "waited", *got.split()]
    assert ("first (logAll): started Python" if where == "loader" else "first (logStatusError): first: creating") in (
        proc.stderr
    )


@pytest.mark.parametrize("unpacked", ["analytic_fmu"], indirect=True)
def test_the_layer_runs_the_python_side_the_fmu_carries(unpacked, importer):
    """The layer's Python code is resources/fmi2_layer.py, not text compiled into the binary: without that file
    fmi2Instantiate returns NULL and says which file is missing."""
    layer = unpacked.dir / "resources" / "fmi2_layer.py"
    assert layer.read_bytes() == (Path(install_runtime.__code__.co_filename).parent / "fmi2_layer.py").read_bytes()
    binary = (unpacked.library.parent / "fmi2_python.abi3.so").read_bytes()
    assert b"def slave_class" not in binary and b"import importlib" not in binary
    layer.unlink()
    rc, statuses, stderr = unpacked.calls(importer, ["instantiate"])
    assert rc == 0, stderr[-2000:]
    assert statuses == [("instantiate", "null")]
    assert "cannot load the layer's Python side, resources/fmi2_layer.py (an incomplete or altered FMU)" in stderr
    assert "FileNotFoundError" in stderr


def slave_fmu(script_name, dest):
    """The FMU of the test slave tests/fmu/<script_name>, built by pythonfmu into dest, with the product's FMI
    layer installed."""
    from pythonfmu.builder import FmuBuilder

    script = Path(__file__).with_name(script_name)
    path = FmuBuilder.build_FMU(script, dest=dest)
    sys.modules.pop(script.stem, None)
    return install_runtime(path)


@pytest.fixture(scope="module")
def failing_fmu(tmp_path_factory):
    """An FMU of tests/fmu/failing_constructor_slave.py with the product's FMI layer."""
    return slave_fmu("failing_constructor_slave.py", tmp_path_factory.mktemp("failing"))


@pytest.fixture(scope="module")
def bad_values_fmu(tmp_path_factory):
    """An FMU of tests/fmu/bad_values_slave.py with the product's FMI layer."""
    return slave_fmu("bad_values_slave.py", tmp_path_factory.mktemp("bad_values"))


def failing_from(fmu_path, construction):
    """The failing FMU unpacked, its constructor failing from the given construction on."""
    fmu = Unpacked(fmu_path)
    (fmu.dir / "resources" / "fail_from.txt").write_text(str(construction))
    return fmu


def test_a_constructor_exception_reaches_the_logger_with_its_text(failing_fmu, importer):
    fmu = failing_from(failing_fmu, 1)
    try:
        rc, statuses, stderr = fmu.calls(importer, ["instantiate"])
    finally:
        fmu.remove()
    assert rc == 0, stderr[-2000:]
    assert statuses == [("instantiate", "null")]
    # printed by a printf-formatting logger: the '%' arrives as written
    assert "creating the slave: RuntimeError: the constructor refuses on purpose (construction 1, 100% planned)" in (
        stderr
    )
    assert "unknown Python error" not in stderr


def test_calls_after_a_failed_reset_return_error(failing_fmu, importer):
    """The reset's new slave fails: the instance has no slave; stepping, reading, setting and another
    reset return fmi2Error (no crash: the process exits 0), and the instance can be freed."""
    fmu = failing_from(failing_fmu, 2)
    try:
        calls = ["instantiate", "setup", "enter", "exit", "step", "reset", "step", "getReal:0", "setReal:0=1"]
        rc, statuses, stderr = fmu.calls(importer, calls + ["reset", "free"])
    finally:
        fmu.remove()
    assert rc == 0, stderr[-2000:]
    assert [s for _, s in statuses] == ["ok", 0, 0, 0, 0, 3, 3, 3, 3, 3, "done"]
    assert "RuntimeError: the constructor refuses on purpose (construction 2, 100% planned)" in stderr
    assert "fmi2GetReal: the instance has no model since fmi2Reset failed" in stderr


def test_a_getter_stops_at_the_first_value_it_cannot_convert(bad_values_fmu, importer):
    """Each getter's second value cannot be converted (a str for a Real, 2**40 for an Integer, an object whose
    truth raises for a Boolean, bytes for a String): fmi2Error, the values after it are left as they were, and
    the message names the variable's value reference and the cause."""
    fmu = Unpacked(bad_values_fmu)
    try:
        calls = ["instantiate", "setup", "enter", "exit"]
        for kind in ("real", "integer", "boolean", "string"):
            calls.append(f"{kind}s:" + ",".join(str(fmu.vr[f"{kind}_{k}"]) for k in range(3)))
        rc, statuses, stderr = fmu.calls(importer, calls + ["free"])
    finally:
        fmu.remove()
    assert rc == 0, stderr[-2000:]
    got = {call.split(":")[0]: status for call, status in statuses[4:8]}
    assert got == {
        "reals": "3|1.5|-7|-7",
        "integers": "3|7|-7|-7",
        "booleans": "3|1|-7|-7",
        "strings": "3|first|unset|unset",
    }
    assert f"get_real, value reference {fmu.vr['real_1']}: TypeError: must be real number, not str" in stderr
    assert f"get_integer, value reference {fmu.vr['integer_1']}: OverflowError: 1099511627776 does not fit an " in (
        stderr
    )
    assert (
        f"get_boolean, value reference {fmu.vr['boolean_1']}: ValueError: this value is neither true nor false"
        in stderr
    )
    assert f"get_string, value reference {fmu.vr['string_1']}: TypeError: " in stderr


TWO_THREAD_RUNS = 3


def two_thread_runs(importer, first, second, runs):
    """Exit codes of `runs` fresh processes that each set up the two FMUs from two threads at once."""
    fmus = [Unpacked(first), Unpacked(second)]
    env = {k: os.environ[k] for k in KEPT if k in os.environ}
    args = [str(importer), "--threads"] + [str(x) for f in fmus for x in (f.library, f.resources, f.guid)]
    try:
        procs = [subprocess.run(args, capture_output=True, text=True, env=env, timeout=600) for _ in range(runs)]
    finally:
        for fmu in fmus:
            fmu.remove()
    return [p.returncode for p in procs], [p.stderr[-1000:] for p in procs if p.returncode]


def test_a_native_host_sets_up_two_fmus_from_two_threads(analytic_fmu, spindle_thermal_fmu, importer):
    """Both copies of the layer start the interpreter at once: the process-wide lock lets one start it.
    Without that lock 10 of 12 such processes segfaulted here; the slow test below runs 100."""
    codes, errors = two_thread_runs(importer, analytic_fmu, spindle_thermal_fmu, TWO_THREAD_RUNS)
    assert codes == [0] * TWO_THREAD_RUNS, errors


def test_a_hundred_native_hosts_set_up_two_fmus_from_two_threads(analytic_fmu, spindle_thermal_fmu, importer):
    """100 fresh processes (about 1.5 s each here), each instantiating BearingAnalytic.fmu and
    SpindleThermal.fmu from two threads at once, initialising, stepping and freeing: all exit 0."""
    codes, errors = two_thread_runs(importer, analytic_fmu, spindle_thermal_fmu, 100)
    assert codes == [0] * 100, (sum(c != 0 for c in codes), errors[:3])


def test_a_native_host_is_told_that_BEARING_FMU_PYTHON_does_not_exist(analytic_fmu, importer):
    fmu = Unpacked(analytic_fmu)
    try:
        rc, got, stderr = fmu.calls(importer, ["instantiate"], {"BEARING_FMU_PYTHON": "/nonexistent/bin/python"})
    finally:
        fmu.remove()
    assert rc == 0 and got == [("instantiate", "null")], stderr
    assert "BEARING_FMU_PYTHON=/nonexistent/bin/python: no such file" in stderr
    assert "nothing else was tried: BEARING_FMU_PYTHON names the interpreter to use" in stderr


def stack_run(fmu, importer, kilobytes, calls, extra):
    """The importer's --stack mode: (returncode, [(call, status)], stack bytes used or None, stderr)."""
    args = [str(importer), "--stack", str(kilobytes), str(fmu.library), fmu.resources, fmu.guid, *calls]
    env = {k: os.environ[k] for k in KEPT if k in os.environ} | extra
    proc = subprocess.run(args, capture_output=True, text=True, env=env, timeout=600)
    lines = [line.split(" ", 1) for line in proc.stdout.splitlines()]
    used = [int(value) for key, value in lines if key == "stack-used"]
    statuses = [(call, int(s) if s.isdigit() else s) for call, s in lines if call != "stack-used"]
    return proc.returncode, statuses, used[0] if used else None, proc.stderr


# stack the test host's thread uses by itself (its thread descriptor, its calls loop, printing): 7.6 kB here
HOST_STACK = 8 * 1024


def test_the_interpreter_search_fits_a_small_host_thread_stack(analytic_fmu, importer, python_without_numba):
    """fmi2Instantiate on a host thread with a 64 kB stack, through the whole interpreter search (a candidate that
    lacks numba, the refusal logged): its buffers are on the heap. The search used 68 kB of stack before (a
    64 kB thread crashed); now about 2 kB beyond the host's own."""
    fmu = Unpacked(analytic_fmu)
    try:
        extra = {"BEARING_FMU_PYTHON": str(python_without_numba / "python")}
        rc, statuses, used, stderr = stack_run(fmu, importer, 64, ["instantiate"], extra)
    finally:
        fmu.remove()
    assert rc == 0, stderr[-2000:]
    assert statuses == [("instantiate", "null")]
    assert "no modules numpy, numba" in stderr
    assert used < HOST_STACK + 8 * 1024, used


def test_a_host_thread_with_a_small_stack_runs_the_fmu(analytic_fmu, importer):
    """Starting Python, instantiating, stepping and freeing on a host thread with a 128 kB stack (Python's own
    start-up and imports take the most: about 55 kB with Python 3.11)."""
    fmu = Unpacked(analytic_fmu)
    try:
        calls = ["instantiate", "setup", "enter", "exit", "step", "free"]
        extra = {"BEARING_FMU_PYTHON": sys.executable}
        rc, statuses, used, stderr = stack_run(fmu, importer, 128, calls, extra)
    finally:
        fmu.remove()
    assert rc == 0, stderr[-2000:]
    assert statuses == [("instantiate", "ok"), ("setup", 0), ("enter", 0), ("exit", 0), ("step", 0), ("free", "done")]
    assert used < 128 * 1024


STARTUP_PROBE = """import sys
sys.stderr.write("STARTED isolated=%d argv=%r\\n" % (sys.flags.isolated, sys.argv))
"""


def test_a_native_host_starts_python_as_python_does(analytic_fmu, importer, tmp_path):
    """The interpreter started in a native host reads PYTHONPATH (a sitecustomize.py there runs), is not isolated,
    and installs none of Python's start-up signal handlers: SIGPIPE, which Python ignores when it installs them,
    stays at its default, and the host's SIGINT handler stays."""
    (tmp_path / "sitecustomize.py").write_text(STARTUP_PROBE)
    fmu = Unpacked(analytic_fmu)
    try:
        extra = {"BEARING_FMU_PYTHON": sys.executable, "PYTHONPATH": str(tmp_path)}
        calls = ["hostsigint", "signals", "instantiate", "signals", "free"]
        rc, statuses, stderr = fmu.calls(importer, calls, extra)
    finally:
        fmu.remove()
    assert rc == 0, stderr[-2000:]
    assert statuses[2] == ("instantiate", "ok"), stderr[-2000:]
    assert statuses[1] == statuses[3] == ("signals", "SIGINT=host,SIGPIPE=default"), statuses
    assert "STARTED isolated=0 argv=['']" in stderr


@pytest.fixture(scope="module")
def python_without_numba(tmp_path_factory):
    """bin/ of a virtual environment of this Python without numpy and numba (no pip: a second or two)."""
    home = tmp_path_factory.mktemp("no_numba") / "env"
    base = getattr(sys, "_base_executable", sys.executable)
    subprocess.run([base, "-m", "venv", "--without-pip", str(home)], check=True, capture_output=True)
    return home / "bin"


def test_a_native_host_is_told_every_interpreter_tried_and_what_it_lacks(analytic_fmu, importer, python_without_numba):
    """PATH has only a Python without numpy and numba, and the build's interpreter has gone: the message names
    each candidate, its version and what it lacks."""
    fmu = Unpacked(analytic_fmu)
    try:
        (fmu.dir / "resources" / "python.txt").write_text("/nonexistent/build/bin/python\n")
        rc, got, stderr = fmu.calls(importer, ["instantiate"], {"PATH": str(python_without_numba)})
    finally:
        fmu.remove()
    assert rc == 0 and got == [("instantiate", "null")], stderr
    version = ".".join(map(str, sys.version_info[:3]))
    assert "BEARING_FMU_PYTHON: not set" in stderr
    for name in ("python3", "python"):
        assert f"{name} on PATH ({python_without_numba / name}), Python {version}: no modules numpy, numba" in stderr
    assert "the interpreter that built the FMU (/nonexistent/build/bin/python, resources/python.txt): no such file" in (
        stderr
    )
    assert "Set BEARING_FMU_PYTHON to such a python executable" in stderr


def test_a_native_host_finds_a_python_with_numpy_and_numba_on_PATH(analytic_fmu, importer, python_without_numba):
    """The first candidate lacks numba, the second (this environment's python) has it: the FMU runs."""
    fmu = Unpacked(analytic_fmu)
    try:
        (fmu.dir / "resources" / "python.txt").unlink()
        path = f"{python_without_numba}:{Path(sys.executable).parent}"
        rc, got, stderr = fmu.calls(importer, ["instantiate", "setup", "enter", "exit", "step", "free"], {"PATH": path})
    finally:
        fmu.remove()
    assert rc == 0 and got[0] == ("instantiate", "ok"), stderr
    assert [status for _, status in got[1:5]] == [0, 0, 0, 0], stderr
