"""SpindleShaftTransient.fmu (docs/shaft.md, "Time-domain mode"): the shaft's time-domain mode as an FMI 2.0
co-simulation FMU, for bearings driven by the inner ring's displacement.

- fmpy.validate_fmu finds no problem; the variables are the declarations of spindle/shaft/declarations.py, named so
  that a bearing FMU's F_x ... M_y, K[i,j] and x ... theta_y connect to F_x_<seat> ..., K_<seat>[i,j], x_<seat> ...;
- a loop closed through FMI on linear bearings (each seat's reaction K d from the seat's motion at the step's
  start, K passed) equals ShaftTransient driven the same way bit for bit, a speed change between steps included
  (set_speed: the state is kept); with implicit_coupling false the K inputs are not used (held forces alone);
- the FMU state restores the shaft's motion (a master's rejected step);
- bad inputs (NaN speed, a seat reaction or a K entry out of range) are refused with fmi2Discard and a message naming
  the variable, its value and the allowed range, the outputs keep their last values and a corrected input steps
  again; at initialisation a bad input is a warning and the first doStep refuses it; a refused parameter fails
  fmi2ExitInitializationMode. Run in a fresh process (tests/fmu/probe.py);
- the shaft file's numbers as parameters (shaft_from_file, shaft_data.*): at their start values the file's motion bit
  for bit; a heavier tool holder ShaftTransient's on the file with it; with the switch true a changed number changes
  nothing; a number out of its range refused at initialisation, named.
"""

import math
import shutil
import textwrap

import numpy as np
import pytest
from fmpy import read_model_description
from fmpy.validation import validate_fmu

from spindle.shaft.declarations import NEWMARK_GAMMA, SEAT_DAMPING, number_declarations
from spindle.shaft.model import ShaftModel
from spindle.shaft.params import DEFAULT_SHAFT
from spindle.shaft.transient import ShaftTransient
from spindle.shaft.transient_stepper import TransientStepper
from tests.cases import shaft_beams as sb
from tests.fmu.harness import assert_refused_with, assert_variables_documented, bad_input_report, init_refusal, opened

OMEGA = 10000.0 * 2.0 * math.pi / 60.0  # rad/s
H = 1e-4  # s: communication step
FORCE_NAMES = ("F_x", "F_y", "F_z", "M_x", "M_y")
MOTION_NAMES = ("x", "y", "z", "theta_x", "theta_y")


@pytest.fixture(scope="module")
def stepper():
    return TransientStepper()


def test_validate_fmu_and_variables_are_the_declarations(spindle_shaft_transient_fmu, stepper):
    assert validate_fmu(str(spindle_shaft_transient_fmu)) == []
    md = read_model_description(str(spindle_shaft_transient_fmu))
    assert md.coSimulation is not None and md.coSimulation.canGetAndSetFMUstate
    assert_variables_documented(md)
    by_causality = {
        c: [v.name for v in md.modelVariables if v.causality == c] for c in ("parameter", "input", "output")
    }
    damping = [f"c_{kind}_{s}" for s in (1, 2) for kind, *_ in SEAT_DAMPING]
    numbers = [v.name for v in number_declarations(DEFAULT_SHAFT)]  # as SpindleShaft.fmu's (its test)
    assert by_causality == {
        "parameter": ["shaft", "substeps", "newmark_gamma", "implicit_coupling", *damping, *numbers],
        "input": [v.name for v in stepper.inputs],
        "output": [v.name for v in stepper.outputs],
    }
    # a bearing FMU's names with the seat appended, both ways
    for s in (1, 2):
        assert {f"{n}_{s}" for n in FORCE_NAMES} | {f"K_{s}[{i},{j}]" for i in range(1, 6) for j in range(1, 6)} <= set(
            by_causality["input"]
        )
        assert {f"{n}_{s}" for n in MOTION_NAMES} | {f"{n}_rate_{s}" for n in MOTION_NAMES} <= set(
            by_causality["output"]
        )


def seat_stiffness(stepper):
    """The start values' K at both seats, (2, 5, 5), bearing's frame."""
    u = [v.start for v in stepper.inputs]
    return stepper.split(u)[2]


def reactions(K, d):
    """Each seat's reaction K d of a linear bearing (the same arithmetic on both sides of a comparison)."""
    return np.einsum("sij,sj->si", K, d)


