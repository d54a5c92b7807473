"""BearingDEM.fmu, the DEM (ball dynamics) scene (docs/dem.md).

- fmpy.validate_fmu finds no problem; the inputs and outputs shared with Bearing.fmu have its names
  and units;
- the 6208 at 500 rad/s, 3 kN through the FMU: cage speed, film parameter and the stiffness against the
  quasi-static fidelity;
- a hand-written FMU2Slave loop over a speed ramp and a load step equals the Python DemModel bit for
  bit: one doStep is one DemModel.update (one advance over the communication step), with the power outputs
  and the capacitance averaged over the step or taken at its end (parameter average_outputs);
- FMU state: get -> step -> set -> step is bit-identical, and a serialised state restored into a new
  instance steps bit-identically (every DEM array travels in the state);
- bad inputs (NaN load, speed beyond the d_m n limit), a bad parameter and a time step the monitor
  flags give a logged message naming the cause and its range, fmi2Discard/fmi2Error, finite outputs,
  and the instance recovers.
"""

import math
from pathlib import Path

import numpy as np
import pytest
from fmpy import read_model_description
from fmpy.validation import validate_fmu

from bearing_fmu.build import SCENES_DIR
from bearing_fmu.kernels.ball_dynamics import state as s
from bearing_fmu.kernels.ball_dynamics.state import (
    ST_CODE,
    STATUS_DAMPING,
    STATUS_ENERGY,
    STATUS_NOT_FINITE,
    STATUS_OK,
    STATUS_PENETRATION,
    STATUS_WHIRL,
)
from bearing_fmu.kernels.ehl import friction_coefficient
from bearing_fmu.models.dem import DemModel, DemUnstableError
from bearing_fmu.models.quasi_static import QuasiStaticModel
from bearing_fmu.scene import Scene
from tests.conftest import _fmu
from tests.fmu import probe
from tests.fmu.harness import opened
from tests.fmu.harness import read_outputs as read_values

H = 0.5e-3  # s, communication step of the scripted sequences
INTEGER_OUTPUTS = ("regime", "n_loaded", "monitor_status")
# speed ramp 0 -> 500 rad/s over 3 ms at 3 kN, then a load step to 4 kN and a lateral load (omega, F_x, F_y)
SCRIPT = [(500.0 * min(1.0, (n + 1) / 6), 3000.0 if n < 8 else 4000.0, 0.0 if n < 8 else -500.0) for n in range(11)]


@pytest.fixture(scope="module")
def dem_fmu():
    return _fmu("BearingDEM", "dem.toml")


def dem_scene():
    return Scene.from_toml(SCENES_DIR / "dem.toml")


def output_names(path):
    return [v.name for v in read_model_description(str(path)).modelVariables if v.causality == "output"]


def read_outputs(fmu, vr, names):
    return read_values(fmu, vr, names, INTEGER_OUTPUTS)


def set_inputs(fmu, vr, omega, F_x, F_y=0.0):
    fmu.setReal([vr["omega"], vr["F_x"], vr["F_y"], vr["T_oil"]], [omega, F_x, F_y, 313.15])


