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
from bearing_fmu.kernels import jones_harris as qk
from bearing_fmu.kernels.lubricant import lubricant_state
from bearing_fmu.models.contacts import race_contacts, traction_block
from bearing_fmu.models.quasi_static import QuasiStaticModel
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
    J = 0.1 * m.qs[qk.QS_M_BALL] * D * D
    return (b[qk.BQ_A_I], b[qk.BQ_A_O], b[qk.BQ_Q_I], b[qk.BQ_Q_O]), tr, omega, D, dm, J, m.X[qk.X_Y :, 0] * omega


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
    assert bt.solve_traction(y, *contacts, omega, D, dm, J, tr, terms, out, Dy)
    twin, ok = ref.solve_traction(*contacts, omega, D, dm, J, tr, start=start)
    assert ok
    assert y == pytest.approx(twin, abs=1e-9 * omega)
    dout = np.zeros((bt.TE_SIZE, 4))
    bt.parameter_derivatives(y, np.array(contacts), omega, D, dm, J, tr, terms, out, Dy, dout, np.zeros((4, 4)))
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
    contact = np.zeros((qk.CS_SIZE, m.bearing.Z))
    for c in range(5):
        loads = []
        for sgn in (1.0, -1.0):
            d = d0.copy()
            d[c] += sgn * 1e-8
            X = X0.copy()
            assert qk.ring_loads(d, m.qs, 0.0, omega, X, F, np.zeros((5, 5)), contact, False, F_z) == 0
            loads.append(F.copy())
        fd = (loads[0] - loads[1]) / 2e-8
        assert K[:, c] == pytest.approx(fd, abs=0.01 * np.abs(fd).max())
