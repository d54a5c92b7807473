"""SpindleShaft.fmu (docs/shaft.md): the shaft's rotor model packaged as an FMI 2.0 co-simulation FMU.

- fmpy.validate_fmu finds no problem; every variable has a description, every Real a unit; the variables are the
  declarations of spindle/shaft/declarations.py (registered from spindle.shaft.stepper's tables);
- fmpy.simulate_fmu of the built FMU, and a hand-written loop changing the speed and the seats' stiffness, equal the
  Python model (spindle.shaft.stepper.ShaftStepper) bit for bit: the FMU runs the same code in the same interpreter;
- a stiffer front seat raises f_1 as the model says; a floating seat (`floating_<seat>`) is the model's;
- the critical speeds (a second eigenproblem) are computed again only when a seat's K or c changes;
- bad inputs (NaN speed, a negative diagonal stiffness, seats that leave the shaft free) are refused with fmi2Discard
  and a message naming the input, its value and the allowed range; a corrected input steps again; an unknown `shaft`
  fails fmi2ExitInitializationMode with fmi2Error. Run in a fresh process (tests/fmu/probe.py);
- the shaft file's numbers as parameters (shaft_from_file, shaft_data.*): at their start values the file's outputs bit
  for bit; a changed outer diameter the model of the file with it; with the switch true a changed number changes
  nothing; a number out of its range or an inner diameter not below the outer refused at initialisation, named.
"""

import json
import math
import shutil
import subprocess
import sys
import textwrap
from pathlib import Path

import pytest
from fmpy import read_model_description, simulate_fmu
from fmpy.validation import validate_fmu

from spindle.shaft.declarations import number_declarations
from spindle.shaft.params import DEFAULT_SHAFT
from spindle.shaft.stepper import ShaftStepper
from tests.cases import shaft_beams as sb
from tests.fmu.harness import (
    assert_refused_with,
    assert_variables_documented,
    bad_input_report,
    init_refusal,
    opened,
    read_outputs,
)

OMEGA = 10000.0 * 2.0 * math.pi / 60.0  # rad/s


@pytest.fixture(scope="module")
def stepper():
    return ShaftStepper()


def start_inputs(stepper):
    return {v.name: v.start for v in stepper.inputs}


def test_validate_fmu_and_variables_are_the_declarations(spindle_shaft_fmu, stepper):
    assert validate_fmu(str(spindle_shaft_fmu)) == []
    md = read_model_description(str(spindle_shaft_fmu))
    assert md.coSimulation is not None
    assert_variables_documented(md)
    by_causality = {
        c: [v.name for v in md.modelVariables if v.causality == c] for c in ("parameter", "input", "output")
    }
    numbers = [v.name for v in number_declarations(DEFAULT_SHAFT)]
    assert numbers[:3] == [
        "shaft_from_file",
        "shaft_data.material_1.youngs_modulus",
        "shaft_data.material_1.poisson_ratio",
    ]
    assert len(numbers) == 1 + 3 + 5 * 3 + 2 * 3  # one material, five sections, two disks
    assert by_causality == {
        "parameter": ["shaft", "tolerance", "floating_1", "floating_2", *numbers],
        "input": [v.name for v in stepper.inputs],
        "output": [v.name for v in stepper.outputs],
    }
    # one stiffness input per entry of a bearing FMU's K[i,j], per seat
    assert {f"K_{s}[{i},{j}]" for s in (1, 2) for i in range(1, 6) for j in range(1, 6)} <= set(by_causality["input"])


def test_simulate_fmu_equals_the_python_model(spindle_shaft_fmu, stepper):
    """fmpy's simulate_fmu with the start values and the reference speed: every output row is the model's."""
    result = simulate_fmu(str(spindle_shaft_fmu), stop_time=1.0, output_interval=0.25, start_values={"omega": OMEGA})
    ref = stepper.outputs_values(list((start_inputs(stepper) | {"omega": OMEGA}).values()))
    assert len(result) == 5
    for row in result:
        assert {n: row[n] for n in ref} == ref
    assert ref["f_1"] > 100.0 and ref["critical_speed_1"] > OMEGA  # a stiff spindle: first critical above 10 000 rpm


