"""kernels.jones_harris against its slow twin (tests/reference/ref_jones_harris.py) and against itself.

The twin solves every ball with scipy.optimize.root on polar unknowns and the bearing with
scipy.optimize.root; the kernel uses nested damped Newton with analytic derivatives. Both follow
the same model definition, with the same Hertz constants (copied from the twin's parameter dict).

Tolerances:
- displacement-controlled loads and ball states: the twin accepts ball residuals of 1e-10 of the
  ball load, the kernel 1e-13: loads agree to 1e-8 relative of the largest load;
- load-controlled solutions: the twin stops at a scaled residual of 1e-9, so displacements agree
  to 1e-6 relative of the largest displacement (a stiffness of ~1e8 N/m turns 1e-9 of the load
  into ~1e-9 of the displacement; 1e-6 leaves room for the twin's step tolerance);
- Jacobian vs central differences: 1e-5 relative on every entry above 1e-6 of
  the largest. The difference step h = 1e-9 m (1e-8 rad) makes the truncation error ~h^2 K'''/6
  ~ 1e-9 relative and the rounding error ~eps F/h ~ 1e-7 relative.
"""

import math

import numpy as np
import pytest

from bearing_fmu.kernels import jones_harris
from tests.reference import ref_jones_harris as ref

RPM = 2.0 * math.pi / 60.0
RACES = {
    "outer": jones_harris.RACE_OUTER,
    "inner": jones_harris.RACE_INNER,
    "hybrid": jones_harris.RACE_HYBRID,
    "hybrid_outer": jones_harris.RACE_HYBRID_OUTER_SPLIT,
    "hybrid_inner": jones_harris.RACE_HYBRID_INNER_SPLIT,
    "hybrid_equal": jones_harris.RACE_HYBRID_EQUAL_SPLIT,
    "hybrid_controlling": jones_harris.RACE_HYBRID_CONTROLLING,
}


def pack(p, tol=1e-12, maxit=100):
    """Kernel parameter array from a twin parameter dict (same K, mass, c_hyb)."""
    qs = np.zeros(jones_harris.QS_SIZE)
    qs[jones_harris.QS_Z] = p["Z"]
    qs[jones_harris.QS_D] = p["D"]
    qs[jones_harris.QS_DM] = p["dm"]
    qs[jones_harris.QS_FI] = p["f_i"]
    qs[jones_harris.QS_FO] = p["f_o"]
    qs[jones_harris.QS_PD] = p["Pd"]
    qs[jones_harris.QS_ANGULAR] = 1.0 if p["angular"] else 0.0
    qs[jones_harris.QS_K_I] = p["K_i"]
    qs[jones_harris.QS_K_O] = p["K_o"]
    qs[jones_harris.QS_M_BALL] = p["m_ball"]
    qs[jones_harris.QS_RACE] = RACES[p["race"]]
    qs[jones_harris.QS_CENTRIFUGAL] = 1.0 if p["centrifugal"] else 0.0
    qs[jones_harris.QS_GYROSCOPIC] = 1.0 if p["gyroscopic"] else 0.0
    qs[jones_harris.QS_C_HYB] = p["c_hyb"]
    qs[jones_harris.QS_TOL] = tol
    qs[jones_harris.QS_MAXIT] = maxit
    qs[jones_harris.QS_STIFFNESS] = 1.0
    return qs


def kernel_loads(qs, d, omega, dPd=0.0, X=None):
    Z = int(qs[jones_harris.QS_Z])
    X = np.zeros((2, Z)) if X is None else X
    F = np.zeros(5)
    K = np.zeros((5, 5))
    balls = np.zeros((jones_harris.BQ_SIZE, Z))
    status = jones_harris.bearing_loads(np.asarray(d, float), qs, dPd, omega, X, F, K, balls)
    return status, F, K, balls, X


def kernel_solve(qs, F_applied, omega, control=(1, 1, 1, 1, 1), d0=None, dPd=0.0):
    Z = int(qs[jones_harris.QS_Z])
    d = np.zeros(5) if d0 is None else np.array(d0, float)
    X = np.zeros((2, Z))
    F = np.zeros(5)
    K = np.zeros((5, 5))
    balls = np.zeros((jones_harris.BQ_SIZE, Z))
    status, iters, res = jones_harris.solve_quasistatic(
        np.asarray(F_applied, float), np.asarray(control, float), d, qs, dPd, omega, X, F, K, balls
    )
    return status, d, F, K, balls, X


