"""AnalyticModel: the analytic fidelity's facade between parameter sets, scenes and the jitted kernels.

Inputs and outputs are SI. The model declares its inputs and outputs (name, unit, description) in
tables that the FMU class turns into FMI variables, so the Python model and the FMU cannot drift.
"""

import math

import numpy as np

from ..kernels import radial_bearing as ak
from ..kernels.geometry import ball_mass, curvature_radii
from ..kernels.hertz import hertz_coefficients_approx, hertz_coefficients_exact, reduced_modulus
from ..kernels.loaddist import gauss_legendre
from ..params import load_bearing, load_lubricant
from ..scene import FILM_FORMULAS, PERMITTIVITY_PRESSURES, Scene
from .variables import DM_N_LIMIT, InputError, Variable, check_oil_temperature, check_speed, pressure_warnings

GAUSS_NODES = 48  # quadrature points on the loaded arc (J_r(0.5) exact to < 1e-8)


INPUTS = (
    Variable("omega", "rad/s", "inner-ring angular speed (outer ring fixed); |omega| <= d_m n limit"),
    Variable("F_y", "N", "radial load on the inner ring along the psi = 0 line"),
    Variable("T_oil", "K", "oil temperature (viscosity, pressure-viscosity, density)"),
)

ANALYTIC_OUTPUTS = (
    Variable("Lambda_inner", "1", "film parameter h_min/sigma, minimum over loaded inner contacts (0 if none)"),
    Variable("Lambda_outer", "1", "film parameter h_min/sigma, minimum over loaded outer contacts (0 if none)"),
    Variable("h_min_inner", "m", "minimum film thickness, minimum over loaded inner contacts"),
    Variable("h_min_outer", "m", "minimum film thickness, minimum over loaded outer contacts"),
    Variable("regime", "1", "lubrication regime of the worst contact: 0 boundary, 1 mixed, 2 full film", "integer"),
    Variable("C_bearing", "F", "electrical capacitance of the bearing (balls in parallel)"),
    Variable("Q_max_inner", "N", "largest inner contact load"),
    Variable("Q_max_outer", "N", "largest outer contact load (includes centrifugal force)"),
    Variable("p_max", "Pa", "largest Hertz contact pressure"),
    Variable("omega_cage", "rad/s", "cage angular speed (pure rolling)"),
    Variable("omega_ball", "rad/s", "ball spin speed about its own axis in the fixed frame (pure rolling)"),
    Variable("n_loaded", "1", "number of balls loaded on both races", "integer"),
    Variable("y", "m", "radial displacement of the inner ring along F_y"),
    Variable("epsilon", "1", "load parameter eps = (1 - P_d/(2 delta_r))/2, capped at 1e6 (centred preloaded ring)"),
)
CAPACITANCE_OUTPUTS = ("C_bearing",)


