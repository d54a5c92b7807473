"""SpindleThermal.fmu and SpindleThermalFixed.fmu behave as well-made FMI 2.0 co-simulation FMUs
(docs/architecture.md, FMUs; the model: docs/spindle_thermal.md).

- fmpy.validate_fmu finds no problem (CI asserts `validate_fmu(path) == []`); every
  variable has a description, every Real a declared unit; state get/set and serialisation are
  declared;
- the FMU's variables are the Python model's tables (spindle.thermal.fmu registers model.inputs/outputs),
  and the fixed-preload FMU alone has the axial-float inputs F_axial_k/K_axial_k (what a scene
  does not need is not exposed; spindle.all_fmus.THERMAL_FMUS);
- a hand-written FMU2Slave loop equals spindle.thermal.model.SpindleThermalModel bit for bit: the FMU runs
  the same model code in the same interpreter (spindle/thermal/fmu.py is a thin wrapper), and the model has
  no history other than its state (temperatures, axial float, held inputs; the operator cache is a
  pure function of omega), so a model fed the same inputs in the same order must give the same
  bits; any difference would be an FMI transport error (wrong variable, lost input, float
  formatting);
- the full state round trip (getFMUstate/setFMUstate and serialize/deserialize, also into a second
  instance) reproduces the continuation exactly (the master's rollback relies on it);
- bad inputs (NaN heat, negative ambient temperature) and an unknown `spindle` parameter give a
  logged message naming the input and fmi2Discard/fmi2Error; the host process survives (run in a
  fresh process through tests/fmu/probe.py's helpers so a crash cannot take pytest down) and a
  corrected input recovers.
"""

import json
import math
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest
from fmpy import read_model_description
from fmpy.validation import validate_fmu

from spindle.thermal.declarations import T_START
from spindle.thermal.model import SpindleThermalModel
from tests.fmu.harness import assert_variables_documented, opened

AXIAL_FLOAT_INPUTS = {"F_axial_1", "F_axial_2", "K_axial_1", "K_axial_2"}
OMEGA = 10000.0 * 2.0 * math.pi / 60.0  # rad/s, the Rabreau rig's 10 000 rpm
FMUS = {"spindle_thermal_fmu": False, "spindle_thermal_fixed_fmu": True}  # fixture -> axial_float built in


def outputs_of(path):
    return [v.name for v in read_model_description(str(path)).modelVariables if v.causality == "output"]


def inputs_of(path):
    return [v.name for v in read_model_description(str(path)).modelVariables if v.causality == "input"]


@pytest.mark.parametrize("fixture", sorted(FMUS))
def test_validate_fmu_and_model_description(fixture, request):
    path = request.getfixturevalue(fixture)
    assert validate_fmu(str(path)) == []
    md = read_model_description(str(path))
    assert md.coSimulation is not None
    assert md.coSimulation.canGetAndSetFMUstate and md.coSimulation.canSerializeFMUstate
    assert_variables_documented(md)
    parameters = {v.name for v in md.modelVariables if v.causality == "parameter"}
    assert {name for name in parameters if "." not in name} == {
        "spindle",
        "integrator",
        "T_initial",
        "network_from_file",
    }
    # the network's main dimensions (docs/parameters.md, numeric parameters)
    groups = {name.split(".")[0] for name in parameters if "." in name}
    assert groups == {"bearing_1", "bearing_2", "expansion", "axial"}


@pytest.mark.parametrize("fixture", sorted(FMUS))
def test_variables_are_the_model_tables(fixture, request):
    """spindle/thermal/fmu.py registers the model's declared inputs and outputs: same names, same order."""
    path = request.getfixturevalue(fixture)
    model = SpindleThermalModel(axial_float=FMUS[fixture])
    assert inputs_of(path) == [v.name for v in model.inputs]
    assert outputs_of(path) == [v.name for v in model.outputs]


def test_axial_float_inputs_only_in_the_fixed_preload_fmu(spindle_thermal_fmu, spindle_thermal_fixed_fmu):
    """What a scene does not need is not exposed (docs/architecture.md, scenes; spindle.all_fmus.THERMAL_FMUS):
    a spring-preloaded pair keeps its axial force whatever the growth, so SpindleThermal has no axial-float
    inputs; the fixed-preload FMU needs the bearings' axial reactions and stiffnesses."""
    spring, fixed = set(inputs_of(spindle_thermal_fmu)), set(inputs_of(spindle_thermal_fixed_fmu))
    assert not spring & AXIAL_FLOAT_INPUTS
    assert AXIAL_FLOAT_INPUTS <= fixed
    assert fixed - spring == AXIAL_FLOAT_INPUTS  # nothing else differs
    assert outputs_of(spindle_thermal_fmu) == outputs_of(spindle_thermal_fixed_fmu)


