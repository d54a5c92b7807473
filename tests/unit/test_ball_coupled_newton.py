"""The coupled Newton of a ball under the race control "traction" (kernels.ball_coupled_newton): its Jacobian is the
derivative of its residuals, and its solution is the nested solve's (kernels.jones_harris: the ball's position by
Newton around kernels.ball_traction.solve_traction, itself compared with its twin in test_ball_traction.py).

Contacts: the cases of test_ball_traction.py, the 218 angular-contact bearing under 8.9 kN at 8 000 rpm (the
balls skid: outer-race control would need more traction than the oil carries) and the B7214C at 10 000 rpm under
800 N, both in a full film (the film terms are then constants, and central differences see the held derivatives).
"""

import math

import numpy as np
import pytest

from bearing_fmu.kernels import ball_coupled_newton as bc
from bearing_fmu.kernels import ball_traction as bt
from bearing_fmu.kernels import jones_harris
from bearing_fmu.kernels.geometry import ball_direction
from bearing_fmu.models.quasi_static import QuasiStaticModel
from bearing_fmu.scene import Scene

CASES = {
    "218 at 8000 rpm, 8.9 kN": ("tests/validation/data/angular_218_textbook.toml", "guessasma_oil", 8000.0, 8900.0),
    "B7214C at 10000 rpm, 800 N": ("B7214C", "iso_vg68_mineral", 10000.0, 800.0),
}
SCENE = Scene(name="traction", fidelity="quasi_static", torque=True, gyroscopic=True, stiffness=True)


def _ball(case, j=0, load=1.0):
    """(ball, its solved z = (X1, X2, y), the traction block, the bearing-level load per ball) of ball j of the bearing
    solved under load x its case's thrust; ball is kernels.ball_coupled_newton._evaluate's tuple."""
    bearing, lubricant, rpm, F_z = CASES[case]
    omega = rpm * math.pi / 30.0
    m = QuasiStaticModel(bearing, lubricant, scene=SCENE, race_control="traction")
    m.evaluate(omega=omega, F_z=load * F_z)
    qs, d = m.qs, m.d
    _, r_i, r_o, A1_0, A2_0, Rr, _ = jones_harris.qs_geometry(qs, 0.0)
    cp, sp = ball_direction(j, m.bearing.Z)
    A1 = A1_0 + d[2] + Rr * (d[3] * sp - d[4] * cp)
    A2 = A2_0 + d[0] * cp + d[1] * sp
    D, dm, m_ball = qs[jones_harris.QS_D], qs[jones_harris.QS_DM], qs[jones_harris.QS_M_BALL]
    ball = (
        A1,
        A2,
        r_i,
        r_o,
        qs[jones_harris.QS_K_I],
        qs[jones_harris.QS_K_O],
        omega,
        D,
        dm,
        0.1 * m_ball * D * D,
        0.5 * m_ball * dm,
    )
    z = np.concatenate([m.X[:2, j], m.X[jones_harris.X_Y :, j] * omega])
    return ball, z, qs[jones_harris.QS_TRACTION :].copy(), F_z / m.bearing.Z


def _work():
    return (np.zeros((2, bt.TT_SIZE)), np.zeros(bt.TE_SIZE), np.zeros((bt.TE_SIZE, 4)), np.zeros((bt.TE_SIZE, 4)))


def _evaluate(z, ball, tr, terms):
    """(R, G, the contacts p) at z."""
    _, out, Dy, Dp = _work()
    R, G, p = np.zeros(6), np.zeros((6, 7)), np.zeros(4)
    assert bc._evaluate(z, ball, tr, terms, out, Dy, Dp, p, R, G)
    return R, G[:, :6], p


