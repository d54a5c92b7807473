"""Twin of the quasi-static 5-DOF ball-bearing model (Jones 1960 / Harris & Kotzalas 2006, Advanced
Concepts ch. 3): plain Python + scipy, one function per equation group, written from the model
definition and nothing else.

Conventions (SI; outer ring fixed; inner-ring displacements d = (x, y, z, theta_x, theta_y)). In the
plane of ball j (azimuth psi_j = pi/2 + 2 pi j / Z from the x axis toward y: ball 0 on +y) the "1" direction is axial
(along z), the "2" direction radial (outward). All positions are taken from the outer groove-curvature
centre:
  A = (A1, A2): the inner groove-curvature centre,
      A1 = A1_0 + z + Rr_i (theta_x sin psi - theta_y cos psi),  A2 = A2_0 + x cos psi + y sin psi;
  X = (X1, X2): the ball centre (the two unknowns of the ball).
Outer contact: L_o = |X|, delta_o = L_o - r_o, (sin a_o, cos a_o) = X / L_o.
Inner contact: V = A - X, L_i = |V|, delta_i = L_i - r_i, (sin a_i, cos a_i) = V / L_i.
Q_k = K_k max(delta_k, 0)^1.5. The inner race pushes the ball along +V/L_i, the outer race along
-X/L_o.

Ball kinematics (race control, cage speed, ball spin), the centrifugal force F_c and the gyroscopic
moment M_g follow the definition literally (see the functions below). At omega = 0, or with both
inertial effects off, the ball equilibrium is solved in closed form (ball on the line of centres,
approaches split so that Q_i = Q_o); otherwise the two ball equations are solved with
scipy.optimize.root on the well-scaled polar unknowns (delta_o in um, a_o in mrad), which are a plain
change of variables for X = (r_o + delta_o)(sin a_o, cos a_o).

The bearing loads are displacement-controlled (bearing_loads); solve_loads inverts them with
scipy.optimize.root on (x, y, z) in um and (theta_x, theta_y) in mrad.

Choices where the definition is silent (each documented where it is made):
- beta = atan2(num, den) of the race-control tangent: beta and beta + pi give the same w_m, the same
  w_R sin(beta) product and hence the same M_g, so the branch is immaterial; atan2 only avoids 1/0.
- hybrid control with Q_o = 0 < Q_i: C = +inf (the limit of the formula, lam_o = 0, lam_i = 2,
  tan beta from the formula divided through by C); with Q_i = Q_o = 0: C = c_hyb.
- an unloaded ball (F_c == 0 and |A| <= r_i + r_o) is reported with Q = 0, F_c = M_g = 0, g = 0, the
  ball on the line of centres with the (negative) gap split as in the loaded closed form, and its
  kinematics evaluated at a_i = a_o = the direction of A.
- "F_c == 0" is read as "centrifugal is off or omega == 0" (F_c itself depends on the unknowns).
"""

import math

import numpy as np
from scipy.optimize import root

from tests.reference import ref_hertz

# ---------------------------------------------------------------------------------------------------
# tolerances of the nested solves
# ---------------------------------------------------------------------------------------------------
BALL_XTOL = 1e-14  # scipy 'hybr' relative step tolerance on (delta_o [um], a_o [mrad])
BALL_RTOL = 1e-10  # accepted ball residual, relative to the ball's largest load or the load floor per ball
LOAD_FLOOR = 1e-3  # N, shared by the Z balls: the scale of a ball whose own loads are the tiny centrifugal
# force of a low speed (its residual cannot fall below 1e-10 of those by rounding in its position alone)
BEARING_XTOL = 1e-13  # scipy 'hybr' relative step tolerance on (x, y, z [um], theta [mrad])
BEARING_RTOL = 1e-9  # accepted bearing residual, relative to the load scale
UM = 1e-6  # m per scaled length unit
MRAD = 1e-3  # rad per scaled angle unit


