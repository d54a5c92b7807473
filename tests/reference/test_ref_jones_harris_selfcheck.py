"""Self-consistency checks of the quasi-static twin tests/reference/ref_jones_harris.py.

The twin is compared elsewhere with the numba kernel; here it is checked against what the model
definition implies independently of how it is coded:
- omega = 0, Pd = 0, pure radial load on a deep-groove bearing: the model reduces exactly to the
  discrete Stribeck sum Q_j = Q_max cos^1.5 psi_j, F_r = Q_max sum cos^2.5 psi_j (and Q_max is within
  2 % of the continuous F_r / (Z J_r(0.5)), J_r(0.5) = 0.2288);
- omega = 0, pure axial load on the angular bearing: the scalar equation
  F_z = Z K (|A| - A)^1.5 A1/|A| (K of the two contacts in series), solved by brentq;
- force balance: the solved displacement carries the applied load, every ball is in equilibrium, and
  the same load reaches the outer ring (plus the centrifugal forces) when summed from Q_o, a_o;
- omega = 0: inner and outer loads equal and collinear with the line of centres; the numerical ball
  solve at vanishing speed meets the closed form;
- kinematics: the cage speed satisfies rolling at the inner contact, outer (inner) race control
  gives zero spin at the outer (inner) contact, hybrid control tends to outer control as C -> 0;
- the static stiffness is symmetric (the forces derive from the Hertz potential).
"""

import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st
from scipy.optimize import brentq

from tests.reference import ref_jones_harris as rq

OMEGA = 10000.0 * 2.0 * math.pi / 60.0  # 10000 rpm
FAST = settings(max_examples=60, deadline=None)


def ball_forces_on_outer_ring(balls, D):
    """Sum over balls of the force of the ball on the outer ring, (x, y, z), from Q_o, a_o, lam_o
    only: axial Q_o sin a_o - lam_o (M_g/D) cos a_o, radial Q_o cos a_o + lam_o (M_g/D) sin a_o."""
    total = np.zeros(3)
    for b in balls:
        G = b["M_g"] / D
        axial = b["Q_o"] * math.sin(b["a_o"]) - b["lam_o"] * G * math.cos(b["a_o"])
        radial = b["Q_o"] * math.cos(b["a_o"]) + b["lam_o"] * G * math.sin(b["a_o"])
        total += [radial * math.cos(b["psi"]), radial * math.sin(b["psi"]), axial]
    return total


# ------------------------------------------------------------------------------------------------
# reduction to closed forms at omega = 0
# ------------------------------------------------------------------------------------------------
def test_6208_radial_load_is_discrete_stribeck():
    p = rq.params_6208()
    F_r = 3000.0
    d = rq.solve_loads([0.0, F_r, 0.0, 0.0, 0.0], p)  # F_y: on the line of ball 1 (docs/conventions.md)
    _, balls = rq.bearing_loads(d, p)
    Q_max = max(b["Q_i"] for b in balls)
    psi = [2.0 * math.pi * j / 9 for j in range(9)]  # from the load line
    discrete = F_r / sum(max(math.cos(s), 0.0) ** 2.5 for s in psi)
    continuous = F_r / (9 * 0.2288)
    assert Q_max == pytest.approx(discrete, rel=1e-9)
    assert Q_max == pytest.approx(continuous, rel=0.02)
    assert balls[0]["Q_i"] == Q_max
    for b, s in zip(balls, psi):
        assert b["Q_i"] == pytest.approx(discrete * max(math.cos(s), 0.0) ** 1.5, rel=1e-9, abs=1e-9)
        assert b["a_i"] == 0.0 and b["a_o"] == 0.0
    assert abs(d[0]) < 1e-15 and abs(d[2]) < 1e-15 and np.all(np.abs(d[3:]) < 1e-12)
    # radial shift: Q_max = K delta^1.5 with the contacts in series, delta = y at Pd = 0
    assert d[1] == pytest.approx((Q_max / rq._series_stiffness(p)) ** (2.0 / 3.0), rel=1e-9)


def test_angular_pure_axial_load_matches_scalar_equation():
    p = rq.params_b7214c()
    g = rq.geometry(p)
    F_z = 800.0
    K = rq._series_stiffness(p)

    def axial_force(z):
        A1, A2 = g["A1_0"] + z, g["A2_0"]
        L = math.hypot(A1, A2)
        return p["Z"] * K * max(L - g["A"], 0.0) ** 1.5 * A1 / L

    z = brentq(lambda z: axial_force(z) - F_z, 0.0, 1e-3, xtol=1e-18, rtol=1e-15)
    d = rq.solve_loads([0.0, 0.0, F_z, 0.0, 0.0], p)
    assert d[2] == pytest.approx(z, rel=1e-8)
    assert np.all(np.abs(d[[0, 1]]) < 1e-15) and np.all(np.abs(d[3:]) < 1e-12)
    _, balls = rq.bearing_loads(d, p)
    Q = [b["Q_i"] for b in balls]
    assert max(Q) == pytest.approx(min(Q), rel=1e-9)
    assert math.degrees(g["alpha0"]) == pytest.approx(15.0, abs=1e-3)