def test_validate_and_variables(dem_fmu):
    assert validate_fmu(str(dem_fmu)) == []
    md = read_model_description(str(dem_fmu))
    assert md.coSimulation.canGetAndSetFMUstate and md.coSimulation.canSerializeFMUstate
    by_name = {v.name: v for v in md.modelVariables}
    inputs = {n for n, v in by_name.items() if v.causality == "input"}
    outputs = {n for n, v in by_name.items() if v.causality == "output"}
    parameters = {n for n, v in by_name.items() if v.causality == "parameter"}
    assert inputs == {"omega", "F_x", "F_y", "F_z", "M_x", "M_y", "T_oil", "dPd_thermal"}
    shared = {"x", "y", "z", "theta_x", "theta_y", "torque", "P_loss", "Q_inner_ring", "Q_outer_ring"}
    shared |= {"Lambda_inner", "Lambda_outer"}
    shared |= {"h_min_inner", "h_min_outer", "regime", "C_bearing", "Q_max_inner", "Q_max_outer", "p_max"}
    shared |= {
        "alpha_inner",
        "alpha_outer",
        "truncation_inner",
        "truncation_outer",
        "omega_cage",
        "omega_ball",
        "n_loaded",
    }
    shared |= {"omega_ball_cage", "FTF", "BPFO", "BPFI", "BSF", "h_c_inner", "h_c_outer"}
    shared |= {f"K[{i},{j}]" for i in range(1, 6) for j in range(1, 6)}
    assert outputs == shared | {"cage_slip", "SRR_max", "monitor_status"}
    assert {name for name in parameters if "." not in name} == {
        "bearing",
        "lubricant",
        "Pd_from_file",
        "Pd",
        "dt",
        "refresh_interval",
        "traction_limit",
        "average_outputs",
        "average_state_outputs",
        "support_stiffness",
        "support_damping",
        "support_axial_damping",
        "support_mass",
        "bearing_from_file",
        "lubricant_from_file",
    }
    # the numeric bearing and lubricant (docs/parameters.md, numeric parameters)
    assert {name.split(".")[0] for name in parameters if "." in name} == {"bearing_data", "lubricant_data"}
    quasi_static = {v.name: v for v in read_model_description(str(_fmu("Bearing", "quasi_static.toml"))).modelVariables}
    for name in shared | inputs:
        assert (by_name[name].unit, by_name[name].type) == (quasi_static[name].unit, quasi_static[name].type), name
    assert by_name["dt"].unit == "s" and by_name["refresh_interval"].unit == "s"
    axial = by_name["support_axial_damping"]  # the ring's axial damper: none by default, the range of the others'
    assert axial.unit == "N.s/m" and [float(v) for v in (axial.start, axial.min, axial.max)] == [0.0, 0.0, 1e6]
    for name in ("M_x", "M_y"):  # the same input as Bearing.fmu's
        assert by_name[name].description == quasi_static[name].description, name


def test_moments_tilt_the_ring_as_the_python_model(dem_fmu):
    """M_x, M_y set through the FMU reach the ring: theta_x, theta_y (and every other output) equal DemModel's bit for
    bit over a few steps of a 6208 under 3 kN radial, 20 N.m about x and -10 N.m about y, and the ring tilts with
    the moments' signs (a positive M_x lifts the +y side: theta_x > 0)."""
    model = DemModel(scene=dem_scene())
    names = output_names(dem_fmu)
    with opened(dem_fmu, "moments") as (fmu, vr):
        for n in range(4):
            omega = 50.0 * n
            fmu.setReal([vr[k] for k in ("omega", "F_y", "M_x", "M_y", "T_oil")], [omega, 3000.0, 20.0, -10.0, 313.15])
            fmu.doStep(n * H, H)
            got = read_outputs(fmu, vr, names)
            ref = model.evaluate(model.time + H, omega=omega, F_y=3000.0, M_x=20.0, M_y=-10.0)
            assert got == ref, n
    assert ref["theta_x"] > 1e-5 and ref["theta_y"] < -1e-6


@pytest.mark.parametrize("averaged, averaged_state", [(True, False), (False, False), (True, True)])
def test_fmu_equals_python_model_over_ramp_and_load_step(dem_fmu, averaged, averaged_state):
    """Every output after every step equals DemModel.evaluate at the same inputs, to the bit, with the power
    outputs and the capacitance averaged over the step (default) or taken at its end (average_outputs false), and
    with the loads, films and displacements averaged too (average_state_outputs)."""
    model = DemModel(scene=dem_scene(), averaged=averaged, averaged_state=averaged_state)
    names = output_names(dem_fmu)
    parameters = {"average_outputs": averaged, "average_state_outputs": averaged_state}
    with opened(dem_fmu, "loop", parameters) as (fmu, vr):
        for n, (omega, F_x, F_y) in enumerate(SCRIPT):
            set_inputs(fmu, vr, omega, F_x, F_y)
            fmu.doStep(n * H, H)
            got = read_outputs(fmu, vr, names)
            ref = model.evaluate(model.time + H, omega=omega, F_x=F_x, F_y=F_y)  # the FMU's step: H from its time
            assert got == ref, n
    assert ref["omega_cage"] > 100.0 and ref["Q_max_outer"] > 1000.0 and ref["torque"] > 0.0