# ---------------------------------------------------------------------------------------------------
# geometry
# ---------------------------------------------------------------------------------------------------
def geometry(p):
    """Bearing geometry at zero displacement.

    A = (f_i + f_o - 1) D, r_i = (f_i - 0.5) D, r_o = (f_o - 0.5) D;
    alpha0 = arccos(1 - Pd / (2 A)) for Pd >= 0, else 0;
    A1_0 = A sin(alpha0) if angular else 0;  A2_0 = A - (Pd + dPd) / 2;
    Rr_i = dm/2 + (f_i - 0.5) D cos(alpha0);  psi_j = pi/2 + 2 pi j / Z;  gp = D / dm.
    """
    D, dm = p["D"], p["dm"]
    A = (p["f_i"] + p["f_o"] - 1.0) * D
    r_i = (p["f_i"] - 0.5) * D
    r_o = (p["f_o"] - 0.5) * D
    Pd = p["Pd"]
    alpha0 = math.acos(1.0 - Pd / (2.0 * A)) if Pd >= 0.0 else 0.0
    A1_0 = A * math.sin(alpha0) if p["angular"] else 0.0
    A2_0 = A - (Pd + p.get("dPd", 0.0)) / 2.0
    Rr_i = dm / 2.0 + (p["f_i"] - 0.5) * D * math.cos(alpha0)
    Z = int(p["Z"])
    psi = [math.pi / 2.0 + 2.0 * math.pi * j / Z for j in range(Z)]
    return dict(A=A, r_i=r_i, r_o=r_o, alpha0=alpha0, A1_0=A1_0, A2_0=A2_0, Rr_i=Rr_i, psi=psi, gp=D / dm, Z=Z)


def groove_centre_offset(d, psi, g):
    """(A1, A2) of the ball at azimuth psi for the inner-ring displacement d = (x, y, z, tx, ty)."""
    x, y, z, tx, ty = (float(v) for v in d)
    A1 = g["A1_0"] + z + g["Rr_i"] * (tx * math.sin(psi) - ty * math.cos(psi))
    A2 = g["A2_0"] + x * math.cos(psi) + y * math.sin(psi)
    return A1, A2


# ---------------------------------------------------------------------------------------------------
# contacts
# ---------------------------------------------------------------------------------------------------
def hertz_load(K, delta):
    """Q = K max(delta, 0)^1.5."""
    return K * max(delta, 0.0) ** 1.5


def contacts(X1, X2, A1, A2, p, g):
    """Both contacts of a ball at X = (X1, X2) with the inner groove centre at A = (A1, A2)."""
    L_o = math.hypot(X1, X2)
    delta_o = L_o - g["r_o"]
    a_o = math.atan2(X1 / L_o, X2 / L_o)
    V1, V2 = A1 - X1, A2 - X2
    L_i = math.hypot(V1, V2)
    delta_i = L_i - g["r_i"]
    a_i = math.atan2(V1 / L_i, V2 / L_i)
    return dict(
        delta_i=delta_i,
        delta_o=delta_o,
        a_i=a_i,
        a_o=a_o,
        Q_i=hertz_load(p["K_i"], delta_i),
        Q_o=hertz_load(p["K_o"], delta_o),
    )


# ---------------------------------------------------------------------------------------------------
# kinematics
# ---------------------------------------------------------------------------------------------------
def race_control(a_i, a_o, Q_i, Q_o, p, gp):
    """(beta, lam_i, lam_o) of the race-control hypothesis p['race'].

    outer:  tan beta = sin a_o / (cos a_o + gp);  lam_i = 0, lam_o = 2.
    inner:  tan beta = sin a_i / (cos a_i - gp);  lam_i = 2, lam_o = 0.
    hybrid: C = c_hyb (Q_i/Q_o)^(4/3); S = (1 + gp cos a_o)/(1 - gp cos a_i);
            Ah = gp C [cos(a_i - a_o) - S];
            tan beta = (C (S+1) sin a_i + 2 sin a_o) / (C (S+1) cos a_i + 2 (cos a_o + gp) + Ah);
            lam_o = 2/(1+C), lam_i = 2C/(1+C).
    The sensitivity readings keep the hybrid beta and share the moment otherwise:
    hybrid_outer lam_i = 0; hybrid_inner lam_i = 2; hybrid_equal lam_i = 1;
    hybrid_controlling lam_i = 2 if C > 1 else 0.
    """
    race = p["race"]
    if race == "outer":
        return math.atan2(math.sin(a_o), math.cos(a_o) + gp), 0.0, 2.0
    if race == "inner":
        return math.atan2(math.sin(a_i), math.cos(a_i) - gp), 2.0, 0.0
    if race not in ("hybrid", "hybrid_outer", "hybrid_inner", "hybrid_equal", "hybrid_controlling"):
        raise ValueError(f"unknown race control {race!r}")
    beta, C = hybrid_pitch_angle(a_i, a_o, Q_i, Q_o, p, gp)
    if race == "hybrid_outer":
        lam_i = 0.0
    elif race == "hybrid_inner":
        lam_i = 2.0
    elif race == "hybrid_equal":
        lam_i = 1.0
    elif race == "hybrid_controlling":
        lam_i = 2.0 if C > 1.0 else 0.0
    elif math.isinf(C):
        lam_i = 2.0
    else:
        lam_i = 2.0 * C / (1.0 + C)
    return beta, lam_i, 2.0 - lam_i


