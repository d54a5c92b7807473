"""Bearing.fmu (load-driven) and BearingDisp.fmu (displacement-driven), the quasi-static scenes (docs/quasistatic.md).

- fmpy.validate_fmu finds no problem; every variable has a description and a unit; K[i,j] exist;
- a hand-written FMU2Slave loop equals the Python model bit for bit when the model sees the same
  sequence of evaluations (construction, initialisation, each step): the solver warm-starts from
  its previous solution, so only an identical history gives identical rounding;
- fmpy simulate_fmu equals a fresh Python model to 1e-8 relative: the histories differ, and the
  equilibrium is converged to 1e-10 of the load, which bounds the difference of the solutions;
- FMU state (including the solver's ball positions) round trip is exact;
- bad inputs (NaN, out of range, overload, unknown race control) give a clear logged message and
  fmi2Discard, the host survives, a corrected input recovers.
"""

import math

import numpy as np
import pytest
from fmpy import read_model_description, simulate_fmu
from fmpy.validation import validate_fmu

from bearing_fmu.build import SCENES_DIR
from bearing_fmu.models.quasi_static import QuasiStaticModel
from bearing_fmu.scene import Scene
from tests.fmu import probe as host
from tests.fmu.harness import close, opened, probe, refused_steps
from tests.fmu.harness import read_outputs as read_values

INTEGER_OUTPUTS = ("regime", "n_loaded", "iterations")


def scene_of(file_name):
    return Scene.from_toml(SCENES_DIR / file_name)


def fmu_outputs(md):
    return [v.name for v in md.modelVariables if v.causality == "output"]


def read_outputs(fmu, vr, names):
    return read_values(fmu, vr, names, INTEGER_OUTPUTS)


@pytest.mark.parametrize("fixture", ["bearing_fmu", "bearing_disp_fmu"])
def test_validate_and_variables(fixture, request):
    path = request.getfixturevalue(fixture)
    assert validate_fmu(str(path)) == []
    md = read_model_description(str(path))
    assert md.coSimulation.canGetAndSetFMUstate and md.coSimulation.canSerializeFMUstate
    names = {v.name for v in md.modelVariables}
    assert {f"K[{i},{j}]" for i in range(1, 6) for j in range(1, 6)} <= names
    assert {
        "torque",
        "P_loss",
        "Q_inner_ring",
        "Q_outer_ring",
        "alpha_inner",
        "alpha_outer",
        "C_bearing",
        "Lambda_inner",
        "Lambda_outer",
        "bearing",
        "lubricant",
        "Pd",
        "race_control",
        "dPd_thermal",
    } <= names
    drive = {"F_x", "F_y", "F_z", "M_x", "M_y"}
    dofs = {"x", "y", "z", "theta_x", "theta_y"}
    inputs = {v.name for v in md.modelVariables if v.causality == "input"}
    outputs = set(fmu_outputs(md))
    if fixture == "bearing_fmu":
        assert drive <= inputs and dofs <= outputs
    else:
        assert dofs <= inputs and drive <= outputs and "dz_thermal" in inputs
    units = {u.name for u in md.unitDefinitions}
    for v in md.modelVariables:
        assert v.description, v.name
        if v.type == "Real":
            assert v.unit in units, v.name
    assert {v.name: v.unit for v in md.modelVariables}["K[1,1]"] == "N/m"
    assert {v.name: v.unit for v in md.modelVariables}["K[4,4]"] == "N.m"


STEPS_LOAD = [  # omega (rad/s), F_x, F_y, F_z (N), M_x (N.m), T_oil (K), dPd_thermal (m)
    dict(omega=0.0, F_x=0.0, F_z=800.0),
    dict(omega=500.0, F_x=300.0, F_z=800.0, T_oil=330.0),
    dict(omega=1047.0, F_x=300.0, F_y=-100.0, F_z=1500.0, M_x=5.0, T_oil=330.0, dPd_thermal=-5e-6),
    dict(omega=-800.0, F_z=200.0),
    dict(omega=1047.0, F_z=3500.0, T_oil=350.0),
]