def run_closed_loop(fmu, vr, stepper, K, speeds, tip):
    """Steps of the FMU with each seat's reaction K d (d: the seat's motion read from the FMU at the step's start)
    and K passed, at the speeds `speeds` (one per step); returns the outputs after each step (rows)."""
    outputs = [v.name for v in stepper.outputs]
    rows = []
    d = np.zeros((2, 5))
    for k, omega in enumerate(speeds):
        values = {"omega": omega, **{f"{n}_tip": x for n, x in zip(FORCE_NAMES, tip, strict=True)}}
        F = reactions(K, d)
        for s in (1, 2):
            values |= {f"{n}_{s}": x for n, x in zip(FORCE_NAMES, F[s - 1], strict=True)}
            values |= {f"K_{s}[{i + 1},{j + 1}]": K[s - 1, i, j] for i in range(5) for j in range(5)}
        fmu.setReal([vr[n] for n in values], list(values.values()))
        fmu.doStep(k * H, H)  # fmpy raises on a status other than fmi2OK
        row = dict(zip(outputs, fmu.getReal([vr[n] for n in outputs]), strict=True))
        d = np.array([[row[f"{n}_{s}"] for n in MOTION_NAMES] for s in (1, 2)])
        rows.append(row)
    return rows


def reference_loop(K, speeds, tip, implicit=True, damping=(2000.0, 2000.0, 0.2), model=None):
    """ShaftTransient of `model` (default: ShaftModel() of the default shaft) driven as run_closed_loop drives the
    FMU (its parameters' start values: 1 substep, Newmark's gamma NEWMARK_GAMMA)."""
    C = np.zeros((2, 5, 5))
    for i, column in enumerate((0, 0, 1, 2, 2)):
        C[:, i, i] = damping[column]
    shaft = ShaftTransient(model or ShaftModel(), speeds[0], C_seats=C, gamma=NEWMARK_GAMMA)
    rows = []
    for omega in speeds:
        if omega != shaft.omega:
            shaft.set_speed(omega)
        F = reactions(K, shaft.outputs()["seat_displacement"])
        rows.append(shaft.step(H, F, F, tip, K if implicit else None))
    return rows


def as_arrays(row):
    disp = [[row[f"{n}_{s}"] for n in MOTION_NAMES] for s in (1, 2)]
    rate = [[row[f"{n}_rate_{s}"] for n in MOTION_NAMES] for s in (1, 2)]
    return np.array(disp), np.array(rate), np.array([row[f"{n}_tip"] for n in MOTION_NAMES])


def test_closed_loop_on_linear_bearings_equals_shaft_transient(spindle_shaft_transient_fmu, stepper):
    """30 steps of 0.1 ms with a 500 N tool-tip force, the speed raised after 15 steps: every output after every step
    is ShaftTransient's (set_speed at the change) bit for bit, and the seats moved (the tip force reached them)."""
    K = seat_stiffness(stepper)
    speeds = [OMEGA] * 15 + [1.5 * OMEGA] * 15
    tip = np.array([500.0, 0.0, 0.0, 0.0, 0.0])
    with opened(spindle_shaft_transient_fmu, "loop") as (fmu, vr):
        rows = run_closed_loop(fmu, vr, stepper, K, speeds, tip)
    reference = reference_loop(K, speeds, tip)
    for k, (row, ref) in enumerate(zip(rows, reference, strict=True)):
        disp, rate, at_tip = as_arrays(row)
        assert np.array_equal(disp, ref["seat_displacement"]), k
        assert np.array_equal(rate, ref["seat_velocity"]), k
        assert np.array_equal(at_tip, ref["tip_displacement"]), k
    assert abs(rows[-1]["x_1"]) > 1e-7 and abs(rows[-1]["x_tip"]) > abs(rows[-1]["x_1"])
    # without set_speed (the first speed kept) the last steps differ: the speed change reached the model
    constant = reference_loop(K, [OMEGA] * 30, tip)
    assert not np.array_equal(constant[-1]["seat_displacement"], reference[-1]["seat_displacement"])


