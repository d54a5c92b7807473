"""Ball-bearing geometry and pure-rolling kinematics (Harris & Kotzalas 2006, ch. 2). SI units, angles in rad.

Outer ring fixed, inner ring turning at omega (rad/s). gamma = D cos(alpha) / d_m.
Harris & Kotzalas (2006), Essential Concepts of Bearing Technology, ch. 2 and 8.
"""

import math

from bearing_fmu_common.jit import kernel

# Frame of every fidelity (docs/conventions.md): z on the bearing axis, azimuth psi from +x toward +y;
# ball 1 (index 0) sits on +y, the line of a radial load F_y (the analytic fidelity's only radial input)
BALL_1_AZIMUTH = 0.5 * math.pi  # rad


@kernel
def ball_direction(j, Z):
    """Radial unit vector (cos psi_j, sin psi_j) of ball j (0-based) of Z, psi_j = BALL_1_AZIMUTH + 2 pi j / Z (rad);
    a half-integer j gives the direction midway between two balls (the DEM's cage balls).

    Written as (-sin t, cos t), t = 2 pi j / Z, so that ball 0 lies exactly on +y (cos(pi/2) would be 6e-17) and
    the ball set is the exact quarter turn of the set that starts on +x.
    """
    t = 2.0 * math.pi * j / Z
    return -math.sin(t), math.cos(t)


@kernel
def gamma_ratio(D, dm, alpha):
    """gamma = D cos(alpha) / d_m (-) for ball diameter D (m), pitch diameter d_m (m), contact angle alpha (rad)."""
    return D * math.cos(alpha) / dm


@kernel
def curvature_radii(D, dm, f_i, f_o, alpha):
    """Reduced radii (Rx_i, Ry_i, Rx_o, Ry_o) in m of the inner and outer ball-race contacts.

    Rx = (D/2)(1 -/+ gamma) in the rolling direction, Ry = f D / (2 f - 1) across the groove
    (f = groove radius / D, conformity).
    """
    g = gamma_ratio(D, dm, alpha)
    Rx_i = 0.5 * D * (1.0 - g)
    Rx_o = 0.5 * D * (1.0 + g)
    Ry_i = f_i * D / (2.0 * f_i - 1.0)
    Ry_o = f_o * D / (2.0 * f_o - 1.0)
    return Rx_i, Ry_i, Rx_o, Ry_o


@kernel
def free_contact_angle(D, f_i, f_o, Pd):
    """Free contact angle alpha0 (rad) = arccos(1 - P_d / (2 A)), A = (f_i + f_o - 1) D (m).

    P_d is the diametral clearance (m); P_d <= 0 (zero clearance or preload) gives 0.
    """
    A = (f_i + f_o - 1.0) * D
    c = 1.0 - Pd / (2.0 * A)
    if c >= 1.0:
        return 0.0
    if c <= -1.0:
        return math.pi
    return math.acos(c)


@kernel
def free_endplay(D, f_i, f_o, Pd):
    """Free endplay P_e (m) = 2 A sin(alpha0)."""
    A = (f_i + f_o - 1.0) * D
    return 2.0 * A * math.sin(free_contact_angle(D, f_i, f_o, Pd))


@kernel
def rolling_kinematics(omega, D, dm, alpha):
    """Pure-rolling speeds for inner-ring speed omega (rad/s), outer ring fixed.

    Returns (omega_cage, omega_ball_rel, omega_ball_fixed, u_entrain), all signed like omega:
    cage speed omega (1 - gamma)/2 (rad/s); ball spin relative to the cage
    (d_m / 2D)(1 - gamma^2) omega (rad/s); ball spin in the fixed frame omega_ball_rel - omega_cage
    (rad/s; the ball turns in the opposite sense to the cage; exact for alpha = 0, where both spins
    share one axis); entrainment (mean rolling) speed u = omega d_m (1 - gamma^2) / 4 (m/s), the same
    at both races.
    """
    g = gamma_ratio(D, dm, alpha)
    omega_cage = 0.5 * omega * (1.0 - g)
    omega_ball_rel = dm / (2.0 * D) * (1.0 - g * g) * omega
    omega_ball_fixed = omega_ball_rel - omega_cage
    u = 0.25 * omega * dm * (1.0 - g * g)
    return omega_cage, omega_ball_rel, omega_ball_fixed, u


@kernel
def defect_frequencies(omega, D, dm, alpha, Z):
    """Bearing defect frequencies in Hz for inner-ring speed omega (rad/s), outer ring fixed.

    Returns (FTF, BPFO, BPFI, BSF): fundamental train (cage), ball pass outer, ball pass inner and
    ball spin frequency, BSF = (d_m / 2D)(1 - gamma^2) f_r (one ball revolution relative to the cage).
    """
    g = gamma_ratio(D, dm, alpha)
    fr = omega / (2.0 * math.pi)
    ftf = 0.5 * fr * (1.0 - g)
    bpfo = 0.5 * Z * fr * (1.0 - g)
    bpfi = 0.5 * Z * fr * (1.0 + g)
    bsf = dm / (2.0 * D) * fr * (1.0 - g * g)
    return ftf, bpfo, bpfi, bsf


@kernel
def pass_frequencies(omega, omega_cage, omega_ball_cage, Z):
    """Bearing defect frequencies in Hz from solved speeds (slip included where the fidelity has it).

    omega: inner-ring speed (rad/s), outer ring fixed; omega_cage: cage speed in the fixed frame (rad/s);
    omega_ball_cage: ball angular speed relative to the cage (rad/s); Z: number of balls.
    Returns (FTF, BPFO, BPFI, BSF) as magnitudes: FTF = |omega_c| / 2 pi (cage turns), BPFO = Z FTF (balls
    passing a point of the outer ring), BPFI = Z |omega - omega_c| / 2 pi (balls passing a point of the
    inner ring), BSF = |omega_ball_cage| / 2 pi (ball turns relative to the cage; a ball defect strikes the
    races at 2 BSF). In pure rolling these are defect_frequencies().
    """
    ftf = abs(omega_cage) / (2.0 * math.pi)
    return ftf, Z * ftf, Z * abs(omega - omega_cage) / (2.0 * math.pi), abs(omega_ball_cage) / (2.0 * math.pi)


@kernel
def ball_mass(D, rho):
    """Mass (kg) of a ball of diameter D (m) and density rho (kg/m^3)."""
    return rho * math.pi * D**3 / 6.0


@kernel
def centrifugal_force(m_ball, dm, omega_cage):
    """Centrifugal force (N) F_c = m (d_m / 2) omega_c^2 of a ball orbiting at the cage speed (rad/s)."""
    return 0.5 * m_ball * dm * omega_cage * omega_cage