def hybrid_pitch_angle(a_i, a_o, Q_i, Q_o, p, gp):
    """(beta, C) of Rabreau's hybrid law (see race_control)."""
    S = (1.0 + gp * math.cos(a_o)) / (1.0 - gp * math.cos(a_i))
    if Q_o > 0.0:
        C = p["c_hyb"] * (Q_i / Q_o) ** (4.0 / 3.0)
    elif Q_i > 0.0:
        C = math.inf
    else:
        C = p["c_hyb"]
    if math.isinf(C):
        # the formula divided through by C, C -> inf
        num = (S + 1.0) * math.sin(a_i)
        den = (S + 1.0) * math.cos(a_i) + gp * (math.cos(a_i - a_o) - S)
        return math.atan2(num, den), C
    Ah = gp * C * (math.cos(a_i - a_o) - S)
    num = C * (S + 1.0) * math.sin(a_i) + 2.0 * math.sin(a_o)
    den = C * (S + 1.0) * math.cos(a_i) + 2.0 * (math.cos(a_o) + gp) + Ah
    return math.atan2(num, den), C


def cage_and_spin_speeds(a_i, a_o, beta, omega, gp):
    """(w_m, w_R): orbital (cage) speed and ball spin speed.

    w_m = omega (1 - gp cos a_i) cos(a_o - beta)
          / [ (1 + gp cos a_o) cos(a_i - beta) + (1 - gp cos a_i) cos(a_o - beta) ];
    w_R = - w_m (1 + gp cos a_o) / (gp cos(a_o - beta)).
    """
    ci, co = math.cos(a_i - beta), math.cos(a_o - beta)
    w_m = omega * (1.0 - gp * math.cos(a_i)) * co / ((1.0 + gp * math.cos(a_o)) * ci + (1.0 - gp * math.cos(a_i)) * co)
    w_R = -w_m * (1.0 + gp * math.cos(a_o)) / (gp * co)
    return w_m, w_R


def inertial_loads(w_m, w_R, beta, p):
    """(F_c, M_g): F_c = 0.5 m dm w_m^2 (if centrifugal), M_g = J w_R w_m sin(beta), J = m D^2/10
    (if gyroscopic)."""
    m = p["m_ball"]
    F_c = 0.5 * m * p["dm"] * w_m**2 if p["centrifugal"] else 0.0
    J = m * p["D"] ** 2 / 10.0
    M_g = J * w_R * w_m * math.sin(beta) if p["gyroscopic"] else 0.0
    return F_c, M_g


