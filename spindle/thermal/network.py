r"""Lumped thermal network of a spindle: numba kernels (docs/spindle_thermal.md). SI units (K, W, J/K, W/K, m, rad/s).

The network has n nodes with capacities C (J/K) and m boundary nodes whose temperatures T_b are
inputs. Links join two nodes or a node and a boundary with a conductance G (W/K), which may depend
on the shaft speed omega. With node heats P (W) the network obeys

    C dT/dt = -L(omega) T + B(omega) T_b + P,

L symmetric (the weighted graph Laplacian restricted to the nodes, plus the boundary conductances on
its diagonal), B[i, b] the conductance from node i to boundary b. If every node has a conductive
path to a boundary, L is positive definite and the steady state T_ss = L^-1 (B T_b + P) exists.

Indexing: a link end index < n is a node, >= n is boundary (index - n). Link kinds (integer codes,
parameters in `par[k, :]`):
    LINK_CONDUCTANCE     [G]                      G given (W/K)
    LINK_SHELL           [k, length, r1, r2]       radial conduction through a cylindrical shell,
                                                  G = 2 pi k length / ln(r2 / r1)
    LINK_CONTACT         [h_c, A]                  G = h_c A (thermal contact conductance)
    LINK_CONVECTION      [h, A]                    G = h A
    LINK_ROTATING_SHAFT  [d, A, k_air, nu_air, Pr] G = Nu k_air / d * A with Nu = 0.133 Re^(2/3) Pr^(1/3),
                                                  Re = (|omega| d / 2) d / nu_air (surface speed x d)
    LINK_ADVECTION       [mdot, c_p]               G = mdot c_p (flow entering at the boundary's
                                                  temperature, leaving well mixed at the node's)

Integrators over one step h with inputs held (zero-order hold):
- exponential (exact): with S = C^-1/2 L C^-1/2 = V diag(lam) V^T (eigendecomposition, done once per
  omega by the caller with numpy), T(t+h) = T_ss + C^-1/2 V exp(-lam h) V^T C^1/2 (T - T_ss).
- implicit (backward) Euler, `substeps` equal sub-steps: (C/dt + L) T_new = C/dt T + B T_b + P.
Both are unconditionally stable. Linear algebra is written out in loops (Cholesky for the symmetric
positive definite systems, plain matrix-vector products), as in the bearing kernels: for n ~ 10 nodes
that is as fast as BLAS, and a non-positive pivot comes back as NaN instead of an exception inside a
kernel. No kernel here calls BLAS or LAPACK (np.dot, np.linalg): numba takes those from scipy, and the
thermal FMU must run in a host without scipy (docs/fmu_runtime.md); the eigendecomposition of the
exponential update is numpy's, done by the caller outside the kernels.
"""

import math

import numpy as np

from bearing_fmu_common.jit import kernel

LINK_CONDUCTANCE = 0
LINK_SHELL = 1
LINK_CONTACT = 2
LINK_CONVECTION = 3
LINK_ROTATING_SHAFT = 4
LINK_ADVECTION = 5
PAR_SIZE = 5

# rotating-shaft correlation (Kreith; used by Bossmanns & Tu 1999 for spindle shafts): Nu = A Re^(2/3) Pr^(1/3)
NU_COEFF = 0.133


@kernel
def rotating_shaft_nusselt(omega, d, nu_air, Pr):
    """Nusselt number (-) of a shaft of diameter d (m) turning at omega (rad/s) in air of kinematic viscosity
    nu_air (m^2/s) and Prandtl number Pr: Nu = 0.133 Re^(2/3) Pr^(1/3), Re = (|omega| d/2) d / nu_air."""
    Re = abs(omega) * d * d / (2.0 * nu_air)
    return NU_COEFF * Re ** (2.0 / 3.0) * Pr ** (1.0 / 3.0)


@kernel
def link_conductance(kind, par, omega):
    """Conductance G (W/K) of one link of `kind` with parameter row `par` at shaft speed omega (rad/s)."""
    if kind == LINK_CONDUCTANCE:
        return par[0]
    if kind == LINK_SHELL:
        return 2.0 * math.pi * par[0] * par[1] / math.log(par[3] / par[2])
    if kind == LINK_CONTACT or kind == LINK_CONVECTION:
        return par[0] * par[1]
    if kind == LINK_ROTATING_SHAFT:
        d = par[0]
        return rotating_shaft_nusselt(omega, d, par[3], par[4]) * par[2] / d * par[1]
    if kind == LINK_ADVECTION:
        return par[0] * par[1]
    return math.nan  # unknown code: poison the result rather than guess


