"""spindle.thermal.network kernels against their twins (tests/reference/ref_network.py) and integrator properties.

Networks: the default spindle (spindle/thermal/params/b7214c_x_pair.toml, 8 nodes, 2 boundaries) and random
connected networks (6-12 nodes, capacities 1-1e4 J/K, conductances 0.1-100 W/K, seeded).
Tolerances:
- Closed forms (conductances, assembly, thermo-mechanics): the kernel and the twin do the same few
  flops in another order or route, 1e-12 relative (a few hundred ulp) leaves ample margin; the shell
  twin integrates numerically (quad, epsrel 1e-13).
- Linear solves and exponentials: errors are bounded by cond(.) x eps; the networks here have
  cond(L) < 1e7, so 1e-9 relative on temperature *rises* (T - T_start, the informative part; T itself
  is ~300 K and would hide errors) is both achievable and meaningful.
"""

import math

import numpy as np
import pytest

from spindle.thermal import network as nk
from spindle.thermal.model import SpindleThermalModel
from tests.reference import ref_network as rn
from tests.unit._compare import assert_close

RTOL = 1e-12
RTOL_LINALG = 1e-9
OMEGA = 10000.0 * 2.0 * math.pi / 60.0
HEATS = dict(Q_inner_ring_1=300.0, Q_outer_ring_1=200.0, Q_inner_ring_2=300.0, Q_outer_ring_2=200.0)


def random_network(seed, n=None, m=2):
    """Connected random network: a chain of nodes to boundary 0 plus random extra links (all kinds)."""
    rng = np.random.default_rng(seed)
    n = n or int(rng.integers(6, 13))
    C = 10.0 ** rng.uniform(0, 4, n)
    ends_i, ends_j, kinds, par = [], [], [], []

    def add(i, j):
        kind = int(rng.integers(0, 6))
        row = np.zeros(nk.PAR_SIZE)
        if kind == nk.LINK_SHELL:
            r1 = rng.uniform(0.01, 0.1)
            row[:4] = rng.uniform(10, 50), rng.uniform(0.01, 0.3), r1, r1 * rng.uniform(1.05, 3.0)
        elif kind == nk.LINK_ROTATING_SHAFT:
            row[:5] = rng.uniform(0.02, 0.2), rng.uniform(0.01, 0.2), 0.0263, 15.89e-6, 0.707
        elif kind == nk.LINK_CONDUCTANCE:
            row[0] = 10.0 ** rng.uniform(-1, 2)
        else:
            row[:2] = 10.0 ** rng.uniform(0, 3), 10.0 ** rng.uniform(-3, -1)
        ends_i.append(i), ends_j.append(j), kinds.append(kind), par.append(row)

    order = rng.permutation(n)
    add(int(order[0]), n)  # the chain's head touches boundary 0
    for a, b in zip(order[:-1], order[1:]):
        add(int(b), int(a))
    for _ in range(n):
        i, j = rng.choice(n + m, 2, replace=False)
        if i < n or j < n:
            add(int(min(i, j)), int(max(i, j)))
    return (
        n,
        m,
        C,
        np.array(ends_i, dtype=np.int64),
        np.array(ends_j, dtype=np.int64),
        np.array(kinds, dtype=np.int64),
        np.array(par),
    )


@pytest.fixture(scope="module")
def default():
    """(model, C, L, B, f, T_start) of the default spindle at 10 000 rpm with 1 kW of bearing heat."""
    m = SpindleThermalModel()
    m.initialize(omega=OMEGA, T_ambient=293.15, T_coolant=293.15, **HEATS)
    op = m._operator(OMEGA)
    P, Tb, _ = m._vectors(m._u)
    f = nk.source_vector(op["B"], Tb, P)
    return m, m.net.C, op["L"], op["B"], f, m.T.copy()


def rise_err(actual, expected, start):
    """max |actual - expected| / max |expected - start| (error relative to the temperature rise)."""
    return float(np.max(np.abs(actual - expected)) / np.max(np.abs(expected - start)))