def kinematics(c, p, g):
    """Race control, speeds and inertial loads of a ball whose contacts are c (dict of contacts).

    The inner angle of the kinematics is a_i, or a_o for an open inner contact whose ball lies beyond the
    inner curvature centre (cos a_i <= 0, at a clearance of the order of the groove's), where the cage
    speed's denominator (1 + gp cos a_o) cos(a_i - beta) + n_o vanishes at a_i = pi."""
    a_k = c["a_o"] if c["Q_i"] <= 0.0 and math.cos(c["a_i"]) <= 0.0 else c["a_i"]
    beta, lam_i, lam_o = race_control(a_k, c["a_o"], c["Q_i"], c["Q_o"], p, g["gp"])
    w_m, w_R = cage_and_spin_speeds(a_k, c["a_o"], beta, p["omega"], g["gp"])
    F_c, M_g = inertial_loads(w_m, w_R, beta, p)
    return dict(beta=beta, lam_i=lam_i, lam_o=lam_o, w_m=w_m, w_R=w_R, F_c=F_c, M_g=M_g)


# ---------------------------------------------------------------------------------------------------
# ball equilibrium
# ---------------------------------------------------------------------------------------------------
def ball_equations(c, k, D):
    """The two ball equilibrium residuals (axial, radial), N:

    axial:  Q_i sin a_i - Q_o sin a_o + (M_g/D)(lam_o cos a_o - lam_i cos a_i)
    radial: Q_i cos a_i - Q_o cos a_o + F_c - (M_g/D)(lam_o sin a_o - lam_i sin a_i)
    """
    Q_i, Q_o, a_i, a_o = c["Q_i"], c["Q_o"], c["a_i"], c["a_o"]
    G = k["M_g"] / D
    axial = Q_i * math.sin(a_i) - Q_o * math.sin(a_o) + G * (k["lam_o"] * math.cos(a_o) - k["lam_i"] * math.cos(a_i))
    radial = (
        Q_i * math.cos(a_i)
        - Q_o * math.cos(a_o)
        + k["F_c"]
        - G * (k["lam_o"] * math.sin(a_o) - k["lam_i"] * math.sin(a_i))
    )
    return axial, radial


def ring_force(c, k, p):
    """(g_z, g_r, m_g) of the ball on the inner ring (the share of the applied load it balances):

    g_z = Q_i sin a_i - lam_i (M_g/D) cos a_i;  g_r = Q_i cos a_i + lam_i (M_g/D) sin a_i;
    m_g = lam_i f_i M_g.
    """
    G = k["M_g"] / p["D"]
    g_z = c["Q_i"] * math.sin(c["a_i"]) - k["lam_i"] * G * math.cos(c["a_i"])
    g_r = c["Q_i"] * math.cos(c["a_i"]) + k["lam_i"] * G * math.sin(c["a_i"])
    m_g = k["lam_i"] * p["f_i"] * k["M_g"]
    return g_z, g_r, m_g


def collinear_position(A1, A2, p, g):
    """Exact omega = 0 answer: X on the line of centres, the total approach |A| - r_i - r_o split so
    that K_i delta_i^1.5 = K_o delta_o^1.5, i.e. delta_o / delta_i = (K_i / K_o)^(2/3)."""
    L = math.hypot(A1, A2)
    total = L - g["r_i"] - g["r_o"]
    ratio = (p["K_i"] / p["K_o"]) ** (2.0 / 3.0)
    delta_o = total * ratio / (1.0 + ratio)
    L_o = g["r_o"] + delta_o
    return L_o * A1 / L, L_o * A2 / L


def inertia_active(p):
    """True when F_c or M_g can be non-zero: omega != 0 and at least one effect switched on."""
    return p["omega"] != 0.0 and (p["centrifugal"] or p["gyroscopic"])


def _state(X1, X2, A1, A2, p, g):
    """Every quantity of the ball with centre X: contacts, kinematics, residuals, ring force."""
    c = contacts(X1, X2, A1, A2, p, g)
    k = kinematics(c, p, g)
    axial, radial = ball_equations(c, k, p["D"])
    g_z, g_r, m_g = ring_force(c, k, p)
    return _ball_row(X1, X2, c, k, (k["F_c"], k["M_g"], g_z, g_r, m_g, axial, radial), True)


# a ball's row after its centre: contact, kinematics, then loads and residuals (ROW_LOADS)
ROW_CONTACT = ("Q_i", "Q_o", "a_i", "a_o", "delta_i", "delta_o")
ROW_KINEMATICS = ("beta", "lam_i", "lam_o", "w_m", "w_R")
ROW_LOADS = ("F_c", "M_g", "g_z", "g_r", "m_g", "res_axial", "res_radial")