@kernel
def link_conductances(kinds, par, omega):
    """Conductances G (W/K) of all links (kinds: int array, par: (n_links, PAR_SIZE)) at omega (rad/s)."""
    G = np.empty(kinds.shape[0])
    for k in range(kinds.shape[0]):
        G[k] = link_conductance(kinds[k], par[k], omega)
    return G


@kernel
def assemble(n, m, ends_i, ends_j, G):
    """Conductance matrices (L (n, n), B (n, m)) in W/K of n nodes and m boundaries from the links
    (ends_i[k], ends_j[k], G[k]); an end index >= n is boundary index - n. Boundary-boundary links carry
    heat between two given temperatures and do not enter the node equations."""
    L = np.zeros((n, n))
    B = np.zeros((n, m))
    for k in range(G.shape[0]):
        i, j, g = ends_i[k], ends_j[k], G[k]
        if i < n and j < n:
            L[i, i] += g
            L[j, j] += g
            L[i, j] -= g
            L[j, i] -= g
        elif i < n:
            L[i, i] += g
            B[i, j - n] += g
        elif j < n:
            L[j, j] += g
            B[j, i - n] += g
    return L, B


@kernel
def boundary_heat_flow(n, ends_i, ends_j, G, T, Tb):
    """Heat (W) flowing from the nodes into the boundaries at node temperatures T and boundary
    temperatures Tb (K): the sum over node-boundary links of G (T_node - T_boundary)."""
    q = 0.0
    for k in range(G.shape[0]):
        i, j = ends_i[k], ends_j[k]
        if i < n and j >= n:
            q += G[k] * (T[i] - Tb[j - n])
        elif j < n and i >= n:
            q += G[k] * (T[j] - Tb[i - n])
    return q


@kernel
def cholesky(A):
    """Lower-triangular factor of a symmetric positive definite matrix A = R R^T.
    Returns an all-NaN matrix if a pivot is not positive (A not positive definite)."""
    n = A.shape[0]
    R = np.zeros((n, n))
    for j in range(n):
        s = A[j, j]
        for k in range(j):
            s -= R[j, k] * R[j, k]
        if not s > 0.0:
            R[:, :] = math.nan
            return R
        R[j, j] = math.sqrt(s)
        for i in range(j + 1, n):
            t = A[i, j]
            for k in range(j):
                t -= R[i, k] * R[j, k]
            R[i, j] = t / R[j, j]
    return R


@kernel
def cholesky_solve(R, b):
    """Solution x of R R^T x = b for the lower-triangular factor R of `cholesky`."""
    n = b.shape[0]
    y = np.empty(n)
    for i in range(n):
        s = b[i]
        for k in range(i):
            s -= R[i, k] * y[k]
        y[i] = s / R[i, i]
    x = np.empty(n)
    for i in range(n - 1, -1, -1):
        s = y[i]
        for k in range(i + 1, n):
            s -= R[k, i] * x[k]
        x[i] = s / R[i, i]
    return x


@kernel
def matvec(A, x):
    """A x for a 2-D A (loops: no BLAS)."""
    y = np.zeros(A.shape[0])
    for i in range(A.shape[0]):
        for j in range(A.shape[1]):
            y[i] += A[i, j] * x[j]
    return y


@kernel
def rmatvec(A, x):
    """A^T x for a 2-D A: matvec of the transposed view, which sums each entry's terms in the same order."""
    return matvec(A.T, x)


@kernel
def source_vector(B, Tb, P):
    """Right-hand side B T_b + P (W) of the node equations."""
    return matvec(B, Tb) + P


@kernel
def implicit_euler_step(C, L, f, T, h, substeps):
    """Temperatures (K) after h seconds of backward Euler in `substeps` equal steps dt = h/substeps:
    (C/dt + L) T_new = C/dt T + f, f = B T_b + P held. L-stable, first order in dt."""
    dt = h / substeps
    A = L.copy()
    for i in range(C.shape[0]):
        A[i, i] += C[i] / dt
    R = cholesky(A)  # C/dt + L is SPD for C > 0 and L positive semi-definite
    x = T.copy()
    for _ in range(substeps):
        x = cholesky_solve(R, C / dt * x + f)
    return x


