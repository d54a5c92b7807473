"""DemModel: facade of the DEM (ball dynamics) fidelity, kernels.ball_dynamics.

Guessasma & Machado (2018) and Farah et al. (2020): Z steel balls and Z PA66 cage balls, inner ring
with translational DOF x, y, z, tilts theta_x, theta_y and prescribed rotation omega(t), fixed outer ring;
per-contact EHL film, regime-dependent damping and friction, Houpert rolling resistances, capacitance. SI units.

The whole state lives in numpy arrays (get_state/set_state copy all of them, for FMU rollback).
advance(t_end, ...) runs every step of the interval in one jitted call; the inner-ring speed goes
linearly from its previous value to the given one over the interval (a start-up ramp is a sequence
of calls), loads and oil temperature are held. The bodies start at rest in their geometric positions
(balls touching the outer race, cage balls midway between them on the pitch circle).

Settling aids for quasi-static comparisons (Guessasma 2018 appendix A): drive slowly (omega = 1 rad/s)
so that centrifugal and film effects vanish; the ring's response to a load step decays in about a
millisecond (hysteretic damping); compare after a few milliseconds.
"""

import math

import numpy as np

from bearing_fmu_common.variables import InputLimits, gather_plan, outputs_as_dict, select

from ...kernels import truncation as tk
from ...kernels.ball_dynamics import integrator as dyn
from ...kernels.ball_dynamics import state as s
from ...kernels.ball_dynamics.monitor import critical_time_step, damping_step_ratio, kinetic_energy
from ...kernels.ball_dynamics.outputs import bearing_outputs, contact_angles, contact_loads, shoulder_truncation
from ...kernels.ball_dynamics.stiffness import stiffness_matrix
from ...kernels.ehl import friction_coefficient
from ...kernels.geometry import (
    ball_direction,
    ball_mass,
    free_contact_angle,
    pass_frequencies,
    rolling_kinematics,
)
from ...kernels.hertz import hertz_contact, hertz_stiffness
from ...params import (
    SUPPORT_DAMPING,
    SUPPORT_STIFFNESS,
    clearance_limits,
    load_bearing,
    load_dem_constants,
    load_lubricant,
)
from ...scene import Scene
from ..contacts import contact_terms, pack, race_contacts, truncation_parameters, truncation_warnings
from ..declarations import DEM_DT_MAX, DEM_INPUTS, DEM_OUTPUTS, DEM_REFRESH_MAX
from ..declarations import DEM_REFRESH_INTERVAL as REFRESH_INTERVAL
from ..variables import (
    DM_N_LIMIT,
    MATERIAL_LIMIT,
    P_MAX_ERROR,
    InputError,
    OilTemperatureWatch,
    check_clearance,
    pressure_warnings,
)

# the contact model's constants with their units and sources (params/dem_model.toml): the cage elements' default
# material (the papers' PA66), the hysteretic damping constant alpha_e, the tangential stiffness ratio
CONSTANTS = load_dem_constants()
# pocket play of an estimated cage ball: the 6208 of Guessasma & Machado (2018) has 0.033 mm for D = 12.6 mm
CAGE_GAP_OVER_D = 0.0026
V_REG = 1e-3  # m/s, speed below which the resistances' directions are regularised
SAFETY = 0.5  # default time step over the stability limit of the stiffest pair (docs/reports/dem_error.md)
# consecutive slipping reversals of one spring that count as chatter: sustained chatter (6208 at 3 kN,
# 500 rad/s, dt >= 7 us) reverses for hundreds of steps and multiplies the torque; a lightly loaded ball
# entering the load zone during a start-up reverses for up to ~15 steps without changing the results
# (cage speed and torque equal within 0.05 % at half the step)
CHATTER_STEPS = 50
# the normal damping of a ball (its loaded contacts' C_n) times the step over its mass: the automatic step keeps
# it at or below DAMPING_PLAN, the monitor stops above DAMPING_STOP (a film that thickened into full film
# within the call); measured on the B7214C entering full film at 10 rad/s: correct up to 0.43, a spurious
# dissipation from 0.48 (docs/dem.md)
DAMPING_PLAN = 0.25
DAMPING_STOP = 0.35
MU_BOUNDARY = friction_coefficient(0.0)  # mu(Lambda) of the boundary regime (0.1), before any contact
TRACTION_LIMIT_MAX = MU_BOUNDARY  # a full film carries no more than the boundary regime
# the film's traction is evaluated linearly implicitly in the slip: a force at the surface of a solid sphere
# changes the surface's speed by 3.5/m per newton and second, and a ball has two contacts (docs/dem.md, Tangential)
FILM_RATE = 2.0 * 3.5
# an automatic step that the monitor stops is halved and the call repeated, at most this often (16x smaller)
AUTO_STEP_HALVINGS = 4
ENERGY_FACTOR = 10.0  # kinetic-energy bound: this factor x (pure-rolling energy + load x groove clearance)
T_OIL_DEFAULT = 313.15  # K
# the outputs that averaged_state replaces by their means over the tribology refreshes of a call: (out, acc sum)
AVERAGED_STATE = (
    (s.O_QMAX_I, s.A_S_QMAX_I),
    (s.O_QMAX_O, s.A_S_QMAX_O),
    (s.O_PMAX, s.A_S_PMAX),
    (s.O_LAMBDA_I, s.A_S_LAMBDA_I),
    (s.O_LAMBDA_O, s.A_S_LAMBDA_O),
    (s.O_HMIN_I, s.A_S_HMIN_I),
    (s.O_HMIN_O, s.A_S_HMIN_O),
    (s.O_HC_I, s.A_S_HC_I),
    (s.O_HC_O, s.A_S_HC_O),
)
# update()'s communication step is rounded to this grid (s), far below any DEM time step (0.1-10 us)
COMMUNICATION_DIGITS = 12
COMMUNICATION_RESOLUTION = 10.0**-COMMUNICATION_DIGITS

STATUS_WORDS = {
    s.STATUS_NOT_FINITE: "a force became NaN or infinite",
    s.STATUS_PENETRATION: "a ball-race penetration passed the physical limit (Hertz pressure above the material limit)",
    s.STATUS_ENERGY: "the kinetic energy grew beyond the bound of the inputs (energy growth without input)",
    s.STATUS_CHATTER: "a tangential spring chattered against its Coulomb limit (slip direction reversing every step)",
    s.STATUS_DAMPING: "a ball's normal damping is beyond what the step integrates ((c_i + c_o) dt / m above "
    f"{DAMPING_STOP}; e.g. a contact that entered full film at low speed, whose squeeze damping overdamps the ball)",
}


class DemUnstableError(InputError):
    """The monitor stopped the integration; the message names the cause and a time step that would work."""


