"""AnalyticModel: the analytic fidelity's facade between parameter sets, scenes and the jitted kernels.

Inputs and outputs are SI and declared once in models.declarations (ANALYTIC_INPUTS, ANALYTIC_OUTPUTS):
the model fills a preallocated output array in that order, and the FMU class registers its FMI
variables from the same declarations, so the Python model and the FMU cannot drift.
"""

import math

import numpy as np

from bearing_fmu_common.variables import InputLimits, gather_plan, outputs_as_dict, select

from ..kernels import radial_bearing
from ..kernels import rating_life as rl
from ..kernels import truncation as tk
from ..kernels.geometry import ball_mass, curvature_radii
from ..kernels.hertz import hertz_coefficients_approx, hertz_coefficients_exact, reduced_modulus
from ..kernels.loaddist import gauss_legendre
from ..params import check_roughness, load_bearing, load_lubricant
from ..scene import FILM_FORMULAS, Scene
from .blocks import capacitance_block, write_blocks
from .declarations import ANALYTIC_INPUTS, ANALYTIC_OUTPUTS, ANALYTIC_PARAMETERS
from .fidelity import Fidelity
from .film_table import film_table_array
from .input_checks import check_clearance
from .limits import (
    DM_N_LIMIT,
    MATERIAL_LIMIT,
    InputError,
    OilTemperatureWatch,
    material_load_limit,
    pressure_warnings,
)
from .lubrication import Lubrication, LubricationWatch, lubrication_block
from .race_contacts import RaceContacts, truncation_parameters, truncation_warnings

GAUSS_NODES = 48  # quadrature points on the loaded arc (J_r(0.5) exact to < 1e-8)
EPSILON_CAP = 1e6  # |epsilon| shown at most (a centred preloaded ring has delta_r = 0: eps is infinite)


def models_bearing(bearing):
    """True if the analytic fidelity models `bearing`: a deep-groove bearing of contact angle 0."""
    return bearing.kind == "deep_groove" and bearing.alpha0 == 0.0