def assert_replay_equals_model(fmu_path, model, steps, parameters=None):
    """Step the FMU and the model through the same history; every output must be bit-identical.
    Returns the model's last outputs."""
    model.evaluate()  # the FMU evaluates its defaults at construction and at initialisation
    model.evaluate()
    with opened(fmu_path, "loop", parameters) as (fmu, vr):
        names = fmu_outputs(read_model_description(str(fmu_path)))
        for n, step in enumerate(steps):
            inputs = {"T_oil": 313.15, **step}
            for var in model.inputs:
                fmu.setReal([vr[var.name]], [inputs.get(var.name, 0.0)])
            fmu.doStep(0.1 * n, 0.1)
            got = read_outputs(fmu, vr, names)
            ref = model.evaluate(**inputs)
            for name in names:
                assert got[name] == ref[name], (n, name, got[name], ref[name])
    return ref


def test_hand_written_loop_equals_python_model(bearing_fmu):
    model = QuasiStaticModel(scene=scene_of("quasi_static.toml"), race_control="hybrid")
    assert_replay_equals_model(bearing_fmu, model, STEPS_LOAD, {"race_control": "hybrid"})


def test_displacement_fmu_equals_python_model(bearing_disp_fmu):
    model = QuasiStaticModel(scene=scene_of("quasi_static_displacement.toml"))
    steps = [
        dict(omega=0.0, z=20e-6),
        dict(omega=1047.0, x=3e-6, z=25e-6, theta_y=1e-4, dz_thermal=2e-6),
        dict(omega=300.0, x=-2e-6, y=1e-6, z=10e-6),
    ]
    ref = assert_replay_equals_model(bearing_disp_fmu, model, steps)
    assert ref["F_z"] > 0.0 and ref["K[3,3]"] > 0.0


def test_simulate_fmu_equals_python_model(bearing_fmu):
    t = np.linspace(0.0, 1.0, 11)
    signals = np.array(
        [(a, 1047.0 * a, 800.0 + 500.0 * a, 100.0 * a) for a in t],
        dtype=[("time", float), ("omega", float), ("F_z", float), ("F_x", float)],
    )
    res = simulate_fmu(
        str(bearing_fmu),
        stop_time=1.0,
        output_interval=0.1,
        input=signals,
        output=["z", "x", "theta_y", "torque", "K[3,3]", "K[1,5]", "alpha_outer", "C_bearing"],
    )
    model = QuasiStaticModel(scene=scene_of("quasi_static.toml"))
    model.evaluate()  # the FMU's history: its defaults (zero load: the clearance centre) at construction
    for row in res[1:]:
        n = int(round(row["time"] / 0.1)) - 1  # outputs at t_n from the inputs held at t_(n-1)
        ref = model.evaluate(omega=1047.0 * t[n], F_z=800.0 + 500.0 * t[n], F_x=100.0 * t[n])
        for name in res.dtype.names[1:]:
            assert close(float(row[name]), ref[name], rel=1e-8), (row["time"], name, row[name], ref[name])


def test_low_speeds_and_run_up_from_rest_step_without_refusal(bearing_fmu):
    """Through the FMU (fmpy raises on a refused step): the B7214C at low speeds 0.1-600 rpm under
    no load, 5 kN radial + 500 N axial and 5 kN + 2 kN radial + 2 kN axial + 60 N.m, then the first 200 ms of a run-up
    from rest to 10 000 rpm in 1 s at 1 ms steps under 5 kN + 500 N: every step accepted, outputs equal
    to the Python model's (the steps that were refused before the ball test was scaled to the bearing)."""
    rpm = 2.0 * np.pi / 60.0
    loads = ({}, dict(F_x=5000.0, F_z=500.0), dict(F_x=5000.0, F_y=2000.0, F_z=2000.0, M_x=60.0))
    steps = [dict(omega=n * rpm, **load) for n in (0.1, 1.0, 10.0, 79.0, 116.0, 537.0, 600.0) for load in loads]
    steps += [dict(omega=10000.0 * rpm * k / 1000, F_x=5000.0, F_z=500.0) for k in range(201)]
    model = QuasiStaticModel(scene=scene_of("quasi_static.toml"))
    ref = assert_replay_equals_model(bearing_fmu, model, steps)
    assert ref["n_loaded"] > 0


