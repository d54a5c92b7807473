"""Twin of bearing_fmu.kernels.ehl_solver: fluid ratios, rectangle influences, film, Reynolds residual,
and the direct-summation deflection that the product computes by FFT.

- Viscosity ratio eta(p)/eta(0): Barus exp(alpha p); Roelands exp[(ln eta0 + 9.67)((1 + p/p0)^Z - 1)],
  Z = alpha p0 / (ln eta0 + 9.67), p0 = 1.96e8 Pa; modified WLF (Bair; Wheeler 2016 thesis eq. 2.1-9) as the
  quotient of the law at p and at 0, capped at 1e20 (also past the glass singularity C2 + (T - T_g) F = 0).
- Density ratio: Dowson-Higginson (0.59e9 + 1.34 p) / (0.59e9 + p); Murnaghan (1 + K' p / K_M)^(1/K'),
  K_M = K_MM exp(-beta_K T) (thesis eq. 2.1-7).
- Rectangle influence: Johnson (1985), Contact Mechanics, eq. 3.25, the closed form of the integral of 1/r
  over a uniformly loaded 2c x 2d rectangle, written with its four logarithms.
- Deflection by direct summation over every pressure cell (no FFT).
- Reynolds residual written with whole-array flux differences (numpy slicing) instead of per-node loops.
- Log slopes of the fluid ratios: Richardson-extrapolated central differences of the twin's laws (also for
  the kernel's closed-form density slope).
- Newton Jacobian: central differences of the twin's residual, each wet pressure moved with its film (direct
  influence sums) and fluid ratios, and H0 moved.
- Relaxation sweep: the same node updates, each node's residual and derivative taken from the twin's
  whole-array residual of the current pressure (recomputed after every Gauss-Seidel update) and the
  derivative of the residual written out from the 5-point stencil and the deflection of a point change
  (Gauss-Seidel) or of the distributed change +d at the node, -d/4 at its four neighbours (Jacobi), and the
  density's part of the Couette derivative, rho_r g_rho H of every stencil node whose pressure moves.
"""

import math

import numpy as np

from bearing_fmu.kernels import ehl_solver as es  # option codes and array layout only

KERNEL_MODULE = "bearing_fmu.kernels.ehl_solver"
ETA_RATIO_MAX = 1e20


def viscosity_ratio(p, fluid):
    code = int(fluid[es.FLUID_VISC])
    if code == es.VISC_BARUS:
        ratio = math.exp(min(fluid[es.FLUID_ALPHA] * p, 700.0))
    elif code == es.VISC_ROELANDS:
        eta0 = fluid[es.FLUID_ETA0]
        s = math.log(eta0) + 9.67
        z = fluid[es.FLUID_ALPHA] * 1.96e8 / s
        ratio = math.exp(min(s * ((1.0 + p / 1.96e8) ** z - 1.0), 700.0))
    else:
        mu_G, T_g0, A1, A2, b1, b2, C1, C2 = fluid[es.FLUID_WLF : es.FLUID_WLF + 8]
        T = fluid[es.FLUID_T]

        def mu(pp):
            Tg = T_g0 + A1 * math.log(1.0 + A2 * pp)
            F = (1.0 + b1 * pp) ** b2
            dT = (T - Tg) * F
            if C2 + dT <= 0.0:
                return math.inf
            e = -2.303 * C1 * dT / (C2 + dT)
            return math.inf if e > 700.0 else mu_G * math.exp(e)

        ratio = mu(p) / mu(0.0)
    return min(ratio, ETA_RATIO_MAX)


def density_ratio(p, fluid):
    code = int(fluid[es.FLUID_DENS])
    if code == es.DENS_DOWSON_HIGGINSON:
        return (0.59e9 + 1.34 * p) / (0.59e9 + p)
    if code == es.DENS_MURNAGHAN:
        T_R, a_v, beta_K, K_MM, kp = fluid[es.FLUID_MURN : es.FLUID_MURN + 5]
        K_M = K_MM * math.exp(-beta_K * fluid[es.FLUID_T])
        return (1.0 + kp * p / K_M) ** (1.0 / kp)
    return 1.0


def fluid_fields(Phi, p_h, fluid, rho_r, eta_r):
    P = np.maximum(Phi, 0.0) * p_h
    rho_r[...] = np.vectorize(lambda p: density_ratio(p, fluid))(P)
    eta_r[...] = np.vectorize(lambda p: viscosity_ratio(p, fluid))(P)


