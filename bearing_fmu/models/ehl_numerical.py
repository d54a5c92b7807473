"""The discrete point-contact EHL problem of one contact on one grid (kernels/ehl_solver.py).

`ContactGrid(...)` takes the contact in SI (reduced radii Rx, Ry in m, load in N, entrainment speed in m/s,
reduced modulus E' in Pa, viscosity at p = 0 in Pa.s and the fluid array of kernels.ehl_solver), sizes the
Hertz contact, lays the node grid in Hertz units and evaluates the discrete equations for a given state:
`residual(Phi, H0)` (the Reynolds residual at every node and the relative load error) and
`deflection(P)` (the dimensionless elastic deflection W of a pressure field by FFT convolution of the
rectangle influences, zero-padded to twice the grid so the convolution is linear, not periodic).
Scalings as in kernels/ehl_solver.py: h = (b^2 / Rx) H, p = p_h P.

The nonlinear solve (`solve_contact`, `solve_grids`, docs/ehl_solver.md): pressure unknown P >= 0
(cavitation by complementarity), relaxation sweeps (kernels.ehl_solver.relaxation_sweep: Gauss-Seidel
where the Poiseuille coefficient is large, Jacobi distributive where it is small), the deflection by FFT
before every sweep, FAS V-cycles over nested grids with the rigid film H0 set by the load balance on the
coarsest grid, and nested iteration from a Hertz start.
"""

import math
from dataclasses import dataclass

import numpy as np

from bearing_fmu.kernels import ehl
from bearing_fmu.kernels import ehl_solver as es
from bearing_fmu.kernels.hertz import hertz_coefficients_exact, hertz_contact

LOAD = 2.0 * math.pi / 3.0  # integral of P over the Hertz-scaled plane (dX dY sum P)


@dataclass
class Domain:
    """Computational box in Hertz units (X = x / b from x_in to x_out, |Y| = |y| / a <= y_half), node counts."""

    x_in: float = -4.0
    x_out: float = 1.5
    y_half: float = 2.5
    nx: int = 129
    ny: int = 97


class ContactGrid:
    """One contact on one grid: Hertz scales, nodes, deflection operator and discrete residual."""

    def __init__(self, Rx, Ry, load, u_e, E_red, eta0, fluid, domain=None):
        d = domain or Domain()
        k, ell_E, ell_K = hertz_coefficients_exact(Rx, Ry)
        a, b, delta, p_h = hertz_contact(load, Rx, Ry, E_red, k, ell_E, ell_K)
        self.k, self.a, self.b, self.p_h, self.delta = k, a, b, p_h, delta
        self.lam = 12.0 * eta0 * u_e * Rx * Rx / (p_h * b**3)  # speed group (-)
        self.curv_y = k * k * Rx / Ry  # (-) curvature of the gap along Y in Hertz units
        self.scale_h = b * b / Rx  # m per unit H
        self.fluid = fluid
        self.X = np.linspace(d.x_in, d.x_out, d.nx)
        self.Y = np.linspace(-d.y_half, d.y_half, d.ny)
        self.dX = self.X[1] - self.X[0]
        self.dY = self.Y[1] - self.Y[0]
        self.nx, self.ny = d.nx, d.ny
        self.kern = es.rectangle_influence(d.nx, d.ny, self.dX * b, self.dY * a)  # m
        self.c_w = 2.0 * p_h / (math.pi * E_red) / self.scale_h  # W = c_w sum kern P
        self.kern_hat = np.fft.rfft2(_wrapped(self.kern))

    def deflection(self, P):
        """Dimensionless deflection W (-) at every node of the dimensionless pressure field P (-)."""
        nx, ny = self.nx, self.ny
        shape = (2 * nx, 2 * ny)
        full = np.fft.irfft2(np.fft.rfft2(P, s=shape) * self.kern_hat, s=shape)
        return self.c_w * full[:nx, :ny]

    def residual(self, Phi, H0):
        """(R, load_error, H, rho_r, eta_r): Reynolds residual (-) at every node, (dX dY sum P - 2 pi/3) / (2 pi/3),
        film and fluid ratios of the state Phi (-, P = max(Phi, 0)), H0 (-)."""
        rho_r = np.empty_like(Phi)
        eta_r = np.empty_like(Phi)
        es.fluid_fields(Phi, self.p_h, self.fluid, rho_r, eta_r)
        P = np.maximum(Phi, 0.0)
        H = np.empty_like(Phi)
        es.film(H0, self.X, self.Y, self.curv_y, self.deflection(P), H)
        R = np.empty_like(Phi)
        es.reynolds_residual(Phi, H, rho_r, eta_r, self.lam, self.k, self.dX, self.dY, R)
        load_error = (self.dX * self.dY * P.sum() - LOAD) / LOAD
        return R, load_error, H, rho_r, eta_r

    def hertz_pressure(self):
        """Hertz pressure P = sqrt(1 - X^2 - Y^2) (-) on the nodes."""
        Xg, Yg = np.meshgrid(self.X, self.Y, indexing="ij")
        return np.sqrt(np.maximum(1.0 - Xg * Xg - Yg * Yg, 0.0))