# ------------------------------------------------------------------------------------------------
# force balance
# ------------------------------------------------------------------------------------------------
CASES = {
    "6208 static radial": (rq.params_6208(), [3000.0, 0.0, 0.0, 0.0, 0.0]),
    "6208 clearance, speed, combined": (
        rq.params_6208(Pd=20e-6, omega=OMEGA, centrifugal=True, gyroscopic=True),
        [2000.0, 0.0, 500.0, 0.0, 0.0],
    ),
    "B7214C static combined": (rq.params_b7214c(), [2000.0, 0.0, 1000.0, 0.0, 20.0]),
    "B7214C outer, speed": (rq.params_b7214c(omega=OMEGA, centrifugal=True), [0.0, 0.0, 800.0, 0.0, 0.0]),
    "B7214C outer gyro, combined": (
        rq.params_b7214c(omega=OMEGA, centrifugal=True, gyroscopic=True),
        [1500.0, -500.0, 1000.0, 10.0, -30.0],
    ),
    "B7214C hybrid gyro, combined": (
        rq.params_b7214c(omega=OMEGA, centrifugal=True, gyroscopic=True, race="hybrid"),
        [1500.0, -500.0, 1000.0, 10.0, -30.0],
    ),
    "B7214C inner gyro": (
        rq.params_b7214c(omega=OMEGA, centrifugal=True, gyroscopic=True, race="inner"),
        [0.0, 0.0, 800.0, 0.0, 0.0],
    ),
}


@pytest.fixture(scope="module", params=list(CASES))
def solved(request):
    p, F = CASES[request.param]
    d = rq.solve_loads(F, p)
    F_d, balls = rq.bearing_loads(d, p)
    return p, np.asarray(F), d, F_d, balls


def test_solution_carries_the_applied_load(solved):
    p, F, d, F_d, balls = solved
    scale = max(np.max(np.abs(F[:3])), 1.0)
    assert np.max(np.abs(F_d[:3] - F[:3])) < 1e-8 * scale
    assert np.max(np.abs(F_d[3:] - F[3:])) < 1e-8 * scale * rq.geometry(p)["Rr_i"]


def test_every_ball_is_in_equilibrium(solved):
    p, F, d, F_d, balls = solved
    for b in balls:
        if b["loaded"]:
            load = max(b["Q_i"], b["Q_o"], b["F_c"])
            assert abs(b["res_axial"]) < 1e-9 * load and abs(b["res_radial"]) < 1e-9 * load
            # recompute the residual from the returned state (not the solver's copy)
            c = rq.contacts(b["X1"], b["X2"], b["A1"], b["A2"], p, rq.geometry(p))
            assert c["Q_i"] == pytest.approx(b["Q_i"], rel=1e-12)
        else:
            assert b["Q_i"] == b["Q_o"] == b["g_r"] == b["g_z"] == b["m_g"] == 0.0


def test_load_reaches_outer_ring(solved):
    """Sum of ball forces on the outer ring = applied (x, y, z) load + resultant of the centrifugal
    forces (which vanishes when they are all equal)."""
    p, F, d, F_d, balls = solved
    centrifugal = np.zeros(3)
    for b in balls:
        centrifugal += [b["F_c"] * math.cos(b["psi"]), b["F_c"] * math.sin(b["psi"]), 0.0]
    outer = ball_forces_on_outer_ring(balls, p["D"])
    scale = max(np.max(np.abs(F[:3])), max(b["F_c"] for b in balls), 1.0)
    assert np.max(np.abs(outer - (F[:3] + centrifugal))) < 1e-8 * scale


