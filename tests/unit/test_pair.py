"""bearing_fmu.models.pair: duplex pairs of quasi-static bearings (X/O, spring or fixed preload).

Two B7214C (iso_vg68_mineral, centrifugal and gyroscopic on), F_p = 800 N, spacing 0.1 m. The pair
Newton stops at a load residual of 1e-12 x F_p (scene tolerance), so loads that are equal by
construction agree to ~1e-12 relative; the tests ask 1e-9 (margin for the rounding of the ball sums
and of the spring-loaded bearing's own Newton, which stops at the same relative tolerance).
"""

import math

import numpy as np
import pytest

from bearing_fmu.kernels.jones_harris import BQ_A_I, BQ_A_O
from bearing_fmu.models.limits import InputError
from bearing_fmu.models.pair import PairAssembly, solve_pair
from bearing_fmu.models.quasi_static import QuasiStaticModel, SolverError
from bearing_fmu.scene import Scene

RPM = 2.0 * math.pi / 60.0
F_P = 800.0
SPACING = 0.1
COMBINED = (500.0, -200.0, 300.0, 20.0, -10.0)  # N, N, N, N.m, N.m at the pair centre


@pytest.fixture(scope="module")
def model():
    scene = Scene(
        name="qs",
        fidelity="quasi_static",
        centrifugal=True,
        gyroscopic=True,
        stiffness=True,
        torque=False,
        tolerance=1e-12,
    )
    return QuasiStaticModel("B7214C", "iso_vg68_mineral", scene)


def pair(model, arrangement="X", preload="spring"):
    return PairAssembly(model, model, arrangement, preload, F_P, SPACING)


def relative_entry_error(K, K_ref, floor=1e-6):
    big = np.abs(K_ref).max()
    mask = np.abs(K_ref) > floor * big
    return np.max(np.abs(K - K_ref)[mask] / np.abs(K_ref)[mask])


@pytest.mark.parametrize("arrangement", ["X", "O"])
def test_spring_preload_at_rest(model, arrangement):
    """Spring preload, at rest: with no external load each bearing carries exactly F_p and the shaft
    stays centred (radial displacements and tilts are rounding of the ball sums: < 1e-9 of the axial
    approach); under F_z = +-300 N the spring-loaded B still carries F_p and A carries F_p + F_z."""
    p = pair(model, arrangement, "spring")
    r = p.solve((0.0,) * 5, 0.0)
    A, B = r.axial_loads
    assert A == pytest.approx(F_P, rel=1e-9) and B == pytest.approx(F_P, rel=1e-9)
    z = r.bearings[0].d[2]
    assert z > 0.0
    assert np.all(np.abs(r.D[[0, 1]]) <= 1e-9 * z)
    assert np.all(np.abs(r.D[[3, 4]]) * 0.5 * SPACING <= 1e-9 * z)
    for F_z in (300.0, -300.0):
        r = p.solve((0.0, 0.0, F_z, 0.0, 0.0), 0.0)
        A, B = r.axial_loads
        assert B == pytest.approx(F_P, rel=1e-9)
        assert A == pytest.approx(F_P + F_z, rel=1e-9)
        assert np.sign(r.D[2]) == np.sign(F_z)  # +F_z pushes the shaft towards +z
        assert np.all(np.abs(r.D[[0, 1]]) <= 1e-9 * z)


@pytest.mark.parametrize("arrangement", ["X", "O"])
def test_fixed_preload(model, arrangement):
    """Fixed preload: at rest with no load both bearings carry F_p (the assembly offset, to 1e-9);
    under F_z = 300 N A's load rises, B's falls, and A - B = F_z (shaft axial equilibrium, 1e-9 of
    F_p); at 10 000 rpm the centrifugal ball loads change the fixed preload (by far more than 1 %)
    while the spring preload stays F_p."""
    p = pair(model, arrangement, "fixed")
    A, B = p.solve((0.0,) * 5, 0.0).axial_loads
    assert A == pytest.approx(F_P, rel=1e-9) and B == pytest.approx(F_P, rel=1e-9)
    A, B = p.solve((0.0, 0.0, 300.0, 0.0, 0.0), 0.0).axial_loads
    assert A > F_P > B
    assert A - B == pytest.approx(300.0, abs=1e-9 * F_P)
    A, B = p.solve((0.0,) * 5, 10000 * RPM).axial_loads
    assert A == pytest.approx(B, rel=1e-9)
    assert abs(A - F_P) > 0.01 * F_P
    spring = pair(model, arrangement, "spring").solve((0.0,) * 5, 10000 * RPM)
    assert spring.axial_loads[0] == pytest.approx(F_P, rel=1e-9)
    assert spring.axial_loads[1] == pytest.approx(F_P, rel=1e-9)