class AnalyticModel:
    """Analytic bearing model for one bearing, lubricant and scene (docs/decisions.md; Harris and Kotzalas 2007).

    Parameters
    ----------
    bearing, lubricant : catalogue name or TOML path (bearing_fmu/params).
    scene : Scene or None (default analytic scene).
    Pd : diametral clearance (m) overriding the bearing file (None: the file's), within
        -(f_i + f_o - 1) D <= Pd <= (f_i + f_o - 1) D (free contact angle up to 60 deg).
    film_tables : directory of the film tables an FMU carries (models.film_table); None = this machine's cache.
    """

    def __init__(self, bearing="6208", lubricant="guessasma_oil", scene=None, Pd=None, film_tables=None):
        self.scene = (scene or Scene()).validate()
        self.film_tables = film_tables
        self.bearing = load_bearing(bearing)
        self.lubricant = load_lubricant(lubricant)
        b = self.bearing
        if not models_bearing(b):
            raise InputError(
                f"bearing '{b.name}': the analytic fidelity models radially loaded "
                f"deep-groove bearings (contact angle 0); use the quasi-static fidelity"
            )
        self.Pd = b.Pd if Pd is None else float(Pd)
        check_clearance(self.Pd, b, Pd is not None)
        self.omega_max = DM_N_LIMIT / (b.dm * 1e3) * 2.0 * math.pi / 60.0
        check_roughness(b.Ra_inner, b.Ra_outer, b.Ra_ball, b.path)  # the reader's check, for a Bearing made by hand
        self.brg = self._pack()
        contacts = [
            [self.brg[k] for k in keys]
            for keys in (
                (
                    radial_bearing.B_RX_I,
                    radial_bearing.B_RY_I,
                    radial_bearing.B_K_I,
                    radial_bearing.B_EE_I,
                    radial_bearing.B_KK_I,
                ),
                (
                    radial_bearing.B_RX_O,
                    radial_bearing.B_RY_O,
                    radial_bearing.B_K_O,
                    radial_bearing.B_EE_O,
                    radial_bearing.B_KK_O,
                ),
            )
        ]
        self.load_limit = material_load_limit(b.Z, self.brg[radial_bearing.B_E_RED], contacts)
        self._limits = InputLimits(
            self.inputs,
            {
                "omega": (-self.omega_max, self.omega_max, f"d_m n <= {DM_N_LIMIT:.0e} mm.rpm"),
                "F_y": (-self.load_limit, self.load_limit, MATERIAL_LIMIT),
            },
        )
        self.nodes, self.weights = gauss_legendre(GAUSS_NODES)
        self._out = np.zeros(radial_bearing.O_SIZE)
        self.ball = np.zeros((8, b.Z))
        self.warnings = []
        self._oil_watch = OilTemperatureWatch(self.lubricant)
        self._lubrication_watch = LubricationWatch(self.lubrication_numbers, self.lubricant)
        self.outputs = select(ANALYTIC_OUTPUTS, self.scene)
        self.output_names = tuple(v.name for v in self.outputs)
        self.values = np.zeros(len(self.outputs))  # outputs of the last evaluation, in self.outputs order
        self._life = np.zeros(rl.LO_SIZE)
        self._life_parameters = np.zeros(rl.LP_SIZE)
        if self.scene.life:  # a radial-contact groove bearing (docs/rating_life.md)
            rl.rating_parameters(0.0, b.Z, b.D, b.dm, b.f_i, b.f_o, 0.0, self._life_parameters)
        # shoulder truncation of the contact ellipses at the groove bottom (contact angle 0, kernels.truncation)
        self._truncation_parameters = truncation_parameters(b, self._race_contacts(), self.Pd)
        self._angles = np.zeros((2, b.Z))
        self._trunc = np.zeros(tk.TR_SIZE)
        self._truncated = [0.0, 0.0]  # per race the truncated fraction at its last warning (0: not truncated)
        self._gather = gather_plan(self.outputs, {"out": self._out, "life": self._life, "trunc": self._trunc})
        self._slot = {name: k for k, name in enumerate(self.output_names)}

    def _pack(self):
        b, s = self.bearing, self.scene
        brg = np.zeros(radial_bearing.B_SIZE)
        Rx_i, Ry_i, Rx_o, Ry_o = curvature_radii(b.D, b.dm, b.f_i, b.f_o, 0.0)
        coeff = hertz_coefficients_exact if s.hertz == "exact" else hertz_coefficients_approx
        brg[radial_bearing.B_Z] = b.Z
        brg[radial_bearing.B_D] = b.D
        brg[radial_bearing.B_DM] = b.dm
        brg[radial_bearing.B_PD] = self.Pd
        (
            brg[radial_bearing.B_RX_I],
            brg[radial_bearing.B_RY_I],
            brg[radial_bearing.B_RX_O],
            brg[radial_bearing.B_RY_O],
        ) = Rx_i, Ry_i, Rx_o, Ry_o
        brg[radial_bearing.B_K_I], brg[radial_bearing.B_EE_I], brg[radial_bearing.B_KK_I] = coeff(Rx_i, Ry_i)
        brg[radial_bearing.B_K_O], brg[radial_bearing.B_EE_O], brg[radial_bearing.B_KK_O] = coeff(Rx_o, Ry_o)
        brg[radial_bearing.B_E_RED] = reduced_modulus(b.ball.E, b.ball.nu, b.ring.E, b.ring.nu)
        brg[radial_bearing.B_M_BALL] = ball_mass(b.D, b.ball.rho)
        brg[radial_bearing.B_SIGMA_I] = s.roughness_factor * math.hypot(b.Ra_inner, b.Ra_ball)
        brg[radial_bearing.B_SIGMA_O] = s.roughness_factor * math.hypot(b.Ra_outer, b.Ra_ball)
        brg[radial_bearing.B_FILM] = FILM_FORMULAS[s.film]
        brg[radial_bearing.B_CENTRIFUGAL] = 1.0 if s.centrifugal else 0.0
        brg[radial_bearing.B_TOL] = s.tolerance
        self.lubrication_numbers = Lubrication(s, b.D, b.dm)
        write_blocks(
            brg,
            (
                (radial_bearing.B_FILM_TABLE, film_table_array(b, self.lubricant, s.film_correction, self.film_tables)),
                (radial_bearing.B_LUBRICATION_BLOCK, lubrication_block(self.lubrication_numbers)),
                (radial_bearing.B_CAPACITANCE_BLOCK, capacitance_block(s)),
            ),
        )
        return brg

    def _race_contacts(self):
        """The contacts as _pack put them into the kernel's array (radial contact, the scene's Hertz coefficients)."""
        brg = self.brg
        return RaceContacts(
            0.0,
            brg[radial_bearing.B_RX_I],
            brg[radial_bearing.B_RY_I],
            brg[radial_bearing.B_RX_O],
            brg[radial_bearing.B_RY_O],
            (brg[radial_bearing.B_K_I], brg[radial_bearing.B_EE_I], brg[radial_bearing.B_KK_I]),
            (brg[radial_bearing.B_K_O], brg[radial_bearing.B_EE_O], brg[radial_bearing.B_KK_O]),
            brg[radial_bearing.B_E_RED],
        )

    inputs = ANALYTIC_INPUTS

    def get_state(self):
        """The analytic model is algebraic: no solver state beyond the FMU variables, but the races whose contact
        ellipse was truncated at the last evaluation (their warning is logged on entry only)."""
        return {"truncated": list(self._truncated)}

    def set_state(self, state):
        self._truncated[:] = state.get("truncated", (0.0, 0.0))

    def check_inputs(self, omega, F_y, T_oil):
        """Raise InputError naming the first input outside its allowed range."""
        self._limits.check((omega, F_y, T_oil))

    def evaluate(self, omega, F_y, T_oil):
        """Outputs (dict name -> SI value) for inner-ring speed omega (rad/s), radial load F_y (N)
        and oil temperature T_oil (K). Raises InputError for inputs outside their ranges or a load
        beyond the material limit; fills self.warnings (e.g. p_max above the ISO 76 limit)."""
        self.update((omega, F_y, T_oil))
        return self.as_dict()

    def as_dict(self):
        """The outputs of the last evaluation as a dict name -> SI value (integers for integer outputs)."""
        return outputs_as_dict(self.outputs, self.values)

    def update(self, u):
        """Evaluate for the inputs u = (omega, F_y, T_oil) in self.inputs order (rad/s, N, K) and fill
        self.values (self.outputs order); returns self.values. Raises as evaluate()."""
        omega, F_y, T_oil = u
        self.check_inputs(omega, F_y, T_oil)
        out = self._out
        radial_bearing.analytic_bearing(
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
        if self.scene.life:  # ball rows 0 and 1: inner and outer contact loads
            rl.rating_life(
                self.ball[0], self.ball[1], abs(float(F_y)), 0.0, float(omega), self._life_parameters, self._life
            )
        self.warnings = pressure_warnings(out[radial_bearing.O_PMAX], f"F_y = {F_y} N") + self._oil_watch.warnings(
            T_oil
        )
        self.warnings += self._lubrication_watch.warnings(
            float(omega), (out[radial_bearing.O_PHI_RS_I], out[radial_bearing.O_PHI_RS_O])
        )
        # ball rows 0 and 1: inner and outer contact loads, all at the groove bottom (angle 0)
        tk.race_truncation(self.ball, 0, self._angles, 0, self._truncation_parameters, self._trunc)
        self.warnings += truncation_warnings(
            self._truncation_parameters, self._trunc, self.ball, 0, self._angles, 0, self._truncated
        )
        sign = -1.0 if F_y < 0.0 else 1.0
        values, slot = self.values, self._slot
        for source, index, target in self._gather:
            values[target] = source[index]
        values[slot["y"]] = sign * out[radial_bearing.O_DELTA_R]
        values[slot["epsilon"]] = min(max(out[radial_bearing.O_EPS], -EPSILON_CAP), EPSILON_CAP)
        if not math.isfinite(values.sum()) and not np.isfinite(values).all():  # NaN and inf propagate into a sum
            k = int(np.argmin(np.isfinite(values)))
            raise InputError(
                f"output {self.output_names[k]} is not finite ({values[k]}) for omega = {omega} rad/s, "
                f"F_y = {F_y} N, T_oil = {T_oil} K: please report this case"
            )
        return values


def reference_inputs(scene):
    """The analytic FMU's reference experiment (SI): the 6208 at 3 kN radial, 40 C, 0-1700 rad/s in steps of 50."""
    return [{"omega": float(w), "F_y": 3000.0, "T_oil": 313.15} for w in range(0, 1701, 50)]


FIDELITY = Fidelity(
    name="analytic",
    model=AnalyticModel,
    parameters=ANALYTIC_PARAMETERS,
    choices=("bearing", "lubricant"),
    reference_step=0.1,
    reference_inputs=reference_inputs,
    summary=lambda scene: "analytic bearing",
)
