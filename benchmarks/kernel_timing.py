"""Time per call of each kernel and of the analytic model's full evaluation (performance budget,
docs/architecture.md: analytic model full evaluation <= 20 us warm). Medians on this machine, called from Python (so
each figure includes numba's dispatch overhead, ~0.1-0.3 us).
Run: python -m benchmarks.kernel_timing: docs/reports/kernel_timing.md
"""

import numpy as np

from bearing_fmu.kernels import radial_bearing
from bearing_fmu.kernels.capacitance import (
    ball_capacitance,
    bearing_capacitance,
    contact_capacitance,
    contact_permittivity,
)
from bearing_fmu.kernels.ehl import (
    film_parameter,
    film_thickness,
    friction_coefficient,
    lubrication_regime,
    normal_damping,
)
from bearing_fmu.kernels.geometry import (
    centrifugal_force,
    curvature_radii,
    defect_frequencies,
    free_contact_angle,
    rolling_kinematics,
)
from bearing_fmu.kernels.hertz import (
    elliptic_integrals,
    hertz_coefficients_approx,
    hertz_coefficients_exact,
    hertz_contact,
    hertz_stiffness,
    reduced_modulus,
)
from bearing_fmu.kernels.loaddist import gauss_legendre, radial_force_and_slope, radial_integral, solve_radial_shift
from bearing_fmu.kernels.lubricant import (
    dowson_higginson_density,
    lubricant_state,
    walther_viscosity,
    wlf_alpha_star,
    wlf_viscosity,
)
from bearing_fmu.models.analytic import AnalyticModel
from bearing_fmu.params import load_lubricant

from .common import median_time
from .render import cli, metric


def cases():
    m = AnalyticModel()
    E = m.brg[radial_bearing.B_E_RED]
    nodes, weights = gauss_legendre(48)
    vg68 = load_lubricant("iso_vg68_mineral").array
    turb = load_lubricant("thesis_turbine_oil").array
    Ci, Co = np.full(9, 3e-11), np.full(9, 4e-11)
    return [
        ("geometry.curvature_radii", curvature_radii, (0.0126, 0.0606, 0.52, 0.52, 0.0)),
        ("geometry.rolling_kinematics", rolling_kinematics, (500.0, 0.0126, 0.0606, 0.0)),
        ("geometry.defect_frequencies", defect_frequencies, (500.0, 0.0126, 0.0606, 0.0, 9)),
        ("geometry.free_contact_angle", free_contact_angle, (0.0126, 0.52, 0.52, 12e-6)),
        ("geometry.centrifugal_force", centrifugal_force, (0.008, 0.0606, 198.0)),
        ("hertz.reduced_modulus", reduced_modulus, (210e9, 0.3, 210e9, 0.3)),
        ("hertz.elliptic_integrals", elliptic_integrals, (0.9,)),
        ("hertz.hertz_coefficients_exact", hertz_coefficients_exact, (5e-3, 0.05)),
        ("hertz.hertz_coefficients_approx", hertz_coefficients_approx, (5e-3, 0.05)),
        ("hertz.hertz_contact", hertz_contact, (1000.0, 5e-3, 0.05, E, 5.0, 1.05, 3.0)),
        ("hertz.hertz_stiffness", hertz_stiffness, (5e-3, 0.05, E, 5.0, 1.05, 3.0)),
        ("loaddist.radial_integral (48 nodes)", radial_integral, (0.5, nodes, weights)),
        ("loaddist.radial_force_and_slope", radial_force_and_slope, (2e-5, 0.0, 6e9, 9, nodes, weights)),
        (
            "loaddist.solve_radial_shift (Pd = 10 um)",
            solve_radial_shift,
            (3000.0, 10e-6, 6e9, 9, nodes, weights, 1e-12),
        ),
        ("ehl.film_thickness (HD)", film_thickness, (0, 0.04, 2.3e-8, E, 10.0, 1500.0, 5e-3, 0.08, 8.0)),
        ("ehl.film_thickness (MK)", film_thickness, (1, 0.04, 2.3e-8, E, 10.0, 1500.0, 5e-3, 0.08, 8.0)),
        ("ehl.film_thickness (Chittenden)", film_thickness, (2, 0.04, 2.3e-8, E, 10.0, 1500.0, 5e-3, 0.08, 8.0)),
        ("ehl.film_parameter", film_parameter, (6e-7, 3.75e-7)),
        ("ehl.lubrication_regime", lubrication_regime, (2.1,)),
        ("ehl.friction_coefficient", friction_coefficient, (2.1,)),
        ("ehl.normal_damping", normal_damping, (2.1, 1500.0, 0.08, 0.04, 2e-3, 6.3e-3, 6e-7)),
        ("lubricant.walther_viscosity", walther_viscosity, (333.0, 9.0, 3.5)),
        (
            "lubricant.wlf_viscosity",
            wlf_viscosity,
            (1e8, 313.0, 1e12, 204.7, 189.0, 5.3e-10, 7.4e-9, -0.62, 15.9, 14.2),
        ),
        ("lubricant.wlf_alpha_star", wlf_alpha_star, (313.0, 1e12, 204.7, 189.0, 5.3e-10, 7.4e-9, -0.62, 15.9, 14.2)),
        ("lubricant.dowson_higginson_density", dowson_higginson_density, (870.0, 2e9)),
        ("lubricant.lubricant_state (VG68, Walther + Gold)", lubricant_state, (333.0, vg68)),
        ("lubricant.lubricant_state (thesis oil, WLF + alpha*)", lubricant_state, (333.0, turb)),
        ("capacitance.contact_permittivity", contact_permittivity, (0.1, 870.0, 2e9, 0)),
        ("capacitance.contact_capacitance", contact_capacitance, (2.3, 2e-3, 3e-4, 6e-7, 1e-8)),
        ("capacitance.ball_capacitance", ball_capacitance, (3e-11, 4e-11)),
        ("capacitance.bearing_capacitance (9 balls)", bearing_capacitance, (Ci, Co, 0.0)),
    ]


