"""Numerical point-contact EHL: the discrete equations of the steady, isothermal, Newtonian problem.

Dimensionless on the Hertz contact (docs/ehl_solver.md): b the semi-axis along the entrainment x, a
across it (k = a / b), p_h the Hertz maximum pressure, X = x / b, Y = y / a, P = p / p_h, H = h Rx / b^2,
rho_r = rho(p) / rho(0), eta_r = eta(p) / eta(0). The Reynolds equation
    d/dX(eps dP/dX) + k^-2 d/dY(eps dP/dY) - d(rho_r H theta)/dX = 0,
    eps = rho_r H^3 / (eta_r lam),  lam = 12 eta0 u_e Rx^2 / (p_h b^3),
with mass-conserving cavitation by one unknown Phi per node (Elrod-Adams through a universal variable):
P = max(Phi, 0) and the fractional film content theta = 1 + min(Phi, 0), so Phi > 0 is the full film
and -1 < Phi < 0 the cavitated film, which carries the flux rho_r H theta at P = 0. The film
    H = H0 + X^2 / 2 + (k^2 Rx / Ry) Y^2 / 2 + W,  W = c_w sum K[i-k, j-l] P_kl
with K the deflection of the half-space under unit pressure on one rectangle of the grid (Johnson 1985,
eq. 3.25, written with the antiderivative u ln(v + r) + v ln(u + r)) and the convolution done by the
caller (FFT). The load: dX dY sum P = 2 pi / 3.

Discretisation: finite volumes on a uniform node grid, face coefficients eps_(i+1/2) = (eps_i + eps_i+1) / 2,
second-order upwind for the flux d(rho_r H theta)/dX (first order next to the inlet boundary), Phi = 0
(ambient pressure, full film) on the boundary.

Lubricant laws (integer codes, parameters in a float64 array `fluid`, layout FLUID_*):
viscosity Barus exp(alpha p), Roelands, or the modified WLF law (capped where it turns glassy);
density incompressible, Dowson-Higginson or Murnaghan.
"""

import math

import numpy as np

from bearing_fmu_common.jit import kernel
from bearing_fmu_common.layout import Layout

VISC_BARUS = 0
VISC_ROELANDS = 1
VISC_WLF = 2

DENS_INCOMPRESSIBLE = 0
DENS_DOWSON_HIGGINSON = 1
DENS_MURNAGHAN = 2

# layout of the fluid array
_FLUID_SLOTS = Layout()
FLUID_VISC = _FLUID_SLOTS.slot()  # viscosity code
FLUID_DENS = _FLUID_SLOTS.slot()  # density code
FLUID_ETA0 = _FLUID_SLOTS.slot()  # Pa.s, viscosity at p = 0 (Barus, Roelands)
FLUID_ALPHA = _FLUID_SLOTS.slot()  # 1/Pa, Barus coefficient; Roelands: alpha gives Z = alpha p0 / (ln eta0 + 9.67)
FLUID_T = _FLUID_SLOTS.slot()  # K, temperature (WLF, Murnaghan)
FLUID_WLF = _FLUID_SLOTS.slot(8)  # 8 values: mu_G (Pa.s), T_g0 (K), A1 (K), A2 (1/Pa), b1 (1/Pa), b2, C1, C2 (K)
FLUID_MURN = _FLUID_SLOTS.slot(5)  # 5 values: T_R (K), a_v (1/K), beta_K (1/K), K_MM (Pa), K' (-)
FLUID_SIZE = _FLUID_SLOTS.size

ROELANDS_P0 = 1.96e8  # Pa, Roelands' pressure constant
ROELANDS_LN_ETA_INF = -9.67  # ln of Roelands' limiting viscosity 6.31e-5 Pa.s, as the law is printed
# Above this viscosity ratio the film is glassy and carries no pressure flow (eps ~ 0): the modified WLF law
# diverges at finite pressure (lubricant 2 of the thesis at 313 K: ~3.1 GPa), so its ratio is capped here.
ETA_RATIO_MAX = 1e20


