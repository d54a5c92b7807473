"""The discrete point-contact EHL problem of one contact on one grid (kernels/ehl_solver.py).

`ContactGrid(...)` takes the contact in SI (reduced radii Rx, Ry in m, load in N, entrainment speed in m/s,
reduced modulus E' in Pa, viscosity at p = 0 in Pa.s and the fluid array of kernels.ehl_solver), sizes the
Hertz contact, lays the node grid in Hertz units and evaluates the discrete equations for a given state:
`residual(Phi, H0)` (the Reynolds residual at every node and the relative load error) and
`deflection(P)` (the dimensionless elastic deflection W of a pressure field by FFT convolution of the
rectangle influences, zero-padded to twice the grid so the convolution is linear, not periodic).
Scalings as in kernels/ehl_solver.py: h = (b^2 / Rx) H, p = p_h P.
"""

import math
from dataclasses import dataclass

import numpy as np

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
