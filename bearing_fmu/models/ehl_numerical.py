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
from dataclasses import dataclass, replace

import numpy as np
import scipy.fft

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
        # a linear convolution needs at least 2 n - 1 points per axis; 2 n itself can have a large prime factor
        # (level 3: 642 = 2 3 107, 514 = 2 257), which makes the FFT ~6x slower than at the next 5-smooth length
        self.fft_shape = tuple(scipy.fft.next_fast_len(2 * n - 1, real=True) for n in (d.nx, d.ny))
        self.kern_hat = scipy.fft.rfft2(_wrapped(self.kern, self.fft_shape), workers=1)

    def deflection(self, P):
        """Dimensionless deflection W (-) at every node of the dimensionless pressure field P (-)."""
        shape = self.fft_shape
        spectrum = scipy.fft.rfft2(P, s=shape, workers=1) * self.kern_hat
        full = scipy.fft.irfft2(spectrum, s=shape, workers=1)
        return self.c_w * full[: self.nx, : self.ny]

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


def _wrapped(kern, shape):
    """Influence array laid out for a linear convolution by FFT of size shape = (Nx, Ny), Nx >= 2 nx - 1,
    Ny >= 2 ny - 1: offset m at index m for m >= 0 and at Nx + m for m < 0 (same along y); the unused
    middle rows and columns stay zero."""
    nx, ny = kern.shape
    Nx, Ny = shape
    out = np.zeros(shape)
    out[:nx, :ny] = kern
    out[Nx - nx + 1 :, :ny] = kern[:0:-1, :]
    out[:nx, Ny - ny + 1 :] = kern[:, :0:-1]
    out[Nx - nx + 1 :, Ny - ny + 1 :] = kern[:0:-1, :0:-1]
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

    xi_switch: float = 1.0  # eps / dX^2 below which a node is relaxed by Jacobi distributive relaxation
    omega_gs: float = 0.6  # Gauss-Seidel under-relaxation
    omega_jac: float = 0.2  # Jacobi distributive under-relaxation
    pre: int = 2  # sweeps before the coarse-grid correction
    post: int = 2  # sweeps after it
    newton_coarse: int = 1  # Newton steps on the coarsest grid per visit of a cycle
    newton_max: int = 40  # Newton steps of the first solve on the coarsest grid (nested iteration start)
    # converged: h_c and h_min each spread by less than tol (relative) over the last `window` cycles, a tenth of
    # the 2 % discretisation error the default grid is chosen for, and the load error below tol_load
    tol: float = 1e-3
    window: int = 4
    tol_load: float = 1e-4
    # on the finest grid: the heavy slender cases 22, 52, 53, 55 of Annexe D need 63-68, the thin films at p_H 1.3-3.2
    # GPa whose coarse grids close the gap 89 (level 2) and 100 (level 3) (docs/ehl_solver.md, Thin films)
    max_cycles: int = 120
    max_damping_cuts: int = 2  # halvings of omega_jac after a diverging cycle on the finest grid (_finest_cycles)
    tol_nested: float = 1e-2  # a coarser grid of the nested iteration is left when h_c, h_min change less than this
    max_nested: int = 6  # or after this many cycles (its solution only starts the finer grid)
    # fraction of the coarse grid's change of H0 a cycle applies on the finer grids; 0.5 settles the films of a
    # nearly rigid contact (M = 10, L = 30, k = 9, level 3: h_c spread 7.5e-3 with 1, 2.9e-4 with 0.5, where
    # the film and the load error alternated from cycle to cycle), but its load error still alternates by 4e-4
    h0_relax: float = 1.0
    # the relaxation's local derivative includes the density's part of the Couette term (relaxation_sweep);
    # solve_contact turns it on with the lines (LINES_MIN_L): for the thick films whose box grows (contact_box,
    # H_c > 0.35) it is several times the elastic part on levels 3-4 and the relaxation diverged without it. Off,
    # the solver is the one the Annexe D validation was made with (on, their h_min moved by up to 0.96 %, cases 18
    # and 21, within the convergence criterion's reach on those slow heavy slender cases)
    density_jac: bool = False
    # eps max(1/dX^2, 1/(k dY)^2) from which a Gauss-Seidel node with a pressurised star is relaxed on its line
    # along X (kernels.ehl_solver.line_gauss_seidel) instead of point by point; inf: no lines
    xi_lines: float = math.inf
    # the coarse grid's pressure in the FAS cycle: injection (False), or full weighting at the coarse nodes whose
    # nine fine nodes are all wet and injection next to a cavitated one (True, restrict_pressure)
    full_weighting: bool = False


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
    change: float  # relative spread of h_c or h_min over the last `window` cycles (SolverSettings), the larger
    load_error: float
    residual: float  # rms complementarity residual over pressurised nodes / rms Couette term there (_residual)
    grid: "ContactGrid" = None
    P: np.ndarray = None
    H: np.ndarray = None
    H0: float = 0.0
    history: list = None
    reason: str = ""  # why the solve is not converged ("" when it is): _solution, _finest_cycles


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
        self.work = np.empty((4, grid.nx))
        self.g_rho = np.zeros(shape)  # d ln(rho_r) / dP for the relaxation (stays 0 unless settings.density_jac)

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
        if s.density_jac:
            es.density_log_slopes(P, g.p_h, g.fluid, self.g_rho)
        fields = (self.H, self.rho, self.eta)
        change = 0.0
        if s.xi_lines < math.inf:  # lines first; relaxation_sweep then relaxes the nodes they leave
            change = es.line_gauss_seidel(
                P, F, *fields, g.lam, g.k, g.dX, g.dY, self.Kc, self.g_rho, s.xi_lines, s.omega_gs, self.work
            )
        sweep = es.relaxation_sweep(
            P, F, *fields, self.g_rho, g.lam, g.k, g.dX, g.dY, self.Kc, s.xi_switch, s.omega_gs, s.omega_jac,
            s.xi_lines, self.delta,
        )  # fmt: skip
        return max(change, sweep)

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