def _wrapped(kern):
    """Influence array laid out for a linear convolution by FFT of size (2 nx, 2 ny): offset m at index m for
    m >= 0 and at 2 nx + m for m < 0 (same along y); the unused middle row and column stay zero."""
    nx, ny = kern.shape
    out = np.zeros((2 * nx, 2 * ny))
    out[:nx, :ny] = kern
    out[nx + 1 :, :ny] = kern[:0:-1, :]
    out[:nx, ny + 1 :] = kern[:, :0:-1]
    out[nx + 1 :, ny + 1 :] = kern[:0:-1, :0:-1]
    return out


def fluid_array(viscosity, density, eta0=0.0, alpha=0.0, T=0.0, wlf=None, murnaghan=None):
    """The fluid array of kernels.ehl_solver: viscosity code (VISC_*), density code (DENS_*), eta0 (Pa.s),
    alpha (1/Pa), T (K), wlf = (mu_G Pa.s, T_g0 K, A1 K, A2 1/Pa, b1 1/Pa, b2, C1, C2 K),
    murnaghan = (T_R K, a_v 1/K, beta_K 1/K, K_MM Pa, K')."""
    f = np.zeros(es.FLUID_SIZE)
    f[es.FLUID_VISC] = viscosity
    f[es.FLUID_DENS] = density
    f[es.FLUID_ETA0] = eta0
    f[es.FLUID_ALPHA] = alpha
    f[es.FLUID_T] = T
    if wlf is not None:
        f[es.FLUID_WLF : es.FLUID_WLF + 8] = wlf
    if murnaghan is not None:
        f[es.FLUID_MURN : es.FLUID_MURN + 5] = murnaghan
    return f


# ---------------------------------------------------------------------------------------------------------
# Nonlinear solver: full approximation scheme (FAS) multigrid with relaxation sweeps, nested iteration


@dataclass
class SolverSettings:
    """Relaxation and multigrid parameters (docs/ehl_solver.md, Solver)."""

    xi_switch: float = 0.3  # eps / dX^2 below which a node is relaxed by Jacobi distributive relaxation
    omega_gs: float = 0.6  # Gauss-Seidel under-relaxation
    omega_jac: float = 0.2  # Jacobi distributive under-relaxation
    pre: int = 2  # sweeps before the coarse-grid correction
    post: int = 2  # sweeps after it
    newton_coarse: int = 3  # Newton steps on the coarsest grid per visit of a cycle
    newton_max: int = 40  # Newton steps of the first solve on the coarsest grid (nested iteration start)
    tol: float = 1e-4  # converged: relative change of h_c and h_min over one cycle below tol
    tol_residual: float = 1e-3  # and the rms Reynolds residual / rms Couette term (Solution.residual) below this
    max_cycles: int = 60  # on the finest grid
    tol_nested: float = 1e-2  # a coarser grid of the nested iteration is left when h_c, h_min change less than this
    max_nested: int = 6  # or after this many cycles (its solution only starts the finer grid)