# Changing inputs: heat steps (also negative: a cooling flow), a speed change (rotating-shaft
# convection, centrifugal growth, a new operator), boundary temperature changes, different step sizes.
STEPS = [
    (1.0, dict(omega=OMEGA, Q_inner_ring_1=300.0, Q_outer_ring_1=200.0, Q_inner_ring_2=280.0, Q_outer_ring_2=190.0)),
    (5.0, dict(Q_inner_ring_1=1200.0, Q_outer_ring_1=50.0, P_motor=400.0)),
    (0.5, dict(omega=0.5 * OMEGA, T_ambient=303.15, Q_inner_ring_2=0.0)),
    (60.0, dict(omega=OMEGA, T_coolant=288.15, Q_outer_ring_2=-50.0)),
    (2.0, dict(Q_inner_ring_1=0.0, Q_outer_ring_1=0.0, Q_inner_ring_2=0.0, Q_outer_ring_2=0.0, P_motor=0.0)),
]
# axial-float inputs of the fixed-preload FMU: unequal axial reactions make the shaft float
AXIAL_STEPS = [
    dict(F_axial_1=1500.0, F_axial_2=1300.0, K_axial_1=2.0e8, K_axial_2=1.8e8),
    dict(F_axial_1=2500.0, F_axial_2=2600.0),
    {},
    dict(K_axial_2=0.0),
    dict(K_axial_2=1.9e8),
]


def start_inputs(model):
    """The FMU's input start values (spindle/thermal/declarations.py: T_START for temperatures, 0 otherwise)."""
    return {v.name: v.start for v in model.inputs}


@pytest.mark.parametrize(
    "fixture,parameters",
    [
        ("spindle_thermal_fmu", {}),
        ("spindle_thermal_fixed_fmu", {}),
        ("spindle_thermal_fmu", {"integrator": "implicit_euler", "T_initial": 300.0}),
    ],
)
def test_hand_written_loop_equals_python_model_bit_for_bit(fixture, parameters, request):
    path = request.getfixturevalue(fixture)
    axial_float = FMUS[fixture]
    model = SpindleThermalModel(
        integrator=parameters.get("integrator", "exponential"),
        T_initial=parameters.get("T_initial"),
        axial_float=axial_float,
    )
    inputs = start_inputs(model)
    ref = model.initialize(**inputs)  # exit_initialization_mode: initialize() with the start values
    names = outputs_of(path)
    with opened(path, "loop", parameters) as (fmu, vr):
        assert dict(zip(names, fmu.getReal([vr[n] for n in names]))) == {n: ref[n] for n in names}
        t = 0.0
        for k, (h, change) in enumerate(STEPS):
            inputs.update(change)
            if axial_float:
                inputs.update(AXIAL_STEPS[k])
            fmu.setReal([vr[n] for n in inputs], list(inputs.values()))
            fmu.doStep(t, h)
            t += h
            ref = model.step(h, **inputs)
            got = dict(zip(names, fmu.getReal([vr[n] for n in names])))
            for n in names:
                assert got[n] == ref[n], (k, n, got[n], ref[n])
    # the history did something: temperatures moved, and (fixed preload) the shaft floated
    assert ref["T_inner_ring_1"] != T_START and ref["E_stored"] != 0.0
    if axial_float:
        assert ref["dz_thermal_1"] != ref["dz_thermal_2"]


def test_state_round_trip_is_exact(spindle_thermal_fixed_fmu):
    """getFMUstate/setFMUstate and serialize/deserialize: after restoring the state of t = 1 s, the
    same inputs give the same outputs, bit for bit, as the first time. The fixed-preload FMU
    is used because its state includes the axial float s, which is no FMI variable. The serialised
    state also restarts a second instance of the FMU (restart from a saved run)."""
    path = spindle_thermal_fixed_fmu
    names = outputs_of(path)
    first = dict(
        omega=OMEGA,
        Q_inner_ring_1=400.0,
        Q_outer_ring_1=250.0,
        F_axial_1=1500.0,
        F_axial_2=1200.0,
        K_axial_1=2e8,
        K_axial_2=2e8,
    )
    second = dict(first, Q_inner_ring_1=900.0, F_axial_2=1700.0)
    third = dict(first, Q_inner_ring_1=50.0, omega=100.0, T_ambient=310.0)

    def step(fmu, vr, t, h, inputs):
        fmu.setReal([vr[n] for n in inputs], list(inputs.values()))
        fmu.doStep(t, h)
        return fmu.getReal([vr[n] for n in names])

    with opened(path, "state") as (fmu, vr):
        step(fmu, vr, 0.0, 1.0, first)
        state = fmu.getFMUstate()
        blob = fmu.serializeFMUstate(state)
        after = step(fmu, vr, 1.0, 10.0, second)
        after_two = step(fmu, vr, 11.0, 30.0, third)
        assert after_two != after
        fmu.setFMUstate(state)
        assert step(fmu, vr, 1.0, 10.0, second) == after
        assert step(fmu, vr, 11.0, 30.0, third) == after_two
        fmu.setFMUstate(fmu.deSerializeFMUstate(blob))
        assert step(fmu, vr, 1.0, 10.0, second) == after
        assert step(fmu, vr, 11.0, 30.0, third) == after_two
        fmu.freeFMUstate(state)
        with opened(path, "restart") as (other, vr2):
            restored = other.deSerializeFMUstate(blob)
            other.setFMUstate(restored)
            assert step(other, vr2, 1.0, 10.0, second) == after
            other.freeFMUstate(restored)