def test_hand_written_loop_with_seat_changes_equals_the_model(spindle_shaft_fmu, stepper):
    """Speed and seat stiffness change between steps; a stiffer front seat (radial and tilt) raises f_1 as the model
    says, and the FMU's outputs are the model's bit for bit."""
    inputs = start_inputs(stepper)
    changes = [
        {"omega": OMEGA},
        {"K_1[1,1]": 5e8, "K_1[2,2]": 5e8, "K_1[4,4]": 1e5, "K_1[5,5]": 1e5},
        {"omega": 2.0 * OMEGA, "c_2": 5000.0},
    ]
    integers = {v.name for v in stepper.outputs if v.kind == "integer"}
    names = [v.name for v in stepper.outputs]
    f_1 = []
    with opened(spindle_shaft_fmu, "loop") as (fmu, vr):
        for k, change in enumerate(changes):
            inputs.update(change)
            fmu.setReal([vr[n] for n in inputs], list(inputs.values()))
            fmu.doStep(0.1 * k, 0.1)
            ref = stepper.outputs_values(list(inputs.values()))
            assert read_outputs(fmu, vr, names, integers) == ref, k
            f_1.append(ref["f_1"])
    assert f_1[1] > f_1[0]


def test_a_floating_seat_is_the_models(spindle_shaft_fmu, stepper):
    """floating_2 = true (the rear outer ring on preload springs) gives the model's outputs with that seat's axial
    freedom condensed out: the front bearing alone holds the shaft axially."""
    floating = ShaftStepper()
    floating.model.set_floating((False, True))
    inputs = start_inputs(stepper) | {"omega": OMEGA}
    names = [v.name for v in stepper.outputs]
    integers = {v.name for v in stepper.outputs if v.kind == "integer"}
    with opened(spindle_shaft_fmu, "floating", {"floating_2": True, "tolerance": 0.0}) as (fmu, vr):
        fmu.setReal([vr[n] for n in inputs], list(inputs.values()))
        fmu.doStep(0.0, 0.1)
        assert read_outputs(fmu, vr, names, integers) == floating.outputs_values(list(inputs.values()))
    held = stepper.outputs_values(list(inputs.values()))
    assert floating.outputs_values(list(inputs.values()))["compliance_axial"] > 1.8 * held["compliance_axial"]


def test_a_tolerance_keeps_the_outputs_while_the_inputs_stay_within_it():
    """tolerance t: an entry K_ij may move by t sqrt(K_ii K_jj) of the last solved inputs, a damping and omega by t
    of theirs, before a step solves again; 0 solves every step."""
    stepper = ShaftStepper()
    stepper.configure((False, False), 1e-2)
    u = list((start_inputs(stepper) | {"omega": OMEGA}).values())
    first = stepper.evaluate(u)
    tilt = 1 + 3 * 5 + 3  # K_1[4,4]: 2.4e4 N.m/rad among entries of 1e8 N/m
    for index, factor in ((1, 1.009), (0, 1.009), (tilt, 1.009)):  # K_1[1,1], omega, K_1[4,4] within 1 %
        u[index] *= factor
        assert stepper.evaluate(u) == first and stepper.solutions == 1
    u[tilt] *= 1.02  # now 2.9 % from the solved K_1[4,4]: the tilt entry counts on its own scale
    moved = stepper.evaluate(u)
    assert stepper.solutions == 2 and moved != first
    stepper.configure((False, False), 0.0)
    stepper.evaluate(u)
    stepper.evaluate(u)
    assert stepper.solutions == 4


def test_critical_speeds_are_kept_until_a_seat_changes():
    stepper = ShaftStepper()
    u = list((start_inputs(stepper) | {"omega": OMEGA}).values())
    first = stepper.evaluate(u)
    assert stepper.critical_evaluations == 1
    u[0] = 2.0 * OMEGA  # the speed does not enter the synchronous critical speeds
    stepper.evaluate(u)
    u[1] *= 1.0 + 1e-12  # K_1[1,1]: below the relative change of 1e-9
    again = stepper.evaluate(u)
    assert stepper.critical_evaluations == 1
    assert again[-2:] == first[-2:]
    u[1] *= 1.5
    changed = stepper.evaluate(u)
    assert stepper.critical_evaluations == 2
    assert changed[-2] != first[-2]
    u[26] *= 2.0  # c_1
    stepper.evaluate(u)
    assert stepper.critical_evaluations == 3