def _ball_row(X1, X2, c, k, loads, loaded):
    """The row of a ball with centre X, contacts c and kinematics k; loads in the order of ROW_LOADS."""
    row = dict(X1=X1, X2=X2)
    row.update((n, c[n]) for n in ROW_CONTACT)
    row.update((n, k[n]) for n in ROW_KINEMATICS)
    row.update(zip(ROW_LOADS, loads, strict=True))
    row["loaded"] = loaded
    return row


def _unloaded_state(A1, A2, p, g):
    """Ball without contact: no load, no inertial load transmitted, kinematics at a = angle of A."""
    X1, X2 = collinear_position(A1, A2, p, g)
    a = math.atan2(A1, A2)
    c = dict(
        Q_i=0.0,
        Q_o=0.0,
        a_i=a,
        a_o=a,
        delta_i=math.hypot(A1 - X1, A2 - X2) - g["r_i"],
        delta_o=math.hypot(X1, X2) - g["r_o"],
    )
    k = kinematics(c, p, g)
    return _ball_row(X1, X2, c, k, (0.0,) * len(ROW_LOADS), False)


def _starting_points(A1, A2, p, g):
    """Starts of the ball solve, tried in turn: the collinear omega = 0 position with the outer
    approach raised, if needed, to carry the centrifugal force of the rigid-cage speed
    omega (1 - gp)/2 (a start on an almost open outer contact has a near-singular Jacobian); then
    the ball pressed on the outer race by that force alone at a_o = 0 (inner contact open)."""
    w_m = 0.5 * p["omega"] * (1.0 - g["gp"])
    F_c = 0.5 * p["m_ball"] * p["dm"] * w_m**2 if p["centrifugal"] else 0.0
    delta_c = (F_c / p["K_o"]) ** (2.0 / 3.0)
    starts = []
    if math.hypot(A1, A2) > g["r_i"] + g["r_o"]:
        X1, X2 = collinear_position(A1, A2, p, g)
        L_o = max(math.hypot(X1, X2), g["r_o"] + delta_c)
        a = math.atan2(X1, X2)
        starts.append((L_o * math.sin(a), L_o * math.cos(a)))
    if F_c > 0.0:
        starts.append((0.0, g["r_o"] + delta_c))
    return starts


def ball_state(A1, A2, p, guess=None, g=None):
    """Equilibrium of one ball for the inner groove centre at (A1, A2) (outer centre at the origin).

    Returns a dict with X1, X2, Q_i, Q_o, a_i, a_o, beta, w_m, w_R, F_c, M_g, g_z, g_r, m_g (plus
    delta_i, delta_o, lam_i, lam_o, the two residuals and 'loaded'). guess: optional (X1, X2) start
    (e.g. the previous solution); g: optional geometry(p) to avoid recomputing it.
    """
    g = geometry(p) if g is None else g
    inertia = inertia_active(p)
    if not (inertia and p["centrifugal"]) and math.hypot(A1, A2) <= g["r_i"] + g["r_o"]:
        return _unloaded_state(A1, A2, p, g)
    if not inertia:
        return _state(*collinear_position(A1, A2, p, g), A1, A2, p, g)

    # polar unknowns u = (delta_o / um, a_o / mrad): X = (r_o + delta_o)(sin a_o, cos a_o)
    def position(u):
        L_o = g["r_o"] + u[0] * UM
        return L_o * math.sin(u[1] * MRAD), L_o * math.cos(u[1] * MRAD)

    starts = ([] if guess is None else [tuple(guess)]) + _starting_points(A1, A2, p, g)
    best = None
    for X1g, X2g in starts:
        u0 = np.array([(math.hypot(X1g, X2g) - g["r_o"]) / UM, math.atan2(X1g, X2g) / MRAD])
        start = _state(X1g, X2g, A1, A2, p, g)
        scale = max(start["Q_i"], start["Q_o"], start["F_c"], 1e-3)

        def residual(u, scale=scale):
            s = _state(*position(u), A1, A2, p, g)
            return np.array([s["res_axial"], s["res_radial"]]) / scale

        for method, options in (("hybr", dict(xtol=BALL_XTOL)), ("lm", dict(xtol=BALL_XTOL, ftol=1e-15))):
            sol = root(residual, u0, method=method, options=options)
            s = _state(*position(sol.x), A1, A2, p, g)
            load = max(s["Q_i"], s["Q_o"], s["F_c"], LOAD_FLOOR / g["Z"])
            err = max(abs(s["res_axial"]), abs(s["res_radial"])) / load
            if best is None or err < best[0]:
                best = (err, s)
            if err <= BALL_RTOL:
                return s
    raise RuntimeError(f"ball equilibrium not reached (relative residual {best[0]:.3e}) at A = ({A1}, {A2})")


