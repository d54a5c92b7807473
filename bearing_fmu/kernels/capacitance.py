"""Electrical capacitance of lubricated ball-race contacts and of the bearing (Farah et al.; docs/decisions.md).

Farah et al. (2020), eqs. 8, 10-12: parallel-plate capacitor over the Hertz ellipse,
  C = eps_0 eps_r(p) pi a b / h_c,
eps_r from Clausius-Mossotti at the Dowson-Higginson density at the contact pressure;
per ball the inner and outer contacts in series; the balls in parallel (insulating cage).
A ball that has lost contact with either ring contributes nothing (Farah: only balls in the
loaded zone count).

Outside the Hertz ellipse (scene option capacitance_region = "lubricated", docs/decisions.md): the gap
around the contact, h_c plus the separation of the Hertz-loaded surfaces (Johnson 1985, Contact Mechanics,
section 3.4: the displacement of an elliptical Hertz pressure at any point of the surface), holds oil up to the
oil-availability gap h_oil; outside_hertz_capacitance integrates eps_0 eps_r / h over that region.

The capacitance submodel is a block of CAP_SIZE numbers (models.race_contacts.capacitance_block) that each
fidelity's parameter array embeds at one offset; capacitance off is the null block, all 0, with which no
permittivity or capacitance is computed and the capacitance outputs are left untouched.

Layout of the block (float64[CAP_SIZE]):
  CAP_ON: 1 = capacitance submodel on; 0 = off: nothing else is read
  CAP_PRESSURE: where the film's permittivity is taken (PRESSURE_MAX, PRESSURE_MEAN)
  CAP_H_FLOOR: film floor of the parallel plates (m)
  CAP_BACKGROUND: background capacitance added to the balls' (F)
  CAP_OIL_GAP: oil-availability gap (m) outside the Hertz zones; 0 = the Hertz zones only (region 'hertz')
"""

import math

from bearing_fmu_common.jit import kernel
from bearing_fmu_common.layout import Layout

from .lubricant import dowson_higginson_density, permittivity_from_density
from .roots import illinois_update

EPSILON_0 = 8.8541878128e-12  # F/m, vacuum permittivity (CODATA 2018)

# the submodel's block (layout in the module docstring), with the codes of its CAP_PRESSURE
_CAP_SLOTS = Layout()
CAP_ON = _CAP_SLOTS.slot()
CAP_PRESSURE = _CAP_SLOTS.slot()
PRESSURE_MAX = 0  # eps_r evaluated at the Hertz maximum pressure (default, Farah)
PRESSURE_MEAN = 1  # eps_r evaluated at the mean Hertz pressure (2/3 p_max)
CAP_H_FLOOR = _CAP_SLOTS.slot()
CAP_BACKGROUND = _CAP_SLOTS.slot()
CAP_OIL_GAP = _CAP_SLOTS.slot()
CAP_SIZE = _CAP_SLOTS.size


@kernel
def contact_permittivity(K_cm, rho0, p_max, pressure_choice):
    """Relative permittivity (-) of the film at the Hertz maximum (or mean) pressure p_max (Pa)."""
    p = p_max if pressure_choice == PRESSURE_MAX else p_max * (2.0 / 3.0)
    return permittivity_from_density(K_cm, dowson_higginson_density(rho0, p))


@kernel
def contact_capacitance(eps_r, a, b, h_c, h_floor):
    """Parallel-plate capacitance (F) of one contact: eps_0 eps_r pi a b / max(h_c, h_floor).

    a, b: Hertz semi-axes (m); h_c: central film thickness (m). An open contact (a b = 0 or
    h_c = inf) gives 0. h_floor (m) bounds the capacitance when the film vanishes (rest, boundary
    regime), where the real contact turns resistive and the plate model loses meaning.
    """
    area = 3.141592653589793 * a * b
    if area <= 0.0:
        return 0.0
    h = h_c if h_c > h_floor else h_floor
    return EPSILON_0 * eps_r * area / h


