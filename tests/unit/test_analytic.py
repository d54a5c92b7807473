"""kernels.radial_bearing against its twin tests/reference/ref_radial_bearing.py (a ball loop over the twins).

Every O_* output is compared (O_ITER, the kernel's Newton count, has no twin: it is checked for
convergence instead), and so are the eight per-ball rows of the work array. The tolerances are
propagated from the two approximate steps, everything else being closed form (RTOL = 1e-12):
- radial shift delta_r: 48-point Gauss-Legendre force, bound TOL_DELTA = RTOL_GL + 8 eps_mach
  (eps + 1/eps) as in test_loaddist;
- loads: Q_j = K (delta_r cos psi_j - P_d/2)^1.5, so dQ_j <= 1.5 delta_r/(delta_r - P_d/2) Q_max
  TOL_DELTA = (1.5/(2 eps)) Q_max TOL_DELTA for every ball (absolute; the relative error of a
  ball at the edge of the loaded zone is unbounded); Q_max, and p_max ~ Q^(1/3), relative;
- pressure-viscosity xi: exact except for WLF oils (Simpson alpha*, tolerance of test_lubricant);
- films: |d ln h / d ln Q| <= 0.13 and |d ln h / d ln xi| <= 0.7 for the three formulas (largest
  exponents: Masjedi-Khonsari W^(-0.09 k^-0.15) at k >= 0.1, G^0.65); capacitance of a contact
  ~ a b eps_r / h_c: |d ln C / d ln Q| <= 0.9, |d ln C / d ln xi| <= 0.6; the bearing total gets the
  sum over the balls of these bounds times each ball's capacitance (absolute);
- eps = (1 - P_d/(2 delta_r))/2: relative error |1 - 2 eps|/(2 eps) TOL_DELTA.
Measured on 1512 cases (2 bearings x 3 clearances x 3 films x 2 Hertz x centrifugal on/off x 5 oils
x 7 operating points): delta_r 4.2e-10, Q_max 1.1e-9, Lambda/h 2e-9 (1e-6 for the WLF oil at 233 K,
through alpha*), C_bearing 1.8e-9 (8.9e-7 WLF at 233 K). Error / bound on the 1440-case grid used
while writing this: delta_r, eps 0.04, Q_max 0.03, p_max 0.01; films and capacitances 0.50-0.58 and
xi 0.67, both set by the WLF oil's alpha* (actual exponents 0.49-0.53 against the bound's 0.6-0.7,
and the 1.5 factor of the alpha* bound).
Integers (regime, balls loaded) must be equal unless a film parameter or a ball's compression lies
within its tolerance of a threshold.
"""

import functools
import math

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from bearing_fmu.kernels import ehl as ek
from bearing_fmu.kernels import lubricant as lk
from bearing_fmu.kernels import radial_bearing
from bearing_fmu.models.analytic import AnalyticModel
from bearing_fmu.params import catalogue
from bearing_fmu.scene import Scene
from tests.reference import ref_lubricant as rlub
from tests.reference import ref_radial_bearing as ra
from tests.unit._compare import assert_close, rel_err
from tests.unit.test_film_correction import made_up_table

RTOL = 1e-12
RTOL_GL = 2.5 * 48**-5.0
METHOD_RTOL = 1e-6  # lubrication method: beta's differences and the meniscus (test_contact_outputs.py)
EPS = np.finfo(float).eps
FAST = settings(max_examples=50, deadline=None)
floats = functools.partial(st.floats, allow_nan=False, allow_infinity=False, allow_subnormal=False)
OUTPUTS = {
    name[2:].lower(): getattr(radial_bearing, name)
    for name in dir(radial_bearing)
    if name.startswith("O_") and name != "O_SIZE"
}
SCENES = {
    "default": Scene(),
    "masjedi_khonsari": Scene(film="masjedi_khonsari"),
    "chittenden": Scene(film="chittenden"),
    "approximate_hertz": Scene(hertz="approximate"),
    "no_centrifugal": Scene(centrifugal=False),
    "mean_pressure_background": Scene(permittivity_pressure="mean", background_capacitance=30e-12),
    "lubricated_region": Scene(capacitance_region="lubricated", oil_gap=20e-6),
    "oil_bath": Scene(lubrication="oil_bath"),
    "oil_air": Scene(lubrication="oil_air"),
    "grease": Scene(lubrication="grease", inlet_oil_layer=3e-7),
}
# (omega rad/s, F_r N, T_oil K, lubricant)
POINTS = [
    (500.0, 3000.0, 313.0, "guessasma_oil"),
    (-500.0, 3000.0, 313.0, "guessasma_oil"),
    (0.0, 3000.0, 313.0, "guessasma_oil"),
    (3000.0, 100.0, 353.0, "iso_vg68_mineral"),
    (200.0, 20000.0, 233.15, "pao_vg48"),
    (1500.0, 5000.0, 473.15, "mineral_oil_capacitance"),
    (800.0, 3000.0, 233.15, "thesis_turbine_oil"),
    (800.0, 0.0, 313.0, "thesis_turbine_oil"),
]


