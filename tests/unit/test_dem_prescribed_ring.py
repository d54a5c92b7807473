"""The DEM with the inner ring's motion prescribed (DemModel drive = "displacement", docs/dem.md, Prescribed ring):
its reaction loads against the load-driven DEM's loads and against its own stiffness, and its input checks.

The operating point: a 6208 under F_y = 2 kN, F_z = 300 N at 300 rad/s (the cage at about 119 rad/s, the ball pass
on the outer ring at about 170 Hz), 22 ms after a start from rest, the speed ramped over 4 ms."""

import math
from dataclasses import replace

import numpy as np
import pytest

from bearing_fmu.kernels.ball_dynamics import state as s
from bearing_fmu.models.dem import DemModel
from bearing_fmu.models.limits import InputError
from bearing_fmu.scene import Scene, SceneError

LOADS = {"F_x": 0.0, "F_y": 2000.0, "F_z": 300.0, "M_x": 0.0, "M_y": 0.0}
DOFS = ("x", "y", "z", "theta_x", "theta_y")
OMEGA = 300.0  # rad/s
CALL = 2e-3  # s
SETTLED = 22e-3  # s, the start-up's end: from here on the ring's motion is steady
WINDOW = 10  # calls averaged: 20 ms, 3.4 ball passes on the outer ring


def _start(model, **inputs):
    """From rest: 2 ms at rest, the speed ramped to OMEGA over 4 ms, held to SETTLED."""
    model.advance(CALL, omega=0.0, **inputs)
    model.advance(3 * CALL, omega=OMEGA, **inputs)
    t = 3 * CALL
    while t < SETTLED - 1e-12:
        t += CALL
        model.advance(t, omega=OMEGA, **inputs)


def load_driven_equilibrium():
    """The load-driven DEM's ring displacement (x, y, z in m, theta_x, theta_y in rad) under LOADS: its mean over the
    WINDOW calls after SETTLED (averaged state outputs: each call's mean over its steps)."""
    model = DemModel("6208", averaged_state=True)
    _start(model, **LOADS)
    means = []
    for k in range(WINDOW):
        model.advance(SETTLED + (k + 1) * CALL, omega=OMEGA, **LOADS)
        means.append(model.out[s.O_X : s.O_X + 5].copy())
    return np.mean(means, axis=0)


@pytest.fixture(scope="module")
def equilibrium():
    return load_driven_equilibrium()


@pytest.fixture(scope="module")
def held(equilibrium):
    """A prescribed-ring 6208 moved to the equilibrium displacement in its first call and held there to SETTLED."""
    model = DemModel("6208", drive="displacement")
    _start(model, **dict(zip(DOFS, equilibrium)))
    return model


def test_ring_held_at_the_equilibrium_gives_back_the_loads(equilibrium, held):
    """Held where the loads put the free ring, the ring needs those loads: the mean reaction over 20 ms equals F_x ...
    M_y within 10 N (0.5 % of |F|) and 0.05 N.m. Why these: the held ring's reaction changes from one 2 ms call to the
    next by the ball pass (standard deviation 11-19 N across the axis, 4 N along it, 0.06-0.1 N.m), and a mean over
    3.4 ball passes keeps about half of that; the free ring's mean displacement carries the same fluctuation (y: 5e-8
    m, times K[2,2] of 2.2e8 N/m: 10 N). Measured: errors of 2.0, -0.5, 1.0 N and 0.002, -0.013 N.m. Before the
    prescribed ring the model had no such mode (drive and x ... theta_y were refused)."""
    model = held
    reactions = []
    for k in range(WINDOW):
        out = model.advance(SETTLED + (k + 1) * CALL, omega=OMEGA, **dict(zip(DOFS, equilibrium)))
        reactions.append([out[name] for name in LOADS])
    error = np.mean(reactions, axis=0) - np.array(list(LOADS.values()))
    print("reaction - loads (N, N.m):", error)
    assert np.all(np.abs(error[:3]) < 10.0)
    assert np.all(np.abs(error[3:]) < 0.05)
    # the ring is where it was put, exactly (the path ends on the given values)
    ring = model.ring
    assert np.array_equal(np.concatenate((ring[s.R_X : s.R_X + 3], ring[s.R_TH : s.R_TH + 2])), equilibrium)


