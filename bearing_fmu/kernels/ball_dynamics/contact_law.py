"""Ball-race contact of the DEM: exact groove-torus geometry, Hertz normal law with C_n(Lambda) damping,
tangential force of the asperities (spring with a Coulomb limit) and of the film (EHL traction curve), and the
Houpert resistances as moments on the ball.

SI units. Guessasma & Machado (2018) and Farah et al. (2020) give the model: Kelvin-Voigt normal
contact with the Hertz elliptical stiffness, regime-dependent damping C_n(Lambda) and friction mu(Lambda),
Cundall-Strack tangential spring K_t in [2/3, 1] K_n with a Coulomb limit.

Geometry. A groove is a torus: its cross-section is a circle of radius f D whose centre runs on the
groove-curvature-centre circle (radius rho, on the ring's axis, at an axial position). The approach
of a ball of diameter D is delta = |s| - (f - 1/2) D, s the vector from the nearest point of that circle
to the ball centre; the contact normal is n = s/|s| (it points from the curvature centre through the
ball centre to the contact point, at the ball centre + (D/2) n). The same expression holds for the
inner and the outer groove (Harris & Kotzalas 2006, ch. 2; the quasi-static model of this package
uses it per ball in the ball's plane).

Tangential force. The papers' Cundall-Strack spring with a Coulomb cap mu(Lambda) F_n stores elastic energy
that a full EHL film does not: a film transmits a traction that depends on the sliding speed. So the spring is
kept for the share of the load that asperities carry (the boundary friction, 1 - phi with phi =
ehl.film_share(Lambda)), and the film's share phi transmits the EHL traction curve mu_lim (1 - exp(-SRR/s_0))
of the lubricant (ehl.film_traction_coefficient) along the sliding velocity. The override traction_limit > 0
keeps the spring alone, capped at the ramp from 0.1 at Lambda = 1 to that value in a full film (0.01: the
papers' mu(Lambda)).

Rolling resistances (Houpert, kernels.torque). The EHL rolling force F_R acts on both surfaces
(power 2 F_R u, Biboulet & Houpert 2010); hysteresis F_h and Heathcote sliding F_H dissipate F u
per contact, taken half on each surface. An offset pressure centre gives each body a moment, no net
force (the normal forces on ball and race stay on one line, so momentum is conserved): the ball
gets the moment (F_R + (F_h + F_H)/2)(D/2) opposing its rolling relative to the contact frame
(power F u_ball with u_ball = |omega_rel| D/2), and the pivoting moment M_s opposing its spin
relative to the race. The race's share acts on the prescribed inner ring or on the fixed outer ring
and only enters the dissipated power. Directions are regularised below the speed v_reg, or below the
angular speed at which the regularised (viscous) moment would exceed I/(4 dt), whichever is larger.
"""

import math

from bearing_fmu_common.jit import kernel

from ..ehl import REGIME_BOUNDARY


# Every function here takes and returns scalars only: the step (integrator.verlet_step) reads
# the state arrays and writes the results. A numba function that receives arrays increments and decrements
# their reference counts at each call (atomic operations, ~2.5 ns per array), which cost more than the
# contact's arithmetic when paid 18 times per step.
@kernel(inline="always")
def groove_approach(px, py, pz, cx, cy, cz, ax, ay, az, rho, rg):
    """Approach and normal of a ball at (px, py, pz) (m) in a groove whose curvature-centre circle has
    centre (cx, cy, cz) (m), lies in the plane normal to the unit vector (ax, ay, az) (the ring's axis: z for
    the outer ring, tilted with the inner one) and has radius rho (m); rg = (f - 1/2) D (m).

    Returns (delta, nx, ny, nz): approach (m, > 0 in contact) and the unit normal from the
    curvature centre to the ball centre. A ball on the axis or on the circle itself has no defined
    normal and is reported open (delta = -1), which no bearing geometry reaches.
    """
    dx = px - cx
    dy = py - cy
    dz = pz - cz
    if ax == 0.0 and ay == 0.0 and az == 1.0:
        # the circle's axis is z (the outer race; the inner one of an untilted ring): h and e below are dz and (dx,
        # dy, 0) exactly, so this gives the same result to the bit with a shorter chain of operations to the root
        h = dz
        ex = dx
        ey = dy
        ez = 0.0
        r = math.sqrt(dx * dx + dy * dy)
    else:
        h = dx * ax + dy * ay + dz * az  # along the axis
        ex = dx - h * ax  # in the circle's plane, toward the nearest point of the circle
        ey = dy - h * ay
        ez = dz - h * az
        r = math.sqrt(ex * ex + ey * ey + ez * ez)
    if r == 0.0:
        return -1.0, 0.0, 0.0, 0.0
    # s = e (r - rho)/r + h a: |s| = sqrt((r - rho)^2 + h^2), and n = s/|s| needs only 1/(r |s|) (one division
    # instead of rho/r and 1/|s|)
    radial = r - rho
    dist = math.sqrt(radial * radial + h * h)
    if dist == 0.0:
        return -1.0, 0.0, 0.0, 0.0
    inv = 1.0 / (r * dist)
    hr = h * r * inv
    return dist - rg, ex * radial * inv + ax * hr, ey * radial * inv + ay * hr, ez * radial * inv + az * hr