def _cage_material(bearing):
    """(E, nu, rho) of the cage balls from the bearing file's [material.cage], else PA66 defaults."""
    cage = bearing.cage_material
    return cage.get("E", CONSTANTS.cage_E), cage.get("nu", CONSTANTS.cage_nu), cage.get("rho", CONSTANTS.cage_rho)


def _checked_support(name, value, default, spec):
    """A support constant (spec's unit) from the argument, or the constants file's when None; checked."""
    value = default if value is None else float(value)
    if not (math.isfinite(value) and spec.low <= value <= spec.high):
        raise InputError(f"{name} = {value} {spec.unit} is outside the allowed range [{spec.low:g}, {spec.high:g}]")
    return value


def _ring_annulus(bearing):
    """(bore, groove bottom, width) in m of the annulus that estimates the inner ring: from the bore to the groove
    bottom over the ring width (shoulders and groove roughly cancel); without bore or width in the file,
    bore = d_m - 2 D, width = 1.5 D."""
    bore = bearing.dm - 2.0 * bearing.D if bearing.bore is None else bearing.bore
    width = 1.5 * bearing.D if bearing.width is None else bearing.width
    return bore, bearing.dm - bearing.D, width


def _ring_mass(bearing):
    """Inner-ring mass (kg): a steel annulus (_ring_annulus, estimated)."""
    bore, groove_bottom, width = _ring_annulus(bearing)
    return bearing.ring.rho * 0.25 * math.pi * (groove_bottom**2 - bore**2) * width


def _ring_inertia(bearing, mass):
    """(about a diameter, about the axis) in kg.m^2 of an inner ring of mass `mass` (kg) shaped as the annulus of
    _ring_mass (estimated): m ((R^2 + r^2)/4 + w^2/12) and m (R^2 + r^2)/2, R and r the outer and bore radii."""
    bore, groove_bottom, width = _ring_annulus(bearing)
    radii = 0.25 * (groove_bottom**2 + bore**2)  # R^2 + r^2
    return mass * (0.25 * radii + width**2 / 12.0), 0.5 * mass * radii


