r"""Rotating shaft as Timoshenko beam elements: numba kernels (docs/shaft.md). SI units (m, kg, Pa, rad).

Degrees of freedom: 5 per node, in the order of the bearings' stiffness K (the quasi-static fidelity's
convention, bearing_fmu/kernels/ball_dynamics/stiffness.py): (x, y, z, theta_x, theta_y), theta a small
rotation vector, so a point at axial distance s from the node moves by (theta_y s, -theta_x s): the slope
of the x-deflection is +theta_y and that of the y-deflection is -theta_x. Node i has the global indices
5 i .. 5 i + 4, and element e joins nodes e and e + 1 (z grows from node 0).

The equations of motion at a constant speed Omega (rad/s, about +z) are

    M q'' + (C + Omega G) q' + K q = f,

M, K symmetric, G skew (Nelson & McVaugh 1976, J. Eng. Ind. 98, 593-600; Friswell, Penny, Garvey & Lees,
Dynamics of Rotating Machines, 2010, ch. 5, the equation of a rotor's finite-element model). Each bending
plane is the textbook Timoshenko element in (w, w') with w' the slope: (x, theta_y) directly, (y, -theta_x)
with the sign of the rotation flipped (Friswell et al. ch. 5 take theta about x and psi about y with u' = psi,
v' = -theta: the same convention).
Per element of length L, area A, second moment I, shear coefficient kappa and Phi = 12 E I / (kappa G A L^2)
(Friswell et al. ch. 5, the Timoshenko shaft element; Przemieniecki 1968, Theory of Matrix Structural
Analysis, ch. 5 and 11, for the same matrices of a non-rotating beam):

    K_b = E I / ((1 + Phi) L^3) [[12, 6L, -12, 6L], [6L, (4+Phi)L^2, -6L, (2-Phi)L^2], ...]
    M_t = rho A L / (840 (1 + Phi)^2) [[m1, m2, m3, m4], ...]   (translational inertia)
    M_r = rho I / (30 L (1 + Phi)^2) [[36, (3-15Phi)L, -36, (3-15Phi)L], ...]   (rotary inertia)
    G   = the rotary inertia matrix with the polar moment I_p = 2 I in place of I, coupling the planes:
          the x-plane's equations get +P T q'_y, the y-plane's -T P q'_x (a disk: I_d theta_x'' + I_p Omega
          theta_y' = M_x, I_d theta_y'' - I_p Omega theta_x' = M_y, angular momentum about the tilted axis)

and the axial bar K_a = E A / L [[1, -1], [-1, 1]], M_a = rho A L / 6 [[2, 1], [1, 2]] (consistent mass).
Forward whirl of the tilt is stiffened by G, backward whirl softened: the gyroscopic splitting.

Kernels write into arrays the caller owns; no BLAS or LAPACK (numba takes those from scipy, which an FMU host
may lack): the eigen-solution is numpy's, in the facade.
"""

import math

import numpy as np

from bearing_fmu_common.jit import kernel

NDOF = 5  # per node: x, y, z, theta_x, theta_y
# element slots of each plane's (w1, w1', w2, w2'): the x-plane (x, theta_y) and the y-plane (y, theta_x)
# with the sign that turns theta_x into the slope of y
X_PLANE = (0, 4, 5, 9)
Y_PLANE = (1, 3, 6, 8)
Y_SIGN = (1.0, -1.0, 1.0, -1.0)
AXIAL = (2, 7)


@kernel
def shear_coefficient(nu, outer_diameter, inner_diameter):
    """Shear coefficient kappa (-) of a hollow circular section (Cowper 1966, J. Appl. Mech. 33, 335-340,
    Table 1: kappa = 6 (1 + nu)(1 + m^2)^2 / ((7 + 6 nu)(1 + m^2)^2 + (20 + 12 nu) m^2), m = d_i / d_o)."""
    m2 = (inner_diameter / outer_diameter) ** 2
    s = (1.0 + m2) ** 2
    return 6.0 * (1.0 + nu) * s / ((7.0 + 6.0 * nu) * s + (20.0 + 12.0 * nu) * m2)