# ---------------------------------------------------------------------------------------------------
# bearing
# ---------------------------------------------------------------------------------------------------
def applied_loads(balls, psi, Rr_i):
    """(F_x, F_y, F_z, M_x, M_y) = sum_j [g_r cos psi, g_r sin psi, g_z,
    (Rr_i g_z + m_g) sin psi, -(Rr_i g_z + m_g) cos psi]."""
    F = np.zeros(5)
    for b, ps in zip(balls, psi):
        moment_arm_term = Rr_i * b["g_z"] + b["m_g"]
        F += [
            b["g_r"] * math.cos(ps),
            b["g_r"] * math.sin(ps),
            b["g_z"],
            moment_arm_term * math.sin(ps),
            -moment_arm_term * math.cos(ps),
        ]
    return F


def bearing_loads(d, p, guesses=None):
    """Displacement-controlled model: (F (5,), list of ball dicts) for the inner-ring displacement d.
    guesses: optional list of (X1, X2) starts per ball (e.g. the balls of a nearby solution)."""
    g = geometry(p)
    balls = []
    for j, ps in enumerate(g["psi"]):
        A1, A2 = groove_centre_offset(d, ps, g)
        guess = None if guesses is None else guesses[j]
        b = ball_state(A1, A2, p, guess=guess, g=g)
        b["A1"], b["A2"], b["psi"] = A1, A2, ps
        balls.append(b)
    return applied_loads(balls, g["psi"], g["Rr_i"]), balls


def _series_stiffness(p):
    """K of the inner and outer contacts in series (equal load): 1/K^(2/3) = 1/K_i^(2/3) + 1/K_o^(2/3)."""
    return (p["K_i"] ** (-2.0 / 3.0) + p["K_o"] ** (-2.0 / 3.0)) ** -1.5


def initial_displacement(F_applied, p):
    """A small displacement along the load: radial shift from a 5 Z-rule most-loaded ball, axial shift
    from Z equally loaded balls at the free contact angle (at least 5 deg), tilts from the moments on
    balls at the groove radius; plus the clearance to be taken up, so that some balls are loaded."""
    g = geometry(p)
    Z, K = g["Z"], _series_stiffness(p)
    Fx, Fy, Fz, Mx, My = (float(v) for v in F_applied)
    d0 = np.zeros(5)
    F_r = math.hypot(Fx, Fy)
    if F_r > 0.0:
        delta_r = (5.0 * F_r / (Z * K)) ** (2.0 / 3.0) + max(g["A"] - g["A2_0"], 0.0)
        d0[0], d0[1] = delta_r * Fx / F_r, delta_r * Fy / F_r
    if Fz != 0.0:
        alpha = max(g["alpha0"], math.radians(5.0))
        delta_a = (abs(Fz) / (Z * K * math.sin(alpha))) ** (2.0 / 3.0) / math.sin(alpha)
        if not p["angular"]:  # deep groove: the axial play sqrt(A^2 - A2_0^2) comes first
            delta_a += math.sqrt(max(g["A"] ** 2 - g["A2_0"] ** 2, 0.0))
        d0[2] = math.copysign(delta_a, Fz)
    M = math.hypot(Mx, My)
    if M > 0.0:
        alpha = max(g["alpha0"], math.radians(5.0))
        Q = 4.0 * M / (Z * g["Rr_i"] * math.sin(alpha))
        theta = ((Q / K) ** (2.0 / 3.0) / math.sin(alpha)) / g["Rr_i"]
        d0[3], d0[4] = theta * Mx / M, theta * My / M
    if not d0.any():
        d0[0] = 1e-9
    return d0