def _johnson(x, y, c, d):
    """Johnson eq. 3.25: integral of 1/r over |x'| <= c, |y'| <= d seen from (x, y)."""

    def r(u, v):
        return math.sqrt(u * u + v * v)

    return (
        (x + c) * math.log((y + d + r(y + d, x + c)) / (y - d + r(y - d, x + c)))
        + (y + d) * math.log((x + c + r(y + d, x + c)) / (x - c + r(y + d, x - c)))
        + (x - c) * math.log((y - d + r(y - d, x - c)) / (y + d + r(y + d, x - c)))
        + (y - d) * math.log((x - c + r(y - d, x - c)) / (x + c + r(y - d, x + c)))
    )


def rectangle_influence(nx, ny, dx, dy):
    out = np.empty((nx, ny))
    for m in range(nx):
        for n in range(ny):
            out[m, n] = _johnson(m * dx, n * dy, 0.5 * dx, 0.5 * dy)
    return out


def deflection_direct(P, kern, c_w):
    """W at every node: c_w sum over all cells (k, l) of kern[|i - k|, |j - l|] P[k, l] (direct summation)."""
    nx, ny = P.shape
    W = np.zeros((nx, ny))
    ii = np.arange(nx)
    jj = np.arange(ny)
    for k in range(nx):
        for l in range(ny):
            if P[k, l] != 0.0:
                W += P[k, l] * kern[np.abs(ii - k)][:, np.abs(jj - l)]
    return c_w * W


def film(H0, X, Y, curv_y, W, H):
    H[...] = H0 + 0.5 * X[:, None] ** 2 + 0.5 * curv_y * Y[None, :] ** 2 + W


def reynolds_residual(Phi, H, rho_r, eta_r, lam, k, dX, dY, R):
    P = np.maximum(Phi, 0.0)
    eps = rho_r * np.maximum(H, 0.0) ** 3 / (eta_r * lam)
    flux = rho_r * H * (1.0 + np.minimum(Phi, 0.0))
    ex = 0.5 * (eps[1:, :] + eps[:-1, :])  # faces i + 1/2
    ey = 0.5 * (eps[:, 1:] + eps[:, :-1])  # faces j + 1/2
    qx = ex * (P[1:, :] - P[:-1, :]) / dX**2
    qy = ey * (P[:, 1:] - P[:, :-1]) / (k * k * dY**2)
    out = np.zeros_like(Phi)
    out[1:-1, 1:-1] = (qx[1:, 1:-1] - qx[:-1, 1:-1]) + (qy[1:-1, 1:] - qy[1:-1, :-1])
    couette = np.zeros_like(Phi)
    couette[2:, :] = (1.5 * flux[2:, :] - 2.0 * flux[1:-1, :] + 0.5 * flux[:-2, :]) / dX
    couette[1, :] = (flux[1, :] - flux[0, :]) / dX
    out[1:-1, 1:-1] -= couette[1:-1, 1:-1]
    R[...] = out