# ------------------------------------------------------------------------------------ closed forms
@pytest.mark.parametrize("omega", [0.0, 1.0, -500.0, OMEGA, 5000.0])
@pytest.mark.parametrize("seed", range(5))
def test_conductances_and_assembly_vs_twin(seed, omega):
    """Each link kind's G (W/K) and the dense loop assembly of L, B (heat balance per node) and the heat
    flow into the boundaries agree with the twin to 1e-12 (same formulas, different route)."""
    n, m, C, ei, ej, kinds, par = random_network(seed)
    G = nk.link_conductances(kinds, par, omega)
    assert_close(G, rn.link_conductances(kinds, par, omega), RTOL, "G", atol=1e-300)
    for kind, row in zip(kinds, par):  # each link on its own
        assert_close(nk.link_conductance(kind, row, omega), rn.link_conductance(kind, row, omega), RTOL, f"G {kind}")
    L, B = nk.assemble(n, m, ei, ej, G)
    L_ref, B_ref = rn.assemble(n, m, ei, ej, G)
    assert_close(L, L_ref, RTOL, "L", atol=1e-300)
    assert_close(B, B_ref, RTOL, "B", atol=1e-300)
    assert np.array_equal(L, L.T)
    # conservation: each row of L sums to that node's conductance to the boundaries
    assert_close(L.sum(axis=1), B.sum(axis=1), 1e-12, "row sums", atol=1e-12 * np.abs(L).max())
    rng = np.random.default_rng(seed)
    T, Tb = rng.uniform(280, 400, n), rng.uniform(280, 320, m)
    assert_close(nk.boundary_heat_flow(n, ei, ej, G, T, Tb), rn.boundary_heat_flow(n, ei, ej, G, T, Tb), 1e-11, "P_out")
    x = rng.normal(size=m)
    assert_close(nk.matvec(B, x), rn.matvec(B, x), RTOL, "matvec", atol=1e-14 * np.abs(B).max())
    y = rng.normal(size=n)
    assert_close(nk.rmatvec(B, y), rn.rmatvec(B, y), RTOL, "rmatvec", atol=1e-14 * np.abs(B).max())
    P = rng.uniform(0, 100, n)
    assert_close(nk.source_vector(B, Tb, P), rn.source_vector(B, Tb, P), RTOL, "B Tb + P")


def test_rotating_shaft_value_by_hand():
    """Nu at 10 000 rpm on a 70 mm shaft in air at 300 K, by hand (docs/spindle_thermal.md):
    Re = (omega d/2) d / nu = 1047.2 x 0.035 x 0.07 / 15.89e-6 = 1.6146e5; Re^(2/3) = 2966.0;
    Pr^(1/3) = 0.707^(1/3) = 0.89087; Nu = 0.133 x 2966.0 x 0.89087 = 351.4; h = Nu k / d = 132.0 W/m^2/K.
    Tolerance 1e-3: the hand values are rounded to 4-5 digits."""
    Nu = nk.rotating_shaft_nusselt(OMEGA, 0.07, 15.89e-6, 0.707)
    assert_close(Nu, 351.4, 1e-3, "Nu")
    assert_close(Nu, rn.rotating_shaft_nusselt(OMEGA, 0.07, 15.89e-6, 0.707), RTOL, "Nu vs twin")
    assert nk.rotating_shaft_nusselt(0.0, 0.07, 15.89e-6, 0.707) == 0.0


def test_cholesky_vs_twin():
    """Hand-written Cholesky (no LAPACK in the FMU) against numpy: factor to 1e-12, solve to 1e-9
    relative (cond(L) of these networks < 1e7); a non-positive-definite matrix gives NaN."""
    for seed in range(5):
        n, m, C, ei, ej, kinds, par = random_network(seed)
        L, _ = nk.assemble(n, m, ei, ej, nk.link_conductances(kinds, par, OMEGA))
        R = nk.cholesky(L)
        assert_close(R, rn.cholesky(L), 1e-10, "R", atol=1e-12 * np.abs(L).max())
        b = np.random.default_rng(seed).normal(size=n)
        assert_close(nk.cholesky_solve(R, b), rn.cholesky_solve(R, b), RTOL_LINALG, "solve")
    assert np.all(np.isnan(nk.cholesky(np.array([[1.0, 2.0], [2.0, 1.0]]))))