def _scales(F_applied, p):
    """(unknown scales, residual scales): um / mrad for d; N and N * Rr_i for the loads."""
    g = geometry(p)
    F = np.asarray(F_applied, dtype=float)
    F_ref = max(np.max(np.abs(F[:3])), np.max(np.abs(F[3:])) / g["Rr_i"], 1.0)
    d_scale = np.array([UM, UM, UM, MRAD, MRAD])
    f_scale = np.array([F_ref, F_ref, F_ref, F_ref * g["Rr_i"], F_ref * g["Rr_i"]])
    return d_scale, f_scale


def zero_load_position(p):
    """The ring's position at zero load when it is free in its clearance (docs/quasistatic.md section 3):
    the centre of the clearance, i.e. no radial shift, no tilt, and axially midway between the two
    shoulders' contacts, where the curvature centres of a ball line up radially: z = -A sin(alpha0) for
    an angular-contact bearing (its z = 0 is where the balls touch at alpha0), 0 for a deep-groove one."""
    return np.array([0.0, 0.0, -geometry(p)["A1_0"], 0.0, 0.0])


def solve_loads(F_applied, p, d0=None):
    """Inner-ring displacement d (5,) carrying F_applied = (F_x, F_y, F_z, M_x, M_y): scipy root
    ('hybr', then 'lm' if needed) on d in um / mrad, residual scaled by the load scale. Under zero load
    the root is searched from zero_load_position, which is the answer itself when no inner contact is
    loaded there (any position inside the clearance balances zero load; this one is documented)."""
    F_applied = np.asarray(F_applied, dtype=float)
    d_scale, f_scale = _scales(F_applied, p)
    if not F_applied.any():
        centre = zero_load_position(p)
        if all(b["Q_i"] == 0.0 for b in bearing_loads(centre, p)[1]):
            return centre
        d0 = centre
    start = initial_displacement(F_applied, p) if d0 is None else np.asarray(d0, dtype=float)

    def residual(u):
        return (bearing_loads(u * d_scale, p)[0] - F_applied) / f_scale

    best = None
    for method, options in (("hybr", dict(xtol=BEARING_XTOL)), ("lm", dict(xtol=BEARING_XTOL, ftol=1e-15))):
        sol = root(residual, start / d_scale, method=method, options=options)
        err = np.max(np.abs(residual(sol.x)))
        if best is None or err < best[0]:
            best = (err, sol.x * d_scale)
        if err <= BEARING_RTOL:
            return sol.x * d_scale
    raise RuntimeError(f"bearing equilibrium not reached (scaled residual {best[0]:.3e})")


def stiffness_fd(d, p, h=None):
    """5x5 central-difference stiffness K[i][j] = dF_i/dd_j at d.

    h: step, scalar or (5,); default 1e-9 m for x, y, z and 1e-8 rad for the tilts. Each perturbed
    state starts its ball solves from the balls of the unperturbed one.
    """
    d = np.asarray(d, dtype=float)
    h = np.array([1e-9, 1e-9, 1e-9, 1e-8, 1e-8]) if h is None else np.broadcast_to(np.asarray(h, float), (5,))
    _, balls = bearing_loads(d, p)
    guesses = [(b["X1"], b["X2"]) if b["loaded"] else None for b in balls]
    K = np.zeros((5, 5))
    for j in range(5):
        e = np.zeros(5)
        e[j] = h[j]
        F_plus = bearing_loads(d + e, p, guesses)[0]
        F_minus = bearing_loads(d - e, p, guesses)[0]
        K[:, j] = (F_plus - F_minus) / (2.0 * h[j])
    return K


# ---------------------------------------------------------------------------------------------------
# test bearings
# ---------------------------------------------------------------------------------------------------
E_RED_STEEL = 2.3077e11  # E' = E / (1 - nu^2), E = 210 GPa, nu = 0.3 (both bodies steel)
RHO_STEEL = 7850.0