@kernel
def viscosity_ratio(p, fluid):
    """eta(p) / eta(0) (-) at pressure p (Pa) of the law fluid[FLUID_VISC]; capped at ETA_RATIO_MAX."""
    code = int(fluid[FLUID_VISC])
    if code == VISC_BARUS:
        e = fluid[FLUID_ALPHA] * p
    elif code == VISC_ROELANDS:
        ln_ratio = math.log(fluid[FLUID_ETA0]) - ROELANDS_LN_ETA_INF
        z = fluid[FLUID_ALPHA] * ROELANDS_P0 / ln_ratio
        e = ln_ratio * ((1.0 + p / ROELANDS_P0) ** z - 1.0)
    else:
        T = fluid[FLUID_T]
        mu_G = fluid[FLUID_WLF]
        T_g0 = fluid[FLUID_WLF + 1]
        A1 = fluid[FLUID_WLF + 2]
        A2 = fluid[FLUID_WLF + 3]
        b1 = fluid[FLUID_WLF + 4]
        b2 = fluid[FLUID_WLF + 5]
        C1 = fluid[FLUID_WLF + 6]
        C2 = fluid[FLUID_WLF + 7]
        d0 = T - T_g0
        ln_mu0 = math.log(mu_G) - 2.303 * C1 * d0 / (C2 + d0)
        d = (T - (T_g0 + A1 * math.log(1.0 + A2 * p))) * (1.0 + b1 * p) ** b2
        if C2 + d <= 0.0:
            return ETA_RATIO_MAX
        e = math.log(mu_G) - 2.303 * C1 * d / (C2 + d) - ln_mu0
    if e >= math.log(ETA_RATIO_MAX):
        return ETA_RATIO_MAX
    return math.exp(e)


@kernel
def density_ratio(p, fluid):
    """rho(p) / rho(0) (-) at pressure p (Pa) of the law fluid[FLUID_DENS]."""
    code = int(fluid[FLUID_DENS])
    if code == DENS_DOWSON_HIGGINSON:
        return (0.59e9 + 1.34 * p) / (0.59e9 + p)
    if code == DENS_MURNAGHAN:
        K_M = fluid[FLUID_MURN + 3] * math.exp(-fluid[FLUID_MURN + 2] * fluid[FLUID_T])
        kp = fluid[FLUID_MURN + 4]
        return (1.0 + kp / K_M * p) ** (1.0 / kp)
    return 1.0


@kernel
def density_log_slopes(P, p_h, fluid, g_rho):
    """d ln(rho_r) / dP (-) at every node of the pressure P (-, P = max(P, 0), times p_h in Pa), in closed form:
    0 (incompressible), 1.34 / (0.59e9 + 1.34 p) - 1 / (0.59e9 + p) (Dowson-Higginson), 1 / (K_M + K' p)
    (Murnaghan), times p_h. The relaxation's density derivative (relaxation_sweep), computed before every sweep
    at the cost of a division per node (fluid_log_slopes differences both laws three times)."""
    code = int(fluid[FLUID_DENS])
    nx, ny = P.shape
    K_M = fluid[FLUID_MURN + 3] * math.exp(-fluid[FLUID_MURN + 2] * fluid[FLUID_T])
    kp = fluid[FLUID_MURN + 4]
    for i in range(nx):
        for j in range(ny):
            p = max(P[i, j], 0.0) * p_h
            if code == DENS_DOWSON_HIGGINSON:
                g_rho[i, j] = (1.34 / (0.59e9 + 1.34 * p) - 1.0 / (0.59e9 + p)) * p_h
            elif code == DENS_MURNAGHAN:
                g_rho[i, j] = p_h / (K_M + kp * p)
            else:
                g_rho[i, j] = 0.0


@kernel
def fluid_fields(Phi, p_h, fluid, rho_r, eta_r):
    """Fill rho_r and eta_r (-) at every node from Phi (pressure P = max(Phi, 0), times p_h in Pa)."""
    nx, ny = Phi.shape
    for i in range(nx):
        for j in range(ny):
            p = max(Phi[i, j], 0.0) * p_h
            rho_r[i, j] = density_ratio(p, fluid)
            eta_r[i, j] = viscosity_ratio(p, fluid)


