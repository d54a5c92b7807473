"""BearingDEMDisp.fmu, the DEM scene with the inner ring's motion prescribed (scene drive = 'displacement',
docs/dem.md, Prescribed ring): a shaft model drives it.

- fmpy.validate_fmu finds no problem; its inputs are the ring's path (x ... theta_y and their rates, the names of
  BearingDisp.fmu's inputs) beside the speed, oil temperature and clearance change; its outputs the reaction loads
  F_x ... M_y and every output of BearingDEM.fmu but the ring's displacement; no support parameters;
- held through FMI at the displacement the load-driven DEM reaches under a load, the ring's reaction gives the load
  back (the model's test, tests/unit/test_dem_prescribed_ring.py), and equals the Python model's bit for bit;
- dz_thermal is added to z (the Python model with z shifted, bit for bit);
- a refused input names the variable, its value and its range (fmi2Discard), and the instance steps on once it is
  corrected.
"""

import math

import numpy as np
from fmpy import read_model_description
from fmpy.validation import validate_fmu

from bearing_fmu.build import SCENES_DIR
from bearing_fmu.fmu import BearingDEM
from bearing_fmu.models.dem import DemModel
from bearing_fmu.models.dem_settings import DEM_SETTINGS
from bearing_fmu.scene import Scene
from tests.fmu import probe
from tests.unit.test_dem_prescribed_ring import CALL, DOFS, LOADS, OMEGA, SETTLED, WINDOW, load_driven_equilibrium

RATES = tuple(f"{name}_rate" for name in DOFS)
H = 0.5e-3  # s, communication step of the refusal cases


def scene():
    return Scene.from_toml(SCENES_DIR / "dem_displacement.toml")


def test_validate_and_variables(dem_disp_fmu):
    assert validate_fmu(str(dem_disp_fmu)) == []
    md = read_model_description(str(dem_disp_fmu))
    by_causality = {}
    for v in md.modelVariables:
        by_causality.setdefault(v.causality, {})[v.name] = v
    assert set(by_causality["input"]) == {"omega", *DOFS, *RATES, "T_oil", "dPd_thermal", "dz_thermal"}
    units = {name: v.declaredType.unit if v.declaredType else v.unit for name, v in by_causality["input"].items()}
    assert [units[name] for name in DOFS] == ["m", "m", "m", "rad", "rad"]
    assert [units[name] for name in RATES] == ["m/s", "m/s", "m/s", "rad/s", "rad/s"]
    assert units["dz_thermal"] == "m"
    # its own wording: no integrated ring, no x ... theta_y outputs to average
    assert md.description == BearingDEM.DESCRIPTIONS["displacement"] != BearingDEM.description
    assert "moved along the master's path" in md.description
    averaged = by_causality["parameter"]["average_state_outputs"].description
    assert "theta_y are means" not in averaged and "reaction loads F_x ... M_y" in averaged
    outputs = set(by_causality["output"])
    load_driven = DemModel("6208", scene=Scene.from_toml(SCENES_DIR / "dem.toml"))
    assert outputs == set(LOADS) | {v.name for v in load_driven.outputs if v.name not in DOFS}
    support = {setting.name for setting in DEM_SETTINGS if setting.name.startswith("support_")}
    assert support and not support & set(by_causality["parameter"])
    assert "traction_limit" in by_causality["parameter"]


def _hold(fmu, vr, position, steps):
    """Step the instance along `steps` ((t, h, omega) each) with the ring held at `position` (rates 0); returns the
    reactions (F_x ... M_y) after each step."""
    fmu.setReal([vr[name] for name in (*DOFS, *RATES)], [*position, 0.0, 0.0, 0.0, 0.0, 0.0])
    reactions = []
    for t, h, omega in steps:
        fmu.setReal([vr["omega"]], [omega])
        assert probe.step_status(fmu, t, h) == 0
        reactions.append(fmu.getReal([vr[name] for name in LOADS]))
    return np.array(reactions)


