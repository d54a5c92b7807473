"""Twin of bearing_fmu.kernels.ball_dynamics.stiffness: the inner ring's 5x5 tangent stiffness in a DEM state.

Written from the definition (docs/dem.md, Stiffness) with vector algebra and numpy matrices, sharing only the
array layout: per ball, each loaded contact's 3x3 spring k_n n n^T + k_t (I - n n^T) with k_n = 1.5 K_h delta^0.5
(Hertz tangent) and k_t = Q/(r_g + delta) (the force turning about the groove's curvature centre), restricted to
the ball's radial plane (e_r, e_z) by the projector P = [e_r; e_z]; the ball eliminated from the two contacts
in series by a linear solve, K_ball = K_i - K_i (K_i + K_o)^-1 K_i; the ring's DOFs (x, y, z, theta_x, theta_y)
move the inner curvature-centre point nearest to the ball, c + L (c the ring's centre, about which it tilts; L of
length rho_i toward the ball in the plane of the ring's tilted circle), by u + theta x L, projected on (e_r, e_z);
K = sum G^T K_ball G. Balls open on either race are skipped.
"""

import numpy as np

from bearing_fmu.kernels.ball_dynamics import state as s
from tests.reference.ref_ball_dynamics_integrator import groove_contact, race_centre

KERNEL_MODULE = "bearing_fmu.kernels.ball_dynamics.stiffness"


def _in_plane_spring(delta, n, K_h, rg, P):
    """2x2 stiffness (N/m) of one contact in the plane spanned by the rows of P."""
    k_n = 1.5 * K_h * np.sqrt(delta)
    k_t = K_h * delta**1.5 / (rg + delta)
    # the normal's component in the radial plane carries k_n (the out-of-plane component is ~0 for a ball
    # centred in its plane: normalised as the definition's in-plane normal)
    m = P @ n
    m = m / np.linalg.norm(m)
    return k_n * np.outer(m, m) + k_t * (np.eye(2) - np.outer(m, m))


def stiffness_matrix(balls, ring, par, K):
    """Fill K (5x5) with sum over the balls of G^T K_ball G (see the module docstring)."""
    K[...] = 0.0
    for j in range(balls.shape[1]):
        p = balls[s.B_X : s.B_X + 3, j]
        e_r = np.array([p[0], p[1], 0.0]) / np.hypot(p[0], p[1])
        e_z = np.array([0.0, 0.0, 1.0])
        P = np.vstack([e_r, e_z])
        springs = []
        for race in (0, 1):
            centre, rho, axis = race_centre(race, ring, par)
            delta, n = groove_contact(p, centre, rho, par[s.P_RG_I + race], axis)
            if delta <= 0.0:
                break
            springs.append(_in_plane_spring(delta, n, par[s.P_KH_I + race], par[s.P_RG_I + race], P))
        if len(springs) < 2:
            continue
        K_i, K_o = springs
        K_ball = K_i - K_i @ np.linalg.solve(K_i + K_o, K_i)
        centre, rho_i, axis = race_centre(0, ring, par)
        toward = (p - centre) - np.dot(p - centre, axis) * axis
        L = rho_i * toward / np.linalg.norm(toward)
        # displacement of c + L for a unit DOF: translations u = e_x, e_y, e_z; tilts theta = e_x, e_y: theta x L
        moves = np.column_stack(
            [np.eye(3)[0], np.eye(3)[1], np.eye(3)[2], np.cross(np.eye(3)[0], L), np.cross(np.eye(3)[1], L)]
        )
        G = P @ moves
        K += G.T @ K_ball @ G
    return K


TWINS = {"stiffness_matrix": stiffness_matrix}