@functools.cache
def model(bearing, scene, Pd, lubricant):
    return AnalyticModel(bearing, lubricant, SCENES[scene], Pd=Pd)


def run_kernel(m, omega, F_r, T):
    out = np.zeros(radial_bearing.O_SIZE)
    ball = np.zeros((8, m.bearing.Z))
    radial_bearing.analytic_bearing(omega, F_r, T, m.brg, m.lubricant.array, m.nodes, m.weights, out, ball)
    return out, ball


def xi_tolerance(T, lub):
    if int(lub[lk.LUB_PIEZO_MODEL]) != lk.PIEZO_WLF:
        return RTOL
    wlf = [lub[i] for i in rlub.WLF_INDEX]
    mu0 = rlub.wlf_viscosity(0.0, T, *wlf)
    h = 1e5
    f = [rlub.wlf_ratio(i * h, T, mu0, *wlf) for i in range(5)]
    f3 = (-5.0 * f[0] + 18.0 * f[1] - 24.0 * f[2] + 14.0 * f[3] - 3.0 * f[4]) / (2.0 * h**3)
    return 1.5 * 2e6**4 / 180.0 * abs(f3) * rlub.wlf_alpha_star(T, *wlf) + 1e-10


def check_against_twin(m, omega, F_r, T):
    """Run kernel and twin and check every output and ball row against the propagated tolerances."""
    out, ball = run_kernel(m, omega, F_r, T)
    ref, balls = ra.analytic_bearing(omega, F_r, T, m.brg, m.lubricant.array)
    Pd = m.brg[radial_bearing.B_PD]
    eps = ref["eps"]
    delta = ref["delta_r"]
    tol_delta = RTOL_GL + (8.0 * EPS * (abs(eps) + 1.0 / abs(eps)) if 0.0 < abs(eps) < math.inf else 0.0)
    amp = 1.5 / (2.0 * eps) if 0.0 < eps < math.inf else 1.5  # d ln Q_max / d ln delta_r
    tol_load = RTOL + max(amp, 1.5) * tol_delta
    tol_xi = xi_tolerance(T, m.lubricant.array)
    q_max = max(ref["qmax_i"], ref["qmax_o"])

    def ball_load_tol(Q):  # relative load error bound of one contact (absolute bound / Q)
        return RTOL + (tol_load * q_max / Q if Q > 0.0 else 0.0)

    tol = {
        "delta_r": tol_delta,
        "qmax_i": tol_load,
        "qmax_o": tol_load,
        "pmax": tol_load,
        "eps": RTOL + abs(1.0 - 2.0 * eps) / (2.0 * abs(eps)) * tol_delta if 0.0 < abs(eps) < math.inf else RTOL,
        "eta": RTOL,
        "xi": tol_xi,
        "omega_cage": RTOL,
        "omega_ball": RTOL,
    }
    film_tol = RTOL + 0.13 * tol_load + 0.7 * tol_xi
    for key in ("lambda_i", "lambda_o", "hmin_i", "hmin_o", "hc_i", "hc_o"):
        tol[key] = film_tol
    # ball rows
    for s in ("i", "o"):
        for j, (Qk, Qr) in enumerate(zip(ball[ra.BALL_ROWS.index(f"Q_{s}")], balls[f"Q_{s}"])):
            assert abs(Qk - Qr) <= tol_load * q_max + RTOL * Qr, f"Q_{s}[{j}]: {Qk} vs {Qr}"
            t_film = RTOL + 0.13 * ball_load_tol(Qr) + 0.7 * tol_xi + (METHOD_RTOL if m.scene.lubricated else 0.0)
            for row in (f"h_min_{s}", f"Lambda_{s}"):
                assert_close(ball[ra.BALL_ROWS.index(row)][j], balls[row][j], t_film, f"{row}[{j}]")
            t_cap = RTOL + outside_gain(m, balls[f"h_c_{s}"][j]) * (0.9 * ball_load_tol(Qr) + 0.6 * tol_xi)
            t_cap += METHOD_RTOL if m.scene.lubricated else 0.0
            assert_close(ball[ra.BALL_ROWS.index(f"C_{s}")][j], balls[f"C_{s}"][j], t_cap, f"C_{s}[{j}]")
    # bearing capacitance: sum of the balls' bounds (series ball: the larger of its two contacts' bounds)
    c_abs = 0.0
    for j in range(m.bearing.Z):
        Ci, Co = balls["C_i"][j], balls["C_o"][j]
        if Ci > 0.0 and Co > 0.0:
            t = max(0.9 * ball_load_tol(balls["Q_i"][j]), 0.9 * ball_load_tol(balls["Q_o"][j])) + 0.6 * tol_xi
            t += METHOD_RTOL if m.scene.lubricated else 0.0
            gain = max(outside_gain(m, balls["h_c_i"][j]), outside_gain(m, balls["h_c_o"][j]))
            c_abs += gain * t * Ci * Co / (Ci + Co)
    assert abs(out[radial_bearing.O_C_BEARING] - ref["c_bearing"]) <= c_abs + RTOL * ref["c_bearing"], "C_bearing"
    if (
        m.scene.lubricated
    ):  # beta's central difference (METHOD_RTOL, test_contact_outputs.py) on top of the films' bound
        for key in ("lambda_i", "lambda_o", "hmin_i", "hmin_o", "hc_i", "hc_o"):
            tol[key] += METHOD_RTOL
        for key in ("phi_ish_i", "phi_ish_o", "phi_rs_i", "phi_rs_o", "p_drag", "torque_drag"):
            tol[key] = film_tol + METHOD_RTOL
    for key, t in tol.items():
        assert_close(out[OUTPUTS[key]], ref[key], t, key)
    # integers: equal unless a threshold lies within the tolerance
    lam_k = min(out[radial_bearing.O_LAMBDA_I], out[radial_bearing.O_LAMBDA_O])
    assert out[radial_bearing.O_REGIME] == ek.lubrication_regime(lam_k)
    lam_r = min(ref["lambda_i"], ref["lambda_o"])
    if all(abs(lam_r - edge) > film_tol * edge for edge in (1.0, 3.0)):
        assert out[radial_bearing.O_REGIME] == ref["regime"]
    loaded = np.count_nonzero((ball[0] > 0.0) & (ball[1] > 0.0))
    assert out[radial_bearing.O_N_LOADED] == loaded
    compressions = [delta * math.cos(2.0 * math.pi * j / m.bearing.Z) - Pd / 2.0 for j in range(m.bearing.Z)]
    if all(abs(c) > 2.0 * tol_delta * max(delta, abs(Pd)) for c in compressions):
        assert out[radial_bearing.O_N_LOADED] == ref["n_loaded"]
    # solver: no iteration without load, converged below the 200-iteration cap under any load
    if F_r == 0.0:
        assert out[radial_bearing.O_ITER] == 0
    else:
        assert 1 <= out[radial_bearing.O_ITER] < 200
    return out, ref


