"""Twin of spindle.thermal.network: the lumped thermal network from first principles, plain numpy/scipy.

Written from the physics (docs/spindle_thermal.md), not from the kernels:
- conductances from their textbook formulas, selected by kind *name* (the shell's resistance by
  numerical quadrature of the thin-shell resistances dr / (k 2 pi r length));
- assembly from the heat balance of each node: C_i dT_i/dt = sum over neighbours x of G_ix (T_x - T_i) + P_i,
  with a dense (nodes + boundaries)^2 conductance table filled link by link;
- time stepping with scipy: the affine ODE dT/dt = A T + c (A = -C^-1 L, c = C^-1 (B T_b + P)) is
  integrated exactly with scipy.linalg.expm of the augmented matrix [[A, c], [0, 0]] (Van Loan 1978),
  extended by one block to give the time integral of T as well; or with solve_ivp (Radau);
- backward Euler with numpy.linalg.solve on the unsymmetrised system (I - dt A) T_new = T + dt c;
- centrifugal growth from Timoshenko's stresses of the rotating disc with a hole,
  u = r (sigma_theta - nu sigma_r) / E;
- clearance and axial interference from the new dimensions (P_d = d_o - d_i - 2 D; shaft minus housing length).
"""

import math

import numpy as np
from scipy.integrate import quad, solve_ivp
from scipy.linalg import expm

KIND_NAMES = {0: "conductance", 1: "shell", 2: "contact", 3: "convection", 4: "rotating_shaft", 5: "advection"}


def rotating_shaft_nusselt(omega, d, nu_air, Pr):
    """Nu = 0.133 Re^(2/3) Pr^(1/3) with Re = u d / nu, u = |omega| d / 2 the surface speed."""
    u = abs(omega) * d / 2.0
    Re = u * d / nu_air
    return 0.133 * Re ** (2.0 / 3.0) * Pr ** (1.0 / 3.0)


def link_conductance(kind, par, omega):
    name = KIND_NAMES.get(int(kind))
    if name == "conductance":
        return par[0]
    if name == "shell":
        k, length, r1, r2 = par[:4]
        # thin shells in series: R = int_r1^r2 dr / (k 2 pi r length), integrated numerically
        R, _ = quad(lambda r: 1.0 / (k * 2.0 * math.pi * r * length), r1, r2, epsabs=0.0, epsrel=1e-13)
        return 1.0 / R
    if name in ("contact", "convection"):
        h, area = par[:2]
        return h * area
    if name == "rotating_shaft":
        d, area, k_air, nu_air, Pr = par[:5]
        h = rotating_shaft_nusselt(omega, d, nu_air, Pr) * k_air / d
        return h * area
    if name == "advection":
        mdot, cp = par[:2]
        return mdot * cp
    return math.nan


def link_conductances(kinds, par, omega):
    return np.array([link_conductance(k, p, omega) for k, p in zip(kinds, par)])


def conductance_table(n, m, ends_i, ends_j, G):
    """Dense symmetric table (n + m)^2 of the conductance between every pair of points."""
    table = np.zeros((n + m, n + m))
    for i, j, g in zip(ends_i, ends_j, G):
        table[i, j] += g
        table[j, i] += g
    return table


def assemble(n, m, ends_i, ends_j, G):
    """(L, B) from the node heat balances: L_ii = sum_x G_ix over all other points, L_ij = -G_ij, B_ib = G_i,n+b."""
    table = conductance_table(n, m, ends_i, ends_j, G)
    L = np.zeros((n, n))
    B = np.zeros((n, m))
    for i in range(n):
        for x in range(n + m):
            if x == i:
                continue
            L[i, i] += table[i, x]
            if x < n:
                L[i, x] -= table[i, x]
            else:
                B[i, x - n] += table[i, x]
    return L, B