@dataclass
class Solution:
    """Result of one solve on its finest grid; lengths in m, pressure in Pa; fields dimensionless."""

    h_c: float  # film at the contact centre (X = Y = 0)
    h_min: float  # global minimum of the film
    hm_centre: float  # minimum on the centre line Y = 0
    hm_lateral: float  # minimum on the sides, |Y| >= 0.5 (the side lobes of the horseshoe)
    p_max: float
    converged: bool
    cycles: int  # V-cycles on the finest grid
    change: float  # last cycle's relative change of h_c or h_min, the larger
    load_error: float
    residual: float  # rms Reynolds residual over pressurised nodes / rms Couette term there
    grid: "ContactGrid" = None
    P: np.ndarray = None
    H: np.ndarray = None
    H0: float = 0.0
    history: list = None


class _Level:
    """One grid of the hierarchy with its work arrays."""

    def __init__(self, grid, settings):
        self.g = grid
        self.s = settings
        self.Kc = grid.c_w * grid.kern
        shape = (grid.nx, grid.ny)
        self.H = np.empty(shape)
        self.rho = np.empty(shape)
        self.eta = np.empty(shape)
        self.delta = np.empty(shape)
        self.R = np.empty(shape)

    def fields(self, P, H0):
        """Film (closed gaps carry no Poiseuille flow, kernels.ehl_solver._eps) and fluid ratios of the pressure P."""
        g = self.g
        es.film(H0, g.X, g.Y, g.curv_y, g.deflection(P), self.H)
        es.fluid_fields(P, g.p_h, g.fluid, self.rho, self.eta)

    def operator(self, P, H0):
        g = self.g
        self.fields(P, H0)
        es.reynolds_residual(P, self.H, self.rho, self.eta, g.lam, g.k, g.dX, g.dY, self.R)
        return self.R.copy()

    def sweep(self, P, F, H0):
        g, s = self.g, self.s
        self.fields(P, H0)
        return es.relaxation_sweep(
            P, F, self.H, self.rho, self.eta, g.lam, g.k, g.dX, g.dY, self.Kc, s.xi_switch, s.omega_gs,
            s.omega_jac, self.delta,
        )  # fmt: skip

    def load(self, P):
        return self.g.dX * self.g.dY * P.sum()


