"""The parts of kernels.jones_harris against their twins in tests/reference/ref_jones_harris.py.

test_quasistatic.py compares the whole solve and load evaluation; these compare the parts a reader
meets first (geometry, kinematics and moment share, one ball's equilibrium, the load evaluation without
per-ball outputs, the small linear solver), so a wrong part is named by its own test.

Tolerances:
- RTOL = 1e-13 for the closed forms (geometry, kinematics): kernel and twin write the same formulas in a
  different order; measured 0 (geometry) and 2.5e-16 (kinematics, through atan and the hybrid law).
- Ball equilibrium: the twin accepts ball residuals of 1e-10 of the ball load (BALL_RTOL), the kernel
  1e-13: loads within 1e-8 of the largest load and angles within 1e-8 rad, as in test_quasistatic.py.
- Linear solver: partial pivoting against LAPACK's, 1e-12 relative on well-conditioned systems
  (condition numbers below 1e3: the error is bounded by cond x eps ~ 2e-13).
"""

import math

import numpy as np
import pytest

from bearing_fmu.kernels import jones_harris
from tests.reference import ref_jones_harris as ref
from tests.unit._compare import assert_close
from tests.unit.test_quasistatic import RACES, pack

RTOL = 1e-13
RPM = 2.0 * math.pi / 60.0
PARAMS = {
    "6208": ref.params_6208(),
    "6208 clearance": ref.params_6208(Pd=20e-6),
    "6208 preload": ref.params_6208(Pd=-10e-6),
    "B7214C": ref.params_b7214c(),
}


@pytest.mark.parametrize("name", list(PARAMS))
@pytest.mark.parametrize("dPd", [0.0, -3e-6])
def test_geometry_matches_twin(name, dPd):
    p = dict(PARAMS[name], dPd=dPd)
    g = ref.geometry(p)
    expected = (g["A"], g["r_i"], g["r_o"], g["A1_0"], g["A2_0"], g["Rr_i"], g["alpha0"])
    assert_close(jones_harris.qs_geometry(pack(p), dPd), expected, RTOL, f"{name}, dPd = {dPd}")


@pytest.mark.parametrize("race", list(RACES))
@pytest.mark.parametrize("loads", [(500.0, 650.0), (900.0, 300.0), (0.0, 400.0)])
def test_kinematics_and_moment_share_match_twin(race, loads):
    p = ref.params_b7214c(race=race, centrifugal=True, gyroscopic=True, omega=10000 * RPM)
    g = ref.geometry(p)
    Q_i, Q_o = loads
    a_i, a_o = 0.31, 0.27
    C = p["c_hyb"] * (Q_i / Q_o) ** (4.0 / 3.0) if race.startswith("hybrid") else 0.0
    twin = ref.kinematics(dict(a_i=a_i, a_o=a_o, Q_i=Q_i, Q_o=Q_o), p, g)
    code = RACES[race]
    out = jones_harris.kinematics(complex(a_i), complex(a_o), complex(C), p["omega"], g["gp"], p["dm"], p["D"],
                                  p["m_ball"], code, True, True)  # fmt: skip
    F_c, Mg_o, Mg_i, w_m, w_R, beta = (v.real for v in out)
    M_g_D = twin["M_g"] / p["D"]
    expected = (twin["F_c"], twin["lam_o"] * M_g_D, twin["lam_i"] * M_g_D, twin["w_m"], twin["w_R"], twin["beta"])
    assert_close((F_c, Mg_o, Mg_i, w_m, w_R, beta), expected, RTOL, f"{race}, Q = {loads}")
    if code >= jones_harris.RACE_HYBRID:
        _, lam_i, _ = ref.race_control(a_i, a_o, Q_i, Q_o, p, g["gp"])
        assert_close(jones_harris.hybrid_inner_share(complex(C), code).real, lam_i, RTOL, "lam_i")


BALL_CASES = [
    ("6208 at rest, balls lifted", ref.params_6208(Pd=-10e-6), (20e-6, 0.0, 0.0, 0.0, 0.0)),
    ("B7214C at rest", ref.params_b7214c(), (0.0, 0.0, 20e-6, 0.0, 0.0)),
    ("B7214C ORCG 10k", ref.params_b7214c(centrifugal=True, gyroscopic=True, omega=10000 * RPM),
     (5e-6, 0.0, 20e-6, 0.0, 0.0)),
    ("B7214C hybrid 10k", ref.params_b7214c(centrifugal=True, gyroscopic=True, race="hybrid", omega=10000 * RPM),
     (5e-6, 0.0, 20e-6, 0.0, 1e-4)),
    ("B7214C IRC 6k, balls lifted", ref.params_b7214c(centrifugal=True, gyroscopic=True, race="inner",
     omega=6000 * RPM), (30e-6, 0.0, 4e-6, 0.0, 0.0)),
]  # fmt: skip