def test_thermal_offset_changes_only_the_fixed_preload(model):
    """dz_thermal > 0 tightens a fixed pair (both axial loads rise, equal by symmetry to 1e-9) and
    leaves a spring-preloaded pair at F_p (the spring takes up the length)."""
    fixed = pair(model, "O", "fixed").solve((0.0,) * 5, 0.0, dz_thermal=2e-6).axial_loads
    assert fixed[0] > F_P and fixed[0] == pytest.approx(fixed[1], rel=1e-9)
    spring = pair(model, "O", "spring").solve((0.0,) * 5, 0.0, dz_thermal=2e-6).axial_loads
    assert spring == pytest.approx((F_P, F_P), rel=1e-9)


CASES = [
    (a, p, n, F)
    for a in ("X", "O")
    for p in ("spring", "fixed")
    for n in (0.0, 10000.0)
    for F in ((0.0,) * 5, COMBINED)
]


@pytest.mark.parametrize("arrangement,preload,rpm,F_ext", CASES)
def test_pair_stiffness_matches_central_differences(model, arrangement, preload, rpm, F_ext):
    """K_pair vs central differences of the loads the shaft needs at D +- h (each bearing re-solved,
    the spring-loaded B's axial DOF again at F_p): <= 1e-5 relative on entries above 1e-6 of the
    largest. h = 1e-9 m (2e-8 rad = 1e-9 m at s/2): truncation ~(h/z)^2 ~ 1e-8 relative for an
    axial approach z ~ 1e-5 m; rounding and the inner solves' 1e-12 tolerance give ~1e-12 F/(K h)
    ~ 1e-8 relative."""
    p = pair(model, arrangement, preload)
    omega = rpm * RPM
    r = p.solve(F_ext, omega)
    K_fd = np.zeros((5, 5))
    for k in range(5):
        e = np.zeros(5)
        e[k] = 1e-9 if k < 3 else 2e-8
        K_fd[:, k] = (p.shaft_loads(r.D + e, omega)[0] - p.shaft_loads(r.D - e, omega)[0]) / (2.0 * e[k])
    assert relative_entry_error(r.K_pair, K_fd) <= 1e-5
    # the loads the shaft needs at the solution are the external loads (equilibrium)
    scale = np.array([1.0, 1.0, 1.0, 0.5 * SPACING, 0.5 * SPACING])
    assert np.max(np.abs((p.shaft_loads(r.D, omega)[0] - np.asarray(F_ext)) / scale)) <= 1e-9 * F_P


@pytest.mark.parametrize("preload", ["spring", "fixed"])
@pytest.mark.parametrize("rpm", [0.0, 10000.0])
def test_o_arrangement_is_stiffer_in_tilt(model, preload, rpm):
    """Back-to-back (O) has the larger tilting stiffness (load centres outside the bearings); the
    radial and axial stiffness do not depend on the arrangement (equal to 1e-9: same bearing states,
    only the order of the sums changes).

    At rest (a_i = a_o = a) the O/X ratio is that of the squared effective spreads,
    ((s + d_m tan a)/(s - d_m tan a))^2, within 3 %: the estimate neglects each bearing's own tilting
    stiffness about its load centre, ~1 % of the X value here. At speed the inner and outer contact
    lines part (a_i > a_o, centrifugal force) and the bearing's stiffness centre e = -K_xty/K_xx lies
    between their axis crossings (d_m/2) tan a_o and (d_m/2) tan a_i, on the local -z side."""
    omega = rpm * RPM
    X = pair(model, "X", preload).solve((0.0,) * 5, omega)
    O = pair(model, "O", preload).solve((0.0,) * 5, omega)
    for i in (3, 4):
        assert O.K_pair[i, i] > X.K_pair[i, i]
    for i in (0, 1, 2):
        assert O.K_pair[i, i] == pytest.approx(X.K_pair[i, i], rel=1e-9)
    balls = O.bearings[0].balls
    a_i, a_o = float(np.mean(balls[BQ_A_I])), float(np.mean(balls[BQ_A_O]))
    half = 0.5 * model.bearing.dm
    if rpm == 0.0:
        spread = 2.0 * half * math.tan(a_i)
        expected = ((SPACING + spread) / (SPACING - spread)) ** 2
        assert O.K_pair[3, 3] / X.K_pair[3, 3] == pytest.approx(expected, rel=0.03)
    else:
        K = O.bearings[0].K
        e = -K[0, 4] / K[0, 0]
        assert half * math.tan(a_o) < e < half * math.tan(a_i)