def outside_gain(m, h_c):
    """How much more the capacitance of a contact moves than the Hertz plate's when its film moves (-): 1 for the
    Hertz zone alone; with the oil-filled gap around the contact (scene capacitance_region = 'lubricated'), whose
    region ends where the gap reaches oil_gap, d ln C / d ln h_c grows by up to h_c / (oil_gap - h_c) as the film
    nears the oil's height (the region shrinks to nothing), so the plate's bound is scaled by 1 + that ratio.
    Measured: a 6208 at 5 rad/s without load, thesis_turbine_oil at 234 K, h_c = 12.5 um of a 20 um oil gap, the
    outer contacts' capacitance 1.6e-6 apart against the plate's bound of 1.4e-6 (the bound here: 3.7e-6)."""
    h_oil = m.scene.oil_gap if m.scene.capacitance_region == "lubricated" else 0.0
    if h_oil <= 0.0 or not 0.0 < h_c < h_oil:
        return 1.0
    return 1.0 + h_c / (h_oil - h_c)


def test_twin_covers_every_output():
    _, ref = check_against_twin(model("6208", "default", 0.0, "guessasma_oil"), 500.0, 3000.0, 313.0)
    assert set(OUTPUTS) == set(ref), set(OUTPUTS) ^ set(ref)


