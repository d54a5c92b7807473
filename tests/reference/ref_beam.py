"""Twin of spindle.shaft.beam: the Timoshenko shaft element from its shape functions, plain numpy.

Written from the mechanics, not from the printed matrices the kernel codes:
- the element's interpolation is the exact static solution of a Timoshenko beam without load (Nelson 1980,
  J. Mech. Des. 102, 793-803; Friswell et al. 2010, ch. 5): the deflection w is cubic, and the stationarity of
  the strain energy in psi, (E I psi')' + kappa G A (w' - psi) = 0, with a constant shear force gives
  psi = w' + (Phi L^2 / 2) a3 (a3 the cubic coefficient of w, Phi = 12 E I / (kappa G A L^2)); the four
  coefficients follow from the nodal (w, psi) by a linear solve;
- the matrices are the energies' integrals by 6-point Gauss-Legendre quadrature (exact for these polynomials):
  K = int E I psi'^T psi' + kappa G A (w' - psi)^T (w' - psi), M = int rho A w^T w + rho I psi^T psi,
  P = int rho I_p psi^T psi (I_p = 2 I);
- the 10x10 element is placed through selection matrices: the x-plane (x, theta_y) as is, the y-plane
  (y, -theta_x) with the rotation's sign flipped, G = S_x^T P S_y - S_y^T P S_x; the axial bar from linear shape
  functions by the same quadrature;
- assembly, disks and seats by index arithmetic over whole blocks (numpy.ix_).
"""

import math

import numpy as np

KERNEL_MODULE = "spindle.shaft.beam"
GAUSS = np.polynomial.legendre.leggauss(6)


def shear_coefficient(nu, outer_diameter, inner_diameter):
    """Cowper 1966, Table 1, hollow circular section, written with the radii ratio m = r_i / r_o."""
    m = inner_diameter / outer_diameter
    return 6.0 * (1.0 + nu) * (1.0 + m * m) ** 2 / ((7.0 + 6.0 * nu) * (1.0 + m * m) ** 2 + (20.0 + 12.0 * nu) * m * m)


def _section(outer_diameter, inner_diameter):
    A = math.pi / 4.0 * (outer_diameter**2 - inner_diameter**2)
    I = math.pi / 64.0 * (outer_diameter**4 - inner_diameter**4)
    return A, I


def _shape_functions(L, phi, s):
    """(N_w, N_w', N_psi, N_psi') at s (rows of length 4 over w1, psi1, w2, psi2)."""
    c = -phi * L * L / 2.0  # psi = w' - c a3
    # rows: w(0), psi(0), w(L), psi(L) in the coefficients a0..a3 of w = a0 + a1 s + a2 s^2 + a3 s^3
    B = np.array(
        [[1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, -c], [1.0, L, L * L, L**3], [0.0, 1.0, 2.0 * L, 3.0 * L * L - c]]
    )
    Binv = np.linalg.inv(B)
    w = np.array([1.0, s, s * s, s**3]) @ Binv
    dw = np.array([0.0, 1.0, 2.0 * s, 3.0 * s * s]) @ Binv
    psi = np.array([0.0, 1.0, 2.0 * s, 3.0 * s * s - c]) @ Binv
    dpsi = np.array([0.0, 0.0, 2.0, 6.0 * s]) @ Binv
    return w, dw, psi, dpsi


def plane_matrices(E, G, rho, kappa, L, outer_diameter, inner_diameter, Kb, Mb, Pb):
    A, I = _section(outer_diameter, inner_diameter)
    phi = 12.0 * E * I / (kappa * G * A * L * L)
    Kb[:], Mb[:], Pb[:] = 0.0, 0.0, 0.0
    for x, weight in zip(*GAUSS):
        s = 0.5 * L * (x + 1.0)
        w, dw, psi, dpsi = _shape_functions(L, phi, s)
        g = 0.5 * L * weight
        gamma = dw - psi
        Kb += g * (E * I * np.outer(dpsi, dpsi) + kappa * G * A * np.outer(gamma, gamma))
        Mb += g * (rho * A * np.outer(w, w) + rho * I * np.outer(psi, psi))
        Pb += g * rho * 2.0 * I * np.outer(psi, psi)