def contact_radii(D, dm, f, inner):
    """(Rx, Ry) of a race contact: Rx = (D/2)(1 -+ D/dm) (inner -, outer +), Ry = f D / (2 f - 1)."""
    Rx = 0.5 * D * (1.0 - D / dm) if inner else 0.5 * D * (1.0 + D / dm)
    Ry = f * D / (2.0 * f - 1.0)
    return Rx, Ry


def hertz_constant(D, dm, f, inner, E_red=E_RED_STEEL):
    """K of Q = K delta^1.5 from the exact Hertz solution (tests/reference/ref_hertz)."""
    Rx, Ry = contact_radii(D, dm, f, inner)
    k, E, K = ref_hertz.hertz_coefficients_exact(Rx, Ry)
    return ref_hertz.hertz_stiffness(Rx, Ry, E_red, k, E, K)


def hybrid_coefficient(D, dm, f_i, f_o, E_red=E_RED_STEEL):
    """c_hyb = a_i E_i / (a_o E_o) at equal load (a: major semi-axis, E: elliptic integral);
    independent of the load since a ~ Q^(1/3) on both contacts."""
    out = []
    for f, inner in ((f_i, True), (f_o, False)):
        Rx, Ry = contact_radii(D, dm, f, inner)
        k, E, K = ref_hertz.hertz_coefficients_exact(Rx, Ry)
        a_y, b_x, _, _ = ref_hertz.hertz_contact(1.0, Rx, Ry, E_red, k, E, K)
        out.append(max(a_y, b_x) * E)
    return out[0] / out[1]


def make_params(
    Z,
    D,
    dm,
    f_i,
    f_o,
    Pd,
    angular,
    omega=0.0,
    race="outer",
    centrifugal=False,
    gyroscopic=False,
    c_hyb=None,
    dPd=0.0,
    rho=RHO_STEEL,
    E_red=E_RED_STEEL,
):
    """Parameter dict of the model, with K_i, K_o from Hertz, m_ball = rho pi D^3 / 6 and c_hyb
    (if None) from hybrid_coefficient."""
    return dict(
        Z=Z,
        D=D,
        dm=dm,
        f_i=f_i,
        f_o=f_o,
        Pd=Pd,
        dPd=dPd,
        angular=angular,
        K_i=hertz_constant(D, dm, f_i, True, E_red),
        K_o=hertz_constant(D, dm, f_o, False, E_red),
        m_ball=rho * math.pi * D**3 / 6.0,
        omega=omega,
        race=race,
        centrifugal=centrifugal,
        gyroscopic=gyroscopic,
        c_hyb=hybrid_coefficient(D, dm, f_i, f_o, E_red) if c_hyb is None else c_hyb,
    )


def params_6208(**overrides):
    """6208-like deep-groove test bearing: Z = 9, D = 12.7 mm, dm = 60.6 mm, f = 0.52, Pd = 0."""
    kw = dict(Z=9, D=12.7e-3, dm=60.6e-3, f_i=0.52, f_o=0.52, Pd=0.0, angular=False)
    kw.update(overrides)
    return make_params(**kw)


def params_b7214c(**overrides):
    """B7214C-like angular-contact test bearing: Z = 17, D = 15.875 mm, dm = 97.5 mm, f_i = 0.52,
    f_o = 0.53, Pd = 54.09 um (alpha0 ~ 15 deg)."""
    kw = dict(Z=17, D=15.875e-3, dm=97.5e-3, f_i=0.52, f_o=0.53, Pd=54.09e-6, angular=True)
    kw.update(overrides)
    return make_params(**kw)


# the kernels this module twins (tests/unit/test_every_kernel_has_a_twin.py); the twin's names follow
# the model's parts, not the kernel's
KERNEL_MODULE = "bearing_fmu.kernels.jones_harris"
TWINS = {
    "qs_geometry": geometry,
    "kinematics": kinematics,
    "hybrid_inner_share": race_control,
    "ball_equilibrium": ball_state,
    "ring_loads": bearing_loads,
    "bearing_loads": bearing_loads,
    "solve_quasistatic": solve_loads,
    "_free_ring_start": zero_load_position,
}