BAD_INPUT_SCRIPT = textwrap.dedent("""
    import json, shutil, sys
    sys.path.insert(0, {fmu_tests!r})
    import probe
    path = {path!r}
    report = {{}}
    fmu, vr, unzip = probe.open_fmu(path)
    fmu.setReal([vr["omega"]], [{omega!r}])
    report["good"] = probe.step_status(fmu, 0.0, 0.1)
    before = fmu.getReal([vr["f_1"], vr["compliance_radial"]])
    free = {{f"K_{{s}}[{{i}},{{j}}]": 0.0 for s in (1, 2) for i in range(1, 6) for j in range(1, 6)}}
    for n, bad in enumerate([{{"omega": float("nan")}}, {{"K_1[3,3]": -5.0}}, free]):
        del probe.messages[:]
        fmu.setReal([vr[k] for k in bad], list(bad.values()))
        status = probe.step_status(fmu, 0.1 * (n + 1), 0.1)
        report[str(n)] = dict(status=status, outputs=fmu.getReal([vr["f_1"], vr["compliance_radial"]]),
                              messages=list(probe.messages))
        fmu.setReal([vr[k] for k in bad], [{start}[k] for k in bad])
    report["recovered"] = dict(status=probe.step_status(fmu, 0.5, 0.1), outputs=fmu.getReal([vr["f_1"]]))
    report["before"] = before
    fmu.terminate(); fmu.freeInstance(); shutil.rmtree(unzip, ignore_errors=True)
    del probe.messages[:]
    fmu, vr, unzip = probe.open_fmu(path, {{"shaft": "no_such_100%_shaft"}})
    report["unknown_shaft"] = dict(init_status=probe.init_statuses[-1], messages=list(probe.messages))
    fmu.freeInstance(); shutil.rmtree(unzip, ignore_errors=True)
    print(json.dumps(report))
""")


def test_bad_inputs_are_refused_with_their_range_and_the_host_survives(spindle_shaft_fmu, stepper):
    start = {v.name: v.start for v in stepper.inputs} | {"omega": OMEGA}
    report = bad_input_report(BAD_INPUT_SCRIPT, spindle_shaft_fmu, OMEGA, start)
    cases = (
        ("0", "omega = nan rad/s is outside the allowed range [0, 10000] rad/s"),
        ("1", "K_1[3,3] = -5.0 N/m is outside the allowed range [0, 1e+13] N/m"),
        ("2", "the seat stiffness leaves the shaft free"),
    )
    assert_refused_with(report, cases)
    assert "K_1[1,1] = 0" in str(report["2"]["messages"]) and "allowed" in str(report["2"]["messages"])
    assert report["recovered"]["status"] == 0 and report["recovered"]["outputs"] == report["before"][:1]
    unknown = report["unknown_shaft"]
    assert unknown["init_status"] == 3  # fmi2Error from fmi2ExitInitializationMode
    assert any("no_such_100%%_shaft" in m["message"] and "rabreau_b7214c" in m["message"] for m in unknown["messages"])


BESIDE_THERMAL_SCRIPT = textwrap.dedent("""
    import json, shutil, sys
    sys.path.insert(0, {fmu_tests!r})
    import probe
    report = {{}}
    for name, path in (("thermal", {thermal!r}), ("shaft", {shaft!r})):
        del probe.messages[:]
        fmu, vr, unzip = probe.open_fmu(path)
        report[name] = dict(init=probe.init_statuses[-1], step=probe.step_status(fmu, 0.0, 0.25),
                            messages=list(probe.messages))
    print(json.dumps(report))
""")


def test_a_host_loads_the_shaft_fmu_after_a_thermal_fmu(spindle_shaft_fmu, spindle_thermal_fmu):
    """A host that imports no product code and loads the thermal FMU first, as the warm-up system's masters do:
    the shaft FMU finds its own files in the copy of `spindle` the thermal FMU put in place (both carry the same one),
    and both initialise and step."""
    script = BESIDE_THERMAL_SCRIPT.format(
        fmu_tests=str(Path(__file__).parent), thermal=str(spindle_thermal_fmu), shaft=str(spindle_shaft_fmu)
    )
    proc = subprocess.run([sys.executable, "-c", script], capture_output=True, text=True, timeout=600)
    assert proc.returncode == 0, (proc.returncode, proc.stderr[-3000:])
    report = json.loads(proc.stdout.strip().splitlines()[-1])
    for name in ("thermal", "shaft"):
        assert report[name]["init"] == 0 and report[name]["step"] == 0, (name, report[name]["messages"])