@pytest.mark.parametrize("case", CASES)
def test_the_jacobian_is_the_derivative_of_the_residuals(case):
    """G against central differences of R (steps 1e-10 m in X, 1e-7 omega in y) at the solution and at a state
    0.2 um and 1 % away from it: within 1e-5 of each row's largest difference (truncation and rounding; the closed
    forms of the traction's partials are themselves checked to 1e-5 in test_ball_traction.py)."""
    ball, solved, tr, _ = _ball(case)
    omega = ball[6]
    terms = np.zeros((2, bt.TT_SIZE))
    moved = solved + np.array([2e-7, -2e-7, 0.01 * solved[2], 0.0, 0.01 * solved[4], 1e-3 * omega])
    for z in (solved, moved):
        R, G, _ = _evaluate(z, ball, tr, terms)
        assert terms[0, bt.TT_LAM] > 3.1 and terms[1, bt.TT_LAM] > 3.1  # a full film: its terms are constants
        fd = np.zeros((6, 6))
        for c in range(6):
            h = 1e-10 if c < 2 else 1e-7 * omega
            plus, minus = z.copy(), z.copy()
            plus[c] += h
            minus[c] -= h
            fd[:, c] = (_evaluate(plus, ball, tr, terms)[0] - _evaluate(minus, ball, tr, terms)[0]) / (2.0 * h)
        for r in range(6):
            assert G[r] == pytest.approx(fd[r], abs=1e-5 * np.abs(fd[r]).max()), r


@pytest.mark.parametrize("case", CASES)
def test_its_solution_is_the_nested_solves(case):
    """From the ball's solution under a thrust 3 % higher (the start a co-simulation step gives it), the coupled
    Newton converges; at its position X the nested solve (the kinematics' own Newton at X's contacts) finds its
    kinematics within 1e-9 omega, and with their traction forces the ball's force balance holds within the ball
    Newton's tolerance (kernels.jones_harris._BALL_RTOL of its loads). The position is the bearing's solution
    within 1e-9. (Far starts are the nested solve's: near outer-race control the regularised pivoting moment is
    steep, and the coupled Newton, without the nested solve's Levenberg-Marquardt steps, may decline.)"""
    ball, solved, tr, f_ball = _ball(case)
    A1, A2, r_i, r_o, K_i, K_o, omega, D, dm, J, fc = ball
    start = _ball(case, load=1.03)[1]
    assert np.abs(start[:2] - solved[:2]).max() > 1e-8  # a start that differs
    x, y = start[:2].copy(), start[2:].copy()
    terms, out, Dy, Dp = _work()
    cw = bc.coupled_work()
    assert bc.coupled_newton(x, y, ball, f_ball, jones_harris._BALL_RTOL, tr, terms, out, Dy, Dp, np.zeros(4), cw)
    assert x == pytest.approx(solved[:2], rel=1e-9)
    _, so, co, _, si, ci, Q_o, _, Q_i, _ = bc.ball_contacts(x[0], x[1], A1, A2, r_i, r_o, K_i, K_o)
    a_i, a_o = math.atan2(A1 - x[0], A2 - x[1]), math.atan2(x[0], x[1])
    nested = start[2:].copy()  # the kinematics' own Newton from the same start
    terms, out, Dy, Dp = _work()
    assert bt.solve_traction(nested, a_i, a_o, Q_i, Q_o, omega, D, dm, J, tr, terms, out, Dy, Dp)
    assert nested == pytest.approx(y, abs=1e-9 * omega)
    Mgi, Mgo = -out[bt.TE_FTAU_I], -out[bt.TE_FTAU_O]
    r1 = Q_i * si - Mgi * ci - Q_o * so + Mgo * co
    r2 = Q_i * ci + Mgi * si - Q_o * co + fc * nested[0] ** 2 - Mgo * so
    assert math.hypot(r1, r2) <= jones_harris._BALL_RTOL * (Q_i + Q_o + f_ball)


def test_it_leaves_the_start_alone_where_a_contact_is_open():
    """A ball whose inner contact is open has no traction kinematics: the coupled Newton declines at once and
    leaves x and y as they were (the nested solve then rolls the ball on its outer race)."""
    ball, solved, tr, f_ball = _ball("B7214C at 10000 rpm, 800 N")
    A1, A2 = ball[0], ball[1]
    n = math.hypot(A1, A2)
    x = solved[:2] - 2e-5 * np.array([A1, A2]) / n  # 20 um away from the inner race, along the line of centres
    y = solved[2:].copy()
    x0, y0 = x.copy(), y.copy()
    terms, out, Dy, Dp = _work()
    assert not bc.coupled_newton(
        x, y, ball, f_ball, jones_harris._BALL_RTOL, tr, terms, out, Dy, Dp, np.zeros(4), bc.coupled_work()
    )
    assert np.array_equal(x, x0) and np.array_equal(y, y0)