def _selection(dofs, signs):
    S = np.zeros((len(dofs), 10))
    for row, (dof, sign) in enumerate(zip(dofs, signs)):
        S[row, dof] = sign
    return S


def element_matrices(E, G, rho, kappa, L, outer_diameter, inner_diameter, Ke, Me, Ge):
    Kb, Mb, Pb = np.zeros((4, 4)), np.zeros((4, 4)), np.zeros((4, 4))
    plane_matrices(E, G, rho, kappa, L, outer_diameter, inner_diameter, Kb, Mb, Pb)
    Sx = _selection((0, 4, 5, 9), (1.0, 1.0, 1.0, 1.0))  # x, theta_y: slope of x is +theta_y
    Sy = _selection((1, 3, 6, 8), (1.0, -1.0, 1.0, -1.0))  # y, theta_x: slope of y is -theta_x
    Sz = _selection((2, 7), (1.0, 1.0))
    A, _ = _section(outer_diameter, inner_diameter)
    Ka, Ma = np.zeros((2, 2)), np.zeros((2, 2))
    for x, weight in zip(*GAUSS):
        s = 0.5 * L * (x + 1.0)
        n = np.array([1.0 - s / L, s / L])
        dn = np.array([-1.0 / L, 1.0 / L])
        Ka += 0.5 * L * weight * E * A * np.outer(dn, dn)
        Ma += 0.5 * L * weight * rho * A * np.outer(n, n)
    Ke[:] = Sx.T @ Kb @ Sx + Sy.T @ Kb @ Sy + Sz.T @ Ka @ Sz
    Me[:] = Sx.T @ Mb @ Sx + Sy.T @ Mb @ Sy + Sz.T @ Ma @ Sz
    Ge[:] = Sx.T @ Pb @ Sy - Sy.T @ Pb @ Sx


def assemble_shaft(elements, K, M, Gy):
    K[:], M[:], Gy[:] = 0.0, 0.0, 0.0
    Ke, Me, Ge = np.zeros((10, 10)), np.zeros((10, 10)), np.zeros((10, 10))
    for e, row in enumerate(elements):
        element_matrices(*row, Ke, Me, Ge)
        dofs = np.arange(5 * e, 5 * e + 10)
        K[np.ix_(dofs, dofs)] += Ke
        M[np.ix_(dofs, dofs)] += Me
        Gy[np.ix_(dofs, dofs)] += Ge


def add_disks(disks, M, Gy):
    """A rigid disk: mass on x, y, z, I_d on both tilts; its moments I_d theta'' + I_p Omega (theta_y', -theta_x')
    from the angular momentum I_p Omega e_z' + I_d theta' of the tilted disk, e_z' = e_z + theta x e_z."""
    for node, mass, Ip, Id in disks:
        dofs = np.arange(5 * int(node), 5 * int(node) + 5)
        M[np.ix_(dofs, dofs)] += np.diag([mass, mass, mass, Id, Id])
        Gd = np.zeros((5, 5))
        Gd[3:, 3:] = Ip * np.array([[0.0, 1.0], [-1.0, 0.0]])
        Gy[np.ix_(dofs, dofs)] += Gd


def add_seats(seat_dofs, seat_K, K):
    for dofs, Ks in zip(seat_dofs, seat_K):
        K[np.ix_(dofs, dofs)] += Ks


TWINS = {
    "shear_coefficient": shear_coefficient,
    "plane_matrices": plane_matrices,
    "element_matrices": element_matrices,
    "assemble_shaft": assemble_shaft,
    "add_disks": add_disks,
    "add_seats": add_seats,
}