def relaxation_sweep(P, F, H, rho_r, eta_r, g_rho, lam, k, dX, dY, Kc, xi_switch, omega_gs, omega_jac, xi_lines, delta):
    nx, ny = P.shape
    kx, ky = 1.0 / dX**2, 1.0 / (k * k * dY**2)
    eps = rho_r * np.maximum(H, 0.0) ** 3 / (eta_r * lam)
    R = np.zeros_like(P)

    def residual(i, j):
        reynolds_residual(P, H, rho_r, eta_r, lam, k, dX, dY, R)
        return R[i, j] - F[i, j]

    def poiseuille_diag(i, j):
        faces = [0.5 * (eps[i, j] + eps[i + a, j + b]) for a, b in ((1, 0), (-1, 0), (0, 1), (0, -1))]
        return -(kx * (faces[0] + faces[1]) + ky * (faces[2] + faces[3]))

    drho = rho_r * g_rho * H  # d(rho_r H) / dP through the density, H held

    def couette_diag(i, j, K, upstream=0.0):
        # upstream: the change of the upstream neighbour's pressure per unit change of the node's (-1/4 for the
        # distributed change when that neighbour is interior, else 0)
        if i >= 2:
            elastic = 1.5 * rho_r[i, j] * K(0) - 2.0 * rho_r[i - 1, j] * K(1) + 0.5 * rho_r[i - 2, j] * K(2)
            return (elastic + 1.5 * drho[i, j] - 2.0 * upstream * drho[i - 1, j]) / dX
        return (rho_r[i, j] * K(0) - rho_r[i - 1, j] * K(1) + drho[i, j]) / dX

    def point(m):
        return Kc[m, 0]

    def distributed(m):  # deflection at offset (-m, 0) of +1 at the node and -1/4 at its neighbours
        around = [(m - 1, 0), (m + 1, 0), (m, 1), (m, -1)]
        return Kc[m, 0] - 0.25 * sum(Kc[abs(a), abs(b)] for a, b in around)

    change = 0.0
    jacobi = []
    for i in range(1, nx - 1):
        for j in range(1, ny - 1):
            star = [P[i, j], P[i + 1, j], P[i - 1, j], P[i, j + 1], P[i, j - 1]]
            if eps[i, j] * max(kx, ky) < xi_switch and min(star) > 0.0:
                jacobi.append((i, j))
                continue
            if eps[i, j] * max(kx, ky) >= xi_lines and min(star) > 0.0:
                continue  # line_gauss_seidel's node
            new = max(P[i, j] - omega_gs * residual(i, j) / (poiseuille_diag(i, j) - couette_diag(i, j, point)), 0.0)
            change = max(change, abs(new - P[i, j]))
            P[i, j] = new
    reynolds_residual(P, H, rho_r, eta_r, lam, k, dX, dY, R)
    steps = {}
    for i, j in jacobi:
        steps[i, j] = (
            -omega_jac
            * (R[i, j] - F[i, j])
            / (1.25 * poiseuille_diag(i, j) - couette_diag(i, j, distributed, -0.25 if i > 1 else 0.0))
        )
    for (i, j), d in steps.items():
        P[i, j] += d
        for a, b in ((i - 1, j), (i + 1, j), (i, j - 1), (i, j + 1)):
            if 0 < a < nx - 1 and 0 < b < ny - 1:
                P[a, b] -= 0.25 * d
        change = max(change, abs(d))
    P[1:-1, 1:-1] = np.maximum(P[1:-1, 1:-1], 0.0)
    return change


def line_gauss_seidel(P, F, H, rho_r, eta_r, lam, k, dX, dY, Kc, g_rho, xi_lines, omega_gs, work):
    """Row by row: the line nodes (eps large, the five-point star pressurised) in runs of consecutive i, each
    run's Newton system written as a dense matrix (own derivative as relaxation_sweep's point step, the
    Poiseuille face coefficients to the neighbours along X) and solved by numpy."""
    nx, ny = P.shape
    kx, ky = 1.0 / dX**2, 1.0 / (k * k * dY**2)
    eps = rho_r * np.maximum(H, 0.0) ** 3 / (eta_r * lam)
    R = np.zeros_like(P)
    drho = rho_r * g_rho * H

    def own_derivative(i, j):
        faces = [0.5 * (eps[i, j] + eps[i + a, j + b]) for a, b in ((1, 0), (-1, 0), (0, 1), (0, -1))]
        poiseuille = -(kx * (faces[0] + faces[1]) + ky * (faces[2] + faces[3]))
        if i >= 2:
            elastic = 1.5 * rho_r[i, j] * Kc[0, 0] - 2.0 * rho_r[i - 1, j] * Kc[1, 0] + 0.5 * rho_r[i - 2, j] * Kc[2, 0]
            return poiseuille - (elastic + 1.5 * drho[i, j]) / dX
        return poiseuille - (rho_r[i, j] * Kc[0, 0] - rho_r[i - 1, j] * Kc[1, 0] + drho[i, j]) / dX

    change = 0.0
    for j in range(1, ny - 1):
        line = [
            i for i in range(1, nx - 1)
            if eps[i, j] * max(kx, ky) >= xi_lines and min(P[i - 1 : i + 2, j].min(), P[i, j - 1], P[i, j + 1]) > 0.0
        ]  # fmt: skip
        runs = [[i] for i in line[:1]]
        for i in line[1:]:
            if i == runs[-1][-1] + 1:
                runs[-1].append(i)
            else:
                runs.append([i])
        reynolds_residual(P, H, rho_r, eta_r, lam, k, dX, dY, R)
        for run in runs:
            A = np.zeros((len(run), len(run)))
            for n, i in enumerate(run):
                A[n, n] = own_derivative(i, j)
                if n > 0:
                    A[n, n - 1] = kx * 0.5 * (eps[i, j] + eps[i - 1, j])
                if n < len(run) - 1:
                    A[n, n + 1] = kx * 0.5 * (eps[i, j] + eps[i + 1, j])
            step = np.linalg.solve(A, np.array([F[i, j] - R[i, j] for i in run]))
            for n, i in enumerate(run):
                new = max(P[i, j] + omega_gs * step[n], 0.0)
                change = max(change, abs(new - P[i, j]))
                P[i, j] = new
    return change