@kernel
def rectangle_influence(nx, ny, dx, dy):
    """Integral of 1/r (m) over one dx x dy rectangle (m) centred at the origin, seen from the node offsets
    (m dx, n dy), m = 0..nx-1, n = 0..ny-1: the deflection under unit pressure is 2 / (pi E') times it.

    Antiderivative of 1/sqrt(u^2 + v^2): F = u ln(v + r) + v ln(u + r), r = sqrt(u^2 + v^2), taken between the
    rectangle's corners; with m, n >= 0 every corner has u >= -dx/2, v >= -dy/2 and never u = v = 0, so both
    logarithms stay finite and free of cancellation."""
    out = np.empty((nx, ny))
    c = 0.5 * dx
    d = 0.5 * dy
    for m in range(nx):
        for n in range(ny):
            x = m * dx
            y = n * dy
            total = 0.0
            for su in (-1.0, 1.0):
                for sv in (-1.0, 1.0):
                    u = x + su * c
                    v = y + sv * d
                    r = math.sqrt(u * u + v * v)
                    total += su * sv * (u * math.log(v + r) + v * math.log(u + r))
            out[m, n] = total
    return out


@kernel
def film(H0, X, Y, curv_y, W, H):
    """Fill H (-) = H0 + X^2/2 + curv_y Y^2/2 + W at every node; curv_y = k^2 Rx / Ry (-)."""
    nx, ny = H.shape
    for i in range(nx):
        for j in range(ny):
            H[i, j] = H0 + 0.5 * X[i] * X[i] + 0.5 * curv_y * Y[j] * Y[j] + W[i, j]


@kernel
def reynolds_residual(Phi, H, rho_r, eta_r, lam, k, dX, dY, R):
    """Residual R (-) of the discrete Reynolds equation at every node (0 on the boundary, where Phi = 0).

    Phi (-) universal variable, H film, rho_r, eta_r fluid ratios, lam speed group, k ellipticity, dX, dY
    node spacings (all dimensionless). R = Poiseuille flow divergence - d(rho_r H theta)/dX."""
    nx, ny = Phi.shape
    ky = 1.0 / (k * k * dY * dY)
    kx = 1.0 / (dX * dX)
    for i in range(nx):
        R[i, 0] = 0.0
        R[i, ny - 1] = 0.0
    for j in range(ny):
        R[0, j] = 0.0
        R[nx - 1, j] = 0.0
    for i in range(1, nx - 1):
        for j in range(1, ny - 1):
            R[i, j] = _node_residual(Phi, H, rho_r, eta_r, lam, kx, ky, dX, i, j)


@kernel
def _eps(Phi, H, rho_r, eta_r, lam, i, j):
    """Poiseuille coefficient eps = rho_r H^3 / (eta_r lam) (-) of node (i, j); 0 where the gap is closed (H <= 0)."""
    h = max(H[i, j], 0.0)
    return rho_r[i, j] * h * h * h / (eta_r[i, j] * lam)


@kernel
def _flux(Phi, H, rho_r, i, j):
    """Couette mass flux (-) rho_r H theta of node (i, j), theta = 1 + min(Phi, 0)."""
    theta = 1.0 + min(Phi[i, j], 0.0)
    return rho_r[i, j] * H[i, j] * theta


@kernel
def _node_residual(Phi, H, rho_r, eta_r, lam, kx, ky, dX, i, j):
    """Discrete Reynolds residual at interior node (i, j)."""
    e0 = _eps(Phi, H, rho_r, eta_r, lam, i, j)
    eE = 0.5 * (e0 + _eps(Phi, H, rho_r, eta_r, lam, i + 1, j))
    eW = 0.5 * (e0 + _eps(Phi, H, rho_r, eta_r, lam, i - 1, j))
    eN = 0.5 * (e0 + _eps(Phi, H, rho_r, eta_r, lam, i, j + 1))
    eS = 0.5 * (e0 + _eps(Phi, H, rho_r, eta_r, lam, i, j - 1))
    p0 = max(Phi[i, j], 0.0)
    pE = max(Phi[i + 1, j], 0.0)
    pW = max(Phi[i - 1, j], 0.0)
    pN = max(Phi[i, j + 1], 0.0)
    pS = max(Phi[i, j - 1], 0.0)
    poiseuille = kx * (eE * (pE - p0) - eW * (p0 - pW)) + ky * (eN * (pN - p0) - eS * (p0 - pS))
    f0 = _flux(Phi, H, rho_r, i, j)
    f1 = _flux(Phi, H, rho_r, i - 1, j)
    if i >= 2:
        couette = (1.5 * f0 - 2.0 * f1 + 0.5 * _flux(Phi, H, rho_r, i - 2, j)) / dX
    else:
        couette = (f0 - f1) / dX
    return poiseuille - couette