def test_spindle_check_runs_the_reference_experiment(spindle_shaft_fmu, tmp_path):
    """`spindle check` finds the shaft FMU's experiment from the shaft file beside it and matches its reference."""
    from spindle.check import check_fmu

    for suffix in (".fmu", "_ref.csv", "_shaft.toml"):
        shutil.copy(spindle_shaft_fmu.with_name(f"SpindleShaft{suffix}"), tmp_path)
    result = check_fmu(tmp_path / "SpindleShaft.fmu")
    assert result.differences == [] and result.rows == 5 and result.outputs == 24


def run_at_speed(path, parameters):
    """fmpy's simulate_fmu at the reference speed with these parameters: two steps of 0.25 s."""
    return simulate_fmu(str(path), stop_time=0.5, output_interval=0.25, start_values={"omega": OMEGA, **parameters})


def assert_rows_are(result, ref):
    assert len(result) == 3
    for row in result:
        assert {n: row[n] for n in ref} == ref


def test_numbers_at_their_start_values_give_the_files_outputs_bit_for_bit(spindle_shaft_fmu, stepper):
    """shaft_from_file = false with every shaft_data.* at its start value: the shaft rebuilt from them (a reduction
    of its own at initialisation) gives the file's outputs bit for bit."""
    ref = stepper.outputs_values(list((start_inputs(stepper) | {"omega": OMEGA}).values()))
    assert_rows_are(run_at_speed(spindle_shaft_fmu, {"shaft_from_file": False}), ref)


def test_a_numeric_outer_diameter_gives_the_model_of_the_file_with_it(spindle_shaft_fmu, stepper, tmp_path):
    """shaft_data.section_3.outer_diameter = 85 mm (the file: 75 mm): the outputs of ShaftStepper built from the file
    with 85 mm written in it; with shaft_from_file true the same number changes nothing."""
    path = sb.default_shaft_with(tmp_path / "thick.toml", "value = 0.075, unit", "value = 0.085, unit")
    thick = ShaftStepper(path)
    u = list((start_inputs(thick) | {"omega": OMEGA}).values())
    ref, default = thick.outputs_values(u), stepper.outputs_values(u)
    assert ref["f_1"] != default["f_1"]
    numbers = {"shaft_data.section_3.outer_diameter": 0.085}
    assert_rows_are(run_at_speed(spindle_shaft_fmu, {"shaft_from_file": False, **numbers}), ref)
    assert_rows_are(run_at_speed(spindle_shaft_fmu, numbers), default)


@pytest.mark.parametrize(
    "parameters,message",
    [
        (
            {"shaft_data.section_3.outer_diameter": 1.5},
            "shaft_data.section_3.outer_diameter = 1.5 m is outside the allowed range [0.005, 1] m",
        ),
        (
            {"shaft_from_file": False, "shaft_data.section_3.inner_diameter": 0.08},
            "shaft_data.section_3.inner_diameter = 0.08 m must be below shaft_data.section_3.outer_diameter = 0.075 m "
            "(section 'between_bearings'); allowed: an inner diameter in [0, 0.075[ m",
        ),
    ],
)
def test_a_refused_number_fails_the_initialisation_naming_it(spindle_shaft_fmu, parameters, message):
    """A number out of its declared range is refused whatever the switch; an inner diameter at the outer one by the
    file's own check with the switch false."""
    status, errors = init_refusal(spindle_shaft_fmu, parameters)
    assert status == 3  # fmi2Error from fmi2ExitInitializationMode
    assert any(message in text for text in errors), errors


def test_numbers_on_a_file_of_another_structure_are_refused(spindle_shaft_fmu, tmp_path):
    """shaft names a file with the same two seats but one section and no disk: the shaft_data.* numbers (five
    sections, two disks) cannot be its numbers."""
    other = sb.shaft_file(tmp_path / "plain.toml", [(0.3, 0.05, 0.0, 6)], seats=(0.1, 0.2))
    status, errors = init_refusal(spindle_shaft_fmu, {"shaft_from_file": False, "shaft": str(other)})
    assert status == 3
    message = f"shaft = {str(other)!r} has other materials, sections or disks than the shaft this FMU was built with"
    assert any(message in text and "allowed with shaft_from_file = false" in text for text in errors), errors
    assert init_refusal(spindle_shaft_fmu, {"shaft": str(other)})[0] == 0  # the file's own numbers: accepted