@kernel
def exponential_step(T, T_ss, sqrt_c, V, lam, h):
    """Exact temperatures (K) after h seconds with inputs held:
    T_ss + C^-1/2 V diag(exp(-lam h)) V^T C^1/2 (T - T_ss), with S = C^-1/2 L C^-1/2 = V diag(lam) V^T
    and sqrt_c = C^1/2 (the diagonal)."""
    y = rmatvec(V, sqrt_c * (T - T_ss))
    y *= np.exp(-lam * h)
    return T_ss + matvec(V, y) / sqrt_c


@kernel
def exponential_heat_integral(T, T_ss, sqrt_c, V, lam, h):
    """Time integral over [0, h] of the temperatures (K.s) of the exact solution of `exponential_step`:
    h T_ss + C^-1/2 V diag((1 - exp(-lam h)) / lam) V^T C^1/2 (T - T_ss)."""
    y = rmatvec(V, sqrt_c * (T - T_ss))
    y *= -np.expm1(-lam * h) / lam
    return h * T_ss + matvec(V, y) / sqrt_c


@kernel
def centrifugal_radial_growth(rho, E, nu, omega, a, b, r):
    """Radial displacement u(r) (m) of a free annular disc (bore radius a, outer radius b, m) of density rho
    (kg/m^3), modulus E (Pa) and Poisson ratio nu turning at omega (rad/s), plane stress (Timoshenko &
    Goodier, rotating disc): u = rho omega^2/(8E) [(3+nu)(1-nu)(a^2+b^2) r + (3+nu)(1+nu) a^2 b^2/r - (1-nu^2) r^3]."""
    a2, b2 = a * a, b * b
    return (
        rho
        * omega
        * omega
        / (8.0 * E)
        * (
            (3.0 + nu) * (1.0 - nu) * (a2 + b2) * r
            + (3.0 + nu) * (1.0 + nu) * a2 * b2 / r
            - (1.0 - nu * nu) * r * r * r
        )
    )


@kernel
def clearance_change(alpha, d_i, d_o, D, T_ir, T_or, T_ball, T_ref, u_c):
    """Change of diametral clearance (m, negative = tighter) dPd = Delta d_o - Delta d_i - 2 Delta D with
    Delta d_i = alpha d_i (T_ir - T_ref) + 2 u_c (u_c: centrifugal radial growth of the inner raceway),
    Delta d_o = alpha d_o (T_or - T_ref), Delta D = alpha D (T_ball - T_ref); alpha (1/K), lengths (m)."""
    dd_i = alpha * d_i * (T_ir - T_ref) + 2.0 * u_c
    dd_o = alpha * d_o * (T_or - T_ref)
    dD = alpha * D * (T_ball - T_ref)
    return dd_o - dd_i - 2.0 * dD


@kernel
def axial_interference(s_arr, alpha_shaft, alpha_housing, spacing, T_shaft, T_housing, T_ref):
    """Change of the axial interference (m, > 0 tightens both bearings) of a fixed-preload pair:
    s_arr (alpha_shaft spacing (T_shaft - T_ref) - alpha_housing spacing (T_housing - T_ref)),
    s_arr = +1 for X (face-to-face), -1 for O (back-to-back)."""
    return s_arr * spacing * (alpha_shaft * (T_shaft - T_ref) - alpha_housing * (T_housing - T_ref))


# -- one model step in two calls: the inputs are a vector in the model's input order; index tables say
# which entries are heats and which are boundary temperatures, and where each output goes
# bearing table rows (float): density rho (kg/m^3), modulus E (Pa), Poisson ratio nu, bore radius a (m),
# groove diameters d_i, d_o (m), ball diameter D (m)
BP_RHO, BP_E, BP_NU, BP_A, BP_DI, BP_DO, BP_D = range(7)
# bearing table rows (int): inner-ring, outer-ring, ball/oil node; output slots of their temperatures and
# of the clearance change
BI_INNER, BI_OUTER, BI_OIL, BI_SLOT_INNER, BI_SLOT_OUTER, BI_SLOT_OIL, BI_SLOT_DPD = range(7)
# scalar parameters (float): expansion of the bearing steel alpha (1/K), assembly temperature T_ref (K);
# with an axial section: arrangement sign, alpha of shaft and housing (1/K), bearing spacing (m)
SP_ALPHA, SP_T_REF, SP_S_ARR, SP_ALPHA_SHAFT, SP_ALPHA_HOUSING, SP_SPACING = range(6)
# output slots and node indices (int): shaft, housing node (-1: no axial section), slots of dz_thermal,
# dz_thermal_1, dz_thermal_2, P_in, P_out, E_stored, and the position of omega in the input vector
LS_SHAFT, LS_HOUSING, LS_DZ, LS_DZ_1, LS_DZ_2, LS_P_IN, LS_P_OUT, LS_E_STORED, LS_OMEGA = range(9)