def test_without_implicit_coupling_the_stiffness_inputs_are_not_used(spindle_shaft_transient_fmu, stepper):
    K = seat_stiffness(stepper)
    speeds = [OMEGA] * 10
    tip = np.array([0.0, 300.0, 0.0, 0.0, 0.0])
    with opened(spindle_shaft_transient_fmu, "held", {"implicit_coupling": False}) as (fmu, vr):
        rows = run_closed_loop(fmu, vr, stepper, K, speeds, tip)
    held = reference_loop(K, speeds, tip, implicit=False)
    implicit = reference_loop(K, speeds, tip)
    assert np.array_equal(as_arrays(rows[-1])[0], held[-1]["seat_displacement"])
    assert not np.array_equal(held[-1]["seat_displacement"], implicit[-1]["seat_displacement"])


def test_the_fmu_state_restores_the_shafts_motion(spindle_shaft_transient_fmu, stepper):
    """getFMUstate after 10 steps, 5 more, setFMUstate, the same 5 again: the same outputs (a rejected step)."""
    K = seat_stiffness(stepper)
    tip = np.array([500.0, 0.0, 0.0, 0.0, 0.0])
    with opened(spindle_shaft_transient_fmu, "state") as (fmu, vr):
        run_closed_loop(fmu, vr, stepper, K, [OMEGA] * 10, tip)
        saved = fmu.getFMUstate()
        first = run_closed_loop(fmu, vr, stepper, K, [OMEGA] * 5, tip)
        fmu.setFMUstate(saved)
        again = run_closed_loop(fmu, vr, stepper, K, [OMEGA] * 5, tip)
        fmu.freeFMUstate(saved)
    # run_closed_loop starts from d = 0 each call, so both repeats see the same inputs
    assert again == first


BAD_INPUT_SCRIPT = textwrap.dedent("""
    import json, shutil, sys
    sys.path.insert(0, {fmu_tests!r})
    import probe
    path = {path!r}
    report = {{}}
    fmu, vr, unzip = probe.open_fmu(path)
    fmu.setReal([vr["omega"], vr["F_x_tip"]], [{omega!r}, 100.0])
    report["good"] = probe.step_status(fmu, 0.0, 1e-4)
    watched = [vr["x_1"], vr["x_tip"]]
    before = fmu.getReal(watched)
    for n, bad in enumerate([{{"omega": float("nan")}}, {{"F_x_1": 2e7}}, {{"K_2[3,3]": -5.0}}]):
        del probe.messages[:]
        fmu.setReal([vr[k] for k in bad], list(bad.values()))
        status = probe.step_status(fmu, 1e-4 * (n + 1), 1e-4)
        report[str(n)] = dict(status=status, outputs=fmu.getReal(watched), messages=list(probe.messages))
        fmu.setReal([vr[k] for k in bad], [{start}[k] for k in bad])
    report["recovered"] = probe.step_status(fmu, 4e-4, 1e-4)
    report["before"] = before
    fmu.terminate(); fmu.freeInstance(); shutil.rmtree(unzip, ignore_errors=True)
    del probe.messages[:]
    fmu, vr, unzip = probe.open_fmu(path, {{"substeps": 0}})
    report["substeps"] = dict(init_status=probe.init_statuses[-1], messages=list(probe.messages))
    fmu.freeInstance(); shutil.rmtree(unzip, ignore_errors=True)
    del probe.messages[:]
    fmu, vr, unzip = probe.open_fmu(path, {{"F_x_1": float("nan")}})
    at_init = list(probe.messages)
    first = probe.step_status(fmu, 0.0, 1e-4)
    fmu.setReal([vr["F_x_1"]], [0.0])
    report["at_init"] = dict(messages=at_init, first=first, corrected=probe.step_status(fmu, 0.0, 1e-4))
    fmu.terminate(); fmu.freeInstance(); shutil.rmtree(unzip, ignore_errors=True)
    print(json.dumps(report))
""")


REFUSALS = {  # case of BAD_INPUT_SCRIPT -> what its message says
    "0": "omega = nan rad/s is outside the allowed range [0, 10000] rad/s",
    "1": "F_x_1 = 20000000.0 N is outside the allowed range [-1e+07, 1e+07] N",
    "2": "K_2[3,3] = -5.0 N/m is outside the allowed range [0, 1e+13] N/m",
}


