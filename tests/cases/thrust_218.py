"""Quasi-static fidelity against the textbook thrust-load case of the 218 angular-contact ball bearing.

Case: Hamrock & Dowson, *Ball Bearing Mechanics*, NASA TM-81691 (1981), ch. 3 (section "Thrust load"); Hamrock &
Anderson, *Rolling-Element Bearings*, NASA RP-1105 (1983), static load distribution, thrust load; the same case over
a range of thrust loads in Ricci, Math. Probl. Eng. 2009, 471804. Bearing: D = 22.23 mm, d_e = 125.3 mm, Z = 16,
f_i = f_o = 0.5232, free contact angle beta_f = 40 deg, steel E = 2.075e11 Pa, nu = 0.3
(tests/validation/data/angular_218_textbook.toml).

What is compared. The sources solve a centred thrust load with the closed form of their thrust-load section (every
ball alike, no centrifugal force or gyroscopic moment, the ball on the line of the groove centres):
    F_a = Z K_n (B d)^1.5 sin(beta) (cos(beta_f)/cos(beta) - 1)^1.5       (contact angle beta, by iteration)
    Q = F_a / (Z sin(beta))                                              (ball load)
    delta_a = (B d + delta_n) sin(beta) - B d sin(beta_f) = B d sin(beta - beta_f)/cos(beta)   (axial deflection)
with B d = (f_i + f_o - 1) D the distance of the groove centres and K_n the load-deflection constant of the two
contacts in series (1/K_n^(2/3) = 1/K_i^(2/3) + 1/K_o^(2/3)). The axial stiffness is the derivative of that curve,
dF_a/d(delta_a), formed analytically through beta. This module solves the closed form itself (scipy brentq, to
1e-15 rad: the reference's uncertainty), with the Hertz constants of the plain-Python twin
tests/reference/ref_hertz.py at the free contact angle (Harris' practice, which the model follows,
docs/quasistatic.md section 1), exact or Hamrock-Brewe like the scene. Nothing of the model under test enters the
expected values. The sources' printed results could not be read here (docs/decisions.md, unverified sources).

Tolerance: both sides solve the same equations; ours in five DOF with two unknowns per ball, the reference in one
unknown. The model's load tolerance is 1e-12 of the load (scene below), brentq's xtol 1e-15 rad; what is left is
rounding. The bounds, 1e-13 rad on the angles and 1e-12 relative on the rest, are ten orders below any physical
effect (a 1 % change of E moves the deflection by 0.7 %).
"""

import math

from scipy.optimize import brentq

from bearing_fmu.models.quasi_static import QuasiStaticModel
from bearing_fmu.scene import Scene
from tests.reference import ref_hertz

from .comparison import DATA, Comparison, ReferenceCase

BEARING = DATA / "angular_218_textbook.toml"
D, D_E, Z, F_CONF = 22.23e-3, 125.3e-3, 16, 0.5232  # m, m, -, - (the case as quoted in the module docstring)
BETA_F = math.radians(40.0)
E, NU = 2.075e11, 0.3  # Pa, -
LBF = 4.4482216152605  # N
THRUST_LOADS = [500.0 * LBF, 1000.0 * LBF, 2000.0 * LBF, 4000.0 * LBF, 8000.0 * LBF]  # N; 4000 lbf = 17.8 kN
ANGLE_TOL = 1e-13  # rad
REL_TOL = 1e-12
XTOL = 1e-15  # rad, the closed form's solve


def textbook_thrust(F_a, hertz):
    """(beta rad, Q N, delta_a m, dF_a/d delta_a N/m) of the sources' closed form for a centred thrust F_a (N)."""
    coefficients = ref_hertz.hertz_coefficients_exact if hertz == "exact" else ref_hertz.hertz_coefficients_approx
    E_red = ref_hertz.reduced_modulus(E, NU, E, NU)
    gamma = D * math.cos(BETA_F) / D_E
    R_y = F_CONF * D / (2.0 * F_CONF - 1.0)
    K_i, K_o = (
        ref_hertz.hertz_stiffness(R_x, R_y, E_red, *coefficients(R_x, R_y))
        for R_x in (0.5 * D * (1.0 - gamma), 0.5 * D * (1.0 + gamma))
    )
    K_n = ref_hertz.series_stiffness(K_i, K_o)
    Bd = (2.0 * F_CONF - 1.0) * D
    c = Z * K_n * Bd**1.5

    def load(beta):
        return c * math.sin(beta) * (math.cos(BETA_F) / math.cos(beta) - 1.0) ** 1.5

    beta = brentq(lambda b: load(b) - F_a, BETA_F, 0.5 * math.pi - 1e-9, xtol=XTOL, rtol=8.9e-16)
    u = math.cos(BETA_F) / math.cos(beta) - 1.0
    du = math.cos(BETA_F) * math.sin(beta) / math.cos(beta) ** 2
    dF = c * (math.cos(beta) * u**1.5 + 1.5 * math.sin(beta) * u**0.5 * du)
    d_delta = Bd * math.cos(BETA_F) / math.cos(beta) ** 2
    delta_a = Bd * math.sin(beta - BETA_F) / math.cos(beta)
    return beta, F_a / (Z * math.sin(beta)), delta_a, dF / d_delta


def model(hertz):
    """The quasi-static model at rest as the sources compute (no centrifugal force, no gyroscopic moment)."""
    off = dict(centrifugal=False, gyroscopic=False, torque=False, life=False)
    scene = Scene(name="worked_example", fidelity="quasi_static", stiffness=True, hertz=hertz, tolerance=1e-12, **off)
    return QuasiStaticModel(str(BEARING), "iso_vg68_mineral", scene)


def load_comparisons(qs, hertz, F_a):
    """Contact angles, ball loads, axial deflection (our z: zero where the balls touch at the free contact angle,
    docs/quasistatic.md section 1) and axial stiffness K[3,3] (the condensed analytic stiffness, not a difference
    quotient) against the closed form at the thrust F_a (N)."""
    beta, Q, delta_a, k_a = textbook_thrust(F_a, hertz)
    out = qs.evaluate(omega=0.0, F_z=F_a)
    u = XTOL / beta
    label = f"{hertz} Hertz, {F_a / LBF:g} lbf"
    return [
        Comparison(f"alpha_inner, {label}", out["alpha_inner"], beta, u, ANGLE_TOL / beta),
        Comparison(f"alpha_outer, {label}", out["alpha_outer"], beta, u, ANGLE_TOL / beta),
        Comparison(f"Q_max_inner, {label}", out["Q_max_inner"], Q, u, REL_TOL),
        Comparison(f"Q_max_outer, {label}", out["Q_max_outer"], Q, u, REL_TOL),
        Comparison(f"z, {label}", out["z"], delta_a, u, REL_TOL),
        Comparison(f"K[3,3], {label}", out["K[3,3]"], k_a, u, REL_TOL),
    ]


def compare(hertz_options=("exact", "approximate")):
    return [c for hertz in hertz_options for F_a in THRUST_LOADS for c in load_comparisons(model(hertz), hertz, F_a)]


def evaluation():
    qs = model("exact")
    loads = iter([THRUST_LOADS[2], 1.01 * THRUST_LOADS[2]] * 10**6)
    return lambda: qs.evaluate(omega=0.0, F_z=next(loads))


CASE = ReferenceCase(
    "thrust_218",
    "quasi-static",
    "218 under thrust: contact angle, ball load, deflection, K[3,3]",
    "Hamrock & Anderson, NASA RP-1105 (1983), thrust load; Hamrock & Dowson, NASA TM-81691 (1981) ch. 3",
    compare,
    evaluation,
)