def test_6208_at_500_rad_s_cage_film_and_stiffness(dem_fmu):
    """The protocol of tests/validation/test_dem_6208.py in 1 ms communication steps (2 ms at rest under
    3 kN, ramp to 500 rad/s over 5 ms, steady to 30 ms, means over 30-40 ms): omega_cage within 1 % of the
    pure-rolling 198.0 rad/s and Lambda_outer in 2.05-2.25 (Guessasma & Machado 2018, section 3.1; the
    tolerances of that test). The diagonal of K within 10 % of the quasi-static K (outer race control) at
    the same point: both are tangent stiffnesses of the same Hertz contacts with the balls condensed; the
    DEM's changes with the balls' positions (K[2,2], across the load, by about 20 % between a ball on the
    load line, the quasi-static configuration, and half a pitch from it; docs/dem.md), the mean over
    10 ms covers three ball pitches."""
    schedule = [(0.0, 3000.0)] * 2 + [(100.0 * k, 3000.0) for k in range(1, 6)] + [(500.0, 3000.0)] * 33
    names = output_names(dem_fmu)
    rows = []
    with opened(dem_fmu, "6208") as (fmu, vr):
        for n, (omega, F_x) in enumerate(schedule):
            set_inputs(fmu, vr, omega, F_x)
            fmu.doStep(n * 1e-3, 1e-3)
            rows.append(read_outputs(fmu, vr, names))
    mean = {name: sum(r[name] for r in rows[30:]) / 10 for name in names}
    assert mean["omega_cage"] == pytest.approx(198.0, rel=0.01)
    assert 2.05 < mean["Lambda_outer"] < 2.25
    scene = Scene(name="qs", fidelity="quasi_static", stiffness=True, gyroscopic=True)  # the DEM has both effects
    qs = QuasiStaticModel("6208", "guessasma_oil", scene=scene)
    ref = qs.evaluate(omega=500.0, F_x=3000.0)
    for i in range(1, 6):
        assert mean[f"K[{i},{i}]"] == pytest.approx(ref[f"K[{i},{i}]"], rel=0.10), i


def test_state_round_trip_and_serialisation_are_bit_identical(dem_fmu):
    names = output_names(dem_fmu)
    with opened(dem_fmu, "state") as (fmu, vr):
        for n, (omega, F_x, F_y) in enumerate(SCRIPT[:4]):
            set_inputs(fmu, vr, omega, F_x, F_y)
            fmu.doStep(n * H, H)
        state = fmu.getFMUstate()
        blob = fmu.serializeFMUstate(state)
        set_inputs(fmu, vr, 450.0, 3500.0, 200.0)
        fmu.doStep(4 * H, H)
        after = read_outputs(fmu, vr, names)
        set_inputs(fmu, vr, 100.0, 500.0)
        fmu.doStep(5 * H, H)  # a different history, to be undone
        fmu.setFMUstate(state)
        set_inputs(fmu, vr, 450.0, 3500.0, 200.0)
        fmu.doStep(4 * H, H)
        assert read_outputs(fmu, vr, names) == after
        fmu.freeFMUstate(state)
    with opened(dem_fmu, "restored") as (fresh, vr):
        fresh.setFMUstate(fresh.deSerializeFMUstate(blob))
        set_inputs(fresh, vr, 450.0, 3500.0, 200.0)
        fresh.doStep(4 * H, H)
        assert read_outputs(fresh, vr, names) == after


def step_status(fmu, t, h):
    return probe.step_status(fmu, t, h)


def error_messages():
    return [m["message"] for m in probe.messages if m["status"] >= 2]