def test_thermomechanics_vs_twin():
    """Centrifugal growth (Timoshenko's stresses in the twin), clearance change (new P_d - old P_d) and
    axial interference (shaft minus housing length) against the kernels' closed forms, 1e-12 (the
    clearance twin subtracts two ~50 um clearances made of ~0.1 m diameters: cancellation costs
    d_o/|dPd| ~ 1e3 ulp at most, so it is compared with an absolute allowance of 1e-12 x d_o)."""
    rng = np.random.default_rng(0)
    for _ in range(50):
        a = rng.uniform(0.01, 0.1)
        b = a * rng.uniform(1.05, 1.5)
        omega = rng.uniform(-3000, 3000)
        for r in (a, 0.5 * (a + b), b):
            assert_close(
                nk.centrifugal_radial_growth(7850.0, 210e9, 0.3, omega, a, b, r),
                rn.centrifugal_radial_growth(7850.0, 210e9, 0.3, omega, a, b, r),
                1e-12,
                "u_c",
                atol=1e-25,
            )
        d_i, D = 2 * b, rng.uniform(0.005, 0.03)
        d_o = d_i + 2 * D + rng.uniform(-50e-6, 50e-6)
        T = rng.uniform(250, 400, 3)
        args = (11.5e-6, d_i, d_o, D, T[0], T[1], T[2], 293.15, rng.uniform(0, 5e-6))
        assert_close(nk.clearance_change(*args), rn.clearance_change(*args), 0.0, "dPd", atol=1e-12 * d_o)
        for s_arr in (1.0, -1.0):
            args = (s_arr, 11.5e-6, 10.5e-6, rng.uniform(0.05, 0.5), T[0], T[1], 293.15)
            assert_close(nk.axial_interference(*args), rn.axial_interference(*args), 0.0, "dz", atol=1e-15)


@pytest.mark.parametrize("axial_float", [False, True])
def test_model_step_kernels_vs_twins(axial_float):
    """The two kernels of a model step (exponential_update, network_outputs) and heat_vector on the default
    spindle's own tables, from a random state with random inputs, against their twins: heats and outputs
    to 1e-12 (closed forms; the clearance change with the absolute allowance of
    test_thermomechanics_vs_twin), the step to 1e-9 of the rise (a linear solve and an exponential)."""
    m = SpindleThermalModel(axial_float=axial_float)
    rng = np.random.default_rng(3)
    for _ in range(5):
        u = np.array([rng.uniform(0.0, 500.0) if v.unit == "W" else rng.uniform(280.0, 320.0) for v in m.inputs])
        u[m.input_names.index("omega")] = rng.uniform(0.0, 1500.0)
        op = m._operator(float(u[m.input_names.index("omega")]))
        T, T0 = rng.uniform(290.0, 360.0, len(m.net.nodes)), rng.uniform(290.0, 300.0, len(m.net.nodes))
        P = nk.heat_vector(u, m._heat_at, m.net.dist)
        assert_close(P, rn.heat_vector(u, m._heat_at, m.net.dist), RTOL, "P", atol=1e-12)
        args = (T, u, m._heat_at, m._boundary_at, m.net.dist, op["B"], op["R"], op["sqrt_c"], op["V"], op["lam"], 7.0)
        assert rise_err(nk.exponential_update(*args), rn.exponential_update(*args), T) < RTOL_LINALG
        s = rng.uniform(-1e-6, 1e-6)
        net = m.net
        common = (T, T0, u, s, m._heat_at, m._boundary_at, net.C, net.ends_i, net.ends_j, op["G"])
        tables = (m._bearing_par, m._bearing_idx, m._par, m._idx)
        got, want = np.full(len(m.outputs), np.nan), np.full(len(m.outputs), np.nan)
        nk.network_outputs(*common, *tables, got)
        rn.network_outputs(*common, *tables, want)
        assert not np.isnan(got).any() and not np.isnan(want).any()  # every output slot is written
        for k, v in enumerate(m.outputs):
            atol = 1e-12 * net.bearings[0]["d_o"] if v.unit == "m" else 0.0
            assert_close(got[k], want[k], RTOL, v.name, atol=atol)