@pytest.mark.parametrize("arrangement", ["X", "O"])
@pytest.mark.parametrize("preload", ["spring", "fixed"])
@pytest.mark.parametrize("F_ext", [(0.0,) * 5, COMBINED])
def test_pair_stiffness_symmetric_at_rest(model, arrangement, preload, F_ext):
    """At rest the ball forces derive from the Hertz potential, so K_pair (a congruence of symmetric
    bearing stiffnesses, and a Schur complement of one for the spring) is symmetric to 1e-8 of its
    largest entry, rotations scaled to arc lengths at s/2."""
    r = pair(model, arrangement, preload).solve(F_ext, 0.0)
    s = np.array([1.0, 1.0, 1.0, 0.5 * SPACING, 0.5 * SPACING])
    Ks = r.K_pair / np.outer(s, s)
    assert np.max(np.abs(Ks - Ks.T)) <= 1e-8 * np.max(np.abs(Ks))


def test_one_shot_helper_and_warm_start(model):
    """solve_pair equals PairAssembly.solve (same arithmetic, to 1e-12), accepts the returned state as
    a warm start, and two distinct model instances give the pair of one instance passed twice."""
    r = solve_pair(model, model, COMBINED, 10000 * RPM, arrangement="O", preload="fixed")
    q = pair(model, "O", "fixed").solve(COMBINED, 10000 * RPM)
    assert np.allclose(r.K_pair, q.K_pair, rtol=1e-12, atol=0.0)
    again = solve_pair(model, model, COMBINED, 10000 * RPM, arrangement="O", preload="fixed", state=r.state)
    assert again.iterations == 0
    twin = QuasiStaticModel("B7214C", "iso_vg68_mineral", model.scene)
    t = solve_pair(model, twin, COMBINED, 10000 * RPM, arrangement="O", preload="fixed")
    assert np.allclose(t.axial_loads, r.axial_loads, rtol=1e-9, atol=0.0)


def test_bad_inputs_raise_clear_errors(model):
    """Unknown arrangement/preload, a non-positive preload or spacing, speeds beyond d_m n and loads
    beyond the material limit are refused with InputError naming the value."""
    with pytest.raises(InputError, match="arrangement"):
        PairAssembly(model, model, "DB")
    with pytest.raises(InputError, match="preload"):
        PairAssembly(model, model, "X", "rigid")
    with pytest.raises(InputError, match="F_preload"):
        PairAssembly(model, model, "X", "spring", 0.0)
    with pytest.raises(InputError, match="spacing"):
        PairAssembly(model, model, "X", "spring", F_P, -0.1)
    p = pair(model)
    with pytest.raises(InputError, match="omega"):
        p.solve((0.0,) * 5, 2.0 * model.omega_max)
    with pytest.raises(InputError, match="p_max"):
        p.solve((0.0, 0.0, 1e6, 0.0, 0.0), 0.0)


def test_spring_pair_pushed_past_its_preload(model):
    """Spring preload: B always carries F_p, so F_z < -F_p has no equilibrium with A in thrust. Pure
    axial: SolverError saying why. With a radial load the kernel's full groove lets A's balls ride the
    opposite flank (A at F_p + F_z < 0): solved, with a warning."""
    p = pair(model)
    with pytest.raises(SolverError, match="lifts bearing A"):
        p.solve((0.0, 0.0, -1.5 * F_P, 0.0, 0.0), 0.0)
    r = p.solve((3000.0, 0.0, -1500.0, 0.0, 0.0), 0.0)
    assert r.axial_loads[0] == pytest.approx(F_P - 1500.0, rel=1e-9)
    assert any("negative contact angle" in w for w in r.warnings)
    assert not p.solve((3000.0, 0.0, 0.0, 0.0, 0.0), 0.0).warnings