def test_bad_inputs_are_refused_with_their_range_and_the_instance_recovers(dem_fmu):
    probe.messages.clear()
    fmu, vr, _ = probe.open_fmu(str(dem_fmu))
    set_inputs(fmu, vr, 100.0, 3000.0)
    assert step_status(fmu, 0.0, H) == 0
    good = read_outputs(fmu, vr, output_names(dem_fmu))
    cases = (("F_x", math.nan), ("F_z", math.inf), ("omega", 1e5), ("T_oil", 0.0), ("dPd_thermal", 1.0))
    for k, (name, bad) in enumerate(cases):
        set_inputs(fmu, vr, 100.0, 3000.0)
        fmu.setReal([vr["F_z"], vr["dPd_thermal"]], [0.0, 0.0])
        fmu.setReal([vr[name]], [bad])
        # fmi2Discard; the runtime turns a second refusal of the same (t, h) into fmi2Error, so each case its own t
        assert step_status(fmu, H + k * 1e-6, H) == 2, name
        assert read_outputs(fmu, vr, output_names(dem_fmu)) == good  # last valid values, all finite
    texts = error_messages()
    assert any("F_x = nan N" in t and "allowed range" in t for t in texts)
    assert any("F_z = inf N" in t for t in texts)
    assert any("omega = 100000.0" in t and "allowed range" in t for t in texts)
    assert any("T_oil = 0.0 K" in t for t in texts)
    assert any("dPd_thermal = 1.0 m" in t for t in texts)
    set_inputs(fmu, vr, 100.0, 3000.0)
    fmu.setReal([vr["F_z"], vr["dPd_thermal"]], [0.0, 0.0])
    assert step_status(fmu, H, H) == 0  # corrected input: the step goes through
    fmu.terminate()
    fmu.freeInstance()


def test_bad_input_at_initialisation_is_a_warning_and_the_first_step_refuses_it(dem_fmu):
    """F_x = NaN set in initialisation mode: fmi2ExitInitializationMode succeeds with one fmi2Warning naming the
    input, its value and range (as the other bearing FMUs), the first doStep refuses it (fmi2Discard) and, with
    the input corrected, the step goes through."""
    probe.messages.clear()
    probe.init_statuses.clear()
    fmu, vr, _ = probe.open_fmu(str(dem_fmu), {"F_x": math.nan})
    assert probe.init_statuses == [0]  # fmpy raises above fmi2Warning only
    warnings = [m["message"] for m in probe.messages if m["status"] == 1]
    assert any("F_x = nan N" in t and "allowed range" in t and "first doStep" in t for t in warnings), warnings
    assert step_status(fmu, 0.0, H) == 2
    set_inputs(fmu, vr, 100.0, 3000.0)
    assert step_status(fmu, 0.0, H) == 0
    fmu.terminate()
    fmu.freeInstance()


def test_bad_parameter_fails_initialisation_with_its_range(dem_fmu):
    probe.messages.clear()
    probe.init_statuses.clear()
    fmu, vr, _ = probe.open_fmu(str(dem_fmu), {"dt": -1e-6})
    assert probe.init_statuses == [3]  # fmi2Error
    assert any("dt = -1e-06 s is outside the allowed range [0, 1e-05] s" in t for t in error_messages())
    assert step_status(fmu, 0.0, H) == 3  # the error state: no step until fmi2Reset
    fmu.freeInstance()