def restrict_pressure(P, full_weighting):
    """The coarse grid's pressure (-) of the FAS cycle: injection of the fine pressure P, or with full_weighting its
    full-weighting average at the coarse nodes whose nine fine nodes are all wet (injection next to a cavitated
    node keeps the free boundary where the fine grid has it; Venner and Lubrecht, Multilevel Methods in
    Lubrication, 2000). The coarse grid evaluates its film, eps and the FAS right-hand side from this pressure:
    injected, a fine-grid pressure spike or lateral edge a few nodes wide reaches the coarse grid as a sample the
    coarse grid cannot represent, and the correction it returns put spikes and bursts of h_min into the fine
    grids of wide contacts (docs/ehl_solver.md, Fine grids)."""
    Pc = P[::2, ::2].copy()
    if full_weighting:
        wet = P > 0.0
        stars = np.ones((P.shape[0] - 2, P.shape[1] - 2), bool)  # fine node and its eight neighbours wet
        for di in range(3):
            for dj in range(3):
                stars &= wet[di : di + P.shape[0] - 2, dj : dj + P.shape[1] - 2]
        interior = stars[1::2, 1::2]  # the fine nodes 2, 4, .. of the coarse interior nodes
        Pc[1:-1, 1:-1][interior] = restrict_full_weighting(P)[1:-1, 1:-1][interior]
    return Pc


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
        try:
            step = np.linalg.solve(J, rhs)
        except np.linalg.LinAlgError:
            # a singular Jacobian (rows of closed or nearly closed gaps): the least-squares step keeps the
            # Newton going instead of raising out of the solve; the merit test below still decides the step
            step = np.linalg.lstsq(J, rhs, rcond=None)[0]
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
    Pc = restrict_pressure(P, s.full_weighting)
    Pc_old = Pc.copy()
    Fc = C.operator(Pc, H0) + restrict_full_weighting(r)
    Fc[0, :] = Fc[-1, :] = Fc[:, 0] = Fc[:, -1] = 0.0
    target_c = target + C.load(Pc) - L.load(P)
    H0_coarse = _cycle(levels, l - 1, Pc, Fc, target_c, H0)
    H0 = H0_coarse if s.h0_relax == 1.0 else H0 + s.h0_relax * (H0_coarse - H0)
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
    over a cycle (at most max_nested cycles), on the finest until their spread over the last `window` cycles
    is below tol and the load error below tol_load, or max_cycles. Returns a Solution.

    The criterion is on the films, not on the residual: the rms residual can sit in a limit cycle (case 6 of
    Annexe D on level 3: 8.5e-4 and 2.7e-2 on alternate cycles, nodes at the cavitation boundary switching)
    with h_c and h_min steady to 1e-4, and a slow mode of the side lobes moves h_min by a few tenths of a
    percent per cycle at residuals ~1e-3 (case 28, level 2), which a spread over several cycles sees."""
    s = settings or SolverSettings()
    levels = [_Level(g, s) for g in grids]
    P, H0, merit = _coarsest_start(levels[0], h_c_guess)
    history = [(0, 0, merit, (levels[0].load(P) - LOAD) / LOAD)]
    if len(levels) == 1:
        return _solution(levels[0], P, H0, merit < 1e-8, 0, merit, history[0][3], history, "Newton not converged")
    for l in range(1, len(levels) - 1):
        P = prolong_bilinear(P)
        H0 = _nested_cycles(levels, l, P, H0, history)
    return _finest_cycles(levels, prolong_bilinear(P), H0, history, h_c_guess or 0.1 * levels[0].g.delta)


def _coarsest_start(L, h_c_guess):
    """(P, H0, merit): the Hertz pressure with H0 from the central film guess, solved by Newton on level 0."""
    g = L.g
    ic = int(np.argmin(np.abs(g.X)))
    jc = int(np.argmin(np.abs(g.Y)))
    P = g.hertz_pressure()
    P *= LOAD / (g.dX * g.dY * P.sum())
    h_c = h_c_guess if h_c_guess is not None else 0.1 * g.delta
    H0 = h_c / g.scale_h - g.deflection(P)[ic, jc] - 0.5 * g.X[ic] ** 2 - 0.5 * g.curv_y * g.Y[jc] ** 2
    H0, merit = newton(L, P, np.zeros_like(P), LOAD, H0, L.s.newton_max)
    return P, H0, merit


def _nested_cycles(levels, l, P, H0, history):
    """Cycles on an intermediate grid of the nested iteration (P in place) until h_c and h_min change less
    than tol_nested over a cycle or max_nested cycles; returns H0."""
    L = levels[l]
    s = L.s
    F = np.zeros_like(P)
    films = [_films(L, P, H0)]
    for cycle in range(1, s.max_nested + 1):
        H0 = _cycle(levels, l, P, F, LOAD, H0)
        films.append(_films(L, P, H0))
        history.append((l, cycle, _spread(films[-2:]), (L.load(P) - LOAD) / LOAD))
        if history[-1][2] < s.tol_nested:
            break
    return H0


def _finest_cycles(levels, P, H0, history, h_c_guess):
    """Cycles on the finest grid until converged (solve_grids) or max_cycles; returns the Solution.

    A cycle that diverges (h_c jumps by more than 5 % and 10 times its smallest change so far, turns non-finite or
    exceeds 100 times the estimate h_c_guess, m) is undone: the state of the calmest cycle so far is restored and
    the Jacobi distributive damping halved, at most max_damping_cuts times; then the calmest state is returned,
    not converged. h_c decides, not h_min: a slender contact's h_min of a few nm moves by 5 % in a normal cycle.
    The default 0.2 is the faster one where it is stable (case 17 of Annexe D: 25 cycles, 58 at 0.1); the wide
    fast cases 34 and 35 (k = 5, 4 at 10 m/s) diverge with it on level 3 after ~8 cycles and converge at 0.1."""
    l = len(levels) - 1
    L = levels[l]
    s = L.s
    F = np.zeros_like(P)
    films = [_films(L, P, H0)]
    blown_h_c = 100.0 * h_c_guess / L.g.scale_h  # no film formula is off by a factor of 100
    calmest = (math.inf, P.copy(), H0)
    cuts = 0
    converged = False
    change = load_error = math.nan
    reason = f"{s.max_cycles} cycles without meeting the criterion"
    for cycle in range(1, s.max_cycles + 1):
        H0 = _cycle(levels, l, P, F, LOAD, H0)
        films.append(_films(L, P, H0))
        load_error = (L.load(P) - LOAD) / LOAD
        # a film 100 times its estimate has blown up even where successive cycles differ little in relative terms
        # (h_c ~ 1e30 and growing, k = 7-9 at M = 15000-30000, L = 20-30): it must never be the calmest state
        blown = not (np.all(np.isfinite(P)) and abs(films[-1][0]) < blown_h_c)
        step = math.inf if blown else _spread(films[-2:], (0,))
        change = _spread(films[-s.window :]) if len(films) > s.window else _spread(films[-2:])
        history.append((l, cycle, change, load_error))
        if not math.isfinite(step) or (len(films) > s.window and step > max(0.05, 10.0 * calmest[0])):
            P[...] = calmest[1]
            H0 = calmest[2]
            if cuts == s.max_damping_cuts:
                reason = f"diverged after {s.max_damping_cuts} cuts of the damping; the calmest state returned"
                break
            cuts += 1
            films = [_films(L, P, H0)]
            for level in levels:
                level.s = replace(level.s, omega_jac=0.5 * level.s.omega_jac)
            continue
        if step < calmest[0]:
            calmest = (step, P.copy(), H0)
        if len(films) > s.window and change < s.tol and abs(load_error) < s.tol_load:
            converged = True
            break
    return _solution(L, P, H0, converged, cycle, change, load_error, history, reason)


def _spread(films, quantities=(0, 1)):
    """Largest relative spread (max - min) / |last| of h_c and of h_min (quantities 0, 1) over a list of
    (h_c, h_min)."""
    return max(np.ptp([f[q] for f in films]) / abs(films[-1][q]) for q in quantities)


def _residual(L, P, H0):
    """rms complementarity residual over the pressurised nodes / rms Couette term there (-): at each interior
    node min(P d, -R) (d the node's own derivative, _ncp_scale), which is the Reynolds residual where the
    pressure is well above 0, a positive residual where a cavitated node should carry pressure, and only
    P d where a node at the cavitation boundary holds a residue of pressure (P ~ 1e-7 p_h) that the
    complementarity will set to 0: the raw residual of such nodes kept the heavy loads' rms at 1.5e-3 with
    the films steady to 5e-5."""
    g = L.g
    R = L.operator(P, H0)
    ncp = np.minimum(P * _ncp_scale(L), -R)[1:-1, 1:-1]
    flux = L.rho * L.H
    couette = np.zeros_like(P)
    couette[1:] = (flux[1:] - flux[:-1]) / g.dX
    wet = P > 0.0
    n_wet = max(int(wet.sum()), 1)
    return math.sqrt(np.sum(ncp**2) / n_wet / max(np.mean(couette[wet] ** 2), 1e-300))


def _solution(L, P, H0, converged, cycles, change, load_error, history, reason="not converged"):
    """The Solution of the state (P, H0) on the finest level L. A state whose film is negative anywhere inside
    the box is never converged: a negative gap is not a lubricated contact, and the discrete Reynolds equation
    admits it (the closed gap carries no Poiseuille flow, its Couette flux turns negative), so the grid is too
    coarse for the film or the iteration has not lifted it yet (docs/ehl_solver.md, Solver)."""
    g = L.g
    residual = _residual(L, P, H0)
    H = L.H.copy()
    ic = int(np.argmin(np.abs(g.X)))
    jc = int(np.argmin(np.abs(g.Y)))
    inner = H[1:-1, 1:-1]
    off = np.abs(g.Y) >= 0.5
    off[0] = off[-1] = False
    scale = g.scale_h
    if inner.min() <= 0.0:
        converged = False
        reason = f"negative film: h_min = {inner.min() * scale * 1e9:.1f} nm (the gap closes on this grid)"
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
        reason="" if converged else reason,
    )


def alpha_star(fluid, p_h):
    """Reciprocal asymptotic isoviscous pressure-viscosity coefficient (1/Pa) of the fluid's law,
    [int_0^inf eta(0) / eta(p) dp]^-1 (trapezoids up to 10 p_h), for the film estimate that starts a solve."""
    p = np.linspace(0.0, 10.0 * p_h, 4001)
    inv = np.array([1.0 / es.viscosity_ratio(q, fluid) for q in p])
    return 1.0 / np.trapezoid(inv, p)


# largest growth of the box (contact_box): s = 4 is the inlet of H_c ~ 5.5 (X_in = -14); the solver did not
# converge on the boxes of the thicker films (M ~ 5-10 at k = 9, H_c 12-130: boxes up to [-78, 34] x 45, the Hertz
# zone under a node of level 0, where the cycles blew up)
BOX_GROWTH_MAX = 4.0


# Gauss-Seidel under-relaxation of the nearly rigid contacts (the box at BOX_GROWTH_MAX, H_c >~ 6: p_max ~ 0.04 p_h,
# every node Gauss-Seidel): with 0.6 their film and load error alternated from cycle to cycle and M = 5-10 at
# L = 20-30 (k = 9, level 3) stopped after 80 cycles; with 0.8 M = 5, L = 20 and M = 10, L = 25 and 30 converge in
# 4 cycles. Not for thinner films: M = 300, L = 40 (H_c = 0.7) diverged with 0.8 and converges with 0.6.
RIGID_OMEGA_GS = 0.8


# Where solve_contact relaxes by lines (kernels.ehl_solver.line_gauss_seidel) and takes the density's derivative:
# the thick films of the grown box, and films of at least LINES_MIN_H Hertz units at Moes L >= LINES_MIN_L. Point
# relaxation left k = 9 contacts at L >= 20 unconverged from M = 100 up (level 3, 120 cycles: h_c steady, h_min
# moving with the exit spike), and lines converge them (docs/ehl_solver.md, Light, fast contacts). Not at thinner
# films: at M = 15000-30000, L = 18 (k = 7-9, H_c ~ 0.03) the lines diverged where the point relaxation converges.
# Nor at the Annexe D cases (L <= 10.4): there lines converged to within 1 % of the point relaxation but took 9 %
# more cycles and 1.6 times the median time, so those keep the solver they were validated with. 11, not 12: the
# 6208's outer contact at 353 K, 20 m/s, 1 GPa (iso_vg68_mineral, L = 11.7 with alpha* at p_h, H_c = 0.33, k = 7.25,
# level 3) ran 120 cycles by points with h_c and the load error alternating from cycle to cycle (spread 1.3e-3,
# load error 2-5e-4) and converges by lines in 11 (docs/ehl_solver.md, Operating box); the largest L of Annexe D
# is 10.4 (case 34)
LINES_MIN_L = 11.0
LINES_MIN_H = 0.1
# Solves whose finest grid is this level or finer, at Moes L >= FINE_MIN_L: the FAS coarse grids take the
# full-weighting pressure (SolverSettings.full_weighting, restrict_pressure), and films of at least FINE_LINES_MIN_H
# Hertz units are relaxed by lines. The
# Poiseuille coefficient eps / dX^2 grows four times a level, so on level 5 a film of 0.033 Hertz units couples its
# nodes along X as a film of 0.083 does on level 3 and point Gauss-Seidel, which does not smooth across the weak
# direction Y (k^2 = 81 times weaker at k = 9), covers the high-pressure zone. Measured at k = 9, M = 13600, L = 18
# (B7214C inner race, film 0.033; points): level 4 blew up at cycle 8, level 5 had bursts of h_min (276-533 nm) for
# 84 cycles; by lines with injection level 5 still swung (h_min 448-544 nm, 23 cycles), by lines with the full
# weighting levels 4 and 5 converge in 14 and 17 cycles without a swing. At M = 2500, L = 23 (6208 inner race, lines
# already) injection left bursts of h_min (level 4: 694-768 nm, p_max up to 6.9 p_h, 68 cycles; level 5 blew up and
# converged after a cut of the damping), full weighting converges levels 4 and 5 in 15 and 16 cycles
# (docs/ehl_solver.md, Fine grids). Level 3 and the contacts of smaller L keep the solver they were validated with.
# Thinner films keep the points (with the full weighting): of the operating box's level-4 contacts at
# 4.2 GPa and L = 11-15 (tests/validation/test_ehl_operating_box.py), those of films 0.018 (6208 outer race, 353 K,
# 20 m/s; B7214C inner race, 313 K, 3.16 m/s) diverged by lines at cycle 3, with injection or full weighting, and
# converge by points in 16 and 42 cycles, as do the films 0.015-0.019; the 6208's inner race at 353 K, 20 m/s (film
# 0.023) did not converge by points and converges by lines, as does the film 0.022
FINE_GRID_LEVEL = 4
FINE_LINES_MIN_H = 0.02
# Moes L* (with alpha* at p_h) from which the fine grids relax films of at least FINE_LINES_MIN_H by lines with the
# full weighting: 10, below LINES_MIN_L. Annexe D cases 34 and 35 (k = 5.03 and 3.96, L* = 10.4 and 10.0, films 0.19
# and 0.18 Hertz units) converge on level 3 by points, but on level 4 they ran 120 cycles by points with injection and
# on level 5 diverged after two cuts of the damping; by lines with full weighting they converge in 14 and 17-21
# cycles, as does the B7214C's inner contact at M = 1000, L = 12 (L* = 10.4; 10 and 7 cycles, not on levels 4-5
# before). Thinner films keep points with injection below LINES_MIN_L: the 6208's inner film-table node at M = 21437,
# L = 11.8 (L* = 10.2, film 0.0185) converges on level 4 that way (24 cycles) and ran 120 cycles by points with full
# weighting. Case 36 (L* = 9.6) and every case of smaller L converge on level 4 by points with injection, which they
# keep; their level 5 is not settled at cases 36-38 (L* = 8.6-9.6), to which no level rule sends a film
# (docs/ehl_solver.md, Fine grids)
FINE_MIN_L = 10.0
# eps max(1/dX^2, 1/(k dY)^2) from which a Gauss-Seidel node is on a line: with 1 (every Gauss-Seidel node) the
# heavy contacts at L = 18 diverged; 10 and 100 converge them and the light ones alike (k = 9, M = 30000 and
# 100-1000 at L = 20-40: 16 / 27 cycles and 10-37 / 8-28)
XI_LINES = 10.0
# Gauss-Seidel under-relaxation where the lines run (not the nearly rigid contacts, RIGID_OMEGA_GS): with 0.6 the
# minimum film of M ~ 1000 at L = 32-40 (k = 9.4, level 3: the 6208's inner contact at 1700 rad/s, 3 kN) cycled
# between 1470 and 1770 nm in a slow relaxation oscillation and never met the criterion, and M = 1000, L = 40
# diverged; with 0.4 every contact of the k = 9 grid M = 5-1000 x L = 20-40 converged (M = 1000, L = 40 in 94
# cycles, the others in 4-25), within 0.4 % of the films of 0.6 where both converge. With 0.4 the same bursts of
# h_min (1280-1770 nm, p_max up to 4.9 p_h) still stopped the 6208's contacts at 3 kN at 2 of 9 speeds from 1650 to
# 1750 rad/s (inner at 1725, outer at 1737.5 rad/s, 120 cycles; the neighbours in 18-94); with 0.3 they converge in
# 20 and 25 cycles (docs/ehl_solver.md, Operating box)
LINES_OMEGA_GS = 0.3


def contact_box(H_c):
    """Computational box (x_in, x_out, y_half) in Hertz units for a contact whose central film is about H_c (-).

    The inlet must be long enough for the film to build fully: Hamrock and Dowson's starvation boundary puts
    it at m* = 1 + 3.06 H_c^0.58 semi-axes from the centre; the box takes 2.4 (m* - 1) past the Hertz edge,
    which is the margin of the box [-3.5, 1.5] x [-2, 2] that matches the thesis within 1 % at the light
    loads (H_c ~ 0.16). Heavy loads (H_c ~ 0.02) need a much shorter inlet, so their box shrinks by a factor
    s (down to 0.6) and the same node count resolves their inlet and exit constriction with spacing s times
    smaller; the exit keeps at least 1.25 (the pressure ends just past X = 1). s = 1 is the box of the
    light loads; X = 0 and Y = 0 stay nodes of every level (grid_hierarchy).

    Light, fast contacts (H_c > 0.35, large Moes L at small M) build their pressure far upstream (m* - 1 = 4.6
    at H_c = 2): the box grows by s > 1 until the inlet is 1.5 (m* - 1) past the Hertz edge (X_in = -3.5 s),
    with the same node count. A shorter inlet starves the film by Hamrock and Dowson's ((m - 1) / (m* - 1))^0.29
    (measured: the B7214C's inner contact at 800 N, 10 000 rpm, H_c = 2.3, 16 % thin on [-3.5, 1.5]) and
    its pressure, which meets the boundary at the inlet, kept the multigrid cycles from converging."""
    s = min(1.0, max(0.6, (2.5 + 2.4 * 3.06 * H_c**0.58) / 5.0))
    s = max(s, min(BOX_GROWTH_MAX, (1.0 + 1.5 * 3.06 * H_c**0.58) / 3.5))
    spacing0 = s / 8.0  # node spacing of level 0 (41 nodes over 5 s)
    x_out = max(12, math.ceil(1.25 / spacing0)) * spacing0
    return (x_out - 5.0 * s, x_out, 2.0 * s)


def grid_hierarchy(Rx, Ry, load, u_e, E_red, eta0, fluid, finest=2, coarsest=0, box=(-3.5, 1.5, 2.0)):
    """Nested grids of the box X in [box[0], box[1]], |Y| <= box[2] (Hertz units): level l has
    (40 2^l + 1) x (32 2^l + 1) nodes (level 2 of the box [-3.5, 1.5] x [-2, 2]: 161 x 129, dX = dY = 0.031),
    so X = 0 and Y = 0 are nodes of every level when box[0] is a multiple of the level-0 spacing."""
    return [
        ContactGrid(Rx, Ry, load, u_e, E_red, eta0, fluid, Domain(box[0], box[1], box[2], 40 * 2**l + 1, 32 * 2**l + 1))
        for l in range(coarsest, finest + 1)
    ]


def film_estimate(U, G, W, k, Rx, Ry):
    """Central film h_c / Rx (-) to size the box and start the solve: the largest of Hamrock and Dowson's
    central film (elastic-piezoviscous, kernels.ehl) and their rigid-regime minimum films (Hamrock and Dowson,
    Ball Bearing Lubrication, Wiley 1981, ch. 8; Esfahanian and Hamrock, Tribol. Trans. 34, 1991, 628-632):
    isoviscous-rigid (Brewe, Hamrock and Taylor 1979) H^ = 128 a_r phi^2 (0.131 atan(a_r / 2) + 1.683)^2,
    phi = (1 + 2 / (3 a_r))^-1, a_r = Ry / Rx, and piezoviscous-rigid H^ = 1.66 g_V^(2/3) (1 - exp(-0.68 k)),
    with H^ = (h / Rx) (W / U)^2, g_V = G W^3 / U^2. The elastic formula alone underestimates the light, fast
    contacts (small Moes M, large L), whose film is the rigid one: at M = 5, L = 20, k = 9 it gives 0.4 of the
    isoviscous-rigid film and the box it sizes starves the contact."""
    h_c = ehl.film_hamrock_dowson(U, G, W, k)[0]
    a_r = Ry / Rx
    phi = 1.0 / (1.0 + 2.0 / (3.0 * a_r))
    rigid_iso = 128.0 * a_r * phi * phi * (0.131 * math.atan(0.5 * a_r) + 1.683) ** 2
    rigid_piezo = 1.66 * (G * W**3 / U**2) ** (2.0 / 3.0) * (1.0 - math.exp(-0.68 * k))
    return max(h_c, max(rigid_iso, rigid_piezo) * (U / W) ** 2)


# The grid level a contact's film needs (resolving_level; solve_contact with finest=None): the coarsest level from 3
# whose node spacing along X is at most RESOLVING_SPACING times the estimated central film, both in Hertz units.
# The heavy contacts' inlet layer, pressure spike and side constrictions narrow with their film, so a fixed level
# loses them: on level 3 (spacing 0.0094 b at the heavy loads' box) the B7214C's outer race (k = 5.86) is 2.7 / 3.4 %
# thin in h_c / h_min at M = 1.05e4 and 9 / 30 % at M = 3.6e4 against the Richardson estimate of levels 3-5. Every
# level at a spacing of at most 0.38 film was within 2 % of the estimate at the nine contacts measured, M = 3000-36000
# at k = 5.9 and 9 (docs/ehl_solver.md, Heavy contacts); 0.35 keeps a margin. FINEST_LEVEL bounds the choice:
# 1281 x 1025 nodes, 20-60 s a heavy contact on one core. The rule is stated to 2 % on h_c and 5 % on h_min: at the
# thin films of 1.3-3.2 GPa the level it picks (4 and, at the cap, 5) is -1.3 / -4.7 % and -1.4 / -2.8 % off the
# Richardson estimate of levels 4-6 (docs/ehl_solver.md, Thin films)
RESOLVING_SPACING = 0.35
COARSEST_RESOLVING_LEVEL = 3  # level 2 is 1-8 % off on h_c even at light loads (docs/ehl_solver.md, Grid convergence)
FINEST_LEVEL = 5


def film_level(H_c):
    """The grid level (COARSEST_RESOLVING_LEVEL to FINEST_LEVEL) for a contact whose central film is about H_c
    (Hertz units, -) on its box contact_box(H_c): the coarsest whose X spacing is at most RESOLVING_SPACING H_c."""
    x_in, x_out, _ = contact_box(H_c)
    for level in range(COARSEST_RESOLVING_LEVEL, FINEST_LEVEL):
        if (x_out - x_in) / (40 * 2**level) <= RESOLVING_SPACING * H_c:
            return level
    return FINEST_LEVEL


def contact_estimate(Rx, Ry, load, u_e, E_red, eta0, fluid):
    """(k, U, G, W, b, h_c) of a contact in SI: ellipticity k, the dimensionless groups of kernels.ehl with the
    fluid's asymptotic pressure-viscosity coefficient, the Hertz semi-axis b along the entrainment (m) and the film
    estimate h_c (m) that sizes the box and starts the solve (film_estimate)."""
    k, ell_E, ell_K = hertz_coefficients_exact(Rx, Ry)
    _, b, _, p_h = hertz_contact(load, Rx, Ry, E_red, k, ell_E, ell_K)
    U, G, W = ehl.dimensionless_groups(eta0, alpha_star(fluid, p_h), E_red, u_e, load, Rx)
    return k, U, G, W, b, film_estimate(U, G, W, k, Rx, Ry) * Rx


def resolving_level(Rx, Ry, load, u_e, E_red, eta0, fluid):
    """The grid level a contact's film needs (film_level of its film estimate; arguments as solve_contact's)."""
    *_, b, h_c = contact_estimate(Rx, Ry, load, u_e, E_red, eta0, fluid)
    return film_level(h_c * Rx / b**2)


def solve_contact(Rx, Ry, load, u_e, E_red, eta0, fluid, finest=3, coarsest=0, settings=None, box=None):
    """Steady isothermal EHL film of one contact in SI: reduced radii Rx (along the entrainment), Ry (m),
    load (N), entrainment speed u_e = (u1 + u2) / 2 (m/s), reduced modulus E' (Pa), viscosity at p = 0
    eta0 (Pa.s), fluid array (fluid_array). Returns a Solution (h_c, h_min, hm_centre, hm_lateral in m,
    p_max in Pa, convergence record, fields) on the grid of level `finest` (grid_hierarchy; level 3, the default,
    is within ~2 % of the grid-converged film up to Moes M ~ 5000 at ball-bearing ellipticities, docs/ehl_solver.md;
    None: the level the contact's film needs, film_level, up to FINEST_LEVEL) of the box (x_in, x_out, y_half), by
    default contact_box of the film estimate (film_estimate: Hamrock-Dowson's central film, or the rigid
    regimes' where larger). Without settings, the relaxation runs along lines and takes the density's
    derivative where that box grows or the film is thick at large Moes L (LINES_MIN_L; SolverSettings.xi_lines,
    density_jac), on levels 4 and 5 from Moes L = FINE_MIN_L down to films of FINE_LINES_MIN_H, where the coarse
    grids take the full-weighting pressure as well (FINE_GRID_LEVEL, SolverSettings.full_weighting; with the points
    of thinner films from LINES_MIN_L), and by points elsewhere."""
    _, U, G, _, b, h_c_guess = contact_estimate(Rx, Ry, load, u_e, E_red, eta0, fluid)
    H_c = h_c_guess * Rx / b**2  # in Hertz units
    own_box = contact_box(H_c)
    finest = film_level(H_c) if finest is None else finest
    thick = own_box[2] > 2.0  # the box grows: a thick film in Hertz units
    rigid = own_box[2] >= 2.0 * BOX_GROWTH_MAX  # the largest box: a nearly rigid contact
    box = box or own_box
    if settings is None:
        L_star = G * (2.0 * U) ** 0.25  # Moes L with the fluid's alpha* at p_h
        fine_grid = finest >= FINE_GRID_LEVEL
        fine_lines = fine_grid and L_star >= FINE_MIN_L and H_c >= FINE_LINES_MIN_H
        fine = fine_lines or (fine_grid and L_star >= LINES_MIN_L)  # full weighting; by points only from LINES_MIN_L
        lines = thick or fine_lines or (L_star >= LINES_MIN_L and H_c >= LINES_MIN_H)
        settings = SolverSettings(
            density_jac=lines,
            xi_lines=XI_LINES if lines else math.inf,
            omega_gs=RIGID_OMEGA_GS if rigid else (LINES_OMEGA_GS if lines else SolverSettings.omega_gs),
            full_weighting=fine,
        )
    grids = grid_hierarchy(Rx, Ry, load, u_e, E_red, eta0, fluid, finest, coarsest, box)
    return solve_grids(grids, settings, h_c_guess)