def _in_phase(model, centre, dof, amplitude, frequency, periods):
    """Move DOF `dof` by amplitude sin(2 pi f t) about `centre` (calls of 1/20 period, each ending on the sinusoid with
    its rate); returns the reactions' in-phase parts over the amplitude (a least-squares fit of each call's mean on
    1 and the means over the call of the sine and the cosine) and the mean of the model's K over the calls."""
    w = 2.0 * math.pi * frequency
    H = 1.0 / frequency / 20
    t0 = model.time
    rows, fits, stiffness = [], [], []
    for k in range(20 * periods):
        a, b = k * H, (k + 1) * H
        path = dict(zip(DOFS, centre))
        path[DOFS[dof]] = centre[dof] + amplitude * math.sin(w * b)
        path[DOFS[dof] + "_rate"] = amplitude * w * math.cos(w * b)
        out = model.advance(t0 + b, omega=OMEGA, **path)
        rows.append([out[name] for name in LOADS])
        fits.append([1.0, (math.cos(w * a) - math.cos(w * b)) / (w * H), (math.sin(w * b) - math.sin(w * a)) / (w * H)])
        stiffness.append(model.stiffness_matrix().copy())
    coefficients = np.linalg.lstsq(np.array(fits), np.array(rows), rcond=None)[0]
    return coefficients[1] / amplitude, np.mean(stiffness, axis=0)