# ------------------------------------------------------------------------------------------------
# omega = 0: equal and collinear contact loads
# ------------------------------------------------------------------------------------------------
@pytest.mark.parametrize(
    "params, F",
    [
        (rq.params_6208(Pd=20e-6), [2000.0, 300.0, 500.0, 5.0, 0.0]),
        (rq.params_b7214c(), [2000.0, 0.0, 1000.0, 0.0, 20.0]),
        (rq.params_b7214c(race="hybrid", gyroscopic=True, centrifugal=True), [500.0, 500.0, 800.0, -10.0, 0.0]),
    ],
)
def test_static_loads_equal_and_collinear(params, F):
    d = rq.solve_loads(F, params)
    _, balls = rq.bearing_loads(d, params)
    g = rq.geometry(params)
    assert any(b["loaded"] for b in balls)
    for b in balls:
        if not b["loaded"]:
            continue
        assert b["Q_i"] == pytest.approx(b["Q_o"], rel=1e-12)
        assert b["a_i"] == pytest.approx(b["a_o"], abs=1e-13)
        assert b["a_i"] == pytest.approx(math.atan2(b["A1"], b["A2"]), abs=1e-13)
        # ball centre on the line of centres, approaches adding up to the total approach
        assert b["X1"] * b["A2"] - b["X2"] * b["A1"] == pytest.approx(0.0, abs=1e-20)
        total = math.hypot(b["A1"], b["A2"]) - g["r_i"] - g["r_o"]
        assert b["delta_i"] + b["delta_o"] == pytest.approx(total, rel=1e-9)
        assert b["F_c"] == 0.0 and b["M_g"] == 0.0
        assert b["g_z"] == pytest.approx(b["Q_i"] * math.sin(b["a_i"]), rel=1e-12, abs=1e-12)


def test_numerical_ball_solve_meets_closed_form_at_vanishing_speed():
    """Both inertial effects on at omega = 1e-3 rad/s: the root-solved ball ~ the collinear one."""
    for race in ("outer", "inner", "hybrid"):
        p0 = rq.params_b7214c(race=race)
        p1 = rq.params_b7214c(race=race, omega=1e-3, centrifugal=True, gyroscopic=True)
        g = rq.geometry(p0)
        A1, A2 = g["A1_0"] + 15e-6, g["A2_0"] + 5e-6
        b0, b1 = rq.ball_state(A1, A2, p0), rq.ball_state(A1, A2, p1)
        assert b1["Q_i"] == pytest.approx(b0["Q_i"], rel=1e-9)
        assert b1["Q_o"] == pytest.approx(b0["Q_o"], rel=1e-9)
        assert b1["a_o"] == pytest.approx(b0["a_o"], abs=1e-10)
        assert b1["X2"] == pytest.approx(b0["X2"], rel=1e-12)


def test_unloaded_ball_without_centrifugal_force():
    p = rq.params_6208(Pd=20e-6, omega=OMEGA, gyroscopic=True)
    g = rq.geometry(p)
    b = rq.ball_state(0.0, g["A2_0"], p)  # the clearance leaves the ball free
    assert not b["loaded"] and b["Q_i"] == b["Q_o"] == b["M_g"] == 0.0
    p_c = dict(p, centrifugal=True)  # the centrifugal force presses it on the outer race
    b = rq.ball_state(0.0, g["A2_0"], p_c)
    assert b["loaded"] and b["Q_i"] == 0.0
    assert b["Q_o"] == pytest.approx(b["F_c"], rel=1e-9) and b["a_o"] == pytest.approx(0.0, abs=1e-12)


# ------------------------------------------------------------------------------------------------
# speed effects
# ------------------------------------------------------------------------------------------------
def test_centrifugal_force_opens_outer_and_closes_inner_contact_angle():
    p = rq.params_b7214c(omega=OMEGA, centrifugal=True)
    d = rq.solve_loads([0.0, 0.0, 800.0, 0.0, 0.0], p)
    _, balls = rq.bearing_loads(d, p)
    b = balls[0]
    assert b["a_o"] < rq.geometry(p)["alpha0"] < b["a_i"]
    assert b["Q_o"] > b["Q_i"]
    # without gyroscopic moment: Q_i sin a_i = Q_o sin a_o, Q_o cos a_o - Q_i cos a_i = F_c
    assert b["Q_i"] * math.sin(b["a_i"]) == pytest.approx(b["Q_o"] * math.sin(b["a_o"]), rel=1e-10)
    assert b["Q_o"] * math.cos(b["a_o"]) - b["Q_i"] * math.cos(b["a_i"]) == pytest.approx(b["F_c"], rel=1e-9)
    assert b["F_c"] == pytest.approx(0.5 * p["m_ball"] * p["dm"] * b["w_m"] ** 2, rel=1e-14)


# ------------------------------------------------------------------------------------------------
# kinematics
# ------------------------------------------------------------------------------------------------
angles = st.floats(min_value=0.0, max_value=math.radians(45.0))


def _spins(a_i, a_o, beta, gp):
    """Spin-to-roll of each contact up to a positive factor (derived with the rolling conditions):
    outer ~ sin(a_o - beta) - gp sin(beta), inner ~ -(sin(a_i - beta) + gp sin(beta))."""
    return -(math.sin(a_i - beta) + gp * math.sin(beta)), math.sin(a_o - beta) - gp * math.sin(beta)