@kernel
def relaxation_sweep(P, F, H, rho_r, eta_r, g_rho, lam, k, dX, dY, Kc, xi_switch, omega_gs, omega_jac, xi_lines, delta):
    """One relaxation sweep of the discrete Reynolds equation reynolds_residual = F on the pressure P (-), in
    place; returns the largest change of P. F (-) is the right-hand side (0 on the finest grid, the FAS
    right-hand side on a coarser one).

    The film H, rho_r and eta_r are held (the caller recomputes them, the deflection by FFT, after the sweep);
    Kc[m, n] (-) is the deflection W at offset (m, n) nodes under unit P on one cell (c_w times the rectangle
    influence). Each interior node's change is the Newton step of its own residual (reynolds_residual with
    theta = 1, P >= 0) with the derivative of the Poiseuille term (eps held) and of the Couette term through
    the local deflection and the density (g_rho = d ln(rho_r) / dP at every node, density_log_slopes; zeros give
    the elastic part alone). The density part, 1.5 rho_r g_rho H / dX at the node, is the larger one wherever
    the film is thick in Hertz units on a fine grid (it does not shrink with the spacing, the elastic one does:
    H = 0.23, Dowson-Higginson at 2.5 GPa, level 3: 5 times the elastic part), and without it the relaxation
    overshoots by that factor and diverges there:
    - Gauss-Seidel, under-relaxed by omega_gs, where eps max(1/dX^2, 1/(k dY)^2) >= xi_switch or the node or
      a neighbour is at P = 0;
    - elsewhere (the high-pressure zone, eps small) Jacobi distributive relaxation: the change d of a node
      is applied as +omega_jac d at the node and -omega_jac d / 4 at each of its four neighbours, which makes
      its effect on the deflection local; the derivative is that of the distributed change. These changes
      are computed from the residuals after the Gauss-Seidel pass and applied together (delta is work space).
    A Gauss-Seidel node with eps max(1/dX^2, 1/(k dY)^2) >= xi_lines and its five-point star pressurised is left
    alone: line_gauss_seidel relaxed it before this sweep (xi_lines = inf: no lines).
    Negative pressures are set to 0 (cavitation by complementarity). Boundary nodes stay at 0."""
    nx, ny = P.shape
    kx = 1.0 / (dX * dX)
    ky = 1.0 / (k * k * dY * dY)
    kmax = max(kx, ky)
    # elastic derivative of the upwind Couette difference: point change and distributed change
    d00 = Kc[0, 0] - 0.5 * (Kc[1, 0] + Kc[0, 1])
    d10 = Kc[1, 0] - 0.25 * (Kc[0, 0] + Kc[2, 0] + 2.0 * Kc[1, 1])
    d20 = Kc[2, 0] - 0.25 * (Kc[1, 0] + Kc[3, 0] + 2.0 * Kc[2, 1])
    change = 0.0
    for i in range(nx):
        for j in range(ny):
            delta[i, j] = 0.0
    for i in range(1, nx - 1):
        for j in range(1, ny - 1):
            e0 = _eps(P, H, rho_r, eta_r, lam, i, j)
            sep = P[i, j] <= 0.0 or P[i + 1, j] <= 0.0 or P[i - 1, j] <= 0.0
            sep = sep or P[i, j + 1] <= 0.0 or P[i, j - 1] <= 0.0
            if e0 * kmax < xi_switch and not sep:
                delta[i, j] = 1.0  # marks a Jacobi node
                continue
            if e0 * kmax >= xi_lines and not sep:
                continue  # relaxed by line_gauss_seidel
            r = _node_residual(P, H, rho_r, eta_r, lam, kx, ky, dX, i, j) - F[i, j]
            jac = _point_derivative(P, H, rho_r, eta_r, g_rho, lam, kx, ky, dX, Kc, i, j)
            new = max(P[i, j] - omega_gs * r / jac, 0.0)
            change = max(change, abs(new - P[i, j]))
            P[i, j] = new
    for i in range(1, nx - 1):
        for j in range(1, ny - 1):
            if delta[i, j] == 0.0:
                continue
            r = _node_residual(P, H, rho_r, eta_r, lam, kx, ky, dX, i, j) - F[i, j]
            jac = 1.25 * _poiseuille_diagonal(P, H, rho_r, eta_r, lam, kx, ky, i, j)
            if i >= 2:
                jac -= (1.5 * rho_r[i, j] * d00 - 2.0 * rho_r[i - 1, j] * d10 + 0.5 * rho_r[i - 2, j] * d20) / dX
                # density: +d at the node, -d/4 at the upstream neighbour (which moves only if it is interior)
                drho = 1.5 * rho_r[i, j] * g_rho[i, j] * H[i, j]
                if i > 1:
                    drho += 0.5 * rho_r[i - 1, j] * g_rho[i - 1, j] * H[i - 1, j]
                jac -= drho / dX
            else:
                jac -= (rho_r[i, j] * d00 - rho_r[i - 1, j] * d10) / dX
                jac -= rho_r[i, j] * g_rho[i, j] * H[i, j] / dX
            delta[i, j] = -omega_jac * r / jac
    for i in range(1, nx - 1):
        for j in range(1, ny - 1):
            d = delta[i, j]
            if d == 0.0:
                continue
            P[i, j] += d
            if i > 1:
                P[i - 1, j] -= 0.25 * d
            if i < nx - 2:
                P[i + 1, j] -= 0.25 * d
            if j > 1:
                P[i, j - 1] -= 0.25 * d
            if j < ny - 2:
                P[i, j + 1] -= 0.25 * d
    for i in range(1, nx - 1):
        for j in range(1, ny - 1):
            if P[i, j] < 0.0:
                P[i, j] = 0.0
            if delta[i, j] != 0.0:
                change = max(change, abs(delta[i, j]))
    return change