@kernel
def lubricated_contact_capacitance(K_cm, rho0, p_max, pressure_choice, a, b, h_c, h_floor, E_red, h_oil):
    """Capacitance (F) of one loaded contact: the Hertz zone (eps_r at the contact pressure, contact_capacitance)
    plus, with h_oil > 0 (m, the oil-availability gap), the oil-filled gap around it (eps_r at ambient pressure,
    outside_hertz_capacitance). h_oil = 0: the Hertz zone alone (the outside term is not computed)."""
    eps = contact_permittivity(K_cm, rho0, p_max, pressure_choice)
    C = contact_capacitance(eps, a, b, h_c, h_floor)
    if h_oil > 0.0:
        eps_ambient = contact_permittivity(K_cm, rho0, 0.0, PRESSURE_MAX)
        C += outside_hertz_capacitance(eps_ambient, a, b, p_max, E_red, h_c, h_oil, h_floor)
    return C


@kernel
def ball_capacitance(C_inner, C_outer):
    """Capacitance (F) of one ball: inner and outer contacts in series; 0 if either contact is open."""
    if C_inner <= 0.0 or C_outer <= 0.0:
        return 0.0
    return C_inner * C_outer / (C_inner + C_outer)


@kernel
def bearing_capacitance(C_inner, C_outer, C_background):
    """Bearing capacitance (F): balls in parallel plus an optional background term (F, 0 by default)."""
    total = C_background
    for j in range(C_inner.shape[0]):
        total += ball_capacitance(C_inner[j], C_outer[j])
    return total


# Gauss-Legendre nodes and weights on [-1, 1], 8 points (the angular integral of a nearly circular ring the oil
# bound cuts, where the closed forms cancel)
_GL_X = (
    -0.9602898564975363,
    -0.7966664774136267,
    -0.5255324099163290,
    -0.1834346424956498,
    0.1834346424956498,
    0.5255324099163290,
    0.7966664774136267,
    0.9602898564975363,
)
_GL_W = (
    0.1012285362903763,
    0.2223810344533745,
    0.3137066458778873,
    0.3626837833783620,
    0.3626837833783620,
    0.3137066458778873,
    0.2223810344533745,
    0.1012285362903763,
)
OUTSIDE_NODES_PER_DECADE = 16  # geometric grid of the confocal coordinate T (-): 10**(1/16) = 1.155 per node
OUTSIDE_START = 1e-2  # first node of that grid, times the edge-layer scale T_e (-); trapezoid from 0 below
OUTSIDE_MAX_NODES = 600  # cap of that grid (9 decades at its finest, 37 at 16 a decade; the integral ends long before)


@kernel
def _gap_integrands(t, k2):
    """Integrands (1/m of the dimensionless gap integrals) at t: 1/((1+t^2) R), t^2/((1+t^2) R), 1/((k^2+t^2) R),
    t^2/((k^2+t^2) R), R = sqrt((k^2+t^2)(1+t^2))."""
    t2 = t * t
    R = math.sqrt((k2 + t2) * (1.0 + t2))
    f1 = 1.0 / ((1.0 + t2) * R)
    f2 = 1.0 / ((k2 + t2) * R)
    return f1, t2 * f1, f2, t2 * f2


@kernel
def _gap_coefficients(T0, q0, T, F0, k2, s):
    """(A, B) (m) at T, the four gap integrals int_0^T and their integrands at T (F0, q0: the integrals and
    integrands at T0 <= T; Simpson on [T0, T])."""
    qm = _gap_integrands(0.5 * (T0 + T), k2)
    q1 = _gap_integrands(T, k2)
    w = (T - T0) / 6.0
    F1 = F0[0] + w * (q0[0] + 4.0 * qm[0] + q1[0])
    G1 = F0[1] + w * (q0[1] + 4.0 * qm[1] + q1[1])
    F2 = F0[2] + w * (q0[2] + 4.0 * qm[2] + q1[2])
    G2 = F0[3] + w * (q0[3] + 4.0 * qm[3] + q1[3])
    return s * (T * T * F1 - G1), s * (T * T * F2 - G2), (F1, G1, F2, G2), q1