def test_state_round_trip_is_exact(bearing_fmu):
    with opened(bearing_fmu, "state") as (fmu, vr):
        names = fmu_outputs(read_model_description(str(bearing_fmu)))
        fmu.setReal([vr["omega"], vr["F_z"], vr["F_x"]], [1047.0, 800.0, 200.0])
        fmu.doStep(0.0, 1.0)
        state = fmu.getFMUstate()
        blob = fmu.serializeFMUstate(state)
        fmu.setReal([vr["omega"], vr["F_z"]], [500.0, 1500.0])
        fmu.doStep(1.0, 1.0)
        after = read_outputs(fmu, vr, names)
        fmu.setReal([vr["omega"], vr["F_z"]], [1200.0, 3000.0])
        fmu.doStep(2.0, 1.0)
        fmu.setFMUstate(fmu.deSerializeFMUstate(blob))
        fmu.setReal([vr["omega"], vr["F_z"]], [500.0, 1500.0])
        fmu.doStep(1.0, 1.0)  # from the restored solver state the same step gives the same bits
        assert read_outputs(fmu, vr, names) == after
        fmu.freeFMUstate(state)


def test_bad_inputs_are_reported_and_host_survives(bearing_fmu):
    report = probe(bearing_fmu, "qs_bad_inputs")
    for case, result in refused_steps(report, 1).items():
        assert all(np.isfinite(result["outputs"])), case
    texts = [m["message"] for m in report["messages"] if m["status"] >= 2]
    assert all(m["status"] == 2 for m in report["messages"] if m["status"] >= 2)  # the status the step returned
    assert any("omega = nan" in t and "allowed range" in t for t in texts)
    assert any("T_oil = 0.0 K" in t and "[233.15, 473.15] K" in t for t in texts)
    assert any("F_z = inf" in t for t in texts)
    assert any("material limit" in t for t in texts)
    assert any("F_z = -500" in t and "missing shoulder" in t for t in texts)  # reported, not computed
    assert any("dPd_thermal = 1.0 m" in t for t in texts)


def test_unknown_race_control_is_reported(bearing_fmu):
    report = probe(bearing_fmu, "qs_bad_race_control")
    assert report["init_status"] == 3  # fmi2Error from fmi2ExitInitializationMode
    assert report["status"] == 3  # the error state: no step until fmi2Reset
    assert report["recovered"] == 0  # reset and initialised with an allowed race control
    assert any("race_control = 'sideways'" in m["message"] and "hybrid" in m["message"] for m in report["messages"])


def test_overload_warning_is_logged():
    """p_max between 4.2 and 6 GPa: computed, with a warning naming the ISO 76 limit (model level;
    the FMU logs the same text as fmi2Warning)."""
    model = QuasiStaticModel(scene=scene_of("quasi_static.toml"))
    out = model.evaluate(omega=100.0, F_z=200000.0)
    assert 4.2e9 < out["p_max"] < 6e9
    assert any("ISO 76" in w for w in model.warnings)