@kernel
def line_gauss_seidel(P, F, H, rho_r, eta_r, lam, k, dX, dY, Kc, g_rho, xi_lines, omega_gs, work):
    """Gauss-Seidel line relaxation along X (P in place) of the nodes with eps max(1/dX^2, 1/(k dY)^2) >= xi_lines
    (at least relaxation_sweep's xi_switch: Gauss-Seidel nodes) and a pressurised five-point star; returns the
    largest change of P. work: (4, nx) scratch.

    The grid is equally spaced in Hertz units, so for k > 1 the Poiseuille coupling along X (eps / dX^2) is k^2
    times the one along Y (eps / (k dY)^2): point relaxation then smooths the error only across X, and the
    coarse grids cannot correct what it leaves (strong anisotropy; Venner & Lubrecht 2000, ch. 3 and 8, relax
    lines in the direction of the strong coupling). Each row j takes the Newton step of its line nodes together:
    the derivative of each residual with respect to its own pressure is relaxation_sweep's (Poiseuille with eps
    held, the upwind Couette term through the local deflection and the density), with respect to its two
    neighbours along X the Poiseuille face coefficients; the tridiagonal system of each run of consecutive line
    nodes is solved by the Thomas algorithm, and the step is under-relaxed by omega_gs. The elastic coupling of
    the neighbours is left out: with it the cycles diverged (k = 9, M = 100-1000, L = 30). Nodes next to a
    cavitated one are left to relaxation_sweep's point relaxation, whose projection P >= 0 is exact for one
    node: a line step clipped at P = 0 left the free boundary out of balance (the load error stalled at 4e-4).
    Lines at every Gauss-Seidel node (xi_lines = xi_switch) diverged at heavy contacts, next to the high-pressure
    zone where the left-out elastic coupling matters (docs/ehl_solver.md, Solver). Rows in order of j, each with
    the pressures of the rows before it; negative pressures set to 0."""
    nx, ny = P.shape
    kx = 1.0 / (dX * dX)
    ky = 1.0 / (k * k * dY * dY)
    kmax = max(kx, ky)
    lower = work[0]
    diag = work[1]
    upper = work[2]
    rhs = work[3]
    change = 0.0
    for j in range(1, ny - 1):
        i = 1
        while i < nx - 1:
            i0 = i  # a run of consecutive line nodes i0 .. i - 1
            while i < nx - 1 and _line_node(P, H, rho_r, eta_r, lam, kmax, xi_lines, i, j):
                n = i - i0
                e0 = _eps(P, H, rho_r, eta_r, lam, i, j)
                lower[n] = kx * 0.5 * (e0 + _eps(P, H, rho_r, eta_r, lam, i - 1, j))
                upper[n] = kx * 0.5 * (e0 + _eps(P, H, rho_r, eta_r, lam, i + 1, j))
                diag[n] = _point_derivative(P, H, rho_r, eta_r, g_rho, lam, kx, ky, dX, Kc, i, j)
                rhs[n] = F[i, j] - _node_residual(P, H, rho_r, eta_r, lam, kx, ky, dX, i, j)
                i += 1
            count = i - i0
            if count == 0:
                i += 1
                continue
            for n in range(1, count):  # Thomas algorithm; rhs becomes the step
                m = lower[n] / diag[n - 1]
                diag[n] -= m * upper[n - 1]
                rhs[n] -= m * rhs[n - 1]
            rhs[count - 1] /= diag[count - 1]
            for n in range(count - 2, -1, -1):
                rhs[n] = (rhs[n] - upper[n] * rhs[n + 1]) / diag[n]
            for n in range(count):
                new = max(P[i0 + n, j] + omega_gs * rhs[n], 0.0)
                change = max(change, abs(new - P[i0 + n, j]))
                P[i0 + n, j] = new
    return change


