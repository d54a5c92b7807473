"""The race control "traction" (kernels.ball_traction) against its twin (tests/reference/ref_ball_traction.py), and
its stiffness against central differences of its own solution.

Contacts: the 218 angular-contact bearing of the textbook thrust cases (40 deg, 16 balls) under 8.9 kN at 8 000 rpm
with the Guessasma oil (eta 0.04 Pa.s, limiting traction coefficient 0.06), where outer-race control would need
more traction than the oil carries, and the B7214C at 10 000 rpm under 800 N with ISO VG68, where it does not.
"""

import math

import numpy as np
import pytest

from bearing_fmu.kernels import ball_traction as bt
from bearing_fmu.kernels import ehl, jones_harris
from bearing_fmu.kernels.lubricant import lubricant_state
from bearing_fmu.models.limits import InputError
from bearing_fmu.models.quasi_static import QuasiStaticModel
from bearing_fmu.models.race_contacts import race_contacts, traction_block
from bearing_fmu.scene import Scene
from tests.reference import ref_ball_traction as ref

B218 = "tests/validation/data/angular_218_textbook.toml"
CASES = {
    "218 at 8000 rpm, 8.9 kN": (B218, "guessasma_oil", 8000.0, 8900.0),
    "B7214C at 10000 rpm, 800 N": ("B7214C", "iso_vg68_mineral", 10000.0, 800.0),
}
SCENE = Scene(name="traction", fidelity="quasi_static", torque=True, gyroscopic=True, stiffness=True)


def _ball(case):
    """(ball 0's contacts of the traction solution, the traction block, omega, D, dm, J, its kinematics y)."""
    bearing, lubricant, rpm, F_z = CASES[case]
    omega = rpm * math.pi / 30.0
    m = QuasiStaticModel(bearing, lubricant, scene=SCENE, race_control="traction")
    m.evaluate(omega=omega, F_z=F_z)
    tr = traction_block(m.bearing, m.scene, race_contacts(m.bearing, m.scene, m.Pd), m.lubricant)
    tr[bt.TR_ETA], tr[bt.TR_XI] = lubricant_state(313.15, m.lubricant.array)[:2]
    b = m.balls[:, 0]
    D, dm = m.bearing.D, m.bearing.dm
    J = 0.1 * m.qs[jones_harris.QS_M_BALL] * D * D
    return (
        (b[jones_harris.BQ_A_I], b[jones_harris.BQ_A_O], b[jones_harris.BQ_Q_I], b[jones_harris.BQ_Q_O]),
        tr,
        omega,
        D,
        dm,
        J,
        m.X[jones_harris.X_Y :, 0] * omega,
    )


@pytest.mark.parametrize("case", CASES)
def test_traction_eval_equals_its_twin(case):
    """Residuals, in-plane forces, powers, entrainment speeds and coefficients of both contacts at the outer-race
    kinematics and at a perturbed state, within 1e-9 of the largest contact load (same formulas, other algebra)."""
    contacts, tr, omega, D, dm, J, _ = _ball(case)
    for y in (ref.rolling_start(*contacts[:2], omega, D, dm), ref.rolling_start(*contacts[:2], omega, D, dm) * 1.01):
        out = np.zeros(bt.TE_SIZE)
        bt.traction_eval(y, *contacts, omega, D, dm, J, tr, out)
        twin = ref.traction_eval(y, *contacts, omega, D, dm, J, tr)
        scale = max(contacts[2:])
        assert out[: bt.TE_U_I] == pytest.approx(twin[: bt.TE_U_I], abs=1e-9 * scale)
        assert out[bt.TE_U_I :] == pytest.approx(twin[bt.TE_U_I :], rel=1e-9)