class AnalyticModel:
    """Analytic bearing model (SPEC 4.1-4.6) for one bearing, lubricant and scene.

    Parameters
    ----------
    bearing, lubricant : catalogue name or TOML path (bearing_fmu/params).
    scene : Scene or None (default analytic scene).
    Pd : diametral clearance (m) overriding the parameter file, |Pd| <= 0.02 D.
    """

    def __init__(self, bearing="6208", lubricant="guessasma_oil", scene=None, Pd=None):
        self.scene = (scene or Scene()).validate()
        self.bearing = load_bearing(bearing)
        self.lubricant = load_lubricant(lubricant)
        b = self.bearing
        if b.kind != "deep_groove" or b.alpha0 != 0.0:
            raise InputError(
                f"bearing '{b.name}': the analytic fidelity models radially loaded "
                f"deep-groove bearings (contact angle 0); use the quasi-static fidelity"
            )
        self.Pd = b.Pd if Pd is None else float(Pd)
        limit = 0.02 * b.D
        if not (math.isfinite(self.Pd) and abs(self.Pd) <= limit):
            raise InputError(f"Pd = {Pd} m is outside the allowed range [{-limit:.4g}, {limit:.4g}] m (|Pd| <= 0.02 D)")
        self.omega_max = DM_N_LIMIT / (b.dm * 1e3) * 2.0 * math.pi / 60.0
        self.brg = self._pack()
        if min(self.brg[ak.B_SIGMA_I], self.brg[ak.B_SIGMA_O]) <= 0.0:
            raise InputError(
                f"bearing '{b.name}': composite roughness sigma must be > 0 (Lambda = h_min/sigma); "
                f"give surface.inner_race_Ra / outer_race_Ra / ball_Ra > 0 m"
            )
        self.nodes, self.weights = gauss_legendre(GAUSS_NODES)
        self._out = np.zeros(ak.O_SIZE)
        self.ball = np.zeros((8, b.Z))
        self.warnings = []

    def _pack(self):
        b, s = self.bearing, self.scene
        brg = np.zeros(ak.B_SIZE)
        Rx_i, Ry_i, Rx_o, Ry_o = curvature_radii(b.D, b.dm, b.f_i, b.f_o, 0.0)
        coeff = hertz_coefficients_exact if s.hertz == "exact" else hertz_coefficients_approx
        brg[ak.B_Z] = b.Z
        brg[ak.B_D] = b.D
        brg[ak.B_DM] = b.dm
        brg[ak.B_PD] = self.Pd
        brg[ak.B_RX_I], brg[ak.B_RY_I], brg[ak.B_RX_O], brg[ak.B_RY_O] = Rx_i, Ry_i, Rx_o, Ry_o
        brg[ak.B_K_I], brg[ak.B_EE_I], brg[ak.B_KK_I] = coeff(Rx_i, Ry_i)
        brg[ak.B_K_O], brg[ak.B_EE_O], brg[ak.B_KK_O] = coeff(Rx_o, Ry_o)
        brg[ak.B_E_RED] = reduced_modulus(b.ball.E, b.ball.nu, b.ring.E, b.ring.nu)
        brg[ak.B_M_BALL] = ball_mass(b.D, b.ball.rho)
        brg[ak.B_SIGMA_I] = s.roughness_factor * math.hypot(b.Ra_inner, b.Ra_ball)
        brg[ak.B_SIGMA_O] = s.roughness_factor * math.hypot(b.Ra_outer, b.Ra_ball)
        brg[ak.B_FILM] = FILM_FORMULAS[s.film]
        brg[ak.B_PRESSURE] = PERMITTIVITY_PRESSURES[s.permittivity_pressure]
        brg[ak.B_H_FLOOR] = s.film_floor
        brg[ak.B_C_BACKGROUND] = s.background_capacitance
        brg[ak.B_CENTRIFUGAL] = 1.0 if s.centrifugal else 0.0
        brg[ak.B_TOL] = s.tolerance
        brg[ak.B_CAPACITANCE] = 1.0 if s.capacitance else 0.0
        return brg

    inputs = INPUTS

    def get_state(self):
        """The analytic model is algebraic: no solver state beyond the FMU variables."""
        return {}

    def set_state(self, state):
        pass

    @property
    def outputs(self):
        """Output variables of this scene (capacitance off removes C_bearing)."""
        if self.scene.capacitance:
            return ANALYTIC_OUTPUTS
        return tuple(v for v in ANALYTIC_OUTPUTS if v.name not in CAPACITANCE_OUTPUTS)

    def check_inputs(self, omega, F_y, T_oil):
        """Raise InputError naming the first input outside its allowed range."""
        check_speed(omega, self.omega_max)
        if not math.isfinite(F_y):
            raise InputError(f"F_y = {F_y} N is not a finite number")
        check_oil_temperature(T_oil)

    def evaluate(self, omega, F_y, T_oil):
        """Outputs (dict name -> SI value) for inner-ring speed omega (rad/s), radial load F_y (N)
        and oil temperature T_oil (K). Raises InputError for inputs outside their ranges or a load
        beyond the material limit; fills self.warnings (e.g. p_max above the ISO 76 limit)."""
        self.check_inputs(omega, F_y, T_oil)
        out = self._out
        ak.analytic_bearing(
            float(omega),
            abs(float(F_y)),
            float(T_oil),
            self.brg,
            self.lubricant.array,
            self.nodes,
            self.weights,
            out,
            self.ball,
        )
        self.warnings = pressure_warnings(out[ak.O_PMAX], f"F_y = {F_y} N")
        sign = -1.0 if F_y < 0.0 else 1.0
        values = {
            "Lambda_inner": out[ak.O_LAMBDA_I],
            "Lambda_outer": out[ak.O_LAMBDA_O],
            "h_min_inner": out[ak.O_HMIN_I],
            "h_min_outer": out[ak.O_HMIN_O],
            "regime": int(out[ak.O_REGIME]),
            "C_bearing": out[ak.O_C_BEARING],
            "Q_max_inner": out[ak.O_QMAX_I],
            "Q_max_outer": out[ak.O_QMAX_O],
            "p_max": out[ak.O_PMAX],
            "omega_cage": out[ak.O_OMEGA_CAGE],
            "omega_ball": out[ak.O_OMEGA_BALL],
            "n_loaded": int(out[ak.O_N_LOADED]),
            "y": sign * out[ak.O_DELTA_R],
            "epsilon": min(max(out[ak.O_EPS], -1e6), 1e6),
        }
        if not self.scene.capacitance:
            del values["C_bearing"]
        for name, value in values.items():
            if not math.isfinite(value):
                raise InputError(
                    f"output {name} is not finite ({value}) for omega = {omega} rad/s, "
                    f"F_y = {F_y} N, T_oil = {T_oil} K: please report this case"
                )
        return values