@kernel(inline="always")
def contact_damping(regime, c_frozen, alpha_e, Q):
    """Normal damping (N.s/m): the boundary law C_hyst = 1.5 alpha_e Q follows the instantaneous load Q (N)
    (it is proportional to it, kernels.ehl.normal_damping); the mixed and full-film values are those of
    the last tribology refresh, c_frozen (N.s/m)."""
    if regime == REGIME_BOUNDARY:
        return 1.5 * alpha_e * Q
    return c_frozen


@kernel(inline="always")
def tangential_spring(ox, oy, oz, nx, ny, nz, vtx, vty, vtz, dt, kt, f_limit):
    """Advance the tangential spring of one contact and return its force on the ball.

    The spring (ox, oy, oz) (m) is projected on the current tangent plane (normal n), lengthened by the
    tangential relative velocity v_t (m/s) times dt (s), and turned into F_t = -kt * spring (kt in N/m).
    Beyond the Coulomb limit f_limit = mu F_n (N) the force is scaled back to the limit and the spring
    shortened to match (Cundall & Strack 1979). Returns (sx, sy, sz, ftx, fty, ftz, slipping, reversed):
    the new spring (m), the force (N), and reversed = True when a slipping spring points against its
    previous direction (a sign of chatter).
    """
    on = ox * nx + oy * ny + oz * nz
    ox -= on * nx
    oy -= on * ny
    oz -= on * nz
    sx = ox + vtx * dt
    sy = oy + vty * dt
    sz = oz + vtz * dt
    fx = -kt * sx
    fy = -kt * sy
    fz = -kt * sz
    f2 = fx * fx + fy * fy + fz * fz
    slipping = f2 > f_limit * f_limit
    reversed_ = False
    if slipping:
        scale = f_limit / math.sqrt(f2)
        fx *= scale
        fy *= scale
        fz *= scale
        sx *= scale  # the spring that carries the capped force, -F/kt (no division)
        sy *= scale
        sz *= scale
        reversed_ = sx * ox + sy * oy + sz * oz < 0.0
    return sx, sy, sz, fx, fy, fz, slipping, reversed_


@kernel(inline="always")
def contact_slip(race, p, v, w, rc, n, frame):
    """(vn, vtx, vty, vtz, wrx, wry, wrz): the approach speed vn (m/s, > 0 approaching) and the tangential slip
    velocity v_t (m/s) of the ball's surface over the race's at the contact point rc (m, from the ball's centre
    p, m) with unit normal n, and the race's angular velocity W (rad/s). v, w: the ball's velocity (m/s) and
    angular velocity (rad/s); frame as ball_race_contact's (race 0 inner: translating, turning at omega about its
    axis and tilting; 1 outer: fixed)."""
    px, py, pz = p
    vx, vy, vz = v
    wx, wy, wz = w
    rcx, rcy, rcz = rc
    nx, ny, nz = n
    omega, vrx0, vry0, vrz0, cx, cy, cz, _, ax, ay, az, wtx, wty = frame
    vbx = vx + wy * rcz - wz * rcy
    vby = vy + wz * rcx - wx * rcz
    vbz = vz + wx * rcy - wy * rcx
    if race == 0:
        # inner-race surface: ring translation + its angular velocity W = omega a + tilt rates, about its centre
        wrx = omega * ax + wtx
        wry = omega * ay + wty
        wrz = omega * az
        lx = px + rcx - cx
        ly = py + rcy - cy
        lz = pz + rcz - cz
        vrx = vrx0 + wry * lz - wrz * ly
        vry = vry0 + wrz * lx - wrx * lz
        vrz = vrz0 + wrx * ly - wry * lx
    else:
        vrx = 0.0
        vry = 0.0
        vrz = 0.0
        wrx = 0.0
        wry = 0.0
        wrz = 0.0
    ux = vbx - vrx
    uy = vby - vry
    uz = vbz - vrz
    vn = ux * nx + uy * ny + uz * nz  # > 0: approaching
    return vn, ux - vn * nx, uy - vn * ny, uz - vn * nz, wrx, wry, wrz