class DemModel:
    """DEM bearing: Z balls + Z cage balls + translating inner ring.

    bearing, lubricant: catalogue name or TOML path (as the other fidelities). scene: Scene with fidelity
    'dem' (film formula, Hertz solution, roughness factor, capacitance on/off, floor, background and
    permittivity pressure). dt: fixed time step (s); None = safety x the
    stability limit of the stiffest contact pair at the loads of each advance() call. refresh: tribology
    refresh interval in steps (>= 1); None = every refresh_interval (s) of simulated time. The defaults
    SAFETY and REFRESH_INTERVAL are chosen from the error-vs-run-time front (docs/reports/dem_error.md). Pd: diametral
    clearance (m) overriding the file. ring_mass: inner-ring mass (kg); None = estimated from the bore.
    ring_inertia: its moment of inertia about a diameter through its centre (kg.m^2), for the tilts; None =
    estimated from the same annulus (the polar moment, for the ring's gyroscopic moment, is always the annulus's
    for the ring's mass).
    kt_ratio: tangential/normal stiffness (-) of the asperities' spring; None = params/dem_model.toml's.
    support_stiffness (N/m), support_damping (N.s/m): the inner ring's support, a spring to its rest position and a
    damper across the axis (x, y; none along z), the same spread over the pitch circle in the tilts (k (d_m/2)^2/2,
    c (d_m/2)^2/2); None = params/dem_model.toml's (no spring; 1000 N.s/m, the shaft it sits on: docs/dem.md, Ring
    support).
    traction_limit: 0 (default) = the tangential force of the film is the lubricant's EHL traction curve
    (kernels.ehl.film_traction_coefficient,
    the film's share ehl.film_share(Lambda)), the asperities' share a spring capped at the boundary friction;
    > 0 = override: a spring alone, capped at the ramp from 0.1 at Lambda = 1 to traction_limit in a full film
    (kernels.ehl.traction_coefficient; 0.01 = the papers' mu(Lambda)) (docs/dem.md, Tangential force).
    averaged: True (default) reports torque, P_loss, Q_inner_ring,
    Q_outer_ring and C_bearing as means over each advance() interval (what a co-simulation partner integrates:
    the energy of the step), False their values at the interval's last step (docs/dem.md, Outputs).
    averaged_state: False (default) reports the loads, pressure, films and the ring's displacement at the end of
    each interval; True as means over it (the displacement over its steps, the others over its tribology
    refreshes): for masters that sample slower than the ball pass (docs/dem.md, Outputs).
    """

    def __init__(
        self,
        bearing="6208",
        lubricant="guessasma_oil",
        scene=None,
        dt=None,
        refresh=None,
        Pd=None,
        ring_mass=None,
        kt_ratio=None,
        ring_inertia=None,
        support_stiffness=None,
        support_damping=None,
        safety=SAFETY,
        refresh_interval=REFRESH_INTERVAL,
        averaged=True,
        traction_limit=0.0,
        averaged_state=False,
    ):
        self.scene = (scene or Scene(name="dem", fidelity="dem")).validate()
        if self.scene.fidelity != "dem":
            raise InputError(f"scene '{self.scene.name}' has fidelity {self.scene.fidelity!r}: DemModel needs 'dem'")
        self.bearing = b = load_bearing(bearing)
        self.lubricant = load_lubricant(lubricant)
        self.Pd = b.Pd if Pd is None else float(Pd)
        check_clearance(self.Pd, b, Pd is not None)
        self._clearance_limits = clearance_limits(b.D, b.f_i, b.f_o)
        if dt is not None and not (math.isfinite(dt) and 0.0 < dt <= DEM_DT_MAX):
            raise InputError(f"dt = {dt} s is outside the allowed range ]0, {DEM_DT_MAX:g}] s")
        if refresh is not None and not (float(refresh) == int(refresh) and 1 <= int(refresh) <= 100000):
            raise InputError(f"refresh = {refresh} steps is outside the allowed range [1, 100000] (a whole number)")
        if not (math.isfinite(safety) and 0.0 < safety <= 1.0):
            raise InputError(f"safety = {safety} is outside the allowed range ]0, 1]")
        # 0 (the declared minimum) refreshes at every step, as any interval below dt does (_run's floor, min 1)
        if not (math.isfinite(refresh_interval) and 0.0 <= refresh_interval <= DEM_REFRESH_MAX):
            raise InputError(
                f"refresh_interval = {refresh_interval} s is outside the allowed range [0, {DEM_REFRESH_MAX:g}] s "
                "(0 = every DEM step)"
            )
        if not (math.isfinite(traction_limit) and 0.0 <= traction_limit <= TRACTION_LIMIT_MAX):
            raise InputError(
                f"traction_limit = {traction_limit} is outside the allowed range [0, {TRACTION_LIMIT_MAX:g}] "
                "(0 = the lubricant's EHL traction curve; 0.01 = the papers' mu(Lambda))"
            )
        self.traction_limit = float(traction_limit)
        self.support = (
            _checked_support("support_stiffness", support_stiffness, CONSTANTS.support_stiffness, SUPPORT_STIFFNESS),
            _checked_support("support_damping", support_damping, CONSTANTS.support_damping, SUPPORT_DAMPING),
        )
        self.averaged = bool(averaged)
        self.averaged_state = bool(averaged_state)
        self.safety = float(safety)
        self.refresh_interval = float(refresh_interval)
        kt_ratio = CONSTANTS.kt_ratio if kt_ratio is None else kt_ratio
        if not (math.isfinite(kt_ratio) and 0.1 <= kt_ratio <= 1.5):
            raise InputError(f"kt_ratio = {kt_ratio} is outside the allowed range [0.1, 1.5]")
        if ring_mass is not None and not (math.isfinite(ring_mass) and ring_mass > 0.0):
            raise InputError(f"ring_mass = {ring_mass} kg is outside the allowed range ]0, inf[ kg")
        if ring_inertia is not None and not (math.isfinite(ring_inertia) and ring_inertia > 0.0):
            raise InputError(f"ring_inertia = {ring_inertia} kg.m^2 is outside the allowed range ]0, inf[ kg.m^2")
        self.ring_mass_estimated = ring_mass is None
        self.ring_inertia_estimated = ring_inertia is None
        self.dt_fixed = dt
        self.refresh_fixed = None if refresh is None else int(refresh)
        self.omega_max = DM_N_LIMIT / (b.dm * 1e3) * 2.0 * math.pi / 60.0
        self.par = self._pack(ring_mass, kt_ratio, ring_inertia)
        self.load_limit = self._load_limit()
        load = self.load_limit
        narrowed = {name: (-load, load, MATERIAL_LIMIT) for name in ("F_x", "F_y", "F_z")}
        # moments: the load limit at the pitch radius, as the quasi-static fidelity's
        narrowed.update({name: (-load * 0.5 * b.dm, load * 0.5 * b.dm, MATERIAL_LIMIT) for name in ("M_x", "M_y")})
        narrowed["omega"] = (-self.omega_max, self.omega_max, f"d_m n <= {DM_N_LIMIT:.0e} mm.rpm")
        # the clearance in effect, P_d + dPd_thermal, keeps the geometric limits of P_d itself (|P_d| <= A:
        # neither an interference beyond the groove clearance nor a free contact angle beyond 60 deg)
        low, high = self._clearance_limits
        narrowed["dPd_thermal"] = (
            low - self.Pd,
            high - self.Pd,
            f"Pd + dPd_thermal within [{low:.4g}, {high:.4g}] m (|Pd| <= (f_i + f_o - 1) D)",
        )
        self._limits = InputLimits(DEM_INPUTS, narrowed)
        self._rho_outer = float(self.par[s.P_RHO_O])  # at the nominal clearance
        Z = b.Z
        self.balls = np.zeros((s.B_SIZE, Z))
        self.cage = np.zeros((s.C_SIZE, Z))
        self.ring = np.zeros(s.R_SIZE)
        self.spring = np.zeros((s.S_SIZE, Z))
        self.trib = np.zeros((s.T_SIZE, 2, Z))
        self.counters = np.zeros(s.K_SIZE + 2 * Z, dtype=np.int64)
        self.omega = 0.0
        self.out = np.zeros(s.O_SIZE)
        self.status = np.zeros(s.ST_SIZE, dtype=np.int64)
        self._work = np.zeros((s.W_SIZE, Z))
        self._acc = np.zeros(s.A_SIZE)
        self._Q = np.zeros((2, Z))
        self._alpha = np.zeros((2, Z))
        self._signed_alpha = np.zeros((2, Z))
        self.trunc = np.zeros(tk.TR_SIZE)  # shoulder truncation of the last advance() (kernels.truncation TR_*)
        self.truncated = np.zeros(2)  # 1 for a race truncated at the last advance() (its warning is logged on entry)
        self.dt = math.nan  # time step of the last advance() call (s)
        self.refresh = 0  # its tribology refresh interval (steps)
        self._place_bodies()
        self._initialise(0.0, 0.0, 0.0, 0.0, T_OIL_DEFAULT)
        # the FMU interface (update): variables of the scene in declaration order, filled by one copy plan
        self.inputs = select(DEM_INPUTS, self.scene)
        self.outputs = select(DEM_OUTPUTS, self.scene)
        self.output_names = tuple(v.name for v in self.outputs)
        self.values = np.zeros(len(self.outputs))
        self.warnings = []  # of the last advance(): p_max above the ISO 76 limit (pressure_warnings)
        self._oil_watch = OilTemperatureWatch(self.lubricant)
        self.K = np.zeros((5, 5))  # condensed stiffness of the last update (scene option stiffness)
        self.frequencies = np.zeros(4)  # FTF, BPFO, BPFI, BSF (Hz) of the last update
        arrays = {
            "out": self.out,
            "ring": self.ring,
            "status": self.status,
            "K": self.K.reshape(-1),
            "freq": self.frequencies,
            "trunc": self.trunc,
        }
        self._plan = gather_plan(self.outputs, arrays)
        # state at the start of the last kernel call: an automatic-step call is repeated from it, and update()
        # restores it when the call fails
        self._start = self.get_state()
        self.step_halvings = 0  # times the last call's automatic step was halved after a monitor stop
        self._gather()

    # -- set-up --------------------------------------------------------------------------------
    def _pack(self, ring_mass, kt_ratio, ring_inertia):
        b, sc = self.bearing, self.scene
        D = b.D
        rc = race_contacts(b, sc, self.Pd)
        alpha0, Rx_i, Ry_i, Rx_o, Ry_o, ci, co, E_red = rc
        self._truncation_parameters = truncation_parameters(b, rc, self.Pd)
        p = np.zeros(s.P_SIZE)
        p[s.P_Z] = b.Z
        p[s.P_D] = D
        p[s.P_DM] = b.dm
        p[s.P_ALPHA0] = alpha0
        p[s.P_M_BALL] = ball_mass(D, b.ball.rho)
        p[s.P_I_BALL] = 0.1 * p[s.P_M_BALL] * D * D
        # groove-curvature-centre circles as in the quasi-static model: the inner one seen from the outer one
        # at (A sin alpha0, A - P_d/2) (axial, radial) for an angular-contact bearing, (0, A - P_d/2) otherwise
        A = (b.f_i + b.f_o - 1.0) * D
        A_axial = A * math.sin(alpha0) if b.kind == "angular_contact" else 0.0
        A_radial = A - 0.5 * self.Pd
        p[s.P_RHO_I] = 0.5 * b.dm + (b.f_i - 0.5) * D * math.cos(alpha0)
        p[s.P_Z_I] = A_axial
        p[s.P_RHO_O] = p[s.P_RHO_I] - A_radial
        p[s.P_Z_O] = 0.0
        p[s.P_RG_I] = (b.f_i - 0.5) * D
        p[s.P_RG_O] = (b.f_o - 0.5) * D
        p[s.P_KH_I] = hertz_stiffness(Rx_i, Ry_i, E_red, *ci)
        p[s.P_KH_O] = hertz_stiffness(Rx_o, Ry_o, E_red, *co)
        pack(p, s, "P_", contact_terms(b, sc, rc))
        p[s.P_ALPHA_E] = CONSTANTS.alpha_e
        p[s.P_KT_RATIO] = kt_ratio
        p[s.P_K_SUPPORT], p[s.P_C_SUPPORT] = self.support
        lever = 0.5 * (0.5 * b.dm) ** 2  # a support spread over the pitch circle, about a diameter (m^2)
        p[s.P_KT_SUPPORT] = lever * p[s.P_K_SUPPORT]
        p[s.P_CT_SUPPORT] = lever * p[s.P_C_SUPPORT]
        p[s.P_V_REG] = V_REG
        # cage balls and their guide
        E_c, nu_c, rho_c = _cage_material(b)
        self.cage_radius_estimated = b.cage_ball_radius <= 0.0
        self._rest = self._ball_rest_position(p[s.P_KH_I], p[s.P_KH_O])
        pitch = self._rest[0]
        half_pocket = pitch * 2.0 * math.sin(0.5 * math.pi / b.Z)  # ball centre to the mid-angle point
        R_z = b.cage_ball_radius if b.cage_ball_radius > 0.0 else half_pocket - 0.5 * D - CAGE_GAP_OVER_D * D
        if R_z <= 0.0:
            raise InputError(
                f"bearing '{b.name}': no room for cage balls between {b.Z} balls of {D} m "
                f"(estimated cage-ball radius {R_z:.3g} m)"
            )
        E_star = 1.0 / ((1.0 - b.ball.nu**2) / b.ball.E + (1.0 - nu_c**2) / E_c)
        R_eq = 0.5 * D * R_z / (0.5 * D + R_z)
        # the cage's inertia: a file that gives the cage's mass shares it over the Z cage balls (their contacts
        # keep the cage balls' radius and material); otherwise solid cage balls of the cage material (seeds)
        p[s.P_M_CAGE] = b.cage_mass / b.Z if b.cage_mass > 0.0 else rho_c * 4.0 / 3.0 * math.pi * R_z**3
        p[s.P_R_CAGE] = R_z
        p[s.P_K_CB] = 4.0 / 3.0 * E_star * math.sqrt(R_eq)
        p[s.P_K_GUIDE] = 4.0 / 3.0 * E_star * math.sqrt(R_z)
        p[s.P_R_GUIDE] = pitch
        p[s.P_Z_GUIDE] = self._rest[1]
        p[s.P_GUIDE_GAP] = 0.0
        p[s.P_ZETA_CAGE] = 1.0
        m_eff = p[s.P_M_BALL] * p[s.P_M_CAGE] / (p[s.P_M_BALL] + p[s.P_M_CAGE])
        p[s.P_C_CB] = 2.0 * p[s.P_ZETA_CAGE] * math.sqrt(1.5 * p[s.P_K_CB] * m_eff)
        p[s.P_C_GUIDE] = 2.0 * p[s.P_ZETA_CAGE] * math.sqrt(1.5 * p[s.P_K_GUIDE] * p[s.P_M_CAGE])
        p[s.P_M_RING] = _ring_mass(b) if ring_mass is None else float(ring_mass)
        p[s.P_I_RING], p[s.P_IP_RING] = _ring_inertia(b, p[s.P_M_RING])
        if ring_inertia is not None:
            p[s.P_I_RING] = float(ring_inertia)
        # physical penetration limit: the approach at which the Hertz pressure reaches the material limit
        for race, (Rx, Ry, c) in enumerate(((Rx_i, Ry_i, ci), (Rx_o, Ry_o, co))):
            q_lim = (P_MAX_ERROR / hertz_contact(1.0, Rx, Ry, E_red, *c)[3]) ** 3
            p[s.P_DELTA_LIM_I + race] = (q_lim / p[s.P_KH_I + race]) ** (2.0 / 3.0)
        # Hertz semi-axes and pressure at 1 N, scaled by Q^(1/3) = K_h^(1/3) delta^(1/2) in the kernel
        for race, (Rx, Ry, c) in enumerate(((Rx_i, Ry_i, ci), (Rx_o, Ry_o, co))):
            a1, b1, _, p1 = hertz_contact(1.0, Rx, Ry, E_red, *c)
            cube = p[s.P_KH_I + race] ** (1.0 / 3.0)
            p[s.P_HA_I + s.P_HERTZ_SCALE_STRIDE * race] = a1 * cube
            p[s.P_HB_I + s.P_HERTZ_SCALE_STRIDE * race] = b1 * cube
            p[s.P_HP_I + s.P_HERTZ_SCALE_STRIDE * race] = p1 * cube
        p[s.P_CHATTER] = CHATTER_STEPS
        p[s.P_DAMPING_STOP] = DAMPING_STOP
        p[s.P_TRACTION] = self.traction_limit
        p[s.P_MU_LIM] = self.lubricant.traction_limit
        p[s.P_S_TRACTION] = self.lubricant.traction_slip
        p[s.P_FILM_RATE] = FILM_RATE
        p[s.P_CAPACITANCE] = 1.0 if sc.capacitance else 0.0
        p[s.P_REFRESH] = 1
        return p

    def _ball_rest_position(self, K_inner, K_outer):
        """(radius, z) in m of a ball at rest: on the line from the outer to the inner curvature centre,
        touching the outer groove (with clearance) or sharing the interference as two Hertz contacts of
        constants K_inner, K_outer (N/m^1.5) under one load (preload)."""
        b = self.bearing
        D = b.D
        alpha0 = free_contact_angle(D, b.f_i, b.f_o, self.Pd) if self.Pd > 0.0 else 0.0
        A = (b.f_i + b.f_o - 1.0) * D
        ax = A * math.sin(alpha0) if b.kind == "angular_contact" else 0.0
        rad = A - 0.5 * self.Pd
        rho_o = 0.5 * b.dm + (b.f_i - 0.5) * D * math.cos(alpha0) - rad
        L = math.hypot(ax, rad)
        r_o = (b.f_o - 0.5) * D
        interference = A - L
        if interference > 0.0:  # preload: equal loads, delta_o / delta_i = (K_i / K_o)^(2/3)
            share = 1.0 / (1.0 + (K_outer / K_inner) ** (2.0 / 3.0))
            r_o -= interference * share
        return rho_o + r_o * rad / L, r_o * ax / L

    def _place_bodies(self):
        Z = self.bearing.Z
        for arr in (self.balls, self.cage, self.spring, self.trib):
            arr[...] = 0.0
        self.ring[:] = 0.0
        self.counters[:] = 0
        for j in range(Z):
            r, z = self._rest
            c, sn = ball_direction(j, Z)  # ball 1 on +y (docs/conventions.md)
            self.balls[s.B_X : s.B_X + 3, j] = (r * c, r * sn, z)
            c, sn = ball_direction(j + 0.5, Z)  # the cage ball half a pitch ahead
            R = self.par[s.P_R_GUIDE]
            self.cage[s.C_X : s.C_X + 3, j] = (R * c, R * sn, self.par[s.P_Z_GUIDE])
        self.omega = 0.0

    def _initialise(self, omega, F_x, F_y, F_z, T_oil, M_x=0.0, M_y=0.0):
        dyn.initialise_accelerations(
            self.balls,
            self.cage,
            self.ring,
            self.spring,
            self.trib,
            self.counters,
            self.par,
            self.lubricant.array,
            omega,
            F_x,
            F_y,
            F_z,
            M_x,
            M_y,
            T_oil,
            self._work,
            self._acc,
        )

    # -- time step -----------------------------------------------------------------------------
    def stable_time_step(self, F_x=0.0, F_y=0.0, F_z=0.0, omega=None, include_state=True, M_x=0.0, M_y=0.0):
        """Stability limit (s) of the stiffest contact pair for the given loads (N, N.m) and speed (rad/s): contact
        loads are an estimate (Stribeck's 5 F_r/Z for the radial load, F_a/(Z sin alpha) for the axial one with alpha >=
        5 deg, 2 M/(Z rho_i sin alpha) for a moment, plus the centrifugal force), or the current ones where larger
        (include_state); the cage-ball load is bounded by the friction force mu Q a ball can transmit (the cage contacts
        are frictionless: only the races' traction pushes a ball against a cage ball), mu the largest mu(Lambda) of the
        loaded contacts at the last tribology refresh (0.1 in the boundary regime, 0.01 in a full film). The normal
        damping C_n of each contact is also that of the last refresh (a cold full film at low speed is overdamped). A
        film that changes within the call is caught by the monitor (the automatic step is then halved)."""
        b = self.bearing
        omega = self.omega if omega is None else omega
        contact_loads(self.balls, self.ring, self.par, self._Q)
        if not include_state:
            self._Q[:] = 0.0
        alpha = max(self.par[s.P_ALPHA0], math.radians(5.0))
        cage_speed = rolling_kinematics(abs(omega), b.D, b.dm, self.par[s.P_ALPHA0])[0]
        F_c = 0.5 * self.par[s.P_M_BALL] * b.dm * cage_speed**2
        axial = abs(F_z) + 2.0 * math.hypot(M_x, M_y) / self.par[s.P_RHO_I]
        estimate = 5.0 * math.hypot(F_x, F_y) / b.Z + axial / (b.Z * math.sin(alpha)) + F_c
        Q_i = np.maximum(self._Q[0], estimate)
        Q_o = np.maximum(self._Q[1], estimate)
        C = self.trib[s.T_C_N]
        loaded = self.trib[s.T_Q] > 0.0
        mu = float(self.trib[s.T_MU][loaded].max()) if loaded.any() else MU_BOUNDARY
        return critical_time_step(self.par, Q_i, Q_o, C[0], C[1], mu * max(Q_i.max(), Q_o.max()))

    def automatic_time_step(self, F_x=0.0, F_y=0.0, F_z=0.0, omega=None, M_x=0.0, M_y=0.0):
        """The automatic step (s) for the given loads (N, N.m) and speed (rad/s; the faster end of a call: the limit
        falls with the centrifugal load): safety x stable_time_step(), and at most DAMPING_PLAN m / c of the ball
        with the largest normal damping c (N.s/m, loaded contacts at the last refresh) or of the ring on its support;
        with a support spring, at most safety x its stability limit 2 / omega_n."""
        dt = self.safety * self.stable_time_step(F_x, F_y, F_z, omega, M_x=M_x, M_y=M_y)
        p = self.par
        # the ring on its support: an explicit spring-mass (2 / omega_n) and damper (c / m) like a contact's
        support = max(p[s.P_K_SUPPORT] / p[s.P_M_RING], p[s.P_KT_SUPPORT] / p[s.P_I_RING])  # omega_n^2 (1/s^2)
        if support > 0.0:
            dt = min(dt, self.safety * 2.0 / math.sqrt(support))
        ratio = damping_step_ratio(self.trib, p, 1.0)[0]  # largest c / m (1/s)
        ratio = max(ratio, p[s.P_C_SUPPORT] / p[s.P_M_RING], p[s.P_CT_SUPPORT] / p[s.P_I_RING])
        return min(dt, DAMPING_PLAN / ratio) if ratio > 0.0 else dt

    # -- inputs --------------------------------------------------------------------------------
    def _check(self, t_end, omega, loads, T_oil, dPd_thermal):
        t = self.time
        if not (math.isfinite(t_end) and t_end > t):
            raise InputError(
                f"t_end = {t_end} s is outside the allowed range ]{t:.9g}, inf[ s (after the current time)"
            )
        self._limits.check((omega, *loads, T_oil, dPd_thermal))  # the order of DEM_INPUTS

    def _load_limit(self):
        """Largest admissible load (N): Z balls at the contact load of the penetration limit (p_max = 6 GPa);
        no load distribution shares a load better than equally over all balls."""
        p = self.par
        q = min((p[s.P_KH_I + r] * p[s.P_DELTA_LIM_I + r] ** 1.5) for r in (0, 1))
        return self.bearing.Z * q

    @property
    def time(self):
        """Simulated time (s)."""
        return float(self.ring[s.R_TIME])

    # -- stepping ------------------------------------------------------------------------------
    def advance(
        self, t_end, omega=None, F_x=0.0, F_y=0.0, F_z=0.0, T_oil=T_OIL_DEFAULT, dPd_thermal=0.0, M_x=0.0, M_y=0.0
    ):
        """Integrate to t_end (s): inner-ring speed from its current value linearly to omega (rad/s; None =
        hold), loads F_x, F_y, F_z (N) and moments M_x, M_y (N.m, about the ring's centre, that of its
        groove-curvature-centre circle: the quasi-static fidelity's) on the inner ring, oil temperature T_oil (K),
        change of diametral clearance dPd_thermal (m, added to Pd, negative = tighter: the outer groove circle
        moves by half of it; the Hertz constants stay those of the nominal geometry, as in the quasi-static
        fidelity). Returns outputs_dict().

        Raises InputError for inputs out of range, DemUnstableError when the monitor stops the run (the
        state is then left at the offending step: restore a saved state to retry)."""
        omega = self.omega if omega is None else float(omega)
        loads = (float(F_x), float(F_y), float(F_z), float(M_x), float(M_y))
        self._advance(float(t_end), omega, loads, float(T_oil), float(dPd_thermal))
        return self.outputs_dict()

    def _advance(self, t_end, omega, loads, T_oil, dPd_thermal):
        """advance() without building the output dict (floats in SI units, omega given; loads = (F_x, F_y, F_z,
        M_x, M_y))."""
        self._check(t_end, omega, loads, T_oil, dPd_thermal)
        F_x, F_y, F_z, M_x, M_y = loads
        self.par[s.P_RHO_O] = self._rho_outer + 0.5 * dPd_thermal
        interval = t_end - self.time
        self._copy_state(self._start, self.__dict__)
        self._start["omega"] = self.omega
        dt = self.dt_fixed
        automatic = dt is None
        if automatic:
            dt = self.automatic_time_step(F_x, F_y, F_z, max(abs(self.omega), abs(omega)), M_x, M_y)
        n_steps = max(1, math.ceil(interval / dt * (1.0 - 1e-12)))
        self.step_halvings = 0
        while True:
            dt = interval / n_steps  # land exactly on t_end
            omega0, orbit0 = self._run(n_steps, dt, omega, loads, T_oil)
            if self.status[s.ST_CODE] == s.STATUS_OK:
                break
            if not automatic or self.step_halvings == AUTO_STEP_HALVINGS:
                self._raise_unstable(dt, *loads)
            # the step was chosen from the state at the start of the call; the film can change within it (a
            # contact entering full film at low speed takes a squeeze damping that overdamps the ball): repeat
            # the call from its start with half the step, or the step the stopped state's film needs if smaller
            smaller = self.automatic_time_step(F_x, F_y, F_z, max(abs(omega0), abs(omega)), M_x, M_y)
            self._restore_start()
            self.step_halvings += 1
            needed = math.ceil(interval / smaller * (1.0 - 1e-12))
            n_steps = max(2 * n_steps, min(needed, 16 * n_steps))  # (a blown-up state's loads are no guide)
        bearing_outputs(
            self.balls,
            self.cage,
            self.ring,
            self.trib,
            self.par,
            self._acc,
            self.omega,
            interval,
            orbit0,
            self.scene.background_capacitance,
            self.averaged,
            self._Q,
            self._alpha,
            self.out,
        )
        self._state_outputs(interval)
        # as the other fidelities: a warning above the ISO 76 limit; beyond the material limit (6 GPa) the
        # monitor has already stopped the step (penetration), so only the warning can apply here
        self.warnings = pressure_warnings(min(self.out[s.O_PMAX], P_MAX_ERROR), "the loads")
        self.warnings += self._oil_watch.warnings(T_oil)
        # the contact ellipses against the shoulders: an output of the interval's end state, not of every step
        tp = self._truncation_parameters
        shoulder_truncation(self.balls, self.ring, self.par, tp, self._Q, self._signed_alpha, self.trunc)
        flags = [bool(v) for v in self.truncated]
        self.warnings += truncation_warnings(tp, self.trunc, self._Q, 0, self._signed_alpha, 0, flags)
        self.truncated[:] = flags

    def _state_outputs(self, interval):
        """The ring's displacement and tilts into out[O_X:O_X + 5]: at the end of the interval, or with averaged_state
        their means over the interval's steps, and then also the loads, pressure and films as means over its tribology
        refreshes (a call without a refresh keeps the end values)."""
        o, acc = self.out, self._acc
        if not self.averaged_state or interval <= 0.0:
            o[s.O_X : s.O_X + 3] = self.ring[s.R_X : s.R_X + 3]
            o[s.O_X + 3 : s.O_X + 5] = self.ring[s.R_TH : s.R_TH + 2]
            return
        o[s.O_X : s.O_X + 5] = acc[s.A_XT : s.A_XT + 5] / interval
        samples = acc[s.A_SAMPLES]
        if samples > 0.0:
            for out_slot, sum_slot in AVERAGED_STATE:
                o[out_slot] = acc[sum_slot] / samples

    def _run(self, n_steps, dt, omega, loads, T_oil):
        """One kernel call of n_steps steps of dt (s) to the inner-ring speed omega; returns the speed and the sum
        of the orbital angles at its start. self.status holds the monitor's verdict."""
        # refreshed at least every refresh_interval: floor, with a guard so that a ratio that is a whole number
        # in exact arithmetic stays one (a round() would flip at x.5 with the last bits of dt, and a master
        # that hands step sizes differing in the last bits would then take other steps)
        refresh = self.refresh_fixed or max(1, math.floor(self.refresh_interval / dt * (1.0 + 1e-9)))
        self.par[s.P_REFRESH] = refresh
        self.dt, self.refresh = dt, refresh
        omega0 = self.omega
        orbit0 = float(self.balls[s.B_ORBIT].sum())
        dyn.advance(
            self.balls,
            self.cage,
            self.ring,
            self.spring,
            self.trib,
            self.counters,
            self.par,
            self.lubricant.array,
            n_steps,
            dt,
            omega0,
            omega,
            *loads,
            T_oil,
            self._energy_limit(max(abs(omega0), abs(omega)), loads),
            self._work,
            self._acc,
            self.status,
        )
        done = int(self.status[s.ST_STEP])
        self.omega = omega0 + (omega - omega0) * done / n_steps
        return omega0, orbit0

    def _energy_limit(self, omega, loads):
        """Bound (J) of the kinetic energy over a call: ENERGY_FACTOR x (pure-rolling kinetic energy at omega + load x
        groove clearance A (a moment M counts as the force M / rho_i, rho_i the radius of the inner groove's
        curvature-centre circle: it tilts the ring by about A / rho_i) + the mechanical energy the state already holds:
        its kinetic energy and the elastic energy of its ball-race contacts, 0.4 Q delta each for Q = K_h delta^1.5).
        Without input the kinetic energy cannot exceed the energy held plus the work of the drive and the loads, so an
        unstable integration passes the bound within a few steps and a physical run never does, also when a load is
        released (its elastic energy turns into motion) or the ring stops while the balls still roll."""
        b, p = self.bearing, self.par
        cage_speed, ball_rel, _, _ = rolling_kinematics(omega, b.D, b.dm, p[s.P_ALPHA0])
        v = 0.5 * b.dm * cage_speed
        rolling = b.Z * (0.5 * (p[s.P_M_BALL] + p[s.P_M_CAGE]) * v * v + 0.5 * p[s.P_I_BALL] * ball_rel**2)
        A = (b.f_i + b.f_o - 1.0) * b.D
        F_x, F_y, F_z, M_x, M_y = loads
        force = math.sqrt(F_x**2 + F_y**2 + F_z**2) + math.hypot(M_x, M_y) / p[s.P_RHO_I]
        held = kinetic_energy(self.balls, self.cage, self.ring, p) + self._elastic_energy()
        return ENERGY_FACTOR * (rolling + force * A + held) + 1e-6

    def _elastic_energy(self):
        """Elastic energy (J) of the current ball-race contacts: sum of the integral of K_h delta^1.5 d delta,
        0.4 Q delta with delta = (Q / K_h)^(2/3)."""
        contact_loads(self.balls, self.ring, self.par, self._Q)
        K_h = self.par[[s.P_KH_I, s.P_KH_O]][:, None]
        return float(0.4 * (self._Q * (self._Q / K_h) ** (2.0 / 3.0)).sum())

    def _raise_unstable(self, dt, F_x, F_y, F_z, M_x=0.0, M_y=0.0):
        code, step, index = (int(v) for v in self.status)
        Z = self.bearing.Z
        where = ""
        # a fixed step that works at these inputs can be stopped again when the film or the loads change (a
        # start-up: the film thickens, the cage's load grows): the automatic step follows them
        alternative = (
            "; or use dt = 0 (automatic: the step follows the loads and the film as they change)"
            if self.dt_fixed is not None
            else ""
        )
        if code == s.STATUS_DAMPING:
            # the stopped state's film; a ball's other contact may still follow into full film: 2 x the largest
            c_max = float(self.trib[s.T_C_N][self.trib[s.T_Q] > 0.0].max())
            raise DemUnstableError(
                f"DEM stopped at t = {self.time:.9g} s (step {step} of the interval) on ball {index}: "
                f"{STATUS_WORDS[code]}. dt = {dt:.3g} s is too large here; use dt <= "
                f"{DAMPING_PLAN * self.par[s.P_M_BALL] / (2.0 * c_max):.3g} s (largest contact damping "
                f"{c_max:.4g} N.s/m){alternative}"
            )
        if index >= 0:
            race = "inner" if index < Z else "outer"
            where = f" at the {race} contact of ball {index % Z}"
        # the state at the stop is already disturbed: judge from the inputs alone, or, when they load no
        # contact (no load, no speed), from the contact loads of the stopped state (larger: a safe side)
        limit = self.stable_time_step(F_x, F_y, F_z, self.omega, include_state=False, M_x=M_x, M_y=M_y)
        basis = "at these inputs"
        if not math.isfinite(limit):
            limit = self.stable_time_step(F_x, F_y, F_z, self.omega, M_x=M_x, M_y=M_y)
            basis = "at the contact loads where the run stopped"
        if math.isfinite(limit):
            suggestion = min(0.5 * dt, self.safety * limit)
            reason = f"stability limit of the stiffest contact pair {basis} {limit:.3g} s"
        else:
            suggestion = 0.5 * dt
            reason = "no contact is loaded, so no contact sets a stability limit"
        raise DemUnstableError(
            f"DEM stopped at t = {self.time:.9g} s (step {step} of the interval){where}: "
            f"{STATUS_WORDS[code]}. dt = {dt:.3g} s is too large here; use dt <= {suggestion:.3g} s ({reason})"
            f"{alternative}"
        )

    # -- outputs -------------------------------------------------------------------------------
    def outputs_dict(self):
        """Bearing-level outputs of the last advance() (names as the quasi-static fidelity), SI units."""
        o = self.out
        result = dict(
            omega_cage=o[s.O_OMEGA_CAGE],
            omega_ball=o[s.O_OMEGA_BALL],
            omega_ball_cage=o[s.O_OMEGA_BALL_REL],
            Q_max_inner=o[s.O_QMAX_I],
            Q_max_outer=o[s.O_QMAX_O],
            p_max=o[s.O_PMAX],
            alpha_inner=o[s.O_ALPHA_I],
            alpha_outer=o[s.O_ALPHA_O],
            Lambda_inner=o[s.O_LAMBDA_I],
            Lambda_outer=o[s.O_LAMBDA_O],
            h_min_inner=o[s.O_HMIN_I],
            h_min_outer=o[s.O_HMIN_O],
            h_c_inner=o[s.O_HC_I],
            h_c_outer=o[s.O_HC_O],
            regime=int(o[s.O_REGIME]),
            C_bearing=o[s.O_C_BEARING],
            n_loaded=int(o[s.O_N_LOADED]),
            P_loss=o[s.O_P_LOSS],
            Q_inner_ring=o[s.O_Q_INNER_RING],
            Q_outer_ring=o[s.O_Q_OUTER_RING],
            torque=o[s.O_TORQUE],
            cage_slip=o[s.O_CAGE_SLIP],
            SRR_max=o[s.O_SRR_MAX],
            kinetic_energy=o[s.O_KINETIC],
            x=o[s.O_X],
            y=o[s.O_X + 1],
            z=o[s.O_X + 2],
            theta_x=o[s.O_X + 3],
            theta_y=o[s.O_X + 4],
        )
        if not self.scene.capacitance:
            del result["C_bearing"]
        return result

    # -- FMU interface ---------------------------------------------------------------------------
    def update(self, u, interval=0.0):
        """Advance by `interval` (s; 0 = only report the current state) with the input values u in self.inputs
        order (omega, F_x, F_y, F_z, M_x, M_y, T_oil, dPd_thermal; SI) as advance() takes them, and fill self.values
        (self.outputs order: the declarations of models.declarations.DEM_OUTPUTS); returns self.values.

        Raises InputError for inputs out of range (nothing changed) and DemUnstableError when the monitor stops
        the step: the state is then restored to the start of the step and self.status keeps the monitor's code."""
        if interval != 0.0:
            if not (math.isfinite(interval) and interval >= COMMUNICATION_RESOLUTION):
                raise InputError(
                    f"communication step = {interval} s is outside the allowed range "
                    f"[{COMMUNICATION_RESOLUTION:g}, inf[ s"
                )
            # on a grid of 1 ps: masters that hand the same nominal step in different roundings (libcosim counts
            # integer nanoseconds, fmpy multiplies n H) then take the same DEM steps, bit for bit
            self._step_to(self.time + round(interval, COMMUNICATION_DIGITS), u)
        self._gather()
        return self.values

    def _step_to(self, t_end, u):
        """update()'s step to t_end (s): advance, or on a monitor stop restore the state and raise."""
        omega, F_x, F_y, F_z, M_x, M_y, T_oil, dPd_thermal = (float(v) for v in u)
        loads = (F_x, F_y, F_z, M_x, M_y)
        self.status[s.ST_CODE] = s.STATUS_OK  # a refused input leaves no stale monitor code
        self.warnings = []  # nor stale warnings
        self._check(t_end, omega, loads, T_oil, dPd_thermal)
        try:
            self._advance(t_end, omega, loads, T_oil, dPd_thermal)
        except DemUnstableError:
            self._restore_start()
            raise

    def _gather(self):
        if self.scene.stiffness:
            self.stiffness_matrix(self.K)
        o = self.out
        self.frequencies[:] = pass_frequencies(self.omega, o[s.O_OMEGA_CAGE], o[s.O_OMEGA_BALL_REL], self.bearing.Z)
        for src, idx, dst in self._plan:
            self.values[dst] = src[idx]

    def stiffness_matrix(self, K=None):
        """5x5 stiffness dF_i/dd_j of the inner ring in the current state, (F) = (F_x, F_y, F_z, M_x, M_y) in N and
        N.m, (d) = (x, y, z, theta_x, theta_y) in m and rad, the quasi-static fidelity's convention: each ball's
        inner and outer contact tangent stiffnesses condensed in series (kernels.ball_dynamics.stiffness,
        docs/dem.md, Stiffness). Written into K (float64[5, 5]) if given; returned."""
        K = np.zeros((5, 5)) if K is None else K
        stiffness_matrix(self.balls, self.ring, self.par, K)
        return K

    def _copy_state(self, target, source):
        for name in self.STATE_ARRAYS:
            np.copyto(target[name], source[name])

    def _restore_start(self):
        """Back to the state at the start of the last kernel call (_advance)."""
        self._copy_state(self.__dict__, self._start)
        self.omega = self._start["omega"]

    def evaluate(self, time, **values):
        """Advance to `time` (s) with the named inputs (missing ones take their start values: 0, T_oil 313.15 K) as
        update() does (update(u, H) is evaluate(self.time + H, ...)); the outputs as a dict name -> SI value
        (integers for integer outputs)."""
        self._step_to(float(time), [values.get(v.name, v.start) for v in self.inputs])
        self._gather()
        return self.as_dict()

    def as_dict(self):
        """The outputs of the last update() as a dict name -> SI value (integers for integer outputs)."""
        return outputs_as_dict(self.outputs, self.values)

    def contacts(self):
        """Per-ball arrays (Z,): azimuth psi (rad, in [0, 2 pi)), orbital and spin speeds (rad/s), and per race
        ('_inner', '_outer') the current load Q (N) and approach delta (m), and the last refresh's film
        h_min, h_c (m), Lambda, regime, mu, normal damping C_n (N.s/m), SRR, entrainment speed u (m/s),
        capacitance C (F) and Hertz semi-axes a, b (m); the current contact angle alpha (rad)."""
        contact_loads(self.balls, self.ring, self.par, self._Q)
        contact_angles(self.balls, self.ring, self.par, self._alpha)
        x, y = self.balls[s.B_X], self.balls[s.B_X + 1]
        r2 = x * x + y * y
        result = {
            "psi": np.mod(np.arctan2(y, x), 2.0 * math.pi),
            "omega_orbit": (x * self.balls[s.B_VX + 1] - y * self.balls[s.B_VX]) / r2,
            "omega_spin": np.linalg.norm(self.balls[s.B_WX : s.B_WX + 3], axis=0),
        }
        names = {
            "Q": None,
            "h_min": s.T_H_MIN,
            "h_c": s.T_H_C,
            "Lambda": s.T_LAMBDA,
            "regime": s.T_REGIME,
            "mu": s.T_MU,
            "C_n": s.T_C_N,
            "SRR": s.T_SRR,
            "u": s.T_U,
            "C": s.T_CAP,
            "a": s.T_A,
            "b": s.T_B,
        }
        for race, suffix in ((0, "_inner"), (1, "_outer")):
            for name, row in names.items():
                result[name + suffix] = self._Q[race].copy() if row is None else self.trib[row, race].copy()
            result["delta" + suffix] = (self._Q[race] / self.par[s.P_KH_I + race]) ** (2.0 / 3.0)
            result["alpha" + suffix] = self._alpha[race].copy()
        return result

    def record(self, t_end, interval, omega=None, **inputs):
        """Advance to t_end (s) in steps of `interval` (s), recording after each: returns a dict of numpy arrays,
        't' (n,) and every bearing output (n,), and under 'contacts' a dict of every per-ball/per-contact
        array of contacts() (n, Z).
        The speed goes linearly from its current value to omega (rad/s; None = hold) over the whole record;
        the other inputs (F_x, F_y, F_z, M_x, M_y, T_oil, dPd_thermal) are held."""
        if not (math.isfinite(interval) and interval > 0.0):
            raise InputError(f"interval = {interval} s is outside the allowed range ]0, inf[ s")
        t0, omega0 = self.time, self.omega
        omega = omega0 if omega is None else float(omega)
        n = max(1, math.ceil((float(t_end) - t0) / interval - 1e-9))
        rows = []
        for k in range(1, n + 1):
            t = min(t0 + k * interval, float(t_end))
            out = self.advance(t, omega=omega0 + (omega - omega0) * (t - t0) / (float(t_end) - t0), **inputs)
            rows.append((t, out, self.contacts()))
        result = {"t": np.array([r[0] for r in rows])}
        for name in rows[0][1]:
            result[name] = np.array([r[1][name] for r in rows])
        result["contacts"] = {name: np.array([r[2][name] for r in rows]) for name in rows[0][2]}
        return result

    # -- state (FMU get/set state, rollback) ---------------------------------------------------
    STATE_ARRAYS = ("balls", "cage", "ring", "spring", "trib", "counters", "truncated")

    def get_state(self):
        """Copy of the whole dynamic state (every array and the current inner-ring speed)."""
        state = {name: getattr(self, name).copy() for name in self.STATE_ARRAYS}
        state["omega"] = self.omega
        return state

    def set_state(self, state):
        """Restore a state from get_state() (arrays are copied in place)."""
        for name in self.STATE_ARRAYS:
            getattr(self, name)[...] = state[name]
        self.omega = float(state["omega"])