def test_ring_held_at_the_equilibrium_gives_back_the_loads(dem_disp_fmu):
    """The ring held through FMI where the load-driven DEM's ring settles under F_y = 2 kN, F_z = 300 N (6208, 300
    rad/s; the model test's start-up: 2 ms at rest, the speed ramped over one 4 ms step, steps of 2 ms): the mean
    reaction over the 10 steps after 22 ms gives the loads back within 10 N and 0.05 N.m (the tolerance and its
    reasons in the model test), and every reaction equals the Python model's (DemModel.update, the same steps) bit
    for bit. Before this FMU a master could not prescribe a DEM ring."""
    position = load_driven_equilibrium()
    steps = [(0.0, CALL, 0.0), (CALL, 2 * CALL, OMEGA)]
    steps += [(t, CALL, OMEGA) for t in np.arange(3 * CALL, SETTLED + WINDOW * CALL - 1e-9, CALL)]
    fmu, vr, _ = probe.open_fmu(str(dem_disp_fmu))
    reactions = _hold(fmu, vr, position, steps)
    fmu.terminate()
    fmu.freeInstance()
    error = reactions[-WINDOW:].mean(axis=0) - np.array(list(LOADS.values()))
    print("reaction - loads (N, N.m):", error)
    assert np.all(np.abs(error[:3]) < 10.0)
    assert np.all(np.abs(error[3:]) < 0.05)
    model = DemModel("6208", scene=scene())
    u = dict.fromkeys(v.name for v in model.inputs)
    u |= (
        dict(zip(DOFS, position)) | dict.fromkeys(RATES, 0.0) | {"T_oil": 313.15, "dPd_thermal": 0.0, "dz_thermal": 0.0}
    )
    slots = [model.output_names.index(name) for name in LOADS]
    for (_, h, omega), got in zip(steps, reactions):
        u["omega"] = omega
        assert np.array_equal(model.update(list(u.values()), h)[slots], got)


def test_bad_inputs_are_refused_naming_the_variable_and_the_instance_recovers(dem_disp_fmu):
    """A displacement beyond half the groove clearance, a NaN rate, a tilt beyond 0.01 rad and a speed beyond the
    d_m n limit: each step returns fmi2Discard with a message naming the variable, its value and its range, the
    outputs keep their last values; corrected, the step goes through."""
    probe.messages.clear()
    fmu, vr, _ = probe.open_fmu(str(dem_disp_fmu))
    fmu.setReal([vr["omega"], vr["y"]], [100.0, 5e-6])
    assert probe.step_status(fmu, 0.0, H) == 0
    names = [v.name for v in read_model_description(str(dem_disp_fmu)).modelVariables if v.causality == "output"]
    reals = [name for name in names if name not in ("regime", "n_loaded", "monitor_status")]
    good = fmu.getReal([vr[name] for name in reals])
    cases = (("y", 1e-3, "y = 0.001 m"), ("z_rate", math.nan, "z_rate = nan m/s"))
    cases += (("theta_x", 0.02, "theta_x = 0.02 rad"), ("omega", 1e5, "omega = 100000.0 rad/s"))
    cases += (("dz_thermal", 1e-3, "dz_thermal = 0.001 m"),)
    for k, (name, bad, text) in enumerate(cases):
        fmu.setReal([vr["omega"], vr["y"], vr["z_rate"], vr["theta_x"], vr["dz_thermal"]], [100.0, 5e-6, 0.0, 0.0, 0.0])
        fmu.setReal([vr[name]], [bad])
        # fmi2Discard; the runtime turns a second refusal of the same (t, h) into fmi2Error: each case its own t
        assert probe.step_status(fmu, H + k * 1e-6, H) == 2, name
        assert fmu.getReal([vr[name] for name in reals]) == good
        messages = [m["message"] for m in probe.messages if m["status"] >= 2]
        assert any(text in m and "allowed range" in m for m in messages), (text, messages)
    fmu.setReal([vr["omega"], vr["y"], vr["z_rate"], vr["theta_x"], vr["dz_thermal"]], [100.0, 5e-6, 0.0, 0.0, 0.0])
    assert probe.step_status(fmu, H, H) == 0
    assert fmu.getReal([vr["F_y"]])[0] > 0.0  # the ring pressed along +y: the balls push back, the holding load +y
    fmu.terminate()
    fmu.freeInstance()


def test_dz_thermal_shifts_z(dem_disp_fmu):
    """dz_thermal (m) is added to the prescribed z at each step's end: the FMU with z = a, dz_thermal = b gives the
    reactions of the Python model with z = a + b, bit for bit, and an axial reaction. Before, the FMU had no such
    input (a shaft model's seat motion, which starts from 0, could not be given the ring's axial preload position)."""
    a, b = 2e-6, -6e-6  # m
    fmu, vr, _ = probe.open_fmu(str(dem_disp_fmu))
    fmu.setReal([vr["y"], vr["z"], vr["dz_thermal"]], [5e-6, a, b])
    model = DemModel("6208", scene=scene())
    u = dict.fromkeys((v.name for v in model.inputs), 0.0) | {"y": 5e-6, "z": a + b, "T_oil": 313.15}
    slots = [model.output_names.index(name) for name in LOADS]
    for k in range(3):
        fmu.setReal([vr["omega"]], [100.0])
        assert probe.step_status(fmu, k * H, H) == 0
        got = fmu.getReal([vr[name] for name in LOADS])
        u["omega"] = 100.0
        assert np.array_equal(model.update(list(u.values()), H)[slots], got)
    assert abs(got[2]) > 1.0  # F_z: the shift presses the ring axially into the balls
    fmu.terminate()
    fmu.freeInstance()