def boundary_heat_flow(n, ends_i, ends_j, G, T, Tb):
    """Heat into the boundaries: sum over boundaries b of sum_i G_ib (T_i - T_b)."""
    m = len(Tb)
    table = conductance_table(n, m, ends_i, ends_j, G)
    return sum(table[i, n + b] * (T[i] - Tb[b]) for i in range(n) for b in range(m))


def cholesky(A):
    return np.linalg.cholesky(A)


def cholesky_solve(R, b):
    return np.linalg.solve(R @ R.T, b)


def matvec(A, x):
    return np.asarray(A) @ np.asarray(x)


def rmatvec(A, x):
    return np.asarray(A).T @ np.asarray(x)


def source_vector(B, Tb, P):
    return B @ Tb + P


def implicit_euler_step(C, L, f, T, h, substeps):
    dt = h / substeps
    A = -L / C[:, None]
    c = f / C
    x = np.array(T, dtype=float)
    for _ in range(substeps):
        x = np.linalg.solve(np.eye(len(C)) - dt * A, x + dt * c)
    return x


def _affine(C, L, f):
    return -L / C[:, None], f / C


def exact_step(C, L, f, T, h):
    """(T(h), int_0^h T dt) of dT/dt = A T + c by expm of [[A, c, 0], [0, 0, 0], [I, 0, 0]] (Van Loan)."""
    n = len(C)
    A, c = _affine(C, L, f)
    M = np.zeros((2 * n + 1, 2 * n + 1))
    M[:n, :n] = A
    M[:n, n] = c
    M[n + 1 :, :n] = np.eye(n)  # d/dt (int T) = T
    z0 = np.concatenate([T, [1.0], np.zeros(n)])
    z = expm(M * h) @ z0
    return z[:n], z[n + 1 :]


def radau_step(C, L, f, T, h, rtol=1e-10, atol=1e-10):
    """T(h) by solve_ivp Radau on the deviation x = T - T(0) (so the tolerances act on the rise)."""
    A, c = _affine(C, L, f)
    T0 = np.array(T, dtype=float)
    sol = solve_ivp(
        lambda t, x: A @ (x + T0) + c, (0.0, h), np.zeros(len(C)), method="Radau", rtol=rtol, atol=atol, jac=A
    )
    return T0 + sol.y[:, -1]


def exponential_step(T, T_ss, sqrt_c, V, lam, h):
    """Same signature as the kernel; rebuilds C, L from the eigen data and uses exact_step."""
    C = sqrt_c**2
    L = np.diag(sqrt_c) @ V @ np.diag(lam) @ V.T @ np.diag(sqrt_c)
    return exact_step(C, L, L @ T_ss, T, h)[0]


def exponential_heat_integral(T, T_ss, sqrt_c, V, lam, h):
    C = sqrt_c**2
    L = np.diag(sqrt_c) @ V @ np.diag(lam) @ V.T @ np.diag(sqrt_c)
    return exact_step(C, L, L @ T_ss, T, h)[1]


def steady_state(L, B, Tb, P):
    return np.linalg.solve(L, B @ Tb + P)


def centrifugal_radial_growth(rho, E, nu, omega, a, b, r):
    """u = r (sigma_t - nu sigma_r) / E with Timoshenko & Goodier's rotating disc with a central hole."""
    k = rho * omega**2 / 8.0
    sigma_r = (3.0 + nu) * k * (b**2 + a**2 - a**2 * b**2 / r**2 - r**2)
    sigma_t = k * ((3.0 + nu) * (b**2 + a**2 + a**2 * b**2 / r**2) - (1.0 + 3.0 * nu) * r**2)
    return r * (sigma_t - nu * sigma_r) / E


def clearance_change(alpha, d_i, d_o, D, T_ir, T_or, T_ball, T_ref, u_c):
    """New P_d minus old, from the new inner/outer raceway and ball diameters."""
    Pd0 = d_o - d_i - 2.0 * D
    d_i1 = d_i * (1.0 + alpha * (T_ir - T_ref)) + 2.0 * u_c
    d_o1 = d_o * (1.0 + alpha * (T_or - T_ref))
    D1 = D * (1.0 + alpha * (T_ball - T_ref))
    return (d_o1 - d_i1 - 2.0 * D1) - Pd0