@kernel
def _bound_crossing(T0, q0, F0, m0, T1, m1, H, k2, s, last):
    """The T in [T0, T1] where m(T) = H, m = max(A, B) (last = 0: the first ring the oil bound cuts) or min(A, B)
    (last = 1: the last ring in the oil), m0 <= H <= m1 its values at the ends; Illinois regula falsi, 8
    iterations. Returns (T, A, B, gap integrals, integrands) at the final estimate."""
    lo, m_lo, hi, m_hi = T0, m0 - H, T1, m1 - H
    side = 0
    T = T1
    A = 0.0
    B = 0.0
    F = F0
    q = q0
    if m_lo >= 0.0 or T1 <= T0:  # the crossing is at T0 (a cell that starts on the bound)
        T = T0
        A, B, F, q = _gap_coefficients(T0, q0, T0, F0, k2, s)
        return T, A, B, F, q
    for _it in range(8):
        if m_hi == m_lo:
            break
        T = (lo * m_hi - hi * m_lo) / (m_hi - m_lo)
        A, B, F, q = _gap_coefficients(T0, q0, T, F0, k2, s)
        m = (min(A, B) if last else max(A, B)) - H
        lo, m_lo, hi, m_hi, side = illinois_update(T, m, lo, m_lo, hi, m_hi, side)
    return T, A, B, F, q


@kernel
def _ring_integrals(T, k, A, B, h0, H):
    """Angular integrals (-, over theta in [0, pi/2]) of the ring of the confocal coordinate T whose gap is
    h0 + A cos^2 theta + B sin^2 theta (m): (sum of dA-weight / h, sum of h0 dA-weight / h^2), over the angles
    where the gap increase A cos^2 + B sin^2 stays within H (m); 1/m and 1/m times h0/h. A ring wholly in the
    oil has closed forms; a ring the bound cuts is integrated over its oil-filled angles.

    The area element of the ring is b^2 T (P cos^2 theta + sin^2 theta / P) dT dtheta, P = sqrt((k^2+T^2)/(1+T^2));
    with tan theta = sqrt(alpha/beta) tan phi (alpha = h0 + A, beta = h0 + B) the 1/h factor becomes uniform
    in phi: closed forms in theta and phi, or, where alpha and beta are within 1 % (the closed forms cancel), an
    8-point Gauss rule in phi on the smooth rest.
    """
    if A > H and B > H:
        return 0.0, 0.0
    P = math.sqrt((k * k + T * T) / (1.0 + T * T))
    alpha = h0 + A
    beta = h0 + B
    if A <= H and B <= H:  # the whole ring: closed forms, int_0^(pi/2) cos^2 / (alpha cos^2 + beta sin^2) =
        # pi / (2 sqrt(alpha) (sqrt(alpha) + sqrt(beta))), and sin^2 with alpha, beta swapped
        ra = math.sqrt(alpha)
        rb = math.sqrt(beta)
        i1 = 0.5 * math.pi * (P * rb + ra / P) / ((ra + rb) * ra * rb)
        i2 = 0.25 * math.pi * h0 * (P * beta + alpha / P) / (alpha * beta * ra * rb)
        return i1, i2
    t_lo = 0.0  # theta range
    t_hi = 0.5 * math.pi
    if A > H:  # the x direction leaves the oil first: theta in [theta_c, pi/2]
        t_lo = math.acos(math.sqrt((H - B) / (A - B)))
    elif B > H:  # the y direction does: theta in [0, theta_c]
        t_hi = math.acos(math.sqrt((B - H) / (B - A)))
    kappa = math.sqrt(alpha / beta)
    p_lo = math.atan(math.tan(t_lo) / kappa)
    p_hi = 0.5 * math.pi if t_hi >= 0.5 * math.pi else math.atan(math.tan(t_hi) / kappa)
    root = math.sqrt(alpha * beta)
    if abs(alpha - beta) > 1e-2 * (alpha + beta):
        # closed forms: with D = alpha cos^2 + beta sin^2, cos^2 = (D - beta)/(alpha - beta), so the integrand is
        # (P - 1/P)/(alpha - beta) + (alpha/P - P beta)/((alpha - beta) D); int dtheta/D = phi/sqrt(alpha beta),
        # int dtheta/D^2 = int (beta cos^2 phi + alpha sin^2 phi) dphi / (alpha beta)^1.5
        u = (P - 1.0 / P) / (alpha - beta)
        v = (alpha / P - P * beta) / (alpha - beta)
        d_phi = p_hi - p_lo
        i_D = d_phi / root
        i_D2 = (
            0.5 * (alpha + beta) * d_phi + 0.25 * (beta - alpha) * (math.sin(2.0 * p_hi) - math.sin(2.0 * p_lo))
        ) / (alpha * beta * root)
        return u * (t_hi - t_lo) + v * i_D, h0 * (u * i_D + v * i_D2)
    # alpha close to beta (a nearly circular ring): the closed forms cancel; Gauss in phi
    half = 0.5 * (p_hi - p_lo)
    mid = 0.5 * (p_hi + p_lo)
    s1 = 0.0
    s2 = 0.0
    for n in range(8):
        phi = mid + half * _GL_X[n]
        c2 = math.cos(phi) ** 2
        s2_ = 1.0 - c2
        num = P * beta * c2 + alpha * s2_ / P
        D = beta * c2 + alpha * s2_
        s1 += _GL_W[n] * num / D
        s2 += _GL_W[n] * num
    return half * s1 / root, half * s2 * h0 / (alpha * beta * root)