@kernel
def plane_matrices(E, G, rho, kappa, L, outer_diameter, inner_diameter, Kb, Mb, Pb):
    """One bending plane's 4x4 matrices in (w1, w1', w2, w2'): stiffness Kb, translational plus rotary mass Mb and
    the polar rotary inertia Pb (the gyroscopic matrix's block) of a Timoshenko element (module docstring)."""
    ro = 0.5 * outer_diameter
    ri = 0.5 * inner_diameter
    A = math.pi * (ro * ro - ri * ri)
    I = 0.25 * math.pi * (ro**4 - ri**4)
    phi = 12.0 * E * I / (kappa * G * A * L * L)
    k = E * I / ((1.0 + phi) * L**3)
    k0 = np.array([12.0, 6.0 * L, -12.0, 6.0 * L])
    k1 = np.array([(4.0 + phi) * L * L, -6.0 * L, (2.0 - phi) * L * L])
    t = rho * A * L / (840.0 * (1.0 + phi) ** 2)
    m1 = 312.0 + 588.0 * phi + 280.0 * phi * phi
    m2 = (44.0 + 77.0 * phi + 35.0 * phi * phi) * L
    m3 = 108.0 + 252.0 * phi + 140.0 * phi * phi
    m4 = -(26.0 + 63.0 * phi + 35.0 * phi * phi) * L
    m5 = (8.0 + 14.0 * phi + 7.0 * phi * phi) * L * L
    m6 = -(6.0 + 14.0 * phi + 7.0 * phi * phi) * L * L
    r = rho * I / (30.0 * L * (1.0 + phi) ** 2)
    r8 = (3.0 - 15.0 * phi) * L
    r9 = (4.0 + 5.0 * phi + 10.0 * phi * phi) * L * L
    r10 = (-1.0 - 5.0 * phi + 5.0 * phi * phi) * L * L
    # upper triangles, rows (w1, w1', w2, w2'); the lower ones by symmetry
    kb = ((k0[0], k0[1], k0[2], k0[3]), (0.0, k1[0], k1[1], k1[2]), (0.0, 0.0, 12.0, -6.0 * L), (0.0, 0.0, 0.0, k1[0]))
    mt = ((m1, m2, m3, m4), (0.0, m5, -m4, m6), (0.0, 0.0, m1, -m2), (0.0, 0.0, 0.0, m5))
    mr = ((36.0, r8, -36.0, r8), (0.0, r9, -r8, r10), (0.0, 0.0, 36.0, -r8), (0.0, 0.0, 0.0, r9))
    for a in range(4):
        for b in range(a, 4):
            Kb[a, b] = k * kb[a][b]
            Mb[a, b] = t * mt[a][b] + r * mr[a][b]
            Pb[a, b] = 2.0 * r * mr[a][b]  # I_p = 2 I for a circular section
            Kb[b, a] = Kb[a, b]
            Mb[b, a] = Mb[a, b]
            Pb[b, a] = Pb[a, b]


@kernel
def element_matrices(E, G, rho, kappa, L, outer_diameter, inner_diameter, Ke, Me, Ge):
    """Fill the 10x10 stiffness Ke, mass Me and gyroscopic Ge (per unit speed) of one shaft element over
    (node 1: x, y, z, theta_x, theta_y; node 2: the same); module docstring for the matrices."""
    Kb = np.empty((4, 4))
    Mb = np.empty((4, 4))
    Pb = np.empty((4, 4))
    plane_matrices(E, G, rho, kappa, L, outer_diameter, inner_diameter, Kb, Mb, Pb)
    for i in range(10):
        for j in range(10):
            Ke[i, j] = 0.0
            Me[i, j] = 0.0
            Ge[i, j] = 0.0
    for a in range(4):
        xa = X_PLANE[a]
        ya = Y_PLANE[a]
        sa = Y_SIGN[a]
        for b in range(4):
            xb = X_PLANE[b]
            yb = Y_PLANE[b]
            sb = Y_SIGN[b]
            Ke[xa, xb] = Kb[a, b]
            Me[xa, xb] = Mb[a, b]
            Ke[ya, yb] = sa * sb * Kb[a, b]
            Me[ya, yb] = sa * sb * Mb[a, b]
            Ge[xa, yb] = Pb[a, b] * sb
            Ge[ya, xb] = -sa * Pb[a, b]
    ro = 0.5 * outer_diameter
    ri = 0.5 * inner_diameter
    A = math.pi * (ro * ro - ri * ri)
    ka = E * A / L
    ma = rho * A * L / 6.0
    for a in range(2):
        for b in range(2):
            Ke[AXIAL[a], AXIAL[b]] = ka if a == b else -ka
            Me[AXIAL[a], AXIAL[b]] = 2.0 * ma if a == b else ma


@kernel
def assemble_shaft(elements, K, M, Gy):
    """Fill the global K, M and Gy (n_nodes * 5 square) of the shaft from its elements: row e of `elements`
    is (E, G, rho, kappa, L, outer diameter, inner diameter) of the element joining nodes e and e + 1."""
    n = K.shape[0]
    for i in range(n):
        for j in range(n):
            K[i, j] = 0.0
            M[i, j] = 0.0
            Gy[i, j] = 0.0
    Ke = np.empty((10, 10))
    Me = np.empty((10, 10))
    Ge = np.empty((10, 10))
    for e in range(elements.shape[0]):
        p = elements[e]
        element_matrices(p[0], p[1], p[2], p[3], p[4], p[5], p[6], Ke, Me, Ge)
        o = NDOF * e
        for i in range(10):
            for j in range(10):
                K[o + i, o + j] += Ke[i, j]
                M[o + i, o + j] += Me[i, j]
                Gy[o + i, o + j] += Ge[i, j]


@kernel
def add_disks(disks, M, Gy):
    """Add rigid disks to M and Gy: row d of `disks` is (node, mass kg, polar inertia kg m^2, diametral inertia
    kg m^2); a disk's gyroscopic moments are I_p Omega (theta_y', -theta_x') (module docstring)."""
    for d in range(disks.shape[0]):
        o = NDOF * int(disks[d, 0])
        for i in range(3):
            M[o + i, o + i] += disks[d, 1]
        M[o + 3, o + 3] += disks[d, 3]
        M[o + 4, o + 4] += disks[d, 3]
        Gy[o + 3, o + 4] += disks[d, 2]
        Gy[o + 4, o + 3] -= disks[d, 2]


@kernel
def add_seats(seat_dofs, seat_K, K):
    """Add each seat's 5x5 matrix seat_K[s] (a bearing's stiffness or damping over x, y, z, theta_x, theta_y)
    onto the rows and columns seat_dofs[s, :] of K (the seat node's dofs in the caller's numbering)."""
    for s in range(seat_K.shape[0]):
        for i in range(NDOF):
            for j in range(NDOF):
                K[seat_dofs[s, i], seat_dofs[s, j]] += seat_K[s, i, j]