def test_shoulder_truncation_is_reported_and_warned_on_entry_and_at_each_doubling(bearing_fmu):
    """Bearing.fmu with the 40 deg 218 of the textbook cases (its own bearing file, iso_vg68_mineral) under 8.9 kN
    thrust: at rest within its shoulders (truncation_inner = 0, no warning); at 10 000 and 12 000 rpm the
    centrifugal force turns the inner contact to 55-57 deg and its ellipse past the estimated 60.7 deg shoulder
    edge: truncation_inner > 0 and one fmi2Warning naming the race, the contact angle and the edge, not one per
    step, and one more when the truncated fraction has doubled since (10 000 -> 12 000 rpm); back at rest it leaves
    truncation, and the next entry is warned again. FMU state: a state saved in truncation and restored gives no new
    warning (the state carries each race's fraction at its last warning)."""
    from tests.validation.test_shoulder_truncation import BEARING

    host.messages.clear()
    fmu, vr, _ = host.open_fmu(str(bearing_fmu), {"bearing": str(BEARING), "lubricant": "iso_vg68_mineral"})
    fmu.setReal([vr["F_z"]], [8900.0])
    rpm = (0.0, 10000.0, 12000.0, 12000.0, 10000.0, 0.0, 0.0, 12000.0)
    truncation, warnings = [], []
    for k, n in enumerate(rpm):
        fmu.setReal([vr["omega"]], [n * math.pi / 30.0])
        host.messages.clear()
        assert host.step_status(fmu, 0.1 * k) == 0
        truncation.append(fmu.getReal([vr["truncation_inner"], vr["truncation_outer"]]))
        warnings.append([m["message"] for m in host.messages if m["status"] == 1 and "truncated" in m["message"]])
    assert [t[0] > 0.0 for t in truncation] == [n > 0.0 for n in rpm]
    assert all(t[1] == 0.0 for t in truncation)
    # 10 000 rpm: 23.2 % of the semi-major axis past the edge; 12 000 rpm: 55.7 %, more than doubled: warned again
    assert [len(w) for w in warnings] == [0, 1, 1, 0, 0, 0, 0, 1]
    assert "grown from 23.2 %" in warnings[2][0]
    assert "inner ring's thrust-side shoulder" in warnings[1][0] and "edge at 60.7 deg" in warnings[1][0]
    state = fmu.getFMUstate()  # in truncation
    fmu.setReal([vr["omega"]], [0.0])
    assert host.step_status(fmu, 0.8) == 0
    fmu.setFMUstate(state)
    fmu.setReal([vr["omega"]], [12000.0 * math.pi / 30.0])
    host.messages.clear()
    assert host.step_status(fmu, 0.9) == 0
    assert not any("truncated" in m["message"] for m in host.messages)
    fmu.freeFMUstate(state)
    fmu.terminate()
    fmu.freeInstance()


def test_oil_outside_its_data_range_is_warned_once_per_entry(bearing_fmu):
    """Bearing.fmu with the B7214C and iso_vg68_mineral (data 0-120 C, the file's [temperature_range]): 250 K oil
    (inside the input range -40..200 C) gives one fmi2Warning naming the temperature and the range at the first
    step there, none at the next; back in range and out again, one more."""
    host.messages.clear()
    fmu, vr, _ = host.open_fmu(str(bearing_fmu), {"bearing": "B7214C", "lubricant": "iso_vg68_mineral"})
    fmu.setReal([vr["F_z"], vr["omega"]], [800.0, 100.0])
    warnings = []
    for k, T in enumerate((313.15, 250.0, 250.0, 313.15, 250.0)):
        fmu.setReal([vr["T_oil"]], [T])
        host.messages.clear()
        assert host.step_status(fmu, 0.1 * k) == 0
        warnings.append(
            [m["message"] for m in host.messages if m["status"] == 1 and "temperature range" in m["message"]]
        )
    assert [len(w) for w in warnings] == [0, 1, 0, 0, 1]
    assert "T_oil = 250 K" in warnings[1][0] and "[273.15, 393.15] K" in warnings[1][0]
    fmu.terminate()
    fmu.freeInstance()