@pytest.mark.parametrize("label, p, d", BALL_CASES, ids=[c[0] for c in BALL_CASES])
def test_ball_equilibrium_matches_twin(label, p, d):
    qs, g = pack(p), ref.geometry(p)
    K_s = (p["K_i"] ** (-2.0 / 3.0) + p["K_o"] ** (-2.0 / 3.0)) ** -1.5
    X = np.zeros((jones_harris.X_SIZE, g["Z"]))
    kg, w, cond = np.empty((3, jones_harris.KG_SIZE)), np.empty(jones_harris.EV_SIZE), np.empty(jones_harris.BE_SIZE)
    inner_free = 0  # balls off the inner race (held on the outer one by the centrifugal force, or free)
    for j, psi in enumerate(g["psi"]):
        A1, A2 = ref.groove_centre_offset(d, psi, g)
        geo = (g["r_i"], g["r_o"], K_s, jones_harris._F_FLOOR / g["Z"])  # the strictest ball test: no applied load
        status = jones_harris.ball_equilibrium(A1, A2, X, j, qs, geo, p["omega"], kg, w, cond)
        twin = ref.ball_state(A1, A2, p, g=g)
        q_scale = max(twin["Q_i"], twin["Q_o"], 1e-3)
        assert status in (0, 1)
        inner_free += cond[jones_harris.BE_Q_I] == 0.0
        for slot, key in (
            (jones_harris.BE_Q_I, "Q_i"),
            (jones_harris.BE_Q_O, "Q_o"),
            (jones_harris.BE_GZ, "g_z"),
            (jones_harris.BE_GR, "g_r"),
        ):
            assert cond[slot] == pytest.approx(twin[key], abs=1e-8 * q_scale), (label, j, key)
        assert cond[jones_harris.BE_MG] == pytest.approx(twin["m_g"], abs=1e-8 * q_scale * p["D"]), (label, j)
        if twin["Q_i"] > 0.0 and twin["Q_o"] > 0.0:
            assert cond[jones_harris.BE_A_I] == pytest.approx(twin["a_i"], abs=1e-8), (label, j)
            assert cond[jones_harris.BE_A_O] == pytest.approx(twin["a_o"], abs=1e-8), (label, j)
            assert X[:2, j] == pytest.approx([twin["X1"], twin["X2"]], abs=1e-8 * p["D"]), (label, j)
    if "lifted" in label:
        assert inner_free > 0


@pytest.mark.parametrize("label, p, d", BALL_CASES, ids=[c[0] for c in BALL_CASES])
def test_ring_loads_and_bearing_loads_match_twin(label, p, d):
    qs = pack(p)
    Z = int(qs[jones_harris.QS_Z])
    d = np.array(d)
    F_ref, twin_balls = ref.bearing_loads(d, p)
    contact = np.empty((jones_harris.CS_SIZE, Z))
    results = []
    for jacobian in (True, False):
        F, K = np.zeros(5), np.full((5, 5), np.nan)
        jones_harris.ring_loads(d, qs, 0.0, p["omega"], np.zeros((jones_harris.X_SIZE, Z)), F, K, contact, jacobian)
        assert np.allclose(F, F_ref, rtol=0, atol=1e-8 * np.max(np.abs(F_ref))), label
        assert np.all(np.isfinite(K)) == jacobian  # without the Jacobian K is not touched
        results.append(F)
    assert np.array_equal(results[0], results[1])
    # bearing_loads = ring_loads with the Jacobian + the per-ball outputs
    balls = np.zeros((jones_harris.BQ_SIZE, Z))
    F = np.zeros(5)
    jones_harris.bearing_loads(d, qs, 0.0, p["omega"], np.zeros((2, Z)), F, np.zeros((5, 5)), balls)
    assert np.array_equal(F, results[0])
    q_scale = max(b["Q_o"] for b in twin_balls)
    for j, b in enumerate(twin_balls):
        assert balls[jones_harris.BQ_Q_I, j] == pytest.approx(b["Q_i"], abs=1e-8 * q_scale), (label, j)
        assert balls[jones_harris.BQ_Q_O, j] == pytest.approx(b["Q_o"], abs=1e-8 * q_scale), (label, j)