def restrict_full_weighting(r):
    """Full-weighting restriction (-) of a node field to the grid of every other node; boundary 0."""
    c = np.zeros(((r.shape[0] + 1) // 2, (r.shape[1] + 1) // 2))
    c[1:-1, 1:-1] = (
        4.0 * r[2:-2:2, 2:-2:2]
        + 2.0 * (r[1:-3:2, 2:-2:2] + r[3:-1:2, 2:-2:2] + r[2:-2:2, 1:-3:2] + r[2:-2:2, 3:-1:2])
        + r[1:-3:2, 1:-3:2] + r[3:-1:2, 1:-3:2] + r[1:-3:2, 3:-1:2] + r[3:-1:2, 3:-1:2]
    ) / 16.0  # fmt: skip
    return c


def prolong_bilinear(c):
    """Bilinear interpolation (-) of a node field onto the grid with a node between every two."""
    f = np.zeros((2 * c.shape[0] - 1, 2 * c.shape[1] - 1))
    f[::2, ::2] = c
    f[1::2, ::2] = 0.5 * (c[1:] + c[:-1])
    f[:, 1::2] = 0.5 * (f[:, :-1:2] + f[:, 2::2])
    return f


def _ncp_scale(L):
    """Per-node scale (-) of the complementarity min(P, -R / d): the magnitude of the derivative of a node's
    residual in its own pressure (Poiseuille diagonal plus the upwind Couette term through the deflection)."""
    g = L.g
    e = L.rho * np.maximum(L.H, 0.0) ** 3 / (L.eta * g.lam)
    kx = 1.0 / g.dX**2
    ky = 1.0 / (g.k**2 * g.dY**2)
    d = np.ones_like(e)
    d[1:-1, 1:-1] = (
        0.5 * kx * (e[2:, 1:-1] + e[:-2, 1:-1] + 2.0 * e[1:-1, 1:-1])
        + 0.5 * ky * (e[1:-1, 2:] + e[1:-1, :-2] + 2.0 * e[1:-1, 1:-1])
        + 1.5 * L.rho[1:-1, 1:-1] * L.Kc[0, 0] / g.dX
    )
    return d


def _merit(L, P, F, target, H0):
    """(merit, R - F, d): rms over the interior of the complementarity function min(P, -(R - F) / d) and the
    relative load error, the residual and its scale."""
    R = L.operator(P, H0) - F
    d = _ncp_scale(L)
    ncp = np.minimum(P, -R / d)[1:-1, 1:-1]
    load_error = (L.load(P) - target) / LOAD
    return math.sqrt(np.mean(ncp**2) + load_error**2), R, d


def newton(L, P, F, target, H0, iters, tol=1e-10):
    """Semismooth (active-set) Newton on one grid for the discrete Reynolds equation R(P, H0) = F with
    cavitation by complementarity (P >= 0, R - F <= 0, P (R - F) = 0, through min(P, -(R - F) / d) = 0) and
    the load balance dX dY sum P = target, with H0 an unknown; P changed in place, returns (H0, merit).

    Each step: nodes with P >= -(R - F) / d are wet (Reynolds row), the others set to P = 0; the Jacobian of
    the wet rows in the wet pressures and H0 is dense through the deflection (kernels.ehl_solver.
    newton_jacobian) and solved by LU; the step is halved until the merit (rms of the complementarity
    function and the load error) decreases. The elastic coupling makes the step converge at any load
    (M ~ 4000 in the tests) where point relaxation stalls; its O(n^3) cost keeps it on the coarsest grid."""
    g = L.g
    g_rho = np.empty_like(P)
    g_eta = np.empty_like(P)
    inner = np.zeros(P.shape, bool)
    inner[1:-1, 1:-1] = True
    m, R, d = _merit(L, P, F, target, H0)
    for _ in range(iters):
        if m < tol:
            break
        wet = inner & (P >= -R / d)
        if np.any(P[inner & ~wet] > 0.0):
            P[inner & ~wet] = 0.0
            m, R, d = _merit(L, P, F, target, H0)
        wi, wj = np.nonzero(wet)
        nw = len(wi)
        widx = np.full(P.shape, -1, np.int64)
        widx[wi, wj] = np.arange(nw)
        es.fluid_log_slopes(P, g.p_h, g.fluid, g_rho, g_eta)
        J = np.zeros((nw + 1, nw + 1))
        es.newton_jacobian(P, L.H, L.rho, L.eta, g_rho, g_eta, g.lam, g.k, g.dX, g.dY, L.Kc, wi, wj, widx, J)
        J[nw, :nw] = g.dX * g.dY / LOAD
        rhs = np.empty(nw + 1)
        rhs[:nw] = -R[wi, wj]
        rhs[nw] = -(L.load(P) - target) / LOAD
        step = np.linalg.solve(J, rhs)
        P_start = P.copy()
        H0_start = H0
        alpha = 1.0
        for _ in range(8):
            P[...] = P_start
            P[wi, wj] += alpha * step[:nw]
            np.maximum(P, 0.0, out=P)
            H0 = H0_start + alpha * step[nw]
            m_new, R, d = _merit(L, P, F, target, H0)
            if m_new < (1.0 - 1e-4 * alpha) * m:
                break
            alpha *= 0.5
        m = m_new
    return H0, m


def _cycle(levels, l, P, F, target, H0):
    """One FAS V-cycle on level l for Reynolds = F with the load dX dY sum P = target; returns H0, which is an
    unknown of the Newton solve on the coarsest grid (the load balance is solved there, with the FAS load
    target of the finer grids)."""
    L = levels[l]
    s = L.s
    if l == 0:
        H0, _ = newton(L, P, F, target, H0, s.newton_coarse)
        return H0
    for _ in range(s.pre):
        L.sweep(P, F, H0)
    r = F - L.operator(P, H0)
    r[P <= 0.0] = 0.0  # cavitated nodes: the complementarity holds, no defect to correct
    C = levels[l - 1]
    Pc = P[::2, ::2].copy()
    Pc_old = Pc.copy()
    Fc = C.operator(Pc, H0) + restrict_full_weighting(r)
    Fc[0, :] = Fc[-1, :] = Fc[:, 0] = Fc[:, -1] = 0.0
    target_c = target + C.load(Pc) - L.load(P)
    H0 = _cycle(levels, l - 1, Pc, Fc, target_c, H0)
    P += prolong_bilinear(Pc - Pc_old)
    np.maximum(P, 0.0, out=P)
    for _ in range(s.post):
        L.sweep(P, F, H0)
    return H0


def _films(L, P, H0):
    """(h_c, h_min) in units of H of the state: the film at X = Y = 0 and the interior minimum."""
    g = L.g
    H = np.empty_like(P)
    es.film(H0, g.X, g.Y, g.curv_y, g.deflection(P), H)
    ic = int(np.argmin(np.abs(g.X)))
    jc = int(np.argmin(np.abs(g.Y)))
    return H[ic, jc], H[1:-1, 1:-1].min()


def solve_grids(grids, settings=None, h_c_guess=None):
    """Solve the contact on the nested grids `grids` (coarsest first, each node count 2 n - 1 of the next
    coarser, same box): Hertz start on the coarsest, solved there by Newton (`newton`, the load balance
    included); on each finer grid the interpolated solution (nested iteration) improved by FAS V-cycles
    down to the coarsest grid: on the intermediate grids until h_c and h_min change by less than tol_nested
    over a cycle (at most max_nested cycles), on the finest until they change by less than tol, the load
    error is below tol and the rms residual below tol_residual, or max_cycles. Returns a Solution."""
    s = settings or SolverSettings()
    levels = [_Level(g, s) for g in grids]
    g0 = grids[0]
    ic = int(np.argmin(np.abs(g0.X)))
    jc = int(np.argmin(np.abs(g0.Y)))
    P = g0.hertz_pressure()
    P *= LOAD / (g0.dX * g0.dY * P.sum())
    h_c = h_c_guess if h_c_guess is not None else 0.1 * g0.delta
    H0 = h_c / g0.scale_h - g0.deflection(P)[ic, jc] - 0.5 * g0.X[ic] ** 2 - 0.5 * g0.curv_y * g0.Y[jc] ** 2
    H0, merit = newton(levels[0], P, np.zeros_like(P), LOAD, H0, s.newton_max)
    history = [(0, 0, merit, (levels[0].load(P) - LOAD) / LOAD)]
    converged = merit < 1e-8
    cycle, change, load_error = 0, merit, history[0][3]
    for l in range(1, len(levels)):
        P = prolong_bilinear(P)
        F = np.zeros_like(P)
        L = levels[l]
        films = _films(L, P, H0)
        converged = False
        last = l == len(levels) - 1
        for cycle in range(1, (s.max_cycles if last else s.max_nested) + 1):
            H0 = _cycle(levels, l, P, F, LOAD, H0)
            new = _films(L, P, H0)
            change = max(abs(new[0] - films[0]) / abs(new[0]), abs(new[1] - films[1]) / abs(new[1]))
            films = new
            load_error = (L.load(P) - LOAD) / LOAD
            history.append((l, cycle, change, load_error))
            if not np.all(np.isfinite(P)):
                break
            if not last and change < s.tol_nested:
                break
            if change < s.tol and abs(load_error) < s.tol and _residual(L, P, H0) < s.tol_residual:
                converged = True
                break
    return _solution(levels[-1], P, H0, converged, cycle, change, load_error, history)


def _residual(L, P, H0):
    """rms Reynolds residual over the pressurised nodes / rms Couette term there (-)."""
    g = L.g
    R = L.operator(P, H0)
    flux = L.rho * L.H
    couette = np.zeros_like(P)
    couette[1:] = (flux[1:] - flux[:-1]) / g.dX
    wet = P > 0.0
    return math.sqrt(np.mean(R[wet] ** 2) / max(np.mean(couette[wet] ** 2), 1e-300))


def _solution(L, P, H0, converged, cycles, change, load_error, history):
    g = L.g
    residual = _residual(L, P, H0)
    H = L.H.copy()
    ic = int(np.argmin(np.abs(g.X)))
    jc = int(np.argmin(np.abs(g.Y)))
    inner = H[1:-1, 1:-1]
    off = np.abs(g.Y) >= 0.5
    off[0] = off[-1] = False
    scale = g.scale_h
    return Solution(
        h_c=H[ic, jc] * scale,
        h_min=inner.min() * scale,
        hm_centre=H[1:-1, jc].min() * scale,
        hm_lateral=H[1:-1][:, off].min() * scale,
        p_max=P.max() * g.p_h,
        converged=converged,
        cycles=cycles,
        change=change,
        load_error=load_error,
        residual=residual,
        grid=g,
        P=P,
        H=H,
        H0=H0,
        history=history,
    )


def alpha_star(fluid, p_h):
    """Reciprocal asymptotic isoviscous pressure-viscosity coefficient (1/Pa) of the fluid's law,
    [int_0^inf eta(0) / eta(p) dp]^-1 (trapezoids up to 10 p_h), for the film estimate that starts a solve."""
    p = np.linspace(0.0, 10.0 * p_h, 4001)
    inv = np.array([1.0 / es.viscosity_ratio(q, fluid) for q in p])
    return 1.0 / np.trapezoid(inv, p)


def grid_hierarchy(Rx, Ry, load, u_e, E_red, eta0, fluid, finest=2, coarsest=0, box=(-3.5, 1.5, 2.0)):
    """Nested grids of the box X in [box[0], box[1]], |Y| <= box[2] (Hertz units): level l has
    (40 2^l + 1) x (32 2^l + 1) nodes (level 2: 161 x 129, dX = 0.031, dY = 0.031), so X = 0 and Y = 0
    are nodes of every level."""
    return [
        ContactGrid(Rx, Ry, load, u_e, E_red, eta0, fluid, Domain(box[0], box[1], box[2], 40 * 2**l + 1, 32 * 2**l + 1))
        for l in range(coarsest, finest + 1)
    ]


def solve_contact(Rx, Ry, load, u_e, E_red, eta0, fluid, finest=2, coarsest=0, settings=None):
    """Steady isothermal EHL film of one contact in SI: reduced radii Rx (along the entrainment), Ry (m),
    load (N), entrainment speed u_e = (u1 + u2) / 2 (m/s), reduced modulus E' (Pa), viscosity at p = 0
    eta0 (Pa.s), fluid array (fluid_array). Returns a Solution (h_c, h_min, hm_centre, hm_lateral in m,
    p_max in Pa, convergence record, fields) on the grid of level `finest` (grid_hierarchy)."""
    grids = grid_hierarchy(Rx, Ry, load, u_e, E_red, eta0, fluid, finest, coarsest)
    g = grids[0]
    U, G, Wd = ehl.dimensionless_groups(eta0, alpha_star(fluid, g.p_h), E_red, u_e, load, Rx)
    h_c_guess = ehl.film_hamrock_dowson(U, G, Wd, g.k)[0] * Rx
    return solve_grids(grids, settings, h_c_guess)