@pytest.mark.parametrize("scene", list(SCENES))
@pytest.mark.parametrize("Pd", [-12.6e-6, 0.0, 12.6e-6])
@pytest.mark.parametrize("bearing", ["6208", "6306"])
def test_analytic_on_grid(bearing, Pd, scene):
    for omega, F_r, T, lubricant in POINTS:
        check_against_twin(model(bearing, scene, Pd, lubricant), omega, F_r, T)


@FAST
@given(
    omega=st.one_of(st.just(0.0), floats(-3000.0, -1e-6), floats(1e-6, 3000.0)),
    F_r=st.one_of(st.just(0.0), floats(1e-6, 20000.0)),
    T=floats(233.15, 473.15),
    Pd=st.one_of(st.just(0.0), floats(-25e-6, -1e-9), floats(1e-9, 25e-6)),
    bearing=st.sampled_from(["6208", "6306"]),
    scene=st.sampled_from(list(SCENES)),
    lubricant=st.sampled_from(catalogue("lubricants")),
)
def test_analytic_random(omega, F_r, T, Pd, bearing, scene, lubricant):
    """Magnitudes below 1 um/s-scale speeds, 1 uN and 1 nm clearance are physically zero and are left to
    the edge-case tests (they reach float underflow, e.g. test_subnormal_loads_do_not_crash)."""
    check_against_twin(AnalyticModel(bearing, lubricant, SCENES[scene], Pd=Pd), omega, F_r, T)


def test_bearing_array_matches_twin_geometry():
    """The Hertz inputs the kernel reads from brg equal the twins' exact solution (default scene)."""
    from tests.reference import ref_geometry, ref_hertz

    m = model("6208", "default", 0.0, "guessasma_oil")
    b = m.bearing
    radii = ref_geometry.curvature_radii(b.D, b.dm, b.f_i, b.f_o, 0.0)
    assert_close(
        m.brg[[radial_bearing.B_RX_I, radial_bearing.B_RY_I, radial_bearing.B_RX_O, radial_bearing.B_RY_O]],
        radii,
        1e-12,
        "radii",
    )
    assert_close(
        m.brg[[radial_bearing.B_K_I, radial_bearing.B_EE_I, radial_bearing.B_KK_I]],
        ref_hertz.hertz_coefficients_exact(radii[0], radii[1]),
        1e-12,
        "inner (k, E, K)",
    )
    assert_close(
        m.brg[[radial_bearing.B_K_O, radial_bearing.B_EE_O, radial_bearing.B_KK_O]],
        ref_hertz.hertz_coefficients_exact(radii[2], radii[3]),
        1e-12,
        "outer (k, E, K)",
    )


def test_seed_case_6208():
    """Guessasma & Machado (2018), Harris & Kotzalas (2006): 6208, omega = 500 rad/s, F_r = 3 kN, P_d = 0,
    eta = 0.04 Pa s, xi = 2.3e-8 1/Pa: Q_max = 1457 N, Lambda_out at psi = 0 ~ 2.1-2.15, bearing capacitance
    of tens of pF."""
    out, ref = check_against_twin(model("6208", "default", 0.0, "guessasma_oil"), 500.0, 3000.0, 313.0)
    assert out[radial_bearing.O_QMAX_I] == pytest.approx(1457.0, abs=0.5)
    assert 2.1 <= out[radial_bearing.O_LAMBDA_O] <= 2.15
    assert 10e-12 <= out[radial_bearing.O_C_BEARING] <= 500e-12
    assert out[radial_bearing.O_EPS] == pytest.approx(0.5, rel=1e-12, abs=0)
    assert out[radial_bearing.O_N_LOADED] == 5  # psi = 0, +-40, +-80 deg


