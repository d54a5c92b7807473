"""The 6208 of Guessasma & Machado (2018) and Farah et al. (2020), analytic and quasi-static fidelities.

Sources: Guessasma & Machado, Lubricants 6 (2018) 46 -- section 3.1 (ball speed 952.38 rad/s at 500 rad/s,
Lambda_out between 2.15 and 3), Fig. 11-12 and App. A (eps values, Q_max); Farah et al. (2020) App. A (eps at
5 kN). Operating point: omega = 500 rad/s, F_r = 3000 N, P_d = 0, the papers' oil (eta = 0.04 Pa.s,
xi = 2.3e-8 1/Pa, sigma = 1.25 x 0.3 um), Hamrock-Dowson film.
"""

from bearing_fmu.models.analytic import AnalyticModel
from bearing_fmu.models.quasi_static import QuasiStaticModel
from bearing_fmu.scene import Scene

from .comparison import Comparison, ReferenceCase, printed_comparison

OIL = "guessasma_oil"
T_OIL = 313.15  # K (the papers' oil has constant properties: any temperature gives the same result)
D = 12.6e-3  # m, ball diameter
EPS_TOL = 0.01  # the papers print 2-3 digits from a 9-ball DEM at 1 rad/s (test docstrings)
# (F_r N, P_d m, eps as printed): Guessasma App. A at 3 kN, Farah App. A at 5 kN
EPS_PUBLISHED = (
    (3000.0, -12.6e-6, "0.685"),
    (3000.0, 0.0, "0.5"),
    (3000.0, 12.6e-6, "0.40"),
    (5000.0, -0.0045 * D, "1.70"),
    (5000.0, 0.0, "0.5"),
    (5000.0, 0.0045 * D, "0.29"),
    (5000.0, -0.0035 * D, "1.32"),
)


def quasi_static_scene(**options):
    """The quasi-static scene of the literature cases (every effect on, tolerance 1e-12), with `options` changed."""
    base = dict(name="qs", fidelity="quasi_static", centrifugal=True, gyroscopic=True, torque=True, stiffness=True)
    return Scene(**{**base, "tolerance": 1e-12, **options})


def analytic_eps(F_r, Pd):
    """eps of the analytic model at rest."""
    return AnalyticModel("6208", OIL, Pd=Pd).evaluate(0.0, F_r, T_OIL)["epsilon"]


def quasi_static_eps(F_r, Pd):
    """eps = (1 - P_d/(2 delta_r))/2 from the solver's radial displacement delta_r = y at omega = 1e-3 rad/s
    (speed effects ~1e-12 of the loads; ball 1 on the load line, as in the papers)."""
    out = QuasiStaticModel("6208", OIL, quasi_static_scene(), Pd=Pd).evaluate(omega=1e-3, F_y=F_r, T_oil=T_OIL)
    return 0.5 * (1.0 - Pd / (2.0 * out["y"]))


def eps_comparisons(eps_of, published=EPS_PUBLISHED):
    """eps of eps_of(F_r, P_d) against the papers' values (rows of EPS_PUBLISHED), tolerance 1 %."""
    return [
        printed_comparison(f"eps at {F_r:g} N, P_d = {Pd * 1e6:+.1f} um", eps_of(F_r, Pd), printed, EPS_TOL)
        for F_r, Pd, printed in published
    ]


def q_max_comparisons():
    """Q_max = F_r / (Z J_r) = 1457 N at 3 kN, P_d = 0 (Guessasma Fig. 12b; J_r of Harris & Kotzalas 2006),
    printed to 4 digits: tolerance the rounding, +-0.5 N."""
    out = AnalyticModel("6208", OIL).evaluate(0.0, 3000.0, T_OIL)
    return [printed_comparison("Q_max inner at 3 kN", out["Q_max_inner"], "1457", 0.5 / 1457.0)]


def lambda_comparisons():
    """Lambda_out at psi = 0 within the paper's band 2.12-2.15 at 500 rad/s, 3 kN (Guessasma section 3.1 and
    Fig. 12): compared with the band's middle, the half-width its uncertainty and the tolerance."""
    model = AnalyticModel("6208", OIL)
    model.evaluate(500.0, 3000.0, T_OIL)
    low, high = 2.12, 2.15
    half = 0.5 * (high - low) / (0.5 * (high + low))
    return [Comparison("Lambda_out at psi = 0", float(model.ball[5, 0]), 0.5 * (high + low), half, half)]


def rolling_comparisons():
    """Cage 198.02 rad/s and ball 952.38 rad/s (fixed frame) at 500 rad/s, P_d = 0, 3 kN (Guessasma section
    3.1; pure rolling at contact angle 0), printed to 5 digits: tolerance 1e-4."""
    out = QuasiStaticModel("6208", OIL, quasi_static_scene(), Pd=0.0).evaluate(omega=500.0, F_y=3000.0, T_oil=T_OIL)
    return [
        printed_comparison("cage speed", out["omega_cage"], "198.02", 1e-4),
        printed_comparison("ball speed, fixed frame", out["omega_ball"], "952.38", 1e-4),
    ]


def analytic_evaluation():
    model = AnalyticModel("6208", OIL)
    return lambda: model.evaluate(500.0, 3000.0, T_OIL)


def quasi_static_evaluation():
    """One warm solve at the papers' point (after a 1 % load change, as a co-simulation step)."""
    model = QuasiStaticModel("6208", OIL, quasi_static_scene(), Pd=0.0)
    loads = iter([3000.0, 3030.0] * 10**6)
    return lambda: model.evaluate(omega=500.0, F_y=next(loads), T_oil=T_OIL)


SOURCE = "Guessasma & Machado (2018) App. A; Farah et al. (2020) App. A"
CASES = (
    ReferenceCase(
        "q_max_6208",
        "analytic",
        "Q_max at 3 kN",
        "Guessasma & Machado (2018) Fig. 12b, App. A",
        q_max_comparisons,
        analytic_evaluation,
    ),
    ReferenceCase(
        "eps_6208_analytic",
        "analytic",
        "load parameter eps vs clearance",
        SOURCE,
        lambda: eps_comparisons(analytic_eps),
        analytic_evaluation,
    ),
    ReferenceCase(
        "lambda_6208",
        "analytic",
        "Lambda_out at psi = 0, 500 rad/s",
        "Guessasma & Machado (2018) 3.1",
        lambda_comparisons,
        analytic_evaluation,
    ),
    ReferenceCase(
        "eps_6208_quasi_static",
        "quasi-static",
        "load parameter eps vs clearance",
        SOURCE,
        lambda: eps_comparisons(quasi_static_eps),
        quasi_static_evaluation,
    ),
    ReferenceCase(
        "rolling_6208",
        "quasi-static",
        "cage and ball speeds at 500 rad/s",
        "Guessasma & Machado (2018) 3.1",
        rolling_comparisons,
        quasi_static_evaluation,
    ),
)