def _held_reaction(centre, shift):
    """The mean reaction (F_x ... M_y) of a ring held at centre + shift, WINDOW calls after SETTLED."""
    model = DemModel("6208", drive="displacement")
    path = dict(zip(DOFS, centre + shift))
    _start(model, **path)
    reactions = []
    for k in range(WINDOW // 2):
        out = model.advance(SETTLED + (k + 1) * CALL, omega=OMEGA, **path)
        reactions.append([out[name] for name in LOADS])
    return np.mean(reactions, axis=0)


def test_in_phase_reaction_of_a_vibrating_ring_and_the_stiffness(equilibrium, held):
    """The ring vibrating along y by 0.5 um at 400 Hz (clear of the outer ring's ball pass, 170 Hz, its second
    harmonic, 340 Hz, and the inner ring's, 259 Hz) about the equilibrium, 16 periods: the in-phase part of the
    reaction over the amplitude is the DEM's dynamic stiffness column dF/dy. Entries are compared on the scale of
    K[2,2] (forces) and K[2,2] d_m/2 (moments).

    Against the static column, the central difference of the held ring's mean reaction at y +- 1 um: within 7 %.
    400 Hz is far below the contacts' resonances (kHz) and the balls' inertia adds m w^2 = 4e4 N/m per ball, so
    the two differ by the ball pass's modulation left in each: 18 N per 2 ms call in F_x over a 2 um difference
    (about 2 % of K[2,2] in the static column) and its leak into the fit. Measured: 4.9 % (F_x), 1.5 % (F_y, F_z),
    0.6 % (moments).

    Against the DEM's K output (kernels/ball_dynamics/stiffness.py): the off-diagonal entries agree within 3 %
    (measured 2.4 %, M_x), but the diagonal is 17 % above K[2,2] (2.56e8 vs 2.20e8 N/m; statically 2.59e8, and
    along z 15 % above K[3,3]): the DEM's balls carry the ring stiffer than K's condensation of each ball's two
    contacts in series, and not through the tangential springs (kt_ratio 0.1 leaves it at 17 %). The test holds
    that gap between 12 and 22 %, so that a change of either side shows (docs/dem.md, Prescribed ring)."""
    dynamic, K = _in_phase(held, equilibrium, 1, 0.5e-6, 400.0, 16)
    h = np.zeros(5)
    h[1] = 1e-6
    static = (_held_reaction(equilibrium, h) - _held_reaction(equilibrium, -h)) / 2e-6
    scale = K[1, 1] * np.array([1.0, 1.0, 1.0, 0.5 * held.bearing.dm, 0.5 * held.bearing.dm])
    print("dynamic dF/dy:", dynamic, "static:", static, "K[:, 1]:", K[:, 1])
    print("dynamic - static:", (dynamic - static) / scale, "dynamic - K:", (dynamic - K[:, 1]) / scale)
    assert np.all(np.abs(dynamic - static) < 0.07 * scale)
    off = np.array([0, 2, 3, 4])
    assert np.all(np.abs(dynamic[off] - K[off, 1]) < 0.03 * scale[off])
    assert 0.12 < dynamic[1] / K[1, 1] - 1.0 < 0.22


def test_prescribed_ring_inputs_are_checked():
    """Each refusal names the input, its value and the allowed range: a displacement beyond half the groove
    clearance A = (f_i + f_o - 1) D (0.5 x 0.48 mm on the 6208), a rate beyond that amplitude at 10 kHz, a load on a
    prescribed ring, a path input of a load-driven model, an unknown drive."""
    model = DemModel("6208", drive="displacement")
    bound = 0.5 * (model.bearing.f_i + model.bearing.f_o - 1.0) * model.bearing.D
    with pytest.raises(InputError, match=r"y = 0\.001 m is outside the allowed range \[-0\.000"):
        model.advance(1e-4, y=1e-3)
    with pytest.raises(InputError, match=r"z_rate = 100\.0 m/s is outside the allowed range"):
        model.advance(1e-4, z_rate=100.0)
    with pytest.raises(InputError, match=r"theta_x = 0\.02 rad is outside the allowed range \[-0\.01, 0\.01\] rad"):
        model.advance(1e-4, theta_x=0.02)
    with pytest.raises(InputError, match=r"F_y = 100\.0 is outside the allowed range \[0, 0\]"):
        model.advance(1e-4, F_y=100.0, y=1e-6)
    with pytest.raises(InputError, match=r"unknown input\(s\) \['w'\]"):
        model.advance(1e-4, w=1.0)
    assert model.time == 0.0  # nothing moved
    assert 20e-6 < bound
    model.advance(1e-4, y=20e-6)  # within the range (a load of about 2 kN): runs
    with pytest.raises(InputError, match=r"x = 1e-06 is an input of drive = 'displacement' only"):
        DemModel("6208").advance(1e-4, x=1e-6)
    with pytest.raises(InputError, match=r"drive = 'shaft' is not one of the allowed \['load', 'displacement'\]"):
        DemModel("6208", drive="shaft")


def test_dz_thermal_is_added_to_z():
    """dz_thermal (m) shifts the prescribed z at the call's end: advance(z=a, dz_thermal=b) gives what
    advance(z=a + b) gives, bit for bit (its rate is not added: z_rate is the same in both). It is refused outside
    |dz_thermal| <= 0.02 D naming it, and refused by a load-driven model. Before, advance() had no dz_thermal."""
    shifted, plain = DemModel("6208", drive="displacement"), DemModel("6208", drive="displacement")
    a, b = 2e-6, -6.75e-6  # m
    path = {"y": 12e-6, "z_rate": 1e-4}
    for k in range(3):
        t = (k + 1) * 2e-4
        by_shift = shifted.advance(t, omega=200.0, z=a, dz_thermal=b, **path)
        by_z = plain.advance(t, omega=200.0, z=a + b, **path)
    assert abs(by_z["F_z"]) > 1.0  # the shift loads the ring axially
    assert by_shift == by_z
    assert np.array_equal(shifted.ring, plain.ring)
    refused = r"dz_thermal = 0\.001 m is outside the allowed range \[-0\.000252, 0\.000252\] m \(\|value\| <= 0\.02 D\)"
    with pytest.raises(InputError, match=refused):
        shifted.advance(shifted.time + 2e-4, omega=200.0, z=a, dz_thermal=1e-3)
    with pytest.raises(InputError, match=r"dz_thermal = 1e-06 is an input of drive = 'displacement' only"):
        DemModel("6208").advance(1e-4, dz_thermal=1e-6)
    assert np.array_equal(shifted.ring, plain.ring)  # the refused call moved nothing


DISPLACEMENT_SCENE = Scene(name="dem_displacement", fidelity="dem", drive="displacement", stiffness=True)


def test_scene_drive_sets_the_variables():
    """The scene option drive = 'displacement' makes the DEM's FMU variables those of a prescribed ring: the inputs
    the ring's path (x ... theta_y and their rates, no loads), the outputs the reaction loads and every other output
    of the load-driven DEM but the ring's displacement (an input now). A drive the DEM has not is refused by the
    scene. Before the scene option the DEM's scene refused every drive but 'load'."""
    model = DemModel("6208", scene=DISPLACEMENT_SCENE)
    load_driven = DemModel("6208", scene=replace(DISPLACEMENT_SCENE, drive="load"))
    assert model.drive == "displacement" and model.displacement_driven
    names = [v.name for v in model.inputs]
    assert names == ["omega", *DOFS, *(f"{d}_rate" for d in DOFS), "T_oil", "dPd_thermal", "dz_thermal"]
    assert "dz_thermal" not in [v.name for v in load_driven.inputs]
    outputs = [v.name for v in model.outputs]
    assert outputs[:5] == list(LOADS)
    assert outputs[5:] == [v.name for v in load_driven.outputs if v.name not in DOFS]
    with pytest.raises(SceneError, match=r"drive = 'fixed_axial' is not a DEM drive"):
        replace(DISPLACEMENT_SCENE, drive="fixed_axial").validate()
    # a drive given to the model replaces the scene's
    assert DemModel("6208", scene=DISPLACEMENT_SCENE, drive="load").inputs == load_driven.inputs


def test_update_follows_the_path_as_advance_does():
    """update(), the FMU's step, takes the path in its inputs' order and gives what advance() gives with the same
    path, bit for bit; its reaction outputs are the model's reaction. Before, update() refused this drive."""
    path = {"x": 3e-6, "y": 12e-6, "z": 2e-6, "theta_x": 1e-5, "theta_y": -2e-5, "y_rate": 1e-3}
    by_advance = DemModel("6208", scene=DISPLACEMENT_SCENE)
    by_update = DemModel("6208", scene=DISPLACEMENT_SCENE)
    u = [path.get(v.name, 0.0) for v in by_update.inputs]
    u[0], u[-3] = 200.0, 323.15  # omega, T_oil
    for _ in range(3):
        expected = by_advance.advance(by_advance.time + 2e-4, omega=200.0, T_oil=323.15, **path)
        values = by_update.update(u, 2e-4)
    got = dict(zip(by_update.output_names, values.tolist()))
    assert abs(expected["F_y"]) > 100.0  # the ring is pressed into the balls
    shared = [name for name in by_update.output_names if name in expected]
    assert set(LOADS) <= set(shared) and "torque" in shared
    for name in shared:
        assert got[name] == expected[name], name
    assert np.array_equal(by_update.ring, by_advance.ring)


def test_update_refuses_a_path_input_out_of_range():
    """A refused input of the prescribed ring's update() names the input, its value and its range, with or without a
    step, and changes nothing."""
    model = DemModel("6208", scene=DISPLACEMENT_SCENE)
    u = [0.0] * len(model.inputs)
    u[-3] = 313.15  # T_oil
    u[2] = 1e-3  # y
    for interval in (0.0, 1e-4):
        with pytest.raises(InputError, match=r"y = 0\.001 m is outside the allowed range \[-0\.000252, 0\.000252\]"):
            model.update(u, interval)
    u[2], u[9] = 0.0, 1e3  # theta_x_rate
    with pytest.raises(InputError, match=r"theta_x_rate = 1000\.0 rad/s is outside the allowed range"):
        model.update(u, 1e-4)
    assert model.time == 0.0


def test_prescribed_ring_has_no_support():
    """The prescribed ring's support is the caller's shaft model: the support settings are 0 and a non-zero one is
    refused naming it (the FMU has no such parameters: scene drive 'displacement'). Before, they were taken and
    moved nothing."""
    model = DemModel("6208", drive="displacement")
    assert all(model.settings[name] == 0.0 for name in model.settings if name.startswith("support_"))
    assert model.par[s.P_C_SUPPORT] == 0.0
    with pytest.raises(InputError, match=r"support_damping = 500\.0 N\.s/m is outside the allowed range \[0, 0\]"):
        DemModel("6208", drive="displacement", support_damping=500.0)
    DemModel("6208", drive="displacement", support_damping=0.0)  # 0: what it is anyway