def density_log_slopes(P, p_h, fluid, g_rho):
    """d ln(rho_r) / dP: the twin's Richardson-extrapolated central differences of its density law
    (fluid_log_slopes), not the kernel's closed form."""
    g_eta = np.empty_like(P)
    fluid_log_slopes(P, p_h, fluid, g_rho, g_eta)


def fluid_log_slopes(P, p_h, fluid, g_rho, g_eta):
    """d ln(ratio) / dP by Richardson-extrapolated central differences (steps 1e-3 and 5e-4 of P + 1), second-
    order one-sided differences at P = 0; 0 where the viscosity is at its cap."""

    def slope(f, p):
        def d(h):
            if p - 2.0 * h < 0.0:
                return (-3.0 * f(p) + 4.0 * f(p + h) - f(p + 2.0 * h)) / (2.0 * h)
            return (f(p + h) - f(p - h)) / (2.0 * h)

        h = 1e-3 * (p + 1.0)
        return (4.0 * d(0.5 * h) - d(h)) / 3.0

    for i, j in np.ndindex(P.shape):
        p = max(P[i, j], 0.0)
        g_rho[i, j] = slope(lambda q: math.log(density_ratio(q * p_h, fluid)), p)
        if viscosity_ratio((p + 1e-6 * (p + 1.0)) * p_h, fluid) >= ETA_RATIO_MAX:
            g_eta[i, j] = 0.0
        else:
            g_eta[i, j] = slope(lambda q: math.log(viscosity_ratio(q * p_h, fluid)), p)


def newton_jacobian(P, H, rho_r, eta_r, g_rho, g_eta, lam, k, dX, dY, Kc, wet_i, wet_j, widx, J):
    """Central differences of the twin's residual: a pressure change d at wet node m changes P there, the film
    at every node by Kc[|di|, |dj|] d and rho_r, eta_r at m by their log slopes; H0 shifts the film."""
    nw = len(wet_i)
    R = np.zeros_like(P)

    def rows(dP, dH, m):
        Pm, Hm, rho, eta = P.copy(), H + dH, rho_r.copy(), eta_r.copy()
        if m is not None:
            a, b = wet_i[m], wet_j[m]
            Pm[a, b] += dP
            rho[a, b] *= math.exp(g_rho[a, b] * dP)
            eta[a, b] *= math.exp(g_eta[a, b] * dP)
        reynolds_residual(Pm, Hm, rho, eta, lam, k, dX, dY, R)
        return R[wet_i, wet_j].copy()

    ii = np.arange(P.shape[0])[:, None]
    jj = np.arange(P.shape[1])[None, :]
    for m in range(nw):
        shape = Kc[np.abs(ii - wet_i[m]), np.abs(jj - wet_j[m])]
        d = 1e-6 * max(P[wet_i[m], wet_j[m]], 1e-3)
        J[:nw, m] = (rows(d, d * shape, m) - rows(-d, -d * shape, m)) / (2.0 * d)
    d = 1e-6
    J[:nw, nw] = (rows(0.0, d, None) - rows(0.0, -d, None)) / (2.0 * d)


TWINS = {
    "fluid_log_slopes": fluid_log_slopes,
    "density_log_slopes": density_log_slopes,
    "newton_jacobian": newton_jacobian,
    "relaxation_sweep": relaxation_sweep,
    "line_gauss_seidel": line_gauss_seidel,
    "viscosity_ratio": viscosity_ratio,
    "density_ratio": density_ratio,
    "fluid_fields": fluid_fields,
    "rectangle_influence": rectangle_influence,
    "film": film,
    "reynolds_residual": reynolds_residual,
}