@kernel
def _line_node(P, H, rho_r, eta_r, lam, kmax, xi_lines, i, j):
    """True where line_gauss_seidel relaxes node (i, j): eps kmax >= xi_lines and the node and its four neighbours
    pressurised."""
    if P[i, j] <= 0.0 or P[i + 1, j] <= 0.0 or P[i - 1, j] <= 0.0 or P[i, j + 1] <= 0.0 or P[i, j - 1] <= 0.0:
        return False
    return _eps(P, H, rho_r, eta_r, lam, i, j) * kmax >= xi_lines


@kernel
def _point_derivative(P, H, rho_r, eta_r, g_rho, lam, kx, ky, dX, Kc, i, j):
    """Derivative (-) of the residual of node (i, j) with respect to its own pressure, the others held: the
    Poiseuille term with eps held, the upwind Couette term through the local deflection Kc and the density."""
    jac = _poiseuille_diagonal(P, H, rho_r, eta_r, lam, kx, ky, i, j)
    if i >= 2:
        jac -= (1.5 * rho_r[i, j] * Kc[0, 0] - 2.0 * rho_r[i - 1, j] * Kc[1, 0]) / dX
        jac -= 0.5 * rho_r[i - 2, j] * Kc[2, 0] / dX
        jac -= 1.5 * rho_r[i, j] * g_rho[i, j] * H[i, j] / dX
    else:
        jac -= (rho_r[i, j] * Kc[0, 0] - rho_r[i - 1, j] * Kc[1, 0]) / dX
        jac -= rho_r[i, j] * g_rho[i, j] * H[i, j] / dX
    return jac


@kernel
def _poiseuille_diagonal(P, H, rho_r, eta_r, lam, kx, ky, i, j):
    """Derivative (-) of the Poiseuille term of node (i, j) with respect to its own P, eps held."""
    e0 = _eps(P, H, rho_r, eta_r, lam, i, j)
    eE = 0.5 * (e0 + _eps(P, H, rho_r, eta_r, lam, i + 1, j))
    eW = 0.5 * (e0 + _eps(P, H, rho_r, eta_r, lam, i - 1, j))
    eN = 0.5 * (e0 + _eps(P, H, rho_r, eta_r, lam, i, j + 1))
    eS = 0.5 * (e0 + _eps(P, H, rho_r, eta_r, lam, i, j - 1))
    return -(kx * (eE + eW) + ky * (eN + eS))


@kernel
def fluid_log_slopes(P, p_h, fluid, g_rho, g_eta):
    """d ln(rho_r) / dP and d ln(eta_r) / dP (-) at every node of the pressure P (-): central differences of
    the laws over +-d, d = 1e-6 (P + 1), second-order one-sided ones (0, d, 2 d) where P < d; 0 where the
    viscosity reaches its cap within the stencil."""
    nx, ny = P.shape
    for i in range(nx):
        for j in range(ny):
            p = max(P[i, j], 0.0)
            d = 1e-6 * (p + 1.0)
            if p < d:
                q = (0.0, d, 2.0 * d)
                c = (-1.5 / d, 2.0 / d, -0.5 / d)
            else:
                q = (p - d, p, p + d)
                c = (-0.5 / d, 0.0, 0.5 / d)
            gr = 0.0
            ge = 0.0
            capped = False
            for s in range(3):
                gr += c[s] * math.log(density_ratio(q[s] * p_h, fluid))
                e = viscosity_ratio(q[s] * p_h, fluid)
                capped = capped or e >= ETA_RATIO_MAX
                ge += c[s] * math.log(e)
            g_rho[i, j] = gr
            g_eta[i, j] = 0.0 if capped else ge