@kernel(inline="always")
def film_traction(ft, dissipating, vt, film_force, slip, kappa):
    """(ftx, fty, ftz, dtx, dty, dtz): the tangential force ft and its dissipating part (N, on the ball) with the
    film's traction of the slip velocity vt (m/s) added, linearly implicit in the slip (unchanged without film force
    or slip). film_force: the plateau phi mu_lim F_n (N); slip = 1/v_s (s/m); kappa = 7 dt / m (s/kg).

    Linearly implicit: F = F(v) / (1 + kappa dF/dv), kappa the slip a force at the surface of a solid sphere removes
    per newton in a step (3.5 dt / m) for both contacts of the ball. Where the curve is steep (low speed, dF/dv dt
    >> m) the film stops at most half the slip in a step (no overshoot, no chatter) and holds what rolling needs, as
    a stick; elsewhere F = F(v)."""
    ftx, fty, ftz = ft
    dtx, dty, dtz = dissipating
    vtx, vty, vtz = vt
    if film_force > 0.0:
        v = math.sqrt(vtx * vtx + vty * vty + vtz * vtz)
        if v > 0.0:
            g = math.exp(-v * slip)  # 1 - g rather than expm1 (twice as fast): its error, 1e-16 film_force, is no force
            scale = film_force * (1.0 - g) / ((1.0 + kappa * film_force * slip * g) * v)  # F(v) / v, one division
            ftx -= scale * vtx
            fty -= scale * vty
            ftz -= scale * vtz
            dtx -= scale * vtx
            dty -= scale * vty
            dtz -= scale * vtz
    return ftx, fty, ftz, dtx, dty, dtz


@kernel(inline="always")
def resistance_moments(m, w, w_orbit, n, w_race, f_roll_surface, m_s, half_d, w_reg, rate_inv):
    """m = (mx, my, mz) (N.m) plus the Houpert resistances' moments on the ball: the rolling resistance
    f_roll_surface (D/2) against its rolling relative to the contact frame (which turns with the ball's orbit,
    w_orbit about z, rad/s) and the pivoting moment m_s against its spin relative to the race (angular velocity
    w_race). w: the ball's angular velocity (rad/s); n: the contact's unit normal.

    Below the regularisation speed w_reg (rad/s) a resistance acts as a viscous damper M/w_reg; its rate is kept
    within a quarter of I/dt (rate_inv = 4 dt / I) so that the explicit step cannot overshoot (with four resistances
    on the ball their sum stays below I/dt: no sign reversal, no chatter)."""
    mx, my, mz = m
    wx, wy, wz = w
    nx, ny, nz = n
    wrx, wry, wrz = w_race
    qx = wx
    qy = wy
    qz = wz - w_orbit
    qn = qx * nx + qy * ny + qz * nz
    qx -= qn * nx
    qy -= qn * ny
    qz -= qn * nz
    q = math.sqrt(qx * qx + qy * qy + qz * qz)
    f_roll = f_roll_surface * half_d
    m_roll = f_roll / max(q, w_reg, f_roll * rate_inv)
    spin = (wx - wrx) * nx + (wy - wry) * ny + (wz - wrz) * nz
    m_spin = m_s / max(abs(spin), w_reg, m_s * rate_inv)
    mx = mx - m_roll * qx - m_spin * spin * nx
    my = my - m_roll * qy - m_spin * spin * ny
    mz = mz - m_roll * qz - m_spin * spin * nz
    return mx, my, mz