ANALYTIC_TARGET = 20e-6  # s, analytic model full evaluation warm (docs/architecture.md, performance budget)
NUMBER = 2000  # calls per batch (common.median_time: the median over 15 batches)


def analytic_rows():
    """[(what, metric key, time per call s)] of the analytic bearing: its kernel and the model's evaluate, P_d = 0
    and 10 um."""
    rows = []
    for Pd, label, key in (
        (0.0, "P_d = 0", "P_d = 0"),
        (10e-6, "P_d = 10 um (Newton on the radial shift)", "P_d = 10 um"),
    ):
        m = AnalyticModel(Pd=Pd)
        out, ball = np.zeros(radial_bearing.O_SIZE), np.zeros((8, 9))
        k_args = (500.0, 3000.0, 313.15, m.brg, m.lubricant.array, m.nodes, m.weights, out, ball)
        kernel = median_time(radial_bearing.analytic_bearing, *k_args, number=NUMBER)
        rows.append((f"kernel analytic_bearing, {label}", f"analytic kernel, {key} (median)", kernel))
        model = median_time(m.evaluate, 500.0, 3000.0, 313.15, number=NUMBER)
        what = f"AnalyticModel.evaluate (input checks + kernel + output dict), {label}"
        rows.append((what, f"analytic model evaluate, {key} (median)", model))
    return rows


def measure():
    analytic = analytic_rows()
    kernels = [(name, median_time(fn, *args, number=NUMBER)) for name, fn, args in cases()]
    return dict(
        name="kernel_timing",
        title="Kernel timing (medians, warm)",
        about=__doc__.split("Run:")[0],
        blocks=[
            dict(
                text="Each figure is the median over 15 batches of {number} calls from Python, dispatch included. "
                "Analytic bearing model: 6208, 500 rad/s, 3 kN (target {target:g} us warm).",
                values=dict(number=NUMBER, target=1e6 * ANALYTIC_TARGET),
            ),
            dict(table=dict(columns=["what", "time per call (us)"], formats=[None, "{:.2f}"],
                            rows=[[w, 1e6 * t] for w, _, t in analytic])),
            dict(table=dict(columns=["kernel", "time per call (us)"], formats=[None, "{:.3f}"],
                            rows=[[w, 1e6 * t] for w, t in kernels])),
        ],
        metrics=[
            metric(key, t, "s", "timing", target=ANALYTIC_TARGET if "evaluate" in key else None)
            for _, key, t in analytic
        ],
    )  # fmt: skip


def main(argv=None):
    cli(measure, "kernel_timing")


if __name__ == "__main__":
    main()