def test_traction_limit_parameter_reaches_the_model_and_is_range_checked(dem_fmu):
    """traction_limit = 0.05 through the FMU gives the outputs of DemModel(traction_limit=0.05) bit for bit (a 6208
    start-up into its mixed film, where the limit changes the balls' Coulomb limit); 0.2 fails initialisation
    with the parameter's range."""
    model = DemModel(scene=dem_scene(), traction_limit=0.05)
    names = output_names(dem_fmu)
    with opened(dem_fmu, "traction", {"traction_limit": 0.05}) as (fmu, vr):
        for n in range(6):
            set_inputs(fmu, vr, 100.0 * n, 3000.0)
            fmu.doStep(n * H, H)
            got = read_outputs(fmu, vr, names)
            ref = model.evaluate(model.time + H, omega=100.0 * n, F_x=3000.0)
            assert got == ref, n
    assert (model.trib[s.T_MU] != [[friction_coefficient(x) for x in row] for row in model.trib[s.T_LAMBDA]]).any()
    probe.messages.clear()
    probe.init_statuses.clear()
    fmu, vr, _ = probe.open_fmu(str(dem_fmu), {"traction_limit": 0.2})
    assert probe.init_statuses == [3]  # fmi2Error
    assert any("traction_limit = 0.2" in t and "allowed range" in t for t in error_messages())
    fmu.freeInstance()


def test_time_step_the_monitor_flags_is_discarded_and_rolled_back(dem_fmu):
    """dt = 10 us is beyond the stability limit at 3 kN (about 6 us, docs/dem.md): the monitor stops the
    step (here a penetration beyond the material limit at the 7th step; with a larger step the boundary film's
    hysteretic damping 1.5 alpha_e Q already gives (c_i + c_o) dt / m above 0.35 at the most loaded ball, status 5);
    the FMU returns fmi2Discard with the monitor's message, names the cause in monitor_status and
    keeps its last valid outputs."""
    probe.messages.clear()
    fmu, vr, _ = probe.open_fmu(str(dem_fmu), {"dt": 10e-6})
    set_inputs(fmu, vr, 0.0, 3000.0)
    assert step_status(fmu, 0.0, 5e-3) == 2
    code = fmu.getInteger([vr["monitor_status"]])[0]
    assert code in (STATUS_NOT_FINITE, STATUS_PENETRATION, STATUS_ENERGY, STATUS_DAMPING)
    assert any("DEM stopped at" in t and "use dt <=" in t for t in error_messages())
    assert all(math.isfinite(v) for v in fmu.getReal([vr["x"], vr["torque"], vr["Q_max_outer"]]))
    fmu.freeInstance()


def test_iso_76_warning_is_logged_and_a_load_release_steps_on(dem_fmu):
    """6208 at rest: 30 kN gives p_max = 4.66 GPa, above the ISO 76 static limit 4.2 GPa: the step succeeds and
    the FMU logs the model's warning as fmi2Warning (as Bearing.fmu). Then 300 N held for one step and released
    to 0 N: the released elastic energy is physical motion, every step succeeds (it used to stop with "energy
    growth" and a limit of "inf s")."""
    probe.messages.clear()
    fmu, vr, _ = probe.open_fmu(str(dem_fmu))
    set_inputs(fmu, vr, 0.0, 30000.0)
    for k in range(6):
        assert step_status(fmu, k * H, H) == 0
    assert 4.2e9 < fmu.getReal([vr["p_max"]])[0] < 6e9
    assert any(m["status"] == 1 and "ISO 76" in m["message"] for m in probe.messages)
    fmu.freeInstance()
    probe.messages.clear()
    fmu, vr, _ = probe.open_fmu(str(dem_fmu))
    for k in range(12):
        set_inputs(fmu, vr, 0.0, 300.0 if k < 2 else 0.0)
        assert step_status(fmu, k * H, H) == 0, k
        assert fmu.getInteger([vr["monitor_status"]])[0] == STATUS_OK
    assert not any("inf s" in m["message"] for m in probe.messages)
    fmu.freeInstance()


def test_monitor_stop_restores_the_state_at_the_start_of_the_step():
    """DemModel.update (the FMU's step) puts every array back when the monitor stops the step, so the
    instance stays at the last communication point (as after a refused input)."""
    model = DemModel(scene=dem_scene(), dt=10e-6)
    before = model.get_state()
    with pytest.raises(DemUnstableError):
        model.update([0.0, 3000.0, 0.0, 0.0, 0.0, 0.0, 313.15, 0.0], 5e-3)  # self.inputs order
    assert model.status[ST_CODE] != STATUS_OK
    after = model.get_state()
    assert after["omega"] == before["omega"] and model.time == 0.0
    for name in DemModel.STATE_ARRAYS:
        assert (after[name] == before[name]).all(), name