def test_centrifugal_growth_b7214c_by_hand():
    """Inner raceway of the B7214C at 10 000 rpm (omega = 1047.2 rad/s), a = 35 mm (bore radius),
    b = r = d_i/2 = (97.5 - 15.875 - 0.054/2)/2 mm = 40.7990 mm; steel rho 7850, E 210 GPa, nu 0.3.
    By hand: rho omega^2/(8E) = 7850 x 1.09662e6 / 1.68e12 = 5.1241e-3 1/m^2;
    bracket = 3.3 x 0.7 x (1.225e-3 + 1.66456e-3) x 0.040799 + 3.3 x 1.3 x 1.225e-3 x 0.040799
              - 0.91 x 0.040799^3 = 2.72349e-4 + 2.14409e-4 - 6.18008e-5 = 4.24957e-4 m^3;
    u = 2.1775e-6 m radial (the ~2.2 um of the brief). Tolerance 1e-4: hand rounding to 5 digits."""
    m = SpindleThermalModel()
    b = m.net.bearings[0]
    r = 0.5 * b["d_i"]
    assert_close(r, 0.0407990, 1e-5, "raceway radius")
    u = nk.centrifugal_radial_growth(b["rho"], b["E"], b["nu"], OMEGA, b["a"], r, r)
    assert_close(u, 2.1775e-6, 1e-4, "u_c")


# ---------------------------------------------------------------------------------------- stepping
def _eigen(C, L):
    sqrt_c = np.sqrt(C)
    lam, V = np.linalg.eigh(L / np.outer(sqrt_c, sqrt_c))
    return sqrt_c, lam, np.ascontiguousarray(V)


@pytest.mark.parametrize("h", [0.1, 10.0, 600.0, 36000.0])
def test_exponential_step_vs_expm_and_radau(default, h):
    """One exact step of the default spindle from ambient with 1 kW held against (a) solve_ivp Radau,
    rtol = atol = 1e-10 on the rise, and (b) scipy expm of the Van Loan augmented matrix (exact for
    held inputs), both to 1e-9 relative to the rise. Measured: Radau agrees to < 1e-13 at every h.
    expm's scaling and squaring loses accuracy in proportion to ||A h|| (measured 8e-12 at 600 s,
    7e-11 at 3600 s, 2e-9 at 36 000 s, while the kernel meets the direct steady state to 3e-15 there):
    at 36 000 s the twin, not the kernel, is the weaker reference, so expm is used up to 3600 s."""
    m, C, L, B, f, T0 = default
    sqrt_c, lam, V = _eigen(C, L)
    T_ss = nk.cholesky_solve(nk.cholesky(L), f)
    T1 = nk.exponential_step(T0, T_ss, sqrt_c, V, lam, h)
    assert rise_err(T1, rn.radau_step(C, L, f, T0, h), T0) < RTOL_LINALG
    if h <= 3600.0:
        assert rise_err(T1, rn.exact_step(C, L, f, T0, h)[0], T0) < RTOL_LINALG
        assert rise_err(T1, rn.exponential_step(T0, T_ss, sqrt_c, V, lam, h), T0) < RTOL_LINALG
    else:
        assert rise_err(T1, np.linalg.solve(L, f), T0) < RTOL_LINALG  # 36 000 s = 55 slowest time constants


@pytest.mark.parametrize("seed", range(4))
def test_random_networks_exponential_and_implicit_vs_twins(seed):
    """Random networks, arbitrary start: exponential step vs expm (1e-9 of the rise) and backward Euler
    vs the twin's dense unsymmetrised solve (same scheme: 1e-9)."""
    n, m, C, ei, ej, kinds, par = random_network(seed)
    L, B = nk.assemble(n, m, ei, ej, nk.link_conductances(kinds, par, 300.0))
    rng = np.random.default_rng(seed)
    f = nk.source_vector(B, rng.uniform(280, 320, m), rng.uniform(0, 200, n))
    T0 = rng.uniform(280, 350, n)
    sqrt_c, lam, V = _eigen(C, L)
    T_ss = nk.cholesky_solve(nk.cholesky(L), f)
    for h in (1.0, 100.0):
        T_ref, I_ref = rn.exact_step(C, L, f, T0, h)
        assert rise_err(nk.exponential_step(T0, T_ss, sqrt_c, V, lam, h), T_ref, T0) < RTOL_LINALG
        I = nk.exponential_heat_integral(T0, T_ss, sqrt_c, V, lam, h)
        assert rise_err(I, I_ref, h * T0) < RTOL_LINALG
        assert rise_err(I, rn.exponential_heat_integral(T0, T_ss, sqrt_c, V, lam, h), h * T0) < RTOL_LINALG
        for k in (1, 3):
            T_ie = nk.implicit_euler_step(C, L, f, T0, h, k)
            assert rise_err(T_ie, rn.implicit_euler_step(C, L, f, T0, h, k), T0) < RTOL_LINALG