@kernel
def heat_vector(u, heat_at, dist):
    """Node heats P (W) = dist q from the input vector u (heats at the positions heat_at, W) and the
    distribution dist (n_nodes, n_heat) of each heat input over the nodes."""
    P = np.zeros(dist.shape[0])
    for i in range(dist.shape[0]):
        for q in range(heat_at.shape[0]):
            P[i] += dist[i, q] * u[heat_at[q]]
    return P


@kernel
def exponential_update(T, u, heat_at, boundary_at, dist, B, R, sqrt_c, V, lam, h):
    """Temperatures (K) after h seconds (s) with the inputs u held: `exponential_step` towards the steady
    state R R^T T_ss = B T_b + P, heats and boundary temperatures (W, K) read from u at heat_at and
    boundary_at."""
    T_ss = cholesky_solve(R, source_vector(B, u[boundary_at], heat_vector(u, heat_at, dist)))
    return exponential_step(T, T_ss, sqrt_c, V, lam, h)


@kernel
def network_outputs(
    T, T0, u, s, heat_at, boundary_at, C, ends_i, ends_j, G, bearing_par, bearing_idx, par, idx, values
):
    """Fill `values` (output slots in idx and bearing_idx) from node temperatures T (K), initial
    temperatures T0 (K), the input vector u (SI) and the axial float s (m) of the shaft: node and bearing
    temperatures, clearance change of each bearing (centrifugal growth of the inner raceway at the omega
    of u), axial interference, heat in and out (W), heat stored sum C (T - T0) (J)."""
    n = T.shape[0]
    values[:n] = T  # the node temperatures come first (declarations)
    omega = u[idx[LS_OMEGA]]
    for k in range(bearing_idx.shape[0]):
        b, p = bearing_idx[k], bearing_par[k]
        values[b[BI_SLOT_INNER]] = T[b[BI_INNER]]
        values[b[BI_SLOT_OUTER]] = T[b[BI_OUTER]]
        values[b[BI_SLOT_OIL]] = T[b[BI_OIL]]
        r = 0.5 * p[BP_DI]
        u_c = centrifugal_radial_growth(p[BP_RHO], p[BP_E], p[BP_NU], omega, p[BP_A], r, r)
        values[b[BI_SLOT_DPD]] = clearance_change(
            par[SP_ALPHA],
            p[BP_DI],
            p[BP_DO],
            p[BP_D],
            T[b[BI_INNER]],
            T[b[BI_OUTER]],
            T[b[BI_OIL]],
            par[SP_T_REF],
            u_c,
        )
    if idx[LS_SHAFT] >= 0:
        dz = axial_interference(
            par[SP_S_ARR],
            par[SP_ALPHA_SHAFT],
            par[SP_ALPHA_HOUSING],
            par[SP_SPACING],
            T[idx[LS_SHAFT]],
            T[idx[LS_HOUSING]],
            par[SP_T_REF],
        )
        values[idx[LS_DZ]] = dz
        values[idx[LS_DZ_1]] = 0.5 * dz + s
        values[idx[LS_DZ_2]] = 0.5 * dz - s
    P_in = 0.0
    for q in range(heat_at.shape[0]):
        P_in += u[heat_at[q]]
    values[idx[LS_P_IN]] = P_in
    values[idx[LS_P_OUT]] = boundary_heat_flow(n, ends_i, ends_j, G, T, u[boundary_at])
    E = 0.0
    for i in range(n):  # a loop, not np.dot: numba's np.dot calls scipy's BLAS, absent from a bare host
        E += C[i] * (T[i] - T0[i])
    values[idx[LS_E_STORED]] = E