def test_master_rollback_with_dem_equals_a_plain_run_on_the_accepted_grid(dem_fmu):
    """The master's step rejection with a DEM instance: at H = 1 ms the inner ring's first approach under
    3 kN (from rest to about 25 um, overshooting to 35 um) changes x by more than max_change = 20 um, so the
    first step is rejected,
    the DEM state restored (setFMUstate) and the step redone in halves. The run equals a plain run stepping the
    accepted sub-steps bit for bit: a rejected attempt leaves no trace in the DEM state."""
    from spindle.cosim.master import run as run_master
    from tests.cosim.test_master import GridMaster, replay, spec_of

    def doc(**extra):
        return {
            "run": {"stop": 6e-3, "step": 1e-3, "record": ["dem.omega_cage", "dem.x", "dem.torque"], **extra},
            "fmus": {"dem": str(dem_fmu)},
            "instances": {"dem": {"fmu": "dem", "inputs": {"omega": 300.0, "F_x": 3000.0}}},
            "connections": [],
        }

    spec = spec_of(doc(rollback=True, max_change={"dem.x": 20e-6}, max_halvings=8))
    with GridMaster(spec) as master:
        result = master.run()
        grid = master.accepted_grid()
    assert result.status == "ok" and result.rejected_steps > 0
    assert min(h for _, h in grid) < 1e-3
    print(f"rejected {result.rejected_steps}, accepted steps (ms): {[round(h * 1e3, 4) for _, h in grid]}")
    plain, _ = replay(spec_of(doc()), grid)
    for name in ("dem.omega_cage", "dem.x", "dem.torque"):
        assert np.array_equal(result.columns[name], plain[name]), name
    assert run_master(spec_of(doc())).status == "ok"


def test_a_whirling_ring_is_reported_through_the_fmu(dem_fmu):
    """The 218 (40 deg) under 8.9 kN thrust at 12 000 rpm on support_damping = 300 N.s/m, kicked radially by 2 % of
    the thrust for 2 ms (tests/validation/test_dem_ring_whirl.py): its ring whirls (about 115 um at 820-830 Hz). Every
    step succeeds (the run is stable; the outputs are those of the whirling ring), monitor_status turns 6 and the
    importer receives one fmi2Warning (status 1) naming the orbit, its frequency and support_damping. With the
    default support the same run reports 0 throughout and no such warning."""
    bearing = str(Path(__file__).parents[1] / "validation" / "data" / "angular_218_textbook.toml")
    omega = 12000.0 * math.pi / 30.0

    def run(parameters):
        probe.messages.clear()
        fmu, vr, _ = probe.open_fmu(str(dem_fmu), {"bearing": bearing, "lubricant": "iso_vg68_mineral", **parameters})
        steps = [(0.01, 0.0)] * 10 + [(0.002, 0.02 * 8900.0)] + [(0.01, 0.0)] * 20  # (H, F_x)
        t, codes = 0.0, []
        for h, F_x in steps:
            fmu.setReal([vr["omega"], vr["F_x"], vr["F_z"], vr["T_oil"]], [omega, F_x, 8900.0, 313.15])
            assert step_status(fmu, t, h) == 0
            t += h
            codes.append(fmu.getInteger([vr["monitor_status"]])[0])
        fmu.freeInstance()
        return codes, [m for m in probe.messages if "whirls" in m["message"]]

    codes, warnings = run({"support_damping": 300.0})
    assert codes[-10:] == [STATUS_WHIRL] * 10
    assert len(warnings) == 1 and warnings[0]["status"] == 1
    assert "support_damping = 300 N.s/m" in warnings[0]["message"] and " Hz" in warnings[0]["message"]
    codes, warnings = run({})
    assert codes == [STATUS_OK] * len(codes) and warnings == []
