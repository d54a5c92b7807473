"""Tangent stiffness K[i, j] = dF_i/dd_j of the inner ring in the current DEM state (docs/dem.md, Stiffness).

(F) = (F_x, F_y, F_z, M_x, M_y) in N and N.m, (d) = (x, y, z, theta_x, theta_y) in m and rad: the
quasi-static fidelity's convention. Each loaded ball-race contact is a spring in the ball's radial plane
(e_r, e_z): the Hertz tangent stiffness k_n = dQ/ddelta = 1.5 K_h delta^0.5 along its normal and
Q/(r_g + delta) across it (the contact force stays on the line through the groove's curvature centre,
r_g = (f - 1/2) D, so a ball moved across the normal is pulled back). Each ball's inner and outer contacts
act in series: the ball's two in-plane coordinates are eliminated, K_ball = K_i - K_i (K_i + K_o)^-1 K_i
(Harris & Kotzalas 2006, vol. 2, ch. 1: the ball's own equilibrium condensed out). The ball acts on the
inner groove's curvature-centre point nearest to it, c + L (L of length rho_i in the plane of the ring's
current, tilted circle, c the ring's centre), which a ring displacement moves by u + theta x L; K = sum over
the balls of G^T K_ball G. The moments are about the ring's centre, the point about which it tilts (the
quasi-static fidelity's). A ball open on either race adds nothing. Computed once per communication step, not
per DEM step.
"""

import math

import numpy as np

from bearing_fmu_common.jit import kernel

from .contact_law import groove_approach
from .state import B_X, P_KH_I, P_RG_I
from .tribology import race_circle


@kernel(inline="always")
def _contact_spring(race, x, y, z, c, sn, ring, par):
    """(a, b, e): the 2x2 stiffness (N/m) [[a, b], [b, e]] of one contact in the ball's radial plane
    (e_r = (c, sn, 0), e_z), or a < 0 when the contact is open."""
    cx, cy, cz, ax, ay, az, rho = race_circle(race, ring, par)
    rg = par[P_RG_I + race]
    delta, nx, ny, nz = groove_approach(x, y, z, cx, cy, cz, ax, ay, az, rho, rg)
    if delta <= 0.0:
        return -1.0, 0.0, 0.0
    K_h = par[P_KH_I + race]
    root = math.sqrt(delta)
    k_n = 1.5 * K_h * root
    k_t = K_h * delta * root / (rg + delta)  # Q / (r_g + delta)
    n_r = nx * c + ny * sn
    n_z = nz
    scale = 1.0 / (n_r * n_r + n_z * n_z)
    d = k_n - k_t
    return k_t + d * n_r * n_r * scale, d * n_r * n_z * scale, k_t + d * n_z * n_z * scale


@kernel
def stiffness_matrix(balls, ring, par, K):
    """Fill K (float64[5, 5]) with the tangent stiffness of the inner ring in the current state (module
    docstring; N/m, N/rad, N.m/m, N.m/rad)."""
    for i in range(5):
        for k in range(5):
            K[i, k] = 0.0
    cx, cy, cz, ax, ay, az, rho_i = race_circle(0, ring, par)
    G = np.empty((2, 5))  # d(e_r, e_z displacement of the ball's inner curvature centre)/d(ring DOFs)
    for j in range(balls.shape[1]):
        x = balls[B_X, j]
        y = balls[B_X + 1, j]
        z = balls[B_X + 2, j]
        r = math.sqrt(x * x + y * y)
        c = x / r
        sn = y / r
        a, b, e = _contact_spring(0, x, y, z, c, sn, ring, par)
        if a < 0.0:
            continue
        a_o, b_o, e_o = _contact_spring(1, x, y, z, c, sn, ring, par)
        if a_o < 0.0:
            continue
        # the ball condensed: K_i - K_i (K_i + K_o)^-1 K_i, i.e. K_i and K_o in series
        sa = a + a_o
        sb = b + b_o
        se = e + e_o
        det = sa * se - sb * sb
        ia = se / det
        ib = -sb / det
        ie = sa / det
        m11 = ia * a + ib * b
        m12 = ia * b + ib * e
        m21 = ib * a + ie * b
        m22 = ib * b + ie * e
        k_rr = a - (a * m11 + b * m21)
        k_rz = b - (a * m12 + b * m22)
        k_zr = b - (b * m11 + e * m21)
        k_zz = e - (b * m12 + e * m22)
        # the lever L from the ring's centre to the inner curvature-centre point nearest to the ball: rho_i along the
        # ball's direction in the plane of the (tilted) circle
        dx = x - cx
        dy = y - cy
        dz = z - cz
        h = dx * ax + dy * ay + dz * az
        dx -= h * ax
        dy -= h * ay
        dz -= h * az
        scale = rho_i / math.sqrt(dx * dx + dy * dy + dz * dz)
        lx = dx * scale
        ly = dy * scale
        lz = dz * scale
        # displacement of that point along e_r and e_z for (x, y, z, theta_x, theta_y): u + theta x L
        G[0, 0] = c
        G[0, 1] = sn
        G[0, 2] = 0.0
        G[0, 3] = -lz * sn
        G[0, 4] = lz * c
        G[1, 0] = 0.0
        G[1, 1] = 0.0
        G[1, 2] = 1.0
        G[1, 3] = ly
        G[1, 4] = -lx
        for i in range(5):
            # (K_ball G)[:, i]
            kr = k_rr * G[0, i] + k_rz * G[1, i]
            kz = k_zr * G[0, i] + k_zz * G[1, i]
            for k in range(5):
                K[k, i] += G[0, k] * kr + G[1, k] * kz