# Run in a fresh process: the probe helpers log every message; the JSON report is the last line.
BAD_INPUT_SCRIPT = textwrap.dedent("""
    import json, math, shutil, sys
    sys.path.insert(0, {fmu_tests!r})
    import probe
    path = {path!r}
    report = {{}}
    good = dict(omega={omega!r}, Q_inner_ring_1=300.0, T_ambient=293.15)
    fmu, vr, unzip = probe.open_fmu(path)
    fmu.setReal([vr[k] for k in good], list(good.values()))
    report["good"] = probe.step_status(fmu, 0.0, 1.0)
    names = ["T_inner_ring_1", "T_housing", "E_stored"]
    before = fmu.getReal([vr[n] for n in names])
    for n, (name, bad) in enumerate([("Q_inner_ring_1", float("nan")), ("T_ambient", -10.0)]):
        del probe.messages[:]
        fmu.setReal([vr[k] for k in good], list(good.values()))
        fmu.setReal([vr[name]], [bad])
        status = probe.step_status(fmu, 1.0 + n, 1.0)
        report[name] = dict(status=status, outputs=fmu.getReal([vr[k] for k in names]), before=before,
                            messages=list(probe.messages))
    fmu.setReal([vr[k] for k in good], list(good.values()))
    report["recovered"] = dict(status=probe.step_status(fmu, 3.0, 1.0), outputs=fmu.getReal([vr[k] for k in names]))
    fmu.terminate(); fmu.freeInstance(); shutil.rmtree(unzip, ignore_errors=True)
    del probe.messages[:]
    fmu, vr, unzip = probe.open_fmu(path, {{"spindle": "no_such_100%_spindle"}})
    report["unknown_spindle"] = dict(init_status=probe.init_statuses[-1], status=probe.step_status(fmu, 0.0, 1.0),
                                     messages=list(probe.messages))
    fmu.freeInstance(); shutil.rmtree(unzip, ignore_errors=True)  # in the error state: no fmi2Terminate
    print(json.dumps(report))
""")


@pytest.mark.parametrize("fixture", sorted(FMUS))
def test_bad_inputs_are_reported_and_host_survives(fixture, request):
    """NaN heat and a negative ambient temperature: fmi2Discard (2) or fmi2Error (3), never Fatal, with
    an error message naming the input, its value and the allowed range (spindle.thermal.model._merge); the
    state is left unchanged (outputs as before the refused step) and a corrected input steps again.
    An unknown `spindle` (with a '%' in it: the FMI logger takes a printf format) fails
    fmi2ExitInitializationMode with fmi2Error and the next doStep is refused (the instance is in the FMI
    error state). The process exits 0."""
    path = request.getfixturevalue(fixture)
    script = BAD_INPUT_SCRIPT.format(fmu_tests=str(Path(__file__).parent), path=str(path), omega=OMEGA)
    proc = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=300)
    assert proc.returncode == 0, (proc.returncode, proc.stderr[-3000:])
    report = json.loads(proc.stdout.strip().splitlines()[-1])
    assert report["good"] == 0
    for name, text in (
        ("Q_inner_ring_1", "Q_inner_ring_1 = nan W is outside the allowed range"),
        ("T_ambient", "T_ambient = -10.0 K is outside the allowed range [150, 1000] K"),
    ):
        case = report[name]
        assert case["status"] == 2, name  # fmi2Discard: the step is refused, the instance lives on
        assert case["outputs"] == case["before"], name  # refused step: state and outputs unchanged
        assert all(m["status"] == 2 for m in case["messages"] if m["status"] >= 2)  # the status the step returned
        errors = [m["message"] for m in case["messages"] if m["status"] == 2]
        assert any(text in m for m in errors), (name, case["messages"])
    assert report["recovered"]["status"] == 0
    assert report["recovered"]["outputs"][0] > report["Q_inner_ring_1"]["before"][0]  # 300 W keep heating
    unknown = report["unknown_spindle"]
    assert unknown["init_status"] == 3  # fmi2Error from fmi2ExitInitializationMode
    assert unknown["status"] == 3
    errors = [m["message"] for m in unknown["messages"] if m["status"] == 3]
    # the FMI logger receives a printf format: the FMU escaped '%' as '%%' (a master prints it as '%')
    assert any("unknown spindle 'no_such_100%%_spindle'" in m and "b7214c_x_pair" in m for m in errors), errors
    assert any("fmi2DoStep is not allowed in state error" in m for m in errors), errors