def test_bad_inputs_are_refused_with_their_range_and_the_host_survives(spindle_shaft_transient_fmu, stepper):
    start = {v.name: v.start for v in stepper.inputs} | {"omega": OMEGA}
    report = bad_input_report(BAD_INPUT_SCRIPT, spindle_shaft_transient_fmu, OMEGA, start)
    assert_refused_with(report, REFUSALS.items())  # the state did not move: the outputs are those before
    assert report["recovered"] == 0
    substeps = report["substeps"]
    assert substeps["init_status"] == 3  # fmi2Error from fmi2ExitInitializationMode
    assert any("substeps = 0" in m["message"] and "[1, 100000]" in m["message"] for m in substeps["messages"])
    # a bad input at initialisation: logged as a warning there, refused by the first doStep, accepted once corrected
    at_init = report["at_init"]
    assert any(m["status"] == 1 and "F_x_1 = nan N is outside" in m["message"] for m in at_init["messages"]), at_init
    assert at_init["first"] == 2 and at_init["corrected"] == 0


def test_spindle_check_runs_the_reference_experiment(spindle_shaft_transient_fmu, tmp_path):
    """`spindle check` finds the experiment from the shaft file beside the FMU, takes this FMU's reference inputs (a
    tool-tip force, not SpindleShaft.fmu's) and matches its reference result, the initialisation's row included."""
    from spindle.check import check_fmu

    for suffix in (".fmu", "_ref.csv", "_shaft.toml"):
        shutil.copy(spindle_shaft_transient_fmu.with_name(f"SpindleShaftTransient{suffix}"), tmp_path)
    result = check_fmu(tmp_path / "SpindleShaftTransient.fmu")
    assert result.differences == [] and result.rows == 21 and result.outputs == 25


def loop_displacements(path, stepper, parameters):
    """The seats' and the tool tip's displacement after each of 10 closed-loop steps (run_closed_loop, a 500 N tool-tip
    force) of the FMU with these parameters."""
    with opened(path, "numbers", parameters) as (fmu, vr):
        rows = run_closed_loop(fmu, vr, stepper, seat_stiffness(stepper), [OMEGA] * 10, TIP)
    return [(as_arrays(row)[0], as_arrays(row)[2]) for row in rows]


def reference_displacements(stepper, model=None):
    rows = reference_loop(seat_stiffness(stepper), [OMEGA] * 10, TIP, model=model)
    return [(row["seat_displacement"], row["tip_displacement"]) for row in rows]


def assert_same_motion(a, b):
    assert len(a) == len(b) == 10
    for k, ((seats_a, tip_a), (seats_b, tip_b)) in enumerate(zip(a, b, strict=True)):
        assert np.array_equal(seats_a, seats_b) and np.array_equal(tip_a, tip_b), k


TIP = np.array([500.0, 0.0, 0.0, 0.0, 0.0])


def test_numbers_at_their_start_values_give_the_files_motion_bit_for_bit(spindle_shaft_transient_fmu, stepper):
    numeric = loop_displacements(spindle_shaft_transient_fmu, stepper, {"shaft_from_file": False})
    assert_same_motion(numeric, reference_displacements(stepper))


def test_a_numeric_tool_holder_mass_gives_the_motion_of_the_file_with_it(
    spindle_shaft_transient_fmu, stepper, tmp_path
):
    """shaft_data.disk_1.mass = 4 kg (the file's tool holder: 1.5 kg): ShaftTransient of the file with 4 kg written in
    it; with shaft_from_file true the same number changes nothing."""
    path = sb.default_shaft_with(tmp_path / "heavy.toml", "value = 1.5, unit", "value = 4.0, unit")
    heavy = reference_displacements(stepper, ShaftModel(path))
    default = reference_displacements(stepper)
    assert not np.array_equal(heavy[-1][1], default[-1][1])
    numbers = {"shaft_data.disk_1.mass": 4.0}
    assert_same_motion(
        loop_displacements(spindle_shaft_transient_fmu, stepper, {"shaft_from_file": False, **numbers}), heavy
    )
    assert_same_motion(loop_displacements(spindle_shaft_transient_fmu, stepper, numbers), default)


def test_a_number_out_of_its_range_fails_the_initialisation_naming_it(spindle_shaft_transient_fmu):
    status, errors = init_refusal(spindle_shaft_transient_fmu, {"shaft_data.disk_1.mass": 2000.0})
    assert status == 3  # fmi2Error from fmi2ExitInitializationMode
    assert any("shaft_data.disk_1.mass = 2000.0 kg is outside the allowed range [0, 1000] kg" in e for e in errors), (
        errors
    )