def central_difference(qs, d, omega, X, h_len=1e-9, h_rot=1e-8):
    """dF/dd by central differences of the kernel's own displacement-controlled loads."""
    K = np.zeros((5, 5))
    for k in range(5):
        h = h_len if k < 3 else h_rot
        plus = d.copy()
        plus[k] += h
        minus = d.copy()
        minus[k] -= h
        Fp = kernel_loads(qs, plus, omega, X=X.copy())[1]
        Fm = kernel_loads(qs, minus, omega, X=X.copy())[1]
        K[:, k] = (Fp - Fm) / (2.0 * h)
    return K


def relative_entry_error(K, K_ref, floor=1e-6):
    big = np.abs(K_ref).max()
    mask = np.abs(K_ref) > floor * big
    return np.max(np.abs(K - K_ref)[mask] / np.abs(K_ref)[mask])


THRUST = (0.0, 0.0, 800.0, 0.0, 0.0)  # F_x, F_y, F_z (N), M_x, M_y (N.m)
COMBINED = (400.0, -200.0, 1500.0, 10.0, 5.0)


def _b7214c_10k(label, race, loads=THRUST):
    """A load case of the B7214C at 10 000 rpm with its centrifugal and gyroscopic loads, under the race control
    `race`: (label, parameters, loads, omega rad/s)."""
    return label, ref.params_b7214c(centrifugal=True, gyroscopic=True, race=race), loads, 10000 * RPM


LOAD_CASES = [
    ("6208 radial at rest", ref.params_6208(), (3000.0, 0.0, 0.0, 0.0, 0.0), 0.0),
    ("6208 clearance, combined", ref.params_6208(Pd=20e-6), (2000.0, 500.0, 300.0, 0.0, 0.0), 0.0),
    ("6208 preloaded, moment", ref.params_6208(Pd=-10e-6), (1000.0, 0.0, 200.0, 5.0, -3.0), 0.0),
    ("B7214C axial at rest", ref.params_b7214c(), THRUST, 0.0),
    ("B7214C ORC 10k", ref.params_b7214c(centrifugal=True, race="outer"), THRUST, 10000 * RPM),
    _b7214c_10k("B7214C ORCG 10k", "outer"),
    _b7214c_10k("B7214C hybrid 10k", "hybrid"),
    _b7214c_10k("B7214C hybrid outer-split 10k", "hybrid_outer"),
    _b7214c_10k("B7214C hybrid inner-split 10k", "hybrid_inner"),
    _b7214c_10k("B7214C hybrid equal-split 10k combined", "hybrid_equal", COMBINED),
    _b7214c_10k("B7214C IRC 10k combined", "inner", COMBINED),
]


@pytest.mark.parametrize("label,p,F_applied,omega", LOAD_CASES, ids=[c[0] for c in LOAD_CASES])
def test_solution_matches_twin(label, p, F_applied, omega):
    """Load-controlled solution: displacements, ball loads and contact angles equal the twin's."""
    p = dict(p, omega=omega)
    status, d, F, K, balls, X = kernel_solve(pack(p), F_applied, omega)
    assert status == jones_harris.QS_OK
    d_ref = ref.solve_loads(F_applied, p)
    scale = np.array([1, 1, 1, p["dm"] / 2, p["dm"] / 2])
    assert np.max(np.abs((d - d_ref) * scale)) <= 1e-6 * np.max(np.abs(d_ref * scale))
    F_ref, ref_balls = ref.bearing_loads(d, p)
    assert np.allclose(F, F_ref, rtol=0, atol=1e-8 * np.max(np.abs(F_ref)))
    q_scale = max(b["Q_o"] for b in ref_balls)
    for j, b in enumerate(ref_balls):
        assert balls[jones_harris.BQ_Q_I, j] == pytest.approx(b["Q_i"], abs=1e-8 * q_scale)
        assert balls[jones_harris.BQ_Q_O, j] == pytest.approx(b["Q_o"], abs=1e-8 * q_scale)
        if b["Q_i"] > 1e-6 * q_scale:
            assert balls[jones_harris.BQ_A_I, j] == pytest.approx(b["a_i"], abs=1e-8)
            assert balls[jones_harris.BQ_A_O, j] == pytest.approx(b["a_o"], abs=1e-8)
            assert balls[jones_harris.BQ_W_M, j] == pytest.approx(b["w_m"], rel=1e-8, abs=1e-9)
            assert balls[jones_harris.BQ_BETA, j] == pytest.approx(b["beta"], abs=1e-8)