def test_race_control_from_traction_and_the_friction_a_hypothesis_assumes(bearing_fmu):
    """Bearing.fmu with the 40 deg 218 of the textbook cases and the Guessasma oil (limiting traction coefficient 0.06)
    under 8.9 kN at 8 000 rpm: race_control_mode = 0 (outer) outputs mu_required_outer = 0.0775 and logs one
    fmi2Warning naming it, the limit and race_control = 'traction' (none at the next step); race_control_mode = 3
    (traction) runs with mu_required 0, no such warning, a cage 8-9 % faster (docs/quasistatic.md, section 2), and an
    FMU state that repeats a step exactly (it carries the balls' kinematics)."""
    from tests.validation.test_shoulder_truncation import BEARING

    rpm = 8000.0 * math.pi / 30.0
    runs = {}
    for mode in (0, 3):
        host.messages.clear()
        parameters = {"bearing": str(BEARING), "lubricant": "guessasma_oil", "race_control_mode": mode}
        fmu, vr, _ = host.open_fmu(str(bearing_fmu), parameters)
        fmu.setReal([vr["F_z"], vr["omega"]], [8900.0, rpm])
        said = []
        for k in range(2):
            host.messages.clear()
            assert host.step_status(fmu, 0.1 * k) == 0
            said.append(
                [m["message"] for m in host.messages if m["status"] == 1 and "traction coefficient" in m["message"]]
            )
        names = ("omega_cage", "mu_required_inner", "mu_required_outer", "torque")
        runs[mode] = (dict(zip(names, fmu.getReal([vr[n] for n in names]))), said)
        if mode == 3:
            state = fmu.getFMUstate()
            before = fmu.getReal([vr["omega_cage"], vr["torque"], vr["z"]])
            fmu.setReal([vr["omega"]], [1.1 * rpm])
            assert host.step_status(fmu, 0.2) == 0
            fmu.setFMUstate(state)
            fmu.setReal([vr["omega"]], [rpm])
            assert host.step_status(fmu, 0.2) == 0
            assert fmu.getReal([vr["omega_cage"], vr["torque"], vr["z"]]) == before
            fmu.freeFMUstate(state)
        fmu.terminate()
        fmu.freeInstance()
    outer, traction = runs[0][0], runs[3][0]
    assert 0.077 < outer["mu_required_outer"] < 0.078 and outer["mu_required_inner"] == 0.0
    assert [len(w) for w in runs[0][1]] == [1, 0]
    assert "0.06" in runs[0][1][0][0] and "race_control = 'traction'" in runs[0][1][0][0]
    assert traction["mu_required_inner"] == traction["mu_required_outer"] == 0.0
    assert runs[3][1] == [[], []]
    assert 1.08 < traction["omega_cage"] / outer["omega_cage"] < 1.09


def test_what_the_lubrication_method_leaves_out_is_warned(bearing_fmu):
    """Bearing.fmu with the 6208, guessasma_oil (constant viscosity) and lubrication = oil_jet
    (docs/lubrication_method.md, section 4): the first step at speed logs two fmi2Warnings, no inlet shear heating
    (phi_ish = 1) and an inlet filled by the 20 um layer (phi_rs = 1); the next steps at speed none."""
    host.messages.clear()
    fmu, vr, _ = host.open_fmu(
        str(bearing_fmu), {"bearing": "6208", "lubricant": "guessasma_oil", "lubrication": "oil_jet"}
    )
    fmu.setReal([vr["F_y"], vr["omega"]], [3000.0, 1000.0])
    told = []
    for k in range(3):
        host.messages.clear()
        assert host.step_status(fmu, 0.1 * k) == 0
        told.append([m["message"] for m in host.messages if m["status"] == 1 and "lubrication = " in m["message"]])
    assert [len(t) for t in told] == [2, 0, 0]
    assert "whose viscosity is constant" in told[0][0] and "fills every loaded inlet" in told[0][1]
    fmu.terminate()
    fmu.freeInstance()