@kernel
def outside_hertz_capacitance(eps_r, a, b, p_max, E_red, h_c, h_oil, h_floor):
    """Capacitance (F) of the lubricated gap around one contact, outside its Hertz ellipse.

    eps_r: relative permittivity (-) of the oil at ambient pressure; a, b: Hertz semi-axes along y and x (m);
    p_max: Hertz maximum pressure (Pa); E_red: reduced modulus E' (Pa, Hamrock's, 2/E' = sum (1-nu^2)/E);
    h_c: central film thickness (m), bounded below by h_floor (m) as in contact_capacitance; h_oil: the
    oil-availability gap (m), the gap at which the oil around the contact ends (meniscus). 0 for an open
    contact or h_oil <= h_c.

    Gap: h = h_c + g, g the separation of the two Hertz-loaded surfaces (Johnson 1985, section 3.4), in the
    confocal coordinates x = sqrt(b^2 + lam) cos theta, y = sqrt(a^2 + lam) sin theta, lam = b^2 T^2:
      g = A(T) cos^2 theta + B(T) sin^2 theta,
      A = s int_0^T (T^2 - t^2) / ((1 + t^2) R(t)) dt,  B = s int_0^T (T^2 - t^2) / ((k^2 + t^2) R(t)) dt,
      s = 2 p_max a / E', k = a/b, R = sqrt((k^2 + t^2)(1 + t^2)).
    Inlet half (x < 0): oil, eps_0 eps_r / h. Outlet half (x > 0): cavitated; the oil leaving the contact (a
    layer h_c thick, mass conservation) bridges the gap in streamers, a fraction h_c/h of it, air (eps = 1) in
    between: eps_0 (1 + (eps_r - 1) h_c/h) / h. Both up to g = h_oil - h_c:
      C = eps_0 [ (eps_r + 1)/2 I_1 + (eps_r - 1)/2 I_2 ],  I_1 = int dA/h,  I_2 = int h_c dA/h^2.
    Quadrature: T on a geometric grid (OUTSIDE_NODES_PER_DECADE, twice finer for k < 1 or a thin oil ring
    h_oil - h_c < 10 h_c, four times for both) from OUTSIDE_START of the edge-layer scale to
    where the whole ring is out of the oil, trapezoid in T, Simpson per cell for A and B; the angle in closed form
    (8-point Gauss for a ring the bound cuts whose alpha, beta are within 1 %). About 60-80 rings a contact.
    """
    if a <= 0.0 or b <= 0.0 or p_max <= 0.0 or math.isinf(h_c):
        return 0.0
    h0 = h_c if h_c > h_floor else h_floor
    H = h_oil - h0
    if H <= 0.0:
        return 0.0
    s = 2.0 * p_max * a / E_red
    k = a / b
    k2 = k * k
    # near the ellipse A ~ (2/3) s T^3 / k: the ring where g reaches h0 sits near T_e
    T_e = (1.5 * k * h0 / s) ** (1.0 / 3.0)
    if T_e > 1.0:
        T_e = 1.0
    # twice finer for a contact elongated along x (k < 1: not a ball on a race) and for a thin oil ring (H < 10 h0:
    # the edge layer, where 1/h turns from 1/h0 to its decay, is then all of the integral); few rings either way
    per_decade = OUTSIDE_NODES_PER_DECADE
    if k < 1.0:
        per_decade *= 2
    if H < 10.0 * h0:
        per_decade *= 2
    ratio = 10.0 ** (1.0 / per_decade)
    T_prev = 0.0
    f1_prev = 0.0  # integrands (T x ring integrals) at T_prev
    f2_prev = 0.0
    F = (0.0, 0.0, 0.0, 0.0)  # int_0^T_prev of the four gap integrands
    q = _gap_integrands(0.0, k2)  # and the integrands at T_prev
    A_prev = 0.0  # gap coefficients at T_prev
    B_prev = 0.0
    i1 = 0.0
    i2 = 0.0
    T = OUTSIDE_START * T_e
    for _ in range(OUTSIDE_MAX_NODES):
        A, B, F_T, q_T = _gap_coefficients(T_prev, q, T, F, k2, s)
        if max(A_prev, B_prev) <= H < max(A, B):
            # the bound starts to cut the rings inside this cell: end the whole rings where max(A, B) = H (with the
            # ring just inside), and go on from there, so that the trapezoid does not straddle the kink
            T_a, A_a, B_a, F_a, q_a = _bound_crossing(T_prev, q, F, max(A_prev, B_prev), T, max(A, B), H, k2, s, 0)
            r1, r2 = _ring_integrals(T_a, k, A_a, B_a, h0, max(H, max(A_a, B_a)))
            i1 += 0.5 * (T_a - T_prev) * (f1_prev + T_a * r1)
            i2 += 0.5 * (T_a - T_prev) * (f2_prev + T_a * r2)
            T_prev, F, q, A_prev, B_prev = T_a, F_a, q_a, A_a, B_a
            f1_prev = T_a * r1
            f2_prev = T_a * r2
            A, B, F_T, q_T = _gap_coefficients(T_prev, q, T, F, k2, s)
        if min(A, B) >= H:
            # the last ring leaves the oil inside this cell: end the integral where min(A, B) = H, with the ring just
            # inside (for a circular contact the whole ring leaves at once)
            T_x, A_x, B_x, _F, _q = _bound_crossing(T_prev, q, F, min(A_prev, B_prev), T, min(A, B), H, k2, s, 1)
            r1, r2 = _ring_integrals(T_x, k, A_x, B_x, h0, max(H, min(A_x, B_x)))
            i1 += 0.5 * (T_x - T_prev) * (f1_prev + T_x * r1)
            i2 += 0.5 * (T_x - T_prev) * (f2_prev + T_x * r2)
            break
        r1, r2 = _ring_integrals(T, k, A, B, h0, H)
        i1 += 0.5 * (T - T_prev) * (f1_prev + T * r1)
        i2 += 0.5 * (T - T_prev) * (f2_prev + T * r2)
        T_prev = T
        f1_prev = T * r1
        f2_prev = T * r2
        A_prev = A
        B_prev = B
        F = F_T
        q = q_T
        T *= ratio
    scale = 4.0 * b * b  # four quadrants, area element b^2 T dT dtheta (P cos^2 + sin^2 / P)
    return EPSILON_0 * scale * (0.5 * (eps_r + 1.0) * i1 + 0.5 * (eps_r - 1.0) * i2)