@pytest.mark.parametrize("label,p,F_applied,omega", LOAD_CASES, ids=[c[0] for c in LOAD_CASES])
def test_jacobian_matches_central_differences(label, p, F_applied, omega):
    """The analytic K vs central differences <= 1e-5 relative (entries above 1e-6 of the largest),
    against the kernel's own loads and against the twin's central differences."""
    p = dict(p, omega=omega)
    status, d, F, K, balls, X = kernel_solve(pack(p), F_applied, omega)
    assert status == jones_harris.QS_OK
    assert relative_entry_error(K, central_difference(pack(p), d, omega, X)) <= 1e-5
    assert relative_entry_error(K, np.asarray(ref.stiffness_fd(d, p))) <= 1e-5


@pytest.mark.parametrize(
    "label,p,F_applied,omega", [c for c in LOAD_CASES if c[3] == 0.0], ids=[c[0] for c in LOAD_CASES if c[3] == 0.0]
)
def test_stiffness_symmetric_at_rest(label, p, F_applied, omega):
    """At zero speed the ball forces derive from the Hertz potential: K is symmetric to 1e-8
    (relative to its largest entry, in consistent units: rotations as arc lengths at Rr_i)."""
    qs = pack(p)
    status, d, F, K, balls, X = kernel_solve(qs, F_applied, 0.0)
    Rr = jones_harris.qs_geometry(qs, 0.0)[5]
    s = np.array([1.0, 1.0, 1.0, Rr, Rr])
    Ks = K / np.outer(s, s)
    assert np.max(np.abs(Ks - Ks.T)) <= 1e-8 * np.max(np.abs(Ks))


@pytest.mark.parametrize("omega", [0.0, 10000 * RPM])
def test_pure_axial_load_gives_axisymmetric_positive_definite_stiffness(omega):
    """Preloaded angular-contact bearing under pure axial load (all balls loaded): K_xx = K_yy and
    K_txtx = K_tyty (to 1e-9: the 17 balls are an evenly spaced ring, sums of cos^2 and sin^2 agree
    to rounding), and the symmetric part of K is positive definite."""
    p = ref.params_b7214c(centrifugal=True, gyroscopic=True, race="outer", omega=omega)
    status, d, F, K, balls, X = kernel_solve(pack(p), (0.0, 0.0, 800.0, 0.0, 0.0), omega)
    assert status == jones_harris.QS_OK and np.all(balls[jones_harris.BQ_Q_I] > 0.0)
    assert K[0, 0] == pytest.approx(K[1, 1], rel=1e-9)
    assert K[3, 3] == pytest.approx(K[4, 4], rel=1e-9)
    Rr = jones_harris.qs_geometry(pack(p), 0.0)[5]
    s = np.array([1.0, 1.0, 1.0, Rr, Rr])
    Ks = K / np.outer(s, s)
    assert np.all(np.linalg.eigvalsh(0.5 * (Ks + Ks.T)) > 0.0)


@pytest.mark.parametrize("omega", [0.0, 10000 * RPM])
def test_axial_stiffness_is_the_slope_of_the_load_deflection_curve(omega):
    """K_zz = dF_z/dz along the load-controlled load-deflection curve (F_z = 800 N +- 1 N, central
    difference: relative truncation error ~(1/800)^2, so 1e-5 holds)."""
    p = ref.params_b7214c(centrifugal=True, gyroscopic=True, race="hybrid", omega=omega)
    qs = pack(p)
    K_zz = kernel_solve(qs, (0.0, 0.0, 800.0, 0.0, 0.0), omega)[3][2, 2]
    z_plus = kernel_solve(qs, (0.0, 0.0, 801.0, 0.0, 0.0), omega)[1][2]
    z_minus = kernel_solve(qs, (0.0, 0.0, 799.0, 0.0, 0.0), omega)[1][2]
    assert K_zz == pytest.approx(2.0 / (z_plus - z_minus), rel=1e-5)