@pytest.mark.parametrize("case", CASES)
def test_solved_kinematics_and_their_derivatives_equal_the_twin(case):
    """Started near the bearing's solution, the kernel's Newton and scipy's root finder on the twin's residual find
    the same kinematics (1e-9 of omega);
    the kernel's implicit-function derivatives of (w_m, F_tau_i, F_tau_o) in (a_i, a_o, Q_i, Q_o) agree with central
    differences of re-solved twin kinematics within 1e-4 relative to each row's largest entry (the differences'
    truncation and the solutions' rounding)."""
    contacts, tr, omega, D, dm, J, solved = _ball(case)
    y = np.zeros(4)
    bt.rolling_start(*contacts[:2], omega, D, dm, y)
    assert y == pytest.approx(ref.rolling_start(*contacts[:2], omega, D, dm), rel=1e-12)
    start = solved * np.array([1.0001, 0.9999, 1.0002, 0.9])  # near the bearing's solution, as its solves start
    y = start.copy()
    out = np.zeros(bt.TE_SIZE)
    Dy = np.zeros((bt.TE_SIZE, 4))
    terms = np.zeros((2, bt.TT_SIZE))
    Dp = np.zeros((bt.TE_SIZE, 4))
    assert bt.solve_traction(y, *contacts, omega, D, dm, J, tr, terms, out, Dy, Dp)
    twin, ok = ref.solve_traction(*contacts, omega, D, dm, J, tr, start=start)
    assert ok
    assert y == pytest.approx(twin, abs=1e-9 * omega)
    dout = np.zeros((bt.TE_SIZE, 4))
    solved_out, solved_Dy = out.copy(), Dy.copy()
    bt.parameter_derivatives(y, np.array(contacts), omega, D, dm, J, tr, terms, out, Dy, dout, np.zeros((4, 4)))
    # the solve leaves the evaluation and its partials at the solution (film terms of its last Newton round, within
    # 1e-12 of the solution's), from which the bearing takes dy/dp
    assert solved_out == pytest.approx(out, rel=1e-9, abs=1e-12 * max(contacts[2:]))
    assert solved_Dy == pytest.approx(Dy, rel=1e-9, abs=1e-9 * np.abs(Dy).max())
    from_solve = Dp.copy()
    bt.implicit_derivatives(solved_Dy, from_solve, np.zeros((4, 4)), np.zeros((4, 8)))
    assert from_solve == pytest.approx(dout, rel=1e-9, abs=1e-9 * np.abs(dout).max())
    kernel = dout[[bt.TE_R, bt.TE_FTAU_I, bt.TE_FTAU_O]]
    expected = ref.parameter_derivatives(*contacts, omega, D, dm, J, tr, twin)
    for row in range(3):
        assert kernel[row] == pytest.approx(expected[row], abs=1e-4 * np.abs(expected[row]).max())


@pytest.mark.parametrize("case", CASES)
def test_the_stiffness_is_the_derivative_of_the_traction_solution(case):
    """K of the traction solution against central differences of the solved bearing's loads in each displacement
    (displacement-controlled, steps of 1e-8 m and 1e-8 rad): within 1 % of the largest entry of each column (the
    acceptance of the race control; measured 1e-6)."""
    bearing, lubricant, rpm, F_z = CASES[case]
    omega = rpm * math.pi / 30.0
    m = QuasiStaticModel(bearing, lubricant, scene=SCENE, race_control="traction")
    m.evaluate(omega=omega, F_z=F_z)
    d0, X0, K = m.d.copy(), m.X.copy(), m.K.copy()
    F = np.zeros(5)
    contact = np.zeros((jones_harris.CS_SIZE, m.bearing.Z))
    for c in range(5):
        loads = []
        for sgn in (1.0, -1.0):
            d = d0.copy()
            d[c] += sgn * 1e-8
            X = X0.copy()
            assert jones_harris.ring_loads(d, m.qs, 0.0, omega, X, F, np.zeros((5, 5)), contact, False, F_z) == 0
            loads.append(F.copy())
        fd = (loads[0] - loads[1]) / 2e-8
        assert K[:, c] == pytest.approx(fd, abs=0.01 * np.abs(fd).max())


def _central_differences(y, contacts, omega, D, dm, J, tr, terms, u, step):
    """Central differences of _residual's outputs in y (steps 1e-7 omega, terms held) and in the contacts (step rad,
    step Q; a load's terms and film follow it at the entrainment speeds u)."""
    p = np.array(contacts)
    fy, fp = np.zeros((bt.TE_SIZE, 4)), np.zeros((bt.TE_SIZE, 4))
    for c in range(4):
        values = []
        for sgn in (1.0, -1.0):
            z = y.copy()
            z[c] += sgn * 1e-7 * omega
            values.append(np.zeros(bt.TE_SIZE))
            bt._residual(z, *p, omega, D, dm, J, tr, terms, values[-1])
        fy[:, c] = (values[0] - values[1]) / 2e-7 / omega
        h = step if c < 2 else step * p[c]
        values = []
        for sgn in (1.0, -1.0):
            q, held = p.copy(), terms.copy()
            q[c] += sgn * h
            if c >= 2:
                bt._load_terms(c - 2, q[c], D, tr, held)
                bt._film(c - 2, u[c - 2], tr, held)
            values.append(np.zeros(bt.TE_SIZE))
            bt._residual(y, *q, omega, D, dm, J, tr, held, values[-1])
        fp[:, c] = (values[0] - values[1]) / (2.0 * h)
    return fy, fp