@FAST
@given(a_i=angles, a_o=angles, race=st.sampled_from(["outer", "inner", "hybrid"]))
def test_cage_speed_rolls_on_both_races(a_i, a_o, race):
    p = rq.params_b7214c(race=race, omega=OMEGA)
    gp = p["D"] / p["dm"]
    beta, lam_i, lam_o = rq.race_control(a_i, a_o, 100.0, 150.0, p, gp)
    assert lam_i + lam_o == pytest.approx(2.0, rel=1e-14)
    w_m, w_R = rq.cage_and_spin_speeds(a_i, a_o, beta, OMEGA, gp)
    # rolling at the outer race (cage frame): w_R gp cos(a_o - beta) = -w_m (1 + gp cos a_o)
    assert w_R * gp * math.cos(a_o - beta) == pytest.approx(-w_m * (1.0 + gp * math.cos(a_o)), rel=1e-12)
    # rolling at the inner race: -w_R gp cos(a_i - beta) = (omega - w_m)(1 - gp cos a_i)
    assert -w_R * gp * math.cos(a_i - beta) == pytest.approx((OMEGA - w_m) * (1.0 - gp * math.cos(a_i)), rel=1e-12)
    spin_i, spin_o = _spins(a_i, a_o, beta, gp)
    if race == "outer":
        assert spin_o == pytest.approx(0.0, abs=1e-14)
    if race == "inner":
        assert spin_i == pytest.approx(0.0, abs=1e-14)


@FAST
@given(a_i=angles, a_o=angles)
def test_hybrid_tends_to_outer_control_as_C_vanishes(a_i, a_o):
    p = rq.params_b7214c(race="hybrid", c_hyb=1e-12)
    gp = p["D"] / p["dm"]
    beta_h, lam_i, lam_o = rq.race_control(a_i, a_o, 100.0, 100.0, p, gp)
    beta_o, _, _ = rq.race_control(a_i, a_o, 100.0, 100.0, dict(p, race="outer"), gp)
    assert beta_h == pytest.approx(beta_o, abs=1e-11)
    assert lam_o == pytest.approx(2.0, rel=1e-11) and lam_i == pytest.approx(0.0, abs=1e-11)


def test_cage_speed_at_zero_contact_angle():
    p = rq.params_6208(omega=OMEGA)
    gp = p["D"] / p["dm"]
    for race in ("outer", "inner", "hybrid"):
        beta, _, _ = rq.race_control(0.0, 0.0, 1.0, 1.0, dict(p, race=race), gp)
        assert beta == 0.0
        w_m, w_R = rq.cage_and_spin_speeds(0.0, 0.0, beta, OMEGA, gp)
        assert w_m == pytest.approx(0.5 * OMEGA * (1.0 - gp), rel=1e-15)
        assert w_R == pytest.approx(-0.5 * OMEGA * (1.0 - gp) * (1.0 + gp) / gp, rel=1e-15)


# ------------------------------------------------------------------------------------------------
# stiffness
# ------------------------------------------------------------------------------------------------
def test_static_stiffness_is_symmetric_and_matches_secant():
    p = rq.params_b7214c()
    F = np.array([1000.0, 0.0, 800.0, 0.0, 10.0])
    d = rq.solve_loads(F, p)
    K = rq.stiffness_fd(d, p)
    assert np.max(np.abs(K - K.T)) < 1e-7 * np.max(np.abs(K))
    assert np.all(np.diag(K) > 0.0) and np.all(np.linalg.eigvalsh(0.5 * (K + K.T)) > 0.0)
    # first-order prediction of a small load step
    dF = np.array([5.0, -3.0, 4.0, 0.02, -0.03])
    d2 = rq.solve_loads(F + dF, p, d0=d)
    assert np.allclose(K @ (d2 - d), dF, rtol=0.0, atol=0.01 * np.max(np.abs(dF)) + 1e-9)


def test_speed_stiffness_finite_and_stable():
    p = rq.params_b7214c(omega=OMEGA, centrifugal=True, gyroscopic=True, race="hybrid")
    d = rq.solve_loads([0.0, 0.0, 800.0, 0.0, 0.0], p)
    K = rq.stiffness_fd(d, p)
    assert np.all(np.isfinite(K)) and np.all(np.diag(K) > 0.0)
    # axial symmetry of the pure-axial state: K_xx = K_yy, K_txtx = K_tyty
    assert K[0, 0] == pytest.approx(K[1, 1], rel=1e-6)
    assert K[3, 3] == pytest.approx(K[4, 4], rel=1e-6)