def test_kinematics_complex_step_matches_real_evaluation():
    """The complex-safe kinematics give the same real values as a direct real evaluation, and the
    outer-race-control law leaves no spin on the outer contact (Jones 1960)."""
    p = ref.params_b7214c(centrifugal=True, gyroscopic=True, race="outer", omega=1000.0)
    status, d, F, K, balls, X = kernel_solve(pack(p), (0.0, 0.0, 800.0, 0.0, 0.0), 1000.0)
    assert np.max(np.abs(balls[jones_harris.BQ_SPIN_O])) <= 1e-9 * np.max(np.abs(balls[jones_harris.BQ_SPIN_I]))
    F_ref, ref_balls = ref.bearing_loads(d, p)
    for j, b in enumerate(ref_balls):
        assert balls[jones_harris.BQ_W_R, j] == pytest.approx(b["w_R"], rel=1e-9)
        assert balls[jones_harris.BQ_F_C, j] == pytest.approx(b["F_c"], rel=1e-9)
        assert balls[jones_harris.BQ_M_G, j] == pytest.approx(b["M_g"], rel=1e-9)


def test_unloaded_bearing_with_clearance_stays_centred():
    """F = 0 with clearance: every ball is free, d = 0, K = 0 (singular, reported as zeros, no NaN)."""
    qs = pack(ref.params_6208(Pd=20e-6))
    status, d, F, K, balls, X = kernel_solve(qs, (0.0,) * 5, 0.0)
    assert status == jones_harris.QS_OK
    assert np.all(d == 0.0) and np.all(K == 0.0) and np.all(balls[jones_harris.BQ_Q_I] == 0.0)


@pytest.mark.parametrize("F_r", [1e-3, 1.0, 50.0])
def test_nearly_unloaded_bearing_converges(F_r):
    """A radial load far below the clearance's scale (one ball barely touching) converges: the
    Newton step from the unloaded start is regularised and capped, then backtracks."""
    qs = pack(ref.params_6208(Pd=20e-6))
    status, d, F, K, balls, X = kernel_solve(qs, (F_r, 0.0, 0.0, 0.0, 0.0), 0.0)
    assert status == jones_harris.QS_OK
    assert F[0] == pytest.approx(F_r, rel=1e-9)
    assert d[0] > 10e-6  # the ring crossed the radial clearance Pd/2
    assert np.all(np.isfinite(K))


def test_centrifugal_dominated_outer_contacts_at_very_high_speed():
    """d_m n = 2.9e6 mm.rpm (30 000 rpm on the B7214C), light axial load: the outer contacts carry
    mostly centrifugal force, and the solver still converges to a finite state."""
    omega = 30000 * RPM
    p = ref.params_b7214c(centrifugal=True, gyroscopic=True, race="outer", omega=omega)
    status, d, F, K, balls, X = kernel_solve(pack(p), (0.0, 0.0, 100.0, 0.0, 0.0), omega)
    assert status == jones_harris.QS_OK
    assert np.all(balls[jones_harris.BQ_Q_O] > 3.0 * balls[jones_harris.BQ_Q_I])
    assert np.all(balls[jones_harris.BQ_F_C] > 0.5 * balls[jones_harris.BQ_Q_O])
    assert np.all(np.isfinite(K))


def test_iteration_cap_reports_instead_of_hanging():
    """With a cap of 1 iteration the solver returns QS_NOT_CONVERGED (the facade turns it into a
    clear error) instead of looping."""
    qs = pack(ref.params_b7214c(centrifugal=True, race="outer"), maxit=1)
    status, *_ = kernel_solve(qs, (500.0, 0.0, 800.0, 0.0, 0.0), 10000 * RPM)
    assert status == jones_harris.QS_NOT_CONVERGED


def test_mixed_control_holds_the_imposed_axial_position():
    """drive 'fixed_axial': z imposed, radial loads applied; the reaction F_z is the axial load of
    the load-controlled solution at the same z (consistency of the two drives to 1e-8)."""
    p = ref.params_b7214c()
    qs = pack(p)
    status, d, F, K, balls, X = kernel_solve(qs, (300.0, 0.0, 800.0, 0.0, 0.0), 0.0)
    d0 = np.zeros(5)
    d0[2] = d[2]
    status2, d2, F2, *_ = kernel_solve(qs, (300.0, 0.0, 0.0, 0.0, 0.0), 0.0, control=(1, 1, 0, 1, 1), d0=d0)
    assert status2 == jones_harris.QS_OK
    assert F2[2] == pytest.approx(800.0, rel=1e-8)
    assert np.allclose(d2, d, rtol=0, atol=1e-12)