@kernel
def newton_jacobian(P, H, rho_r, eta_r, g_rho, g_eta, lam, k, dX, dY, Kc, wet_i, wet_j, widx, J):
    """Jacobian (-) of the discrete Reynolds residual (reynolds_residual with theta = 1) at the wet nodes
    (wet_i[n], wet_j[n]) with respect to their pressures and the rigid film H0 (last column): J[n, m] =
    dR(wet n) / dP(wet m), J[n, len(wet)] = dR(wet n) / dH0. The pressure acts on a residual directly (the
    5-point Poiseuille stencil), through rho_r and eta_r in eps and in the upwind Couette flux (log slopes
    g_rho, g_eta of fluid_log_slopes), and through the film: every node of the residual's stencil sees the
    deflection Kc[|di|, |dj|] of every wet node's pressure. widx[i, j] is the wet index of node (i, j), -1 if
    it is not wet. Closed gaps (H <= 0) carry no Poiseuille flow (_eps)."""
    nw = wet_i.shape[0]
    kx = 1.0 / (dX * dX)
    ky = 1.0 / (k * k * dY * dY)
    di = np.array([0, 1, -1, 0, 0, -2])
    dj = np.array([0, 0, 0, 1, -1, 0])
    dp = np.zeros(6)  # dR / dP at the stencil nodes, direct and through the fluid
    dh = np.zeros(6)  # dR / dH at the stencil nodes
    eps = np.zeros(6)
    for n in range(nw):
        i = wet_i[n]
        j = wet_j[n]
        for s in range(5):
            eps[s] = _eps(P, H, rho_r, eta_r, lam, i + di[s], j + dj[s])
        p0 = P[i, j]
        gE = P[i + 1, j] - p0
        gW = p0 - P[i - 1, j]
        gN = P[i, j + 1] - p0
        gS = p0 - P[i, j - 1]
        fE = 0.5 * (eps[0] + eps[1])
        fW = 0.5 * (eps[0] + eps[2])
        fN = 0.5 * (eps[0] + eps[3])
        fS = 0.5 * (eps[0] + eps[4])
        de = np.zeros(6)  # dR / d eps at the stencil nodes
        de[0] = 0.5 * kx * (gE - gW) + 0.5 * ky * (gN - gS)
        de[1] = 0.5 * kx * gE
        de[2] = -0.5 * kx * gW
        de[3] = 0.5 * ky * gN
        de[4] = -0.5 * ky * gS
        for s in range(6):
            dp[s] = 0.0
            dh[s] = 0.0
        dp[0] = -(kx * (fE + fW) + ky * (fN + fS))
        dp[1] = kx * fE
        dp[2] = kx * fW
        dp[3] = ky * fN
        dp[4] = ky * fS
        for s in range(5):
            a = i + di[s]
            b = j + dj[s]
            dp[s] += de[s] * eps[s] * (g_rho[a, b] - g_eta[a, b])
            if H[a, b] > 0.0:
                dh[s] += de[s] * 3.0 * eps[s] / H[a, b]
        if i >= 2:
            c = (1.5 / dX, -2.0 / dX, 0.5 / dX)
        else:
            c = (1.0 / dX, -1.0 / dX, 0.0)
        for q in range(3):
            s = 0 if q == 0 else (2 if q == 1 else 5)
            a = i + di[s]
            b = j + dj[s]
            if c[q] == 0.0:
                continue
            dp[s] -= c[q] * rho_r[a, b] * g_rho[a, b] * H[a, b]
            dh[s] -= c[q] * rho_r[a, b]
        h0 = 0.0
        for s in range(6):
            h0 += dh[s]
        J[n, nw] = h0
        for m in range(nw):
            im = wet_i[m]
            jm = wet_j[m]
            v = 0.0
            for s in range(6):
                if dh[s] != 0.0:
                    v += dh[s] * Kc[abs(i + di[s] - im), abs(j + dj[s] - jm)]
            J[n, m] = v
        for s in range(6):
            a = i + di[s]
            b = j + dj[s]
            m = widx[a, b]
            if m >= 0:
                J[n, m] += dp[s]