def axial_interference(s_arr, alpha_shaft, alpha_housing, spacing, T_shaft, T_housing, T_ref):
    """X (s_arr = +1): the shaft pushes the inner rings apart by its extra growth over the housing's."""
    shaft = spacing * (1.0 + alpha_shaft * (T_shaft - T_ref))
    housing = spacing * (1.0 + alpha_housing * (T_housing - T_ref))
    return (shaft - housing) if s_arr > 0 else (housing - shaft)


def heat_vector(u, heat_at, dist):
    """Node heats: each heat input of u spread over the nodes by its column of dist."""
    return np.asarray(dist) @ np.asarray(u, dtype=float)[heat_at]


def exponential_update(T, u, heat_at, boundary_at, dist, B, R, sqrt_c, V, lam, h):
    """The exact step towards the steady state L T_ss = B T_b + P, L rebuilt from its Cholesky factor."""
    u = np.asarray(u, dtype=float)
    T_ss = steady_state(R @ R.T, B, u[boundary_at], heat_vector(u, heat_at, dist))
    return exponential_step(T, T_ss, sqrt_c, V, lam, h)


def network_outputs(
    T, T0, u, s, heat_at, boundary_at, C, ends_i, ends_j, G, bearing_par, bearing_idx, par, idx, values
):
    """Every output from its own definition, through the twins above: node and bearing temperatures,
    new minus old clearance of each bearing, shaft minus housing growth, heat balance, stored heat."""
    u = np.asarray(u, dtype=float)
    n = len(T)
    values[:n] = T
    omega = u[idx[8]]
    for (rho, E, nu, a, d_i, d_o, D), (inner, outer, oil, s_inner, s_outer, s_oil, s_dpd) in zip(
        bearing_par, bearing_idx
    ):
        values[s_inner], values[s_outer], values[s_oil] = T[inner], T[outer], T[oil]
        u_c = centrifugal_radial_growth(rho, E, nu, omega, a, 0.5 * d_i, 0.5 * d_i)
        values[s_dpd] = clearance_change(par[0], d_i, d_o, D, T[inner], T[outer], T[oil], par[1], u_c)
    shaft, housing, s_dz, s_dz1, s_dz2, s_in, s_out, s_e = idx[:8]
    if shaft >= 0:
        dz = axial_interference(par[2], par[3], par[4], par[5], T[shaft], T[housing], par[1])
        values[s_dz], values[s_dz1], values[s_dz2] = dz, dz / 2 + s, dz / 2 - s
    values[s_in] = sum(u[k] for k in heat_at)
    values[s_out] = boundary_heat_flow(n, ends_i, ends_j, G, T, u[boundary_at])
    values[s_e] = sum(c * (t - t0) for c, t, t0 in zip(C, T, T0))


# the kernels this module twins, by name (tests/unit/test_every_kernel_has_a_twin.py)
KERNEL_MODULE = "spindle.thermal.network"
TWINS = {
    "rotating_shaft_nusselt": rotating_shaft_nusselt,
    "link_conductance": link_conductance,
    "link_conductances": link_conductances,
    "assemble": assemble,
    "boundary_heat_flow": boundary_heat_flow,
    "cholesky": cholesky,
    "cholesky_solve": cholesky_solve,
    "matvec": matvec,
    "rmatvec": rmatvec,
    "source_vector": source_vector,
    "implicit_euler_step": implicit_euler_step,
    "exponential_step": exponential_step,
    "exponential_heat_integral": exponential_heat_integral,
    "centrifugal_radial_growth": centrifugal_radial_growth,
    "clearance_change": clearance_change,
    "axial_interference": axial_interference,
    "heat_vector": heat_vector,
    "exponential_update": exponential_update,
    "network_outputs": network_outputs,
}
