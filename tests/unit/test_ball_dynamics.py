"""kernels.ball_dynamics against its twin tests/reference/ref_ball_dynamics_integrator.py, plus contact-geometry checks.

Kernel vs twin: both start from one state taken in the middle of a start-up of the 6208 of Guessasma & Machado (2018)
(3 kN radial, speed ramping through 300 rad/s, so springs are loaded, some contacts slip, the
films are in the mixed regime) and run STEPS steps of 3 us with the tribology refreshed every 10 steps.
Tolerance RTOL = 1e-8 on every state array, relative to each array's scale: the two differ only in
the order of floating-point operations (about 1e-16 per operation), and the stiff contacts amplify a
perturbation at most like exp(lambda t) with lambda dt ~ 1 for the stiffest oscillator over a step
that is stable, i.e. bounded. Measured (printed by the test), worst over the three film formulas: cage
1.7e-10, balls 1.5e-10, ring 3e-11, springs 2e-11, tribology 3e-11, dissipated energy 1e-12.
The orbital angle is compared to ORBIT_TOL: the kernel's per-step increment cross/dot is the tangent
of the twin's exact atan2 increment, which differs by dpsi^3/3 = (198 rad/s x 3 us)^3/3 = 7e-11 rad
per step, 2e-8 rad over 300 steps.
"""

import math

import numpy as np
import pytest

from bearing_fmu.kernels.ball_dynamics import integrator as dyn
from bearing_fmu.kernels.ball_dynamics import state as s
from bearing_fmu.kernels.ball_dynamics.contact_law import groove_approach
from bearing_fmu.kernels.ball_dynamics.monitor import critical_time_step
from bearing_fmu.kernels.ball_dynamics.tribology import ring_axis
from bearing_fmu.kernels.capacitance import CAP_OIL_GAP
from bearing_fmu.kernels.hertz import hertz_contact
from bearing_fmu.models.declarations import DEM_DT_MAX
from bearing_fmu.models.dem import DemModel, DemUnstableError
from bearing_fmu.models.limits import InputError
from tests.reference import ref_ball_dynamics_integrator as ref
from tests.unit.test_film_correction import made_up_table

STEPS = 300
DT = 3e-6
RTOL = 1e-8
ORBIT_TOL = 1e-7  # rad


@pytest.fixture(scope="module")
def running_6208():
    """A 6208 under 3 kN in the middle of its speed ramp (0 -> 300 rad/s over 3 ms after 1 ms at rest)."""
    model = DemModel("6208", "guessasma_oil", dt=DT, refresh=10)
    model.advance(1e-3, omega=0.0, F_y=3000.0)
    for k in range(1, 16):
        model.advance(1e-3 + k * 1e-4, omega=300.0 * k / 30, F_y=3000.0)
    return model


def _scale_err(a, b):
    scale = max(np.max(np.abs(b[np.isfinite(b)])), 1e-300)
    same = a == b  # also equal infinities (open contacts' films), whose difference would be NaN
    diff = np.abs(np.where(same, 0.0, a) - np.where(same, 0.0, b))
    return float(np.max(diff)) / scale