def test_implicit_euler_first_order(default):
    """Backward Euler is first order: over a 600 s step from ambient with 1 kW, the error against the
    exact step halves when the sub-step halves (ratio -> 2 as dt -> 0; 1.9-2.1 once dt is below the
    fastest, 2.8 s, time constant). Measured max errors 0.156, 0.078, 0.039, 0.020 K for 64, 128, 256,
    512 substeps (ratios 1.99-2.00)."""
    m, C, L, B, f, T0 = default
    exact, _ = rn.exact_step(C, L, f, T0, 600.0)
    errors = [np.max(np.abs(nk.implicit_euler_step(C, L, f, T0, 600.0, k) - exact)) for k in (64, 128, 256, 512)]
    print("implicit Euler max error (K) at 600 s with 64..512 substeps:", errors)
    ratios = [e1 / e2 for e1, e2 in zip(errors[:-1], errors[1:])]
    assert all(1.9 < r < 2.1 for r in ratios), ratios


def test_steady_state_of_both_integrators(default):
    """Integrated long enough (exponential: one step of 1e6 s = 1500 slowest time constants; backward
    Euler: 100 steps of 1 h, each multiplying the slowest error mode by 1/(1 + 3600/650) < 0.16), both
    equal the direct solve of L T = B T_b + P (numpy.linalg.solve twin) to 1e-9 of the rise: the fixed
    point of both schemes is exactly T_ss."""
    m, C, L, B, f, T0 = default
    T_direct = np.linalg.solve(L, f)
    sqrt_c, lam, V = _eigen(C, L)
    T_ss = nk.cholesky_solve(nk.cholesky(L), f)
    assert rise_err(T_ss, T_direct, T0) < RTOL_LINALG
    assert rise_err(nk.exponential_step(T0, T_ss, sqrt_c, V, lam, 1e6), T_direct, T0) < RTOL_LINALG
    T = T0.copy()
    for _ in range(100):
        T = nk.implicit_euler_step(C, L, f, T, 3600.0, 1)
    assert rise_err(T, T_direct, T0) < RTOL_LINALG


@pytest.mark.parametrize("h", [1.0, 60.0, 3600.0])
def test_energy_conservation_over_a_step(default, h):
    """Summing the node equations, internal links cancel: d/dt sum C T = P_in - P_out(T) exactly. So
    over an exact step Delta E = P_in h - int P_out dt, with int P_out dt = P_out evaluated on the
    time-integral of T (P_out is affine in T): from the kernel's analytic integral and from the twin's
    augmented expm; 1e-9 relative to P_in h. Backward Euler conserves energy discretely with the
    end-point flux: C (T1 - T0) = dt (f - L T1), so Delta E = dt (P_in - P_out(T1)) per substep (1e-9)."""
    m, C, L, B, f, T0 = default
    net, op = m.net, m._operator(OMEGA)
    n = len(C)
    Tb = np.array([293.15, 293.15])
    P_in = sum(HEATS.values())
    sqrt_c, lam, V = _eigen(C, L)
    T_ss = nk.cholesky_solve(nk.cholesky(L), f)
    T1 = nk.exponential_step(T0, T_ss, sqrt_c, V, lam, h)
    dE = float(np.dot(C, T1 - T0))
    for integral in (nk.exponential_heat_integral(T0, T_ss, sqrt_c, V, lam, h), rn.exact_step(C, L, f, T0, h)[1]):
        # int P_out dt = sum_links G (int T_i dt - h T_b): boundary_heat_flow is linear in (T, Tb)
        out = nk.boundary_heat_flow(n, net.ends_i, net.ends_j, op["G"], integral, Tb * h)
        assert_close(dE, P_in * h - out, RTOL_LINALG, "energy", atol=RTOL_LINALG * P_in * h)
    T = T0.copy()
    for _ in range(4):
        T_new = nk.implicit_euler_step(C, L, f, T, h, 1)
        out = nk.boundary_heat_flow(n, net.ends_i, net.ends_j, op["G"], T_new, Tb)
        assert_close(
            float(np.dot(C, T_new - T)), h * (P_in - out), RTOL_LINALG, "IE energy", atol=RTOL_LINALG * P_in * h
        )
        T = T_new