def test_zero_speed():
    """u = 0: no film, Lambda = 0 on both races, boundary regime; capacitance bounded by the film floor."""
    m = model("6208", "default", 0.0, "guessasma_oil")
    out, ref = check_against_twin(m, 0.0, 3000.0, 313.0)
    for key in ("lambda_i", "lambda_o", "hmin_i", "hmin_o", "hc_i", "hc_o", "omega_cage", "omega_ball"):
        assert out[OUTPUTS[key]] == 0.0 == ref[key]
    assert out[radial_bearing.O_REGIME] == ek.REGIME_BOUNDARY
    assert out[radial_bearing.O_C_BEARING] > 0.0 and math.isfinite(out[radial_bearing.O_C_BEARING])


def test_negative_speed_mirrors_kinematics_and_keeps_films():
    m = model("6208", "default", 12.6e-6, "iso_vg68_mineral")
    fwd, _ = check_against_twin(m, 800.0, 3000.0, 330.0)
    back, _ = check_against_twin(m, -800.0, 3000.0, 330.0)
    assert back[radial_bearing.O_OMEGA_CAGE] == -fwd[radial_bearing.O_OMEGA_CAGE] < 0.0
    assert back[radial_bearing.O_OMEGA_BALL] == -fwd[radial_bearing.O_OMEGA_BALL] < 0.0
    same = [v for k, v in OUTPUTS.items() if k not in ("omega_cage", "omega_ball")]
    assert np.array_equal(back[same], fwd[same])


def test_no_load_with_clearance():
    """F_r = 0, P_d > 0: the ring rests at P_d/2, no ball is pinched (eps = 0); with centrifugal force
    the outer contacts still carry F_c but no ball conducts, so C_bearing is the background term."""
    m = model("6208", "mean_pressure_background", 12.6e-6, "guessasma_oil")
    out, ref = check_against_twin(m, 500.0, 0.0, 313.0)
    assert (
        out[radial_bearing.O_DELTA_R] == 6.3e-6
        and out[radial_bearing.O_EPS] == 0.0
        and out[radial_bearing.O_N_LOADED] == 0
    )
    assert (
        out[radial_bearing.O_QMAX_I] == 0.0
        and out[radial_bearing.O_LAMBDA_I] == 0.0
        and out[radial_bearing.O_HMIN_I] == 0.0
    )
    assert out[radial_bearing.O_QMAX_O] > 0.0  # F_c on every outer contact
    assert out[radial_bearing.O_C_BEARING] == 30e-12


def test_no_load_with_preload():
    """F_r = 0, P_d < 0: centred ring, every ball equally loaded (eps = inf, all balls loaded)."""
    m = model("6208", "default", -12.6e-6, "guessasma_oil")
    out, ref = check_against_twin(m, 500.0, 0.0, 313.0)
    assert (
        out[radial_bearing.O_DELTA_R] == 0.0
        and out[radial_bearing.O_EPS] == math.inf
        and out[radial_bearing.O_N_LOADED] == 9
    )
    _, ball = run_kernel(m, 500.0, 0.0, 313.0)
    assert np.all(ball[0] == ball[0][0]) and ball[0][0] > 0.0


def test_eps_above_one_loads_every_ball():
    m = model("6208", "default", -25e-6, "guessasma_oil")
    out, _ = check_against_twin(m, 500.0, 1000.0, 313.0)
    assert out[radial_bearing.O_EPS] >= 1.0 and out[radial_bearing.O_N_LOADED] == 9