@pytest.mark.parametrize(
    "film, steps, traction, support, oil_gap, film_table",
    [
        (0, STEPS, 0.0, None, 0.0, False),
        (1, STEPS // 3, 0.0, None, 0.0, False),
        (2, STEPS // 3, 0.0, None, 0.0, False),
        (0, STEPS // 3, 0.05, None, 0.0, False),
        (0, STEPS // 3, 0.0, (2e7, 2e3, 1.5e3), 0.0, False),
        (0, STEPS // 3, 0.0, None, 10e-6, False),
        (0, STEPS // 3, 0.0, None, 0.0, True),
        (2, STEPS // 3, 0.0, None, 0.0, True),
    ],
)
def test_kernel_matches_twin_over_steps(running_6208, film, steps, traction, support, oil_gap, film_table):
    """Film formulas: 0 Hamrock-Dowson (the kernel's fused fast path), 1 Masjedi-Khonsari and 2 Chittenden
    (through kernels.ehl.film_thickness); the papers' mu(Lambda) and a traction limit of 0.05 (mixed film here:
    the tangential limit differs from the Houpert terms' mu); a ring support with a spring, a damper across the
    axis and one along it far above the defaults (N/m, N.s/m), so that their terms weigh in the ring's motion; the
    capacitance of the oil around the contacts up to a 10 um gap (scene capacitance_region = 'lubricated'); the film
    correction on (a table of made-up ratios) on the fused and on the general film path."""
    model = running_6208
    state = model.get_state()
    kernel_state = {k: (v.copy() if isinstance(v, np.ndarray) else v) for k, v in state.items()}
    twin_state = {k: (v.copy() if isinstance(v, np.ndarray) else v) for k, v in state.items()}
    par = model.par.copy()
    par[s.P_REFRESH] = 10
    par[s.P_FILM] = film
    par[s.P_TRACTION] = traction
    par[s.P_CAPACITANCE_BLOCK + CAP_OIL_GAP] = oil_gap
    if film_table:
        par[s.P_FILM_TABLE :] = made_up_table()
    if support is not None:
        lever = 0.5 * (0.5 * model.bearing.dm) ** 2
        par[[s.P_K_SUPPORT, s.P_C_SUPPORT, s.P_C_SUPPORT_AXIAL]] = support
        par[[s.P_KT_SUPPORT, s.P_CT_SUPPORT]] = lever * np.array(support[:2])
    lub = model.lubricant.array
    omega0, omega1, F, T_oil = 150.0, 160.0, (0.0, 3000.0, 0.0, 0.0, 0.0), 313.15  # F_y, on the line of ball 1
    if support is not None:
        F = (0.0, 3000.0, 0.0, 2.0, -1.0)  # moments (N.m) that tilt the ring against the support's tilt terms
    acc = np.zeros(s.A_SIZE)
    status = np.zeros(s.ST_SIZE, dtype=np.int64)
    dyn.advance(
        tuple(kernel_state[k] for k in s.STATE_GROUP),
        (par, lub),
        (steps, DT, omega0, omega1, F, T_oil, 1e9),
        (np.zeros((s.W_SIZE, model.bearing.Z)), acc, status),
    )
    assert status[s.ST_CODE] == s.STATUS_OK
    if traction:  # some loaded contact above Lambda = 1, where the traction limit changes the Coulomb limit
        lam = kernel_state["trib"][s.T_LAMBDA][kernel_state["trib"][s.T_Q] > 0.0]
        assert (lam > 1.0).any()
    energy, last_power, capacitance, state_sums = ref.advance(
        twin_state, par, lub, steps, DT, omega0, omega1, np.array(F), T_oil
    )
    report = {}
    for name in ("balls", "cage", "ring", "spring", "trib"):
        a, b = kernel_state[name], twin_state[name]
        if name == "balls":
            orbit = np.max(np.abs(a[s.B_ORBIT] - b[s.B_ORBIT]))
            assert orbit < ORBIT_TOL, f"orbital angle differs by {orbit:.3g} rad"
            a, b = np.delete(a, s.B_ORBIT, axis=0), np.delete(b, s.B_ORBIT, axis=0)
        if name == "balls":  # compare each quantity on its own scale
            errs = [_scale_err(a[r : r + 3], b[r : r + 3]) for r in range(0, s.B_SIZE - 1, 3)]
        elif name == "trib":
            errs = [_scale_err(a[r], b[r]) for r in range(s.T_SIZE)]
        elif name == "ring":
            errs = _ring_errors(a, b)
        else:
            errs = [_scale_err(a, b)]
        report[name] = max(errs)
    report["dissipated"] = _scale_err(acc[s.A_DISS_I : s.A_DISS_O + 1], energy)
    report["last step's power"] = _scale_err(acc[s.A_POWER_I : s.A_POWER_O + 1], last_power)
    report["capacitance x time"] = _scale_err(acc[s.A_CAP : s.A_CAP + 1], np.array([capacitance]))
    # the averaged state outputs' integrals and sums: the displacement and tilts over the steps, the refresh samples
    report["displacement x time"] = _scale_err(acc[s.A_XT : s.A_XT + 3], state_sums[:3])
    if support is not None:  # (elsewhere the ring does not tilt: both are exactly 0)
        assert np.max(np.abs(state_sums[3:5])) > 0.0
    report["tilt x time"] = _scale_err(acc[s.A_XT + 3 : s.A_XT + 5], state_sums[3:5])
    assert acc[s.A_SAMPLES] == state_sums[5] > 0.0
    for k in range(9):  # each sum on its own scale (loads, pressure, Lambda, films)
        report[f"refresh sum {k}"] = _scale_err(acc[s.A_S_QMAX_I + k : s.A_S_QMAX_I + k + 1], state_sums[6 + k : 7 + k])
    for k, name in enumerate(("x^2", "y^2", "theta_x^2", "theta_y^2", "|v|^2", "|theta'|^2")):
        report[f"{name} x time"] = _scale_err(acc[s.A_RING_SQ + k : s.A_RING_SQ + k + 1], state_sums[15 + k : 16 + k])
    print("kernel vs twin, largest scaled difference:", {k: f"{v:.2e}" for k, v in report.items()})
    assert np.array_equal(kernel_state["counters"], twin_state["counters"])
    for name, err in report.items():
        assert err < RTOL, f"{name}: kernel and twin differ by {err:.3g} (scaled)"
    # the state really is in motion and loaded: the comparison is not trivial
    assert np.max(twin_state["trib"][s.T_Q]) > 1000.0
    assert np.max(np.abs(twin_state["spring"])) > 0.0
    assert capacitance > 0.0 and last_power.min() > 0.0


def test_kernel_matches_twin_with_a_tilting_ring():
    """The B7214C under 2 kN radial, 3 kN axial and moments M_x = 20 N.m, M_y = -10 N.m, 3 ms after a jump to
    300 rad/s: its inner ring is tilted (0.6 mrad) and still tilting, every ball is loaded at non-zero contact
    angles, the race turns about its tilted axis. 200 steps of the kernel against the twin (exact rotation of the
    groove circle, race velocity omega a + tilt rates, the ring's moments about its centre, gyroscopic moment),
    same RTOL as above; the twin's tilt accelerations come from its own vector algebra."""
    model = DemModel("B7214C", "iso_vg68_mineral")
    F = (0.0, 2000.0, 3000.0, 20.0, -10.0)
    loads = dict(zip(("F_x", "F_y", "F_z", "M_x", "M_y"), F))
    model.advance(2e-3, omega=0.0, **loads)
    model.advance(5e-3, omega=300.0, **loads)
    state = model.get_state()
    kernel_state = {k: (v.copy() if isinstance(v, np.ndarray) else v) for k, v in state.items()}
    twin_state = {k: (v.copy() if isinstance(v, np.ndarray) else v) for k, v in state.items()}
    par = model.par.copy()
    par[s.P_REFRESH] = 10
    steps, dt, T_oil = 200, model.dt, 313.15
    status = np.zeros(s.ST_SIZE, dtype=np.int64)
    acc = np.zeros(s.A_SIZE)
    dyn.advance(
        tuple(kernel_state[k] for k in s.STATE_GROUP),
        (par, model.lubricant.array),
        (steps, dt, 300.0, 320.0, F, T_oil, 1e9),
        (np.zeros((s.W_SIZE, model.bearing.Z)), acc, status),
    )
    assert status[s.ST_CODE] == s.STATUS_OK
    ref.advance(twin_state, par, model.lubricant.array, steps, dt, 300.0, 320.0, np.array(F), T_oil)
    a, b = kernel_state["ring"], twin_state["ring"]
    assert abs(b[s.R_TH]) > 3e-4 and abs(b[s.R_TH + 1]) > 1e-5 and np.abs(b[s.R_VTH : s.R_VTH + 2]).max() > 0.0
    errors = {"ring": max(_ring_errors(a, b))}
    a, b = kernel_state["balls"], twin_state["balls"]
    errors["balls"] = max(_scale_err(a[r : r + 3], b[r : r + 3]) for r in range(0, s.B_SIZE - 1, 3))
    for name in ("cage", "spring"):
        errors[name] = _scale_err(kernel_state[name], twin_state[name])
    a, b = kernel_state["trib"], twin_state["trib"]
    errors["trib"] = max(_scale_err(a[r], b[r]) for r in range(s.T_SIZE))
    print("tilted ring, kernel vs twin:", {k: f"{v:.2e}" for k, v in errors.items()})
    for name, err in errors.items():
        assert err < RTOL, f"{name}: kernel and twin differ by {err:.3g} (scaled)"
    assert np.array_equal(kernel_state["counters"], twin_state["counters"])


def test_kernel_matches_twin_with_a_prescribed_ring(running_6208):
    """The inner ring on a prescribed path (par[P_DRIVE] = 1): from the running 6208's state (3 kN, 150 rad/s) the
    ring moves 300 steps along the cubic to 2 um further along y, 1 um along x and z, tilts of 0.2 and -0.1 mrad,
    with end rates; the kernel's state, its sums and the load that held the ring (acc[A_REACTION]) against the
    twin's (the cubic solved as a 4 x 4 system in time), same RTOL. The ring ends exactly on the given values, and
    the reaction is of the order of the 3 kN the ring carried (the comparison is not trivial)."""
    model = running_6208
    kernel_state, twin_state = (model.get_state() for _ in range(2))  # (get_state copies every array)
    par = model.par.copy()
    par[s.P_DRIVE] = 1.0
    par[s.P_REFRESH] = 10
    ring = kernel_state["ring"].copy()
    start = np.concatenate((ring[s.R_X : s.R_X + 3], ring[s.R_TH : s.R_TH + 2]))
    rates0 = np.concatenate((ring[s.R_VX : s.R_VX + 3], ring[s.R_VTH : s.R_VTH + 2]))
    end = start + np.array([1e-6, 2e-6, 1e-6, 2e-4, -1e-4])
    rates1 = np.array([1e-3, -2e-3, 0.0, 0.1, 0.05])
    par[s.P_PATH_T] = STEPS * DT
    par[s.P_PATH : s.P_PATH + 20] = np.concatenate((start, rates0, end, rates1))
    acc = np.zeros(s.A_SIZE)
    status = np.zeros(s.ST_SIZE, dtype=np.int64)
    F = (0.0, 0.0, 0.0, 0.0, 0.0)
    dyn.advance(
        tuple(kernel_state[k] for k in s.STATE_GROUP),
        (par, model.lubricant.array),
        (STEPS, DT, 150.0, 160.0, F, 313.15, 1e9),
        (np.zeros((s.W_SIZE, model.bearing.Z)), acc, status),
    )
    assert status[s.ST_CODE] == s.STATUS_OK
    energy, _, _, sums = ref.advance(
        twin_state, par, model.lubricant.array, STEPS, DT, 150.0, 160.0, np.array(F), 313.15
    )
    a = kernel_state["ring"]
    assert np.array_equal(np.concatenate((a[s.R_X : s.R_X + 3], a[s.R_TH : s.R_TH + 2])), end)
    assert np.array_equal(np.concatenate((a[s.R_VX : s.R_VX + 3], a[s.R_VTH : s.R_VTH + 2])), rates1)
    errors = {"ring": max(_ring_errors(a, twin_state["ring"]))}
    a, b = kernel_state["balls"], twin_state["balls"]
    errors["balls"] = max(_scale_err(a[r : r + 3], b[r : r + 3]) for r in range(0, s.B_SIZE - 1, 3))
    for name in ("cage", "spring"):
        errors[name] = _scale_err(kernel_state[name], twin_state[name])
    errors["trib"] = max(_scale_err(kernel_state["trib"][r], twin_state["trib"][r]) for r in range(s.T_SIZE))
    errors["dissipated"] = _scale_err(acc[s.A_DISS_I : s.A_DISS_O + 1], energy)
    held = acc[s.A_REACTION : s.A_REACTION + 5]
    errors["reaction forces"] = _scale_err(held[:3], sums[21:24])
    errors["reaction moments"] = _scale_err(held[3:], sums[24:29])
    print("prescribed ring, kernel vs twin:", {k: f"{v:.2e}" for k, v in errors.items()})
    for name, err in errors.items():
        assert err < RTOL, f"{name}: kernel and twin differ by {err:.3g} (scaled)"
    assert np.array_equal(kernel_state["counters"], twin_state["counters"])
    assert 2000.0 < held[1] / (STEPS * DT) < 10000.0  # N: the 3 kN the ring carried, and more as it moves on


@pytest.mark.parametrize("theta", [(0.0, 0.0), (1e-9, -2e-9), (3e-5, 7e-5), (-2e-3, 1e-3), (0.3, -0.1)])
def test_ring_axis_is_the_exact_rotation_of_z(theta):
    """The tilted ring's axis (tribology.ring_axis: its series below 1e-4 rad, sin and cos above) equals the
    twin's Rodrigues rotation of e_z by the rotation vector (theta_x, theta_y, 0) to rounding, is a unit vector,
    and is (theta_y, -theta_x, 1) to first order: a positive theta_x turns the +y side toward +z."""
    ring = np.zeros(s.R_SIZE)
    ring[s.R_TH : s.R_TH + 2] = theta
    axis = np.array(ring_axis(*theta))
    np.testing.assert_allclose(axis, ref.ring_axis(ring), rtol=0.0, atol=1e-15)
    assert np.linalg.norm(axis) == pytest.approx(1.0, abs=1e-15)
    t2 = theta[0] ** 2 + theta[1] ** 2
    np.testing.assert_allclose(axis, (theta[1], -theta[0], 1.0), rtol=0.0, atol=t2)


def _ring_errors(a, b):
    """Scaled differences of the ring's translation, velocity, acceleration, tilts, tilt rates and tilt
    accelerations (each on its own scale) and of its time."""
    blocks = [(r, 3) for r in (s.R_X, s.R_VX, s.R_AX)] + [(r, 2) for r in (s.R_TH, s.R_VTH, s.R_ATH)]
    return [_scale_err(a[r : r + n], b[r : r + n]) for r, n in blocks] + [
        _scale_err(a[s.R_TIME : s.R_TIME + 1], b[s.R_TIME : s.R_TIME + 1])
    ]


def test_groove_approach_radial_ball_gives_hertz_load():
    """A ball pushed radially into the outer groove by delta: the contact law gives Q of kernels.hertz at
    that approach, the normal is radial, and the approach is exact for the torus."""
    model = DemModel("6208", "guessasma_oil")
    p = model.par
    for delta in (1e-6, 5e-6, 2e-5):
        r = p[s.P_RHO_O] + p[s.P_RG_O] + delta
        psi = 0.7
        approach, nx, ny, nz = groove_approach(
            r * math.cos(psi), r * math.sin(psi), 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, p[s.P_RHO_O], p[s.P_RG_O]
        )
        assert approach == pytest.approx(delta, rel=1e-9, abs=1e-15)
        assert (nx, ny, nz) == pytest.approx((math.cos(psi), math.sin(psi), 0.0), abs=1e-12)
        Q = p[s.P_KH_O] * approach**1.5
        hertz_delta = hertz_contact(Q, p[s.P_RX_O], p[s.P_RY_O], p[s.P_E_RED], p[s.P_K_O], p[s.P_EE_O], p[s.P_KK_O])[2]
        assert hertz_delta == pytest.approx(delta, rel=1e-9)


def test_groove_approach_axial_offset_follows_the_torus():
    """A ball moved axially by z in a deep groove: the distance to the curvature-centre circle grows as
    sqrt(rg^2 + z^2) when the ball stays on the sphere about the curvature centre of radius rg + delta."""
    rho, rg = 0.03, 0.000252
    for angle in (0.05, 0.2, 0.4):
        d = rg + 3e-6
        x = rho + d * math.cos(angle)
        z = d * math.sin(angle)
        delta, nx, _, nz = groove_approach(x, 0.0, z, 0.0, 0.0, 0.0, 0.0, 0.0, 1.0, rho, rg)
        assert delta == pytest.approx(3e-6, rel=1e-8)
        assert math.atan2(nz, nx) == pytest.approx(angle, rel=1e-12)


def test_static_load_matches_hertz_ball_on_the_load_line():
    """At rest under F_y = 3 kN ball 1 (on +y, the load line) carries the same load on both races (no speed, no
    centrifugal force), and its approaches are those of kernels.hertz at that load."""
    model = DemModel("6208", "guessasma_oil")
    model.advance(4e-3, omega=0.0, F_y=3000.0)
    c = model.contacts()
    j = int(np.argmax(c["Q_inner"]))
    assert j == 0  # ball 1 starts on +y (docs/conventions.md)
    assert c["Q_inner"][j] == pytest.approx(c["Q_outer"][j], rel=2e-3)
    assert 1300.0 < c["Q_inner"][j] < 1600.0


def test_critical_time_step_of_the_squeezed_ball():
    """Ball between two races at 1457 N: sqrt(2)/omega with omega^2 = 3.5 k_t/m (tangential, the stiffer; sqrt(2)
    for a spring lengthened by the predicted velocity, kernels.ball_dynamics.monitor) where
    k_t = (2/3)(K_i^(2/3) + K_o^(2/3)) Q^(1/3); about 4.3 us for the 6208 (the papers run at 1 us)."""
    model = DemModel("6208", "guessasma_oil")
    p = model.par
    Z = model.bearing.Z
    Q = np.zeros(Z)
    Q[0] = 1457.0
    dt = critical_time_step(p, Q, Q, np.zeros(Z), np.zeros(Z), 0.0)
    k = (p[s.P_KH_I] ** (2 / 3) + p[s.P_KH_O] ** (2 / 3)) * 1457.0 ** (1 / 3)
    expected = math.sqrt(2.0) / math.sqrt(3.5 * p[s.P_KT_RATIO] * k / p[s.P_M_BALL])
    assert dt == pytest.approx(expected, rel=1e-12)
    assert 3e-6 < dt < 6e-6


def test_state_round_trip_reproduces_the_run(running_6208):
    """get_state/set_state restore everything: two runs from one saved state agree bit for bit."""
    model = running_6208
    saved = model.get_state()
    first = model.advance(model.time + 2e-4, omega=model.omega, F_y=3000.0)
    model.set_state(saved)
    second = model.advance(model.time + 2e-4, omega=model.omega, F_y=3000.0)
    assert first == second
    model.set_state(saved)


@pytest.mark.parametrize(
    "kwargs, word",
    [
        (dict(omega=math.nan), "omega"),
        (dict(omega=1e6), "omega"),
        (dict(F_x=math.nan), "F_x"),
        (dict(F_y=1e9), "F_y"),
        (dict(M_x=math.nan), "M_x"),
        (dict(M_y=1e9), "M_y"),
        (dict(T_oil=-5.0), "T_oil"),
        (dict(dPd_thermal=math.nan), "dPd_thermal"),
        (dict(dPd_thermal=1e-3), "dPd_thermal"),
    ],
)
def test_bad_inputs_are_rejected_with_their_range(running_6208, kwargs, word):
    with pytest.raises(InputError, match=f"{word} = .* allowed range"):
        running_6208.advance(running_6208.time + 1e-4, **kwargs)


def test_capacitance_off_is_not_computed():
    """A scene without capacitance neither computes the contact capacitances nor exposes C_bearing."""
    from bearing_fmu.scene import Scene

    model = DemModel("6208", "guessasma_oil", scene=Scene(name="dem", fidelity="dem", capacitance=False))
    out = model.advance(2e-3, omega=50.0, F_y=3000.0)
    assert "C_bearing" not in out
    assert not model.trib[s.T_CAP].any()
    assert model.trib[s.T_H_C].max() > 0.0


def test_thermal_clearance_change_acts_like_the_clearance():
    """dPd_thermal = +12.6 um on a P_d = 0 bearing loads the balls as P_d = 12.6 um does (same groove
    circles; the Hertz constants differ only through the free contact angle's effect on R_x: < 0.3 %).
    Compared in slow rolling (100 rad/s), where the centrifugal force seats the unloaded balls on the outer
    race: at rest they float wherever they were (no gravity), which differs between the two set-ups."""
    loads = []
    for Pd, dPd in ((12.6e-6, 0.0), (0.0, 12.6e-6)):
        model = DemModel("6208", "guessasma_oil", Pd=Pd)
        model.advance(2e-3, omega=0.0, F_y=3000.0, dPd_thermal=dPd)
        model.advance(7e-3, omega=100.0, F_y=3000.0, dPd_thermal=dPd)
        model.advance(15e-3, omega=100.0, F_y=3000.0, dPd_thermal=dPd)
        loads.append(model.contacts()["Q_inner"])
    assert np.max(np.abs(loads[0] - loads[1])) < 0.005 * np.max(loads[0])


def _after_a_ramp(refresh):
    """A 6208 at dt = 2^-19 s (exact in binary: runs of the same steps are bit-identical) ramped to 300 rad/s under
    3 kN, the tribology refreshed every `refresh` steps; returns (model, dt)."""
    dt = 2.0**-19
    model = DemModel("6208", "guessasma_oil", dt=dt, refresh=refresh)
    for k in range(1, 11):
        model.advance(400 * k * dt, omega=30.0 * k, F_x=3000.0)
    return model, dt


def test_averaged_outputs_are_the_mean_of_the_per_step_values():
    """An interval of N steps with averaged outputs against the same N steps taken one call each with end-of-step
    outputs: the power outputs and the capacitance of the first equal the mean of the N end values of the second.

    dt = 2^-19 s and times that are multiples of it are exact in binary, so both runs take the same steps bit for
    bit (the state is restored between them); the averages differ from the means only by the order of the
    additions (sum of p dt / (N dt) against sum of p / N): rtol 1e-12 for N = 40 terms. The 6208 at 300 rad/s,
    3 kN, in the ramp's aftermath (springs slipping, powers varying from step to step), tribology refreshed every
    7 steps so that the capacitance changes within the interval."""
    model, dt = _after_a_ramp(refresh=7)
    start = model.get_state()
    N = 40
    model.averaged = True
    averaged = model.advance(model.time + N * dt, F_x=3000.0)
    end_state = model.get_state()
    model.set_state(start)
    model.averaged = False
    steps = [model.advance(model.time + dt, F_x=3000.0) for _ in range(N)]
    for name in ("balls", "cage", "ring", "spring", "trib", "counters"):
        np.testing.assert_array_equal(model.get_state()[name], end_state[name])  # the same steps
    for name in ("P_loss", "Q_inner_ring", "Q_outer_ring", "torque", "C_bearing"):
        values = np.array([out[name] for out in steps])
        assert averaged[name] == pytest.approx(values.mean(), rel=1e-12), name
        assert np.ptp(values) > 1e-6 * abs(values.mean()), name  # the values do vary over the interval
    assert steps[-1]["P_loss"] == steps[-1]["Q_inner_ring"] + steps[-1]["Q_outer_ring"]
    assert averaged["Q_max_outer"] == steps[-1]["Q_max_outer"]  # loads are end values in both modes


def test_averaged_state_outputs_are_the_means_over_the_interval():
    """averaged_state (FMU parameter average_state_outputs): the ring's displacement is its mean over the interval's
    DEM steps, and the loads, pressure and films their means over its tribology refreshes. The same 42 steps
    (dt = 2^-19 s, exact in binary: bit-identical runs, the state restored between them) as one call with
    averaged_state and as 42 one-step calls: x, y, z equal the means of the 42 end values (rtol 1e-12: the order
    of the additions); with a refresh every step (refresh = 1) each one-step call's refresh sample is the film
    its step starts from, so Lambda_outer, h_min_outer and Q_max_outer averaged equal the means of the samples the
    refreshes wrote (trib after each one-step call; rtol 1e-12); without averaged_state they are end values."""
    model, dt = _after_a_ramp(refresh=1)
    start = model.get_state()
    N = 42
    model.averaged_state = True
    averaged = model.advance(model.time + N * dt, F_x=3000.0)
    model.set_state(start)
    model.averaged_state = False
    ends, samples = [], []
    for _ in range(N):
        ends.append(model.advance(model.time + dt, F_x=3000.0))
        loaded = model.trib[s.T_Q, 1] > 0.0
        samples.append(
            (
                model.trib[s.T_LAMBDA, 1][loaded].min(),
                model.trib[s.T_H_MIN, 1][loaded].min(),
                model.trib[s.T_Q, 1].max(),
            )
        )
    for name in ("x", "y", "z"):
        values = np.array([out[name] for out in ends])
        assert averaged[name] == pytest.approx(values.mean(), rel=1e-12, abs=1e-18), name
    assert np.ptp([out["x"] for out in ends]) > 0.0  # the ring moves over the interval
    means = np.array(samples).mean(axis=0)
    for k, name in enumerate(("Lambda_outer", "h_min_outer", "Q_max_outer")):
        assert averaged[name] == pytest.approx(means[k], rel=1e-12), name
    assert ends[-1]["x"] == model.ring[s.R_X]  # end values without averaged_state


def test_clearance_limits_follow_the_groove_geometry():
    """P_d and P_d + dPd_thermal are refused beyond the geometric limits |P_d| <= A = (f_i + f_o - 1) D
    (params.clearance_limits, as the quasi-static fidelity); inside them, beyond the former 0.02 D, they run.
    6208: D = 12.6 mm, f = 0.52 on both races, so A = 0.04 D = 504 um."""
    A = 0.04 * 0.0126
    with pytest.raises(InputError, match=r"Pd = .* \(set\) is outside the allowed range \[-0.000504, 0.000504\]"):
        DemModel("6208", "guessasma_oil", Pd=1.01 * A)
    model = DemModel("6208", "guessasma_oil", Pd=0.5 * A)  # 252 um: 0.02 D, the former limit, accepted
    model.advance(1e-4, omega=10.0, F_x=1000.0, dPd_thermal=0.4 * A)  # P_d in effect 0.9 A
    with pytest.raises(InputError, match=r"dPd_thermal = .* allowed range \[-0.000756, 0.000252\]"):
        model.advance(2e-4, omega=10.0, F_x=1000.0, dPd_thermal=0.51 * A)
    with pytest.raises(InputError, match="dPd_thermal = .* allowed range"):
        model.advance(2e-4, omega=10.0, F_x=1000.0, dPd_thermal=-1.51 * A)


@pytest.mark.parametrize("dt", [-1e-6, 0.0, math.nan])
def test_bad_time_step_is_rejected(dt):
    with pytest.raises(InputError, match="dt = .* allowed range"):
        DemModel("6208", "guessasma_oil", dt=dt)


@pytest.mark.parametrize(
    "kwargs, word",
    [
        ({"safety": 0.0}, "safety"),
        ({"safety": 1.5}, "safety"),
        ({"safety": math.nan}, "safety"),
        ({"refresh_interval": -1e-6}, "refresh_interval"),
        ({"refresh_interval": math.inf}, "refresh_interval"),
        ({"support_damping": -1.0}, "support_damping"),
        ({"support_damping": math.nan}, "support_damping"),
        ({"support_stiffness": 2e10}, "support_stiffness"),
    ],
)
def test_bad_step_settings_are_rejected(kwargs, word):
    with pytest.raises(InputError, match=f"{word} = .* allowed range"):
        DemModel("6208", "guessasma_oil", **kwargs)


def test_step_settings_set_the_time_step_and_the_refresh():
    """dt = safety x the stability limit at the call's loads; refresh = the interval in whole steps."""
    model = DemModel("6208", "guessasma_oil", safety=0.25, refresh_interval=30e-6)
    limit = model.stable_time_step(F_y=3000.0, omega=0.0)  # at the state the call starts from
    model.advance(1e-4, omega=0.0, F_y=3000.0)
    assert model.dt <= 0.25 * limit and model.dt == pytest.approx(0.25 * limit, rel=0.05)
    assert model.refresh == math.floor(30e-6 / model.dt * (1.0 + 1e-9))  # refreshed at least every 30 us


def test_too_large_time_step_is_reported():
    """dt = 10 us (the largest allowed) is beyond the stability limit (about 6 us at 3 kN): the monitor stops the
    run and names a time step that works at these inputs, and the automatic step (dt = 0 in the FMU), which follows
    the loads and the film as they change (a fixed step that works now can be stopped again later in a start-up)."""
    model = DemModel("6208", "guessasma_oil", dt=10e-6)
    with pytest.raises(DemUnstableError, match=r"use dt <= .* s \(.*\); or use dt = 0 \(automatic"):
        model.advance(5e-3, omega=0.0, F_y=3000.0)


@pytest.mark.parametrize(
    "inputs", [{"omega": 0.0, "F_x": 100.0}, {"omega": 500.0, "F_x": 100.0}, {"omega": 500.0, "F_z": 100.0}]
)
def test_the_largest_allowed_time_step_runs_the_default_bearing_under_a_light_load(inputs):
    """dt = DEM_DT_MAX (the declared maximum of the FMU's dt) runs the 6208 under 100 N, radial at rest or at
    500 rad/s or axial at 500 rad/s, for 4 calls of 0.5 ms: the declared range holds a step that works."""
    model = DemModel("6208", "guessasma_oil", dt=DEM_DT_MAX)
    for k in range(1, 5):
        model.advance(k * 0.5e-3, **inputs)
    assert math.isclose(model.dt, DEM_DT_MAX, rel_tol=1e-12) and model.status[s.ST_CODE] == s.STATUS_OK


def test_the_advised_time_step_holds_as_the_film_thickens():
    """The B7214C with ISO VG 68 at 40 C started to 10 000 rpm under 2 kN of thrust at dt = 10 us: the monitor
    stops the first call at 0.12 ms. The step it advises runs 4 ms: it keeps the damping check for the thinnest
    full film the contacts can reach, not only for the films of the stopped state (from those, 3.57 us was
    advised and stopped again 0.23 ms into the run, when the film turned full)."""
    inputs = {"omega": 1047.1975511965977, "F_z": 2000.0}
    model = DemModel("B7214C", "iso_vg68_mineral", dt=10e-6)
    with pytest.raises(DemUnstableError) as stop:
        model.advance(0.5e-3, **inputs)
    advised = float(str(stop.value).split("use dt <= ")[1].split(" s")[0])
    model = DemModel("B7214C", "iso_vg68_mineral", dt=advised)
    for k in range(1, 9):
        model.advance(k * 0.5e-3, **inputs)
    assert model.status[s.ST_CODE] == s.STATUS_OK and model.out[s.O_N_LOADED] == 17


def test_load_release_at_rest_is_not_flagged_as_energy_growth():
    """6208 at rest, 300 N held for one 1 ms step, then 0 N: the elastic energy of the loaded contacts turns into
    motion of the released ring and balls (physical), which the energy bound must allow: before, the bound at
    zero speed and zero load was 1 uJ and the first released step stopped with "energy growth" quoting a
    stability limit of "inf s". The ring then rings down inside the groove clearance (|x| < A = 60 um)."""
    model = DemModel("6208", "guessasma_oil")
    model.evaluate(1e-3, F_x=300.0)
    for k in range(2, 12):
        out = model.evaluate(k * 1e-3, F_x=0.0)
        assert out["monitor_status"] == 0
    A = (model.bearing.f_i + model.bearing.f_o - 1.0) * model.bearing.D
    assert abs(out["x"]) < A and math.isfinite(out["x"])


def test_unstable_message_without_loaded_contact_names_no_infinite_limit():
    """A monitor stop where neither the inputs nor the state load any contact (rest, no load, balls clear of
    both races): the message suggests half the step and says why, never a limit of "inf s"."""
    model = DemModel("6208", "guessasma_oil", dt=8e-6, Pd=25e-6)
    model.balls[s.B_X : s.B_X + 2] *= 1.0 - 1e-6 / model._rest[0]  # 1 um off the outer race: every contact open
    model.status[:] = (s.STATUS_ENERGY, 3, -1)
    with pytest.raises(DemUnstableError, match=r"use dt <= 4e-06 s \(no contact is loaded") as info:
        model._raise_unstable(8e-6, (0.0, 0.0, 0.0, 0.0, 0.0), 313.15, 0.0)
    assert "inf" not in str(info.value)


def test_pressure_above_the_iso_76_limit_gives_a_warning():
    """6208 at rest under 30 kN: p_max = 4.66 GPa at the most loaded contact, above the ISO 76 static limit
    4.2 GPa: warned as by the other fidelities (models.limits.pressure_warnings); 3 kN gives no warning."""
    model = DemModel("6208", "guessasma_oil")
    out = model.evaluate(3e-3, F_x=30000.0)
    assert 4.2e9 < out["p_max"] < 6e9
    assert any("ISO 76" in w and f"{out['p_max'] / 1e9:.3g} GPa" in w for w in model.warnings)
    model = DemModel("6208", "guessasma_oil")
    model.evaluate(3e-3, F_x=3000.0)
    assert model.warnings == []


@pytest.mark.parametrize("lubricant, T_oil", [("guessasma_oil", 313.15), ("iso_vg68_mineral", 343.15)])
def test_fused_power_laws_equal_the_film_and_houpert_kernels(lubricant, T_oil):
    """The refresh writes the Hamrock-Dowson films and Houpert's rolling force as exp(c + p ln u + q ln delta);
    at every contact they equal kernels.ehl.film_thickness and kernels.torque.houpert_rolling_force at the
    contact's own load and entrainment speed to rounding (1e-12: a handful of logs and exps)."""
    from bearing_fmu.kernels.ehl import FILM_HAMROCK_DOWSON, film_thickness, friction_coefficient
    from bearing_fmu.kernels.lubricant import lubricant_state
    from bearing_fmu.kernels.torque import heathcote_force, houpert_rolling_force, hysteresis_force

    model = DemModel("6208", lubricant)
    rng = np.random.default_rng(7)
    Z = model.bearing.Z
    p = model.par
    for j in range(Z):  # each ball pressed into the outer groove by its own approach, spinning about z
        psi = 2.0 * math.pi * j / Z
        r = p[s.P_RHO_O] + p[s.P_RG_O] + rng.uniform(1e-7, 4e-5)
        model.balls[s.B_X : s.B_X + 3, j] = (r * math.cos(psi), r * math.sin(psi), 0.0)
        model.balls[s.B_WX + 2, j] = rng.uniform(1.0, 5000.0)
    model._initialise(0.0, 0.0, 0.0, 0.0, T_oil)
    eta, xi, _ = lubricant_state(T_oil, model.lubricant.array)
    t = model.trib
    for j in range(Z):
        Q, u, a, b = t[s.T_Q, 1, j], t[s.T_U, 1, j], t[s.T_A, 1, j], t[s.T_B, 1, j]
        h_c, h_min = film_thickness(
            FILM_HAMROCK_DOWSON, eta, xi, p[s.P_E_RED], u, Q, p[s.P_RX_O], p[s.P_RY_O], p[s.P_K_O]
        )
        assert t[s.T_H_MIN, 1, j] == pytest.approx(h_min, rel=1e-12)
        assert t[s.T_H_C, 1, j] == pytest.approx(h_c, rel=1e-12)
        F_R = houpert_rolling_force(Q, u, p[s.P_RX_O], p[s.P_RY_O], p[s.P_E_RED], eta, xi)
        F_hh = hysteresis_force(Q, b, p[s.P_RX_O], p[s.P_ALPHA_H]) + heathcote_force(
            Q, a, p[s.P_RX_O], p[s.P_F_O], p[s.P_D], friction_coefficient(t[s.T_LAMBDA, 1, j])
        )  # the Houpert terms keep the papers' mu(Lambda); T_MU is the tangential law's limit
        assert t[s.T_F_ROLL, 1, j] == pytest.approx(F_R + 0.5 * F_hh, rel=1e-12)
        a_ref, b_ref, _, p_ref = hertz_contact(
            Q, p[s.P_RX_O], p[s.P_RY_O], p[s.P_E_RED], p[s.P_K_O], p[s.P_EE_O], p[s.P_KK_O]
        )
        assert (a, b, t[s.T_P_MAX, 1, j]) == pytest.approx((a_ref, b_ref, p_ref), rel=1e-12)


def test_record_returns_time_series_of_outputs_and_contacts():
    """record() samples every interval: times, bearing outputs and per-ball arrays (n, Z) under 'contacts'; the last
    sample equals a direct advance() from the same state."""
    model = DemModel("6208", "guessasma_oil")
    model.advance(1e-3, omega=0.0, F_y=3000.0)
    saved = model.get_state()
    rec = model.record(1.5e-3, 1e-4, omega=10.0, F_y=3000.0)
    np.testing.assert_allclose(rec["t"], np.linspace(1.1e-3, 1.5e-3, 5), rtol=1e-12)
    assert rec["contacts"]["Q_inner"].shape == (5, model.bearing.Z) and rec["omega_cage"].shape == (5,)
    assert rec["Lambda_outer"][-1] == model.outputs_dict()["Lambda_outer"]
    model.set_state(saved)
    t0 = model.time
    for k in range(1, 6):  # the same times and speeds as record() computes them (bit for bit)
        t = t0 + k * 1e-4
        out = model.advance(t, omega=10.0 * (t - t0) / (1.5e-3 - t0), F_y=3000.0)
    assert out["Q_max_inner"] == rec["Q_max_inner"][-1]


def test_refresh_interval_0_is_accepted_and_refreshes_at_every_step():
    """refresh_interval's declared range (BearingDEM.fmu's FMI min/max) is [0, 1e-3] s, and the model accepts
    all of it: 0 means a tribology refresh at every DEM step, what any interval shorter than the step gives
    (refresh = max(1, floor(interval / dt))). The same steps with refresh = 1 step give the same bits."""
    from bearing_fmu.models.declarations import DEM_PARAMETERS

    declared = next(v for v in DEM_PARAMETERS if v.name == "refresh_interval")
    assert declared.min == 0.0
    dt = 2.0**-19
    every = DemModel("6208", "guessasma_oil", dt=dt, refresh_interval=0.0)
    fixed = DemModel("6208", "guessasma_oil", dt=dt, refresh=1)
    for k in range(1, 4):
        a = every.advance(20 * k * dt, omega=30.0 * k, F_x=3000.0)
        b = fixed.advance(20 * k * dt, omega=30.0 * k, F_x=3000.0)
        assert every.refresh == 1
        assert a == b
    with pytest.raises(InputError, match=r"refresh_interval = -1e-06 s is outside the allowed range \[0, 0.001\] s"):
        DemModel("6208", "guessasma_oil", refresh_interval=-1e-6)


def test_unloaded_bearing_reports_no_load_pressure_or_loaded_ball():
    """6208 at rest without load: the balls touch nothing but within rounding (approaches of 1e-18-1e-15 m, loads of
    1e-16 N) and p_max read 1.4 kPa with n_loaded 0; a contact counts as loaded from an approach of 1 pm
    (state.LOADED_APPROACH, about 1e-8 N), so p_max, Q_max and n_loaded are all 0. With 10 N radial the loaded
    contacts are counted and the pressure follows (Hertz: about 0.5 GPa at 10 N on a 6208 ball)."""
    model = DemModel("6208", "guessasma_oil")
    out = model.advance(0.01)
    assert (out["p_max"], out["Q_max_inner"], out["Q_max_outer"], out["n_loaded"]) == (0.0, 0.0, 0.0, 0)
    out = model.advance(0.02, F_y=10.0)
    assert out["n_loaded"] > 0 and out["Q_max_outer"] > 1.0 and 1e8 < out["p_max"] < 2e9