@kernel(inline="always")
def ball_race_contact(race, geometry, ball, spring, refreshed, film, frame, steps):
    """Forces of the contact of a ball with one race.

    geometry = (delta, nx, ny, nz): the contact's approach (m) and unit normal, groove_approach of the ball's centre.
    Why the caller evaluates it for all the balls of a race first: it is a chain of two square roots and a division,
    each waiting for the one before; in a loop of its own the chains of different balls are independent and the
    processor overlaps them, where inside the contact law they would run one after another (the step's ball-race
    contacts took a sixth less time).

    race 0 inner (turning at omega about its axis a through its centre c, tilting at (wtx, wty) about x and y,
    translating at (vrx0, vry0, vrz0)), 1 outer (fixed).
    ball = (p, v, w, w_orbit): the ball's centre p = (px, py, pz) (m), predicted velocity v = (vx, vy, vz) (m/s)
    and angular velocity w = (wx, wy, wz) (rad/s), orbital speed w_orbit (rad/s).
    spring = (ox, oy, oz): the contact's tangential spring (m).
    refreshed = (mu (-), regime code, c_frozen (N.s/m), f_roll_surface = F_R + (F_h + F_H)/2 (N), m_s (N.m)): the
    last tribology refresh's friction coefficient, regime, normal damping, rolling resistance and pivoting moment.
    film = (phi (-), slip = 1/v_s (s/m), mu_lim (-), kappa (s/kg)): the film's share of the tangential force, its
    traction curve mu_lim (1 - exp(-v_t / v_s)) (ehl.film_slip_speed) and the slip a newton removes from the ball's
    two contacts in a step (7 dt / m), for the curve's implicit evaluation.
    frame = (omega (rad/s), vrx0, vry0, vrz0 (m/s), cx, cy, cz (m), K_h (N/m^1.5), ax, ay, az (-), wtx, wty (rad/s)):
    the race's motion, the centre c of its groove's curvature-centre circle and its axis a, Hertz constant and tilt
    rates.
    steps = (half_d = D/2 (m), alpha_e (s/m), kt_ratio (-), rate_inv = 4 dt / I (1/(N.m.s)), the inverse of the
    largest viscous rate of a regularised moment, w_reg = v_reg / (D/2) (rad/s), dt (s)).
    The groups are tuples: inlined into the step, they cost nothing over separate arguments.

    Returns (delta, fx, fy, fz, mx, my, mz, sx, sy, sz, slipping, reversed, power, dtx, dty, dtz, rcx, rcy, rcz):
    approach (m, <= 0 open: everything else 0, spring reset), force (N) and moment (N.m) on the ball, the new spring
    (m), the spring's slip and reversal flags, the power (W) dissipated in the contact itself at the predicted
    velocities (normal damping, tangential slip; the Houpert part is booked per step by the integrator), the
    tangential force on the ball that dissipates (N: a slipping spring's and the film's traction) and the contact
    point from the ball's centre (m): with them the integrator books the slip's power at the velocities the step
    ends with (integrator.verlet_step says why).
    """
    half_d, alpha_e, kt_ratio, rate_inv, w_reg, dt = steps
    delta, nx, ny, nz = geometry
    p, v, w, w_orbit = ball
    ox, oy, oz = spring
    mu, regime, c_frozen, f_roll_surface, m_s = refreshed
    if delta <= 0.0:  # open: the spring and the chatter count start again at the next touch
        return delta, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, False, False, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0
    K_h = frame[7]
    root = math.sqrt(delta)
    Q = K_h * delta * root
    # contact point relative to the ball centre and the surfaces' relative velocity there
    rcx = half_d * nx
    rcy = half_d * ny
    rcz = half_d * nz
    vn, vtx, vty, vtz, wrx, wry, wrz = contact_slip(race, p, v, w, (rcx, rcy, rcz), (nx, ny, nz), frame)
    c_n = contact_damping(regime, c_frozen, alpha_e, Q)
    F_n = Q + c_n * vn
    if F_n < 0.0:  # a damper cannot pull the surfaces together
        F_n = 0.0
    phi, slip, mu_lim, kappa = film
    # tangential force: where asperities carry load (share 1 - phi) an elastic stick, the Cundall-Strack spring
    # capped at the boundary friction; the film (share phi) has no elastic stick, it transmits the EHL traction
    # of the sliding speed (ehl.film_traction_coefficient): a damper at small slip, the limiting traction beyond
    film_force = phi * mu_lim * F_n  # plateau of the film's traction (N)
    if phi < 1.0:
        kt = kt_ratio * K_h * root
        sx, sy, sz, ftx, fty, ftz, slipping, reversed_ = tangential_spring(
            ox, oy, oz, nx, ny, nz, vtx, vty, vtz, dt, kt, max(mu * F_n - film_force, 0.0)
        )
    else:
        sx, sy, sz, ftx, fty, ftz, slipping, reversed_ = 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, False, False
    power = c_n * vn * vn if F_n > 0.0 else 0.0
    # the tangential forces that dissipate: a slipping spring's and the film's traction (a sticking spring stores)
    dtx, dty, dtz = (ftx, fty, ftz) if slipping else (0.0, 0.0, 0.0)
    ftx, fty, ftz, dtx, dty, dtz = film_traction(
        (ftx, fty, ftz), (dtx, dty, dtz), (vtx, vty, vtz), film_force, slip, kappa
    )
    power -= dtx * vtx + dty * vty + dtz * vtz
    # force on the ball: normal push back towards the curvature centre, tangential traction
    fx = -F_n * nx + ftx
    fy = -F_n * ny + fty
    fz = -F_n * nz + ftz
    mx, my, mz = resistance_moments(
        (rcy * ftz - rcz * fty, rcz * ftx - rcx * ftz, rcx * fty - rcy * ftx),
        w,
        w_orbit,
        (nx, ny, nz),
        (wrx, wry, wrz),
        f_roll_surface,
        m_s,
        half_d,
        w_reg,
        rate_inv,
    )
    return delta, fx, fy, fz, mx, my, mz, sx, sy, sz, slipping, reversed_, power, dtx, dty, dtz, rcx, rcy, rcz