def test_compiled_kernel_is_current():
    """The jitted dispatcher computes what its source computes (run as Python, calling the same
    jitted callees). numba's cache=True only checks the caller's own file: a callee changed in another
    kernel module would leave a stale compiled analytic_bearing in a fixed cache directory (seen once:
    the pre-'wlf_ratio' alpha* raising ZeroDivisionError for the WLF oil). The cache directory keyed on
    the kernel sources (bearing_fmu_common/jit.py, tests/unit/test_jit_cache.py) prevents it."""
    for lubricant, T in (("thesis_turbine_oil", 313.0), ("iso_vg68_mineral", 313.0), ("guessasma_oil", 233.15)):
        m = model("6208", "default", 5e-6, lubricant)
        out = np.zeros(radial_bearing.O_SIZE)
        ball = np.zeros((8, 9))
        radial_bearing.analytic_bearing.py_func(
            700.0, 3000.0, T, m.brg, m.lubricant.array, m.nodes, m.weights, out, ball
        )
        try:
            jit_out, jit_ball = run_kernel(m, 700.0, 3000.0, T)
        except ZeroDivisionError as exc:
            pytest.fail(f"compiled analytic_bearing raised {exc!r} where its source does not: stale numba cache")
        assert rel_err(jit_out, out) <= 1e-14 and rel_err(jit_ball, ball) <= 1e-14, lubricant


def test_eps_without_load_and_clearance():
    out, ref = check_against_twin(model("6208", "default", 0.0, "guessasma_oil"), 500.0, 0.0, 313.0)
    assert out[radial_bearing.O_EPS] == ref["eps"] == 0.5


def test_load_zone_is_mirror_symmetric():
    m = model("6306", "default", 0.0, "guessasma_oil")
    out, ball = run_kernel(m, 300.0, 2000.0, 313.0)
    Z = m.bearing.Z
    assert all(ball[0][j] == ball[0][(Z - j) % Z] for j in range(Z))
    assert out[radial_bearing.O_N_LOADED] % 2 == 1  # the ball on the load line plus mirror pairs


@pytest.mark.parametrize("omega, F_r", [(500.0, 1e-310), (5.6e-160, 0.0)])
def test_subnormal_loads_do_not_crash(omega, F_r):
    out, _ = run_kernel(model("6208", "default", 0.0, "guessasma_oil"), omega, F_r, 313.0)
    assert np.all(np.isfinite(out[[radial_bearing.O_QMAX_I, radial_bearing.O_PMAX, radial_bearing.O_DELTA_R]]))


def test_smooth_surfaces_keep_their_film():
    m = AnalyticModel("6208", "guessasma_oil", Scene(), Pd=0.0)
    m.brg[radial_bearing.B_SIGMA_I] = 0.0
    m.brg[radial_bearing.B_SIGMA_O] = 0.0
    out, ball = run_kernel(m, 500.0, 3000.0, 313.0)
    ref, _ = ra.analytic_bearing(500.0, 3000.0, 313.0, m.brg, m.lubricant.array)
    assert ref["hmin_i"] > 0.0 and ref["lambda_i"] == math.inf and ref["regime"] == ek.REGIME_FULL_FILM
    assert out[radial_bearing.O_HMIN_I] == pytest.approx(ref["hmin_i"], rel=1e-6, abs=0)
    assert out[radial_bearing.O_LAMBDA_I] == math.inf and out[radial_bearing.O_REGIME] == ek.REGIME_FULL_FILM


@pytest.mark.parametrize(
    "omega, F_r, T, scene",
    [
        (500.0, 3000.0, 313.0, "default"),
        (1700.0, 8000.0, 353.0, "default"),
        (0.0, 3000.0, 313.0, "default"),
        (1700.0, 3000.0, 313.0, "oil_air"),
        (500.0, 3000.0, 313.0, "grease"),
    ],
)
def test_analytic_with_a_film_table_matches_twin(omega, F_r, T, scene):
    """The film correction on (a table of made-up ratios in the bearing array): films and what depends on them as
    the twin corrects them; with a lubrication method the method's factors multiply the corrected film (the
    correction is the flooded isothermal film's, the factors scale that film)."""
    m = AnalyticModel("6208", "iso_vg68_mineral", SCENES[scene])
    plain = run_kernel(m, omega, F_r, T)[0][radial_bearing.O_HMIN_I]
    m.brg[radial_bearing.B_FILM_TABLE :] = made_up_table()
    check_against_twin(m, omega, F_r, T)
    if omega != 0.0:
        assert run_kernel(m, omega, F_r, T)[0][radial_bearing.O_HMIN_I] != plain  # the table is read