@pytest.mark.parametrize("case", CASES)
@pytest.mark.parametrize("film", ["full film", "mixed film, Hamrock-Dowson", "mixed film, Masjedi-Khonsari"])
def test_closed_form_partials_equal_central_differences(case, film):
    """_residual_d: the same outputs as _residual (bit for bit), and partials in y and in the contacts within 1e-5 of
    each row's largest central difference, at the solved kinematics and at a state that slides and spins; in a full
    film and in a mixed one (Lambda = 2) (the film share and mu(Lambda) then follow the load). The contacts'
    differences take steps of 1e-6 and 1e-8 (relative for the loads), each row the closer: near a spin of 0 the
    regularised pivoting moment curves the moments too much for the first (2e-4 of error) and the powers round too
    much for the second (3e-5)."""
    contacts, tr, omega, D, dm, J, solved = _ball(case)
    tr = tr.copy()
    if film != "full film":  # the roughness that puts both contacts at Lambda = 2 in the solved kinematics
        tr[bt.TR_FILM] = 1.0 if "Masjedi" in film else 0.0
        terms, out = np.zeros((2, bt.TT_SIZE)), np.zeros(bt.TE_SIZE)
        bt._terms_at(solved, *contacts, omega, D, dm, tr, terms)
        bt._residual(solved, *contacts, omega, D, dm, J, tr, terms, out)
        for race in range(2):
            o = bt.TR_STRIDE * race
            args = (tr[bt.TR_ETA], tr[bt.TR_XI], tr[bt.TR_E_RED], out[bt.TE_U_I + race], contacts[2 + race])
            h_min = ehl.film_thickness(int(tr[bt.TR_FILM]), *args, tr[o + bt.TR_RX], tr[o + bt.TR_RY], tr[o + bt.TR_K])[
                1
            ]
            tr[o + bt.TR_SIGMA] = h_min / 2.0
    p = np.array(contacts)
    for y in (solved, solved * np.array([1.001, 0.999, 1.01, 1.0]) + np.array([0.0, 0.0, 0.0, 1e-3 * omega])):
        terms = np.zeros((2, bt.TT_SIZE))
        bt._terms_at(y, *contacts, omega, D, dm, tr, terms)
        if film != "full film":
            assert 0.0 < terms[0, bt.TT_PHI] < 1.0 and 0.0 < terms[1, bt.TT_PHI] < 1.0
            assert terms[0, bt.TT_DPHI] != 0.0 and terms[1, bt.TT_DMU] != 0.0
        out, Dy, Dp = np.zeros(bt.TE_SIZE), np.zeros((bt.TE_SIZE, 4)), np.zeros((bt.TE_SIZE, 4))
        bt._residual_d(y, p, omega, D, dm, J, tr, terms, out, Dy, Dp)
        plain = np.zeros(bt.TE_SIZE)
        bt._residual(y, *contacts, omega, D, dm, J, tr, terms, plain)
        assert np.array_equal(out, plain)
        u = out[bt.TE_U_I : bt.TE_U_O + 1]
        fy, fp = _central_differences(y, contacts, omega, D, dm, J, tr, terms, u, 1e-6)
        fp_fine = _central_differences(y, contacts, omega, D, dm, J, tr, terms, u, 1e-8)[1]
        for row in range(bt.TE_SIZE):
            assert Dy[row] == pytest.approx(fy[row], abs=1e-5 * np.abs(fy[row]).max()), row
            err = min(np.abs(Dp[row] - f).max() / np.abs(f).max() for f in (fp[row], fp_fine[row]))
            assert err <= 1e-5, row


def test_a_ball_beyond_its_groove_centre_is_refused_for_that_reason():
    """The 6208 with the largest clearance its grooves allow (P_d = (f_i + f_o - 1) D, free contact angle 60 deg)
    under 3 kN radial load at 500 rad/s: a ball on the unloaded side turns beyond the centre of its inner groove
    (inner contact angle 180 deg), where the rolling start of its traction kinematics has a zero denominator. The
    model refuses the state naming that reason (an InputError), as it does under outer-race control; it raised a
    bare ZeroDivisionError from inside the solve before."""
    b = QuasiStaticModel("6208").bearing
    m = QuasiStaticModel("6208", Pd=(b.f_i + b.f_o - 1.0) * b.D, race_control="traction")
    with pytest.raises(InputError, match="beyond the centre of curvature of its inner groove"):
        m.evaluate(omega=500.0, F_y=3000.0)
