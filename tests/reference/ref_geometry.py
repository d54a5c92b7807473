"""Twin of bearing_fmu.kernels.geometry: bearing geometry and pure-rolling kinematics.

Harris & Kotzalas (2006), Essential Concepts of Bearing Technology, ch. 2 (geometry) and ch. 8
(kinematics), outer ring fixed, inner ring at omega. Written from the curvature sums and the
textbook kinematic relations, not from the kernel.
"""

import math


def gamma_ratio(D, dm, alpha):
    """gamma = D cos(alpha) / d_m."""
    return D * math.cos(alpha) / dm


def curvature_radii(D, dm, f_i, f_o, alpha):
    """(Rx_i, Ry_i, Rx_o, Ry_o) from the principal curvatures of ball and raceways (Harris ch. 2).

    Ball: 1/R = 2/D in both planes. Raceways in the rolling plane: inner +(2/D) gamma/(1 - gamma)
    (convex), outer -(2/D) gamma/(1 + gamma) (concave); across the groove: -1/(f D) (concave).
    The reduced radius is the inverse of the curvature sum in each plane.
    """
    g = gamma_ratio(D, dm, alpha)
    ball = 2.0 / D
    inner_x = (2.0 / D) * g / (1.0 - g)
    outer_x = -(2.0 / D) * g / (1.0 + g)
    Rx_i = 1.0 / (ball + inner_x)
    Rx_o = 1.0 / (ball + outer_x)
    Ry_i = 1.0 / (ball - 1.0 / (f_i * D))
    Ry_o = 1.0 / (ball - 1.0 / (f_o * D))
    return Rx_i, Ry_i, Rx_o, Ry_o


def free_contact_angle(D, f_i, f_o, Pd):
    """alpha0 = arccos(1 - P_d/(2A)), A = (f_i + f_o - 1) D (Harris ch. 2); no clearance (P_d <= 0) -> 0.

    Beyond P_d = 4A (more clearance than the grooves allow) the angle saturates at pi.
    """
    A = (f_i + f_o - 1.0) * D
    if Pd <= 0.0:
        return 0.0
    if Pd >= 4.0 * A:
        return math.pi
    # 1 - cos(alpha0) = 2 sin^2(alpha0/2) = P_d/(2A): the half-angle form stays accurate for tiny
    # clearances, where arccos(1 - x) loses about eps/x of relative precision
    return 2.0 * math.asin(math.sqrt(Pd / (4.0 * A)))


def free_endplay(D, f_i, f_o, Pd):
    """Free endplay P_e = sqrt(P_d (4A - P_d)) (Harris ch. 2; = 2A sin alpha0); 0 without clearance."""
    A = (f_i + f_o - 1.0) * D
    if Pd <= 0.0 or Pd >= 4.0 * A:
        return 0.0
    return math.sqrt(Pd * (4.0 * A - Pd))


def rolling_kinematics(omega, D, dm, alpha):
    """(omega_cage, omega_ball_rel, omega_ball_fixed, u) for inner-ring speed omega, outer ring fixed.

    Harris ch. 8: cage omega_c = omega (1 - gamma)/2; ball about its own axis relative to the cage
    omega_R = (d_m / 2D)(1 - gamma^2) omega; the fixed-frame spin is counted in the sense opposite to
    the cage, omega_R - omega_c (the two rotations are about parallel axes for alpha = 0, where the
    unit tests also check it by the no-slip conditions); entrainment speed = mean surface speed at
    the inner contact relative to the cage, u = (d_m/2)(1 - gamma) (omega - omega_c) (same value at
    the outer contact, (d_m/2)(1 + gamma) omega_c).
    """
    g = gamma_ratio(D, dm, alpha)
    omega_cage = omega * (1.0 - g) / 2.0
    omega_ball_rel = (dm / (2.0 * D)) * (1.0 - g * g) * omega
    omega_ball_fixed = omega_ball_rel - omega_cage
    u = (dm / 2.0) * (1.0 - g) * (omega - omega_cage)
    return omega_cage, omega_ball_rel, omega_ball_fixed, u


def defect_frequencies(omega, D, dm, alpha, Z):
    """(FTF, BPFO, BPFI, BSF) in Hz: f_r = omega/2pi; FTF = f_r (1 - gamma)/2; BPFO = Z FTF;
    BPFI = Z (f_r - FTF) (balls passing a point of the rotating inner ring); BSF = (d_m/2D)(1 - gamma^2) f_r."""
    g = gamma_ratio(D, dm, alpha)
    fr = omega / (2.0 * math.pi)
    ftf = fr * (1.0 - g) / 2.0
    return ftf, Z * ftf, Z * (fr - ftf), (dm / (2.0 * D)) * (1.0 - g * g) * fr


def pass_frequencies(omega, omega_cage, omega_ball_cage, Z):
    """(FTF, BPFO, BPFI, BSF) in Hz from the speeds, outer ring fixed: in the cage's frame the outer ring turns
    at -omega_c and the inner ring at omega - omega_c, and Z balls pass a point of each ring per relative turn;
    the ball turns at omega_ball_cage relative to the cage. Frequencies are counts per second (magnitudes)."""
    turns = [abs(w) / (2.0 * math.pi) for w in (0.0 - omega_cage, omega - omega_cage, omega_ball_cage)]
    outer, inner, ball = turns
    return outer, Z * outer, Z * inner, ball


def ball_direction(j, Z):
    """Unit vector toward ball j: azimuth pi/2 + 2 pi j / Z from +x toward +y (ball 0 on +y)."""
    psi = math.pi / 2.0 + 2.0 * math.pi * j / Z
    return math.cos(psi), math.sin(psi)


def ball_mass(D, rho):
    """m = rho (4/3) pi (D/2)^3."""
    return rho * 4.0 / 3.0 * math.pi * (D / 2.0) ** 3


def centrifugal_force(m_ball, dm, omega_cage):
    """F_c = m r omega^2 with orbit radius r = d_m / 2."""
    return m_ball * (dm / 2.0) * omega_cage**2


# the kernels this module twins, by name (tests/unit/test_every_kernel_has_a_twin.py)
KERNEL_MODULE = "bearing_fmu.kernels.geometry"
TWINS = {
    "gamma_ratio": gamma_ratio,
    "curvature_radii": curvature_radii,
    "free_contact_angle": free_contact_angle,
    "free_endplay": free_endplay,
    "rolling_kinematics": rolling_kinematics,
    "defect_frequencies": defect_frequencies,
    "pass_frequencies": pass_frequencies,
    "ball_direction": ball_direction,
    "ball_mass": ball_mass,
    "centrifugal_force": centrifugal_force,
}
