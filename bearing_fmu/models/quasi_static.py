"""QuasiStaticModel: facade of the quasi-static fidelity (kernels.jones_harris + kernels.contact_outputs).

One bearing, lubricant and scene; inputs and outputs are SI and declared once in models.declarations
(QUASI_STATIC_INPUTS, QUASI_STATIC_OUTPUTS): the model fills a preallocated output array in that order
and the FMU class registers its FMI variables from the same declarations. The solver state (inner-ring
displacements and ball positions) is kept between calls for warm starts and is part of the FMU state.
"""

import math
from dataclasses import replace

import numpy as np

from bearing_fmu_common.variables import InputLimits, outputs_as_dict, select

from ..kernels import ball_traction as bt
from ..kernels import bearing_outputs as bo
from ..kernels import contact_outputs as ck
from ..kernels import jones_harris
from ..kernels import rating_life as rl
from ..kernels import truncation as tk
from ..kernels.geometry import ball_mass, free_contact_angle
from ..kernels.hertz import hertz_contact, hertz_stiffness
from ..kernels.lubricant import lubricant_state
from ..kernels.torque import TL_SIZE
from ..params import check_roughness, load_bearing, load_lubricant
from ..scene import LUBRICATION_METHODS, RACE_CONTROLS, Scene
from .blocks import capacitance_block, write_blocks
from .declarations import (
    DEFAULT_FIXED_PRELOAD,
    DISPLACEMENT_LIMIT,
    DOF_NAMES,
    DRIVE_CONTROL,
    LOAD_NAMES,
    QUASI_STATIC_INPUTS,
    QUASI_STATIC_OUTPUTS,
    QUASI_STATIC_PARAMETERS,
)
from .fidelity import Fidelity
from .film_table import film_table_array
from .friction import FrictionWatch
from .input_checks import check_clearance, named_bearing
from .limits import (
    DM_N_LIMIT,
    MATERIAL_LIMIT,
    TILT_LIMIT,
    InputError,
    OilTemperatureWatch,
    material_load_limit,
    pressure_warnings,
)
from .lubrication import Lubrication, LubricationWatch, lubrication_block
from .race_contacts import (
    contact_terms,
    pack,
    race_contacts,
    traction_block,
    truncation_parameters,
    truncation_warnings,
)

RACE_CODES = {
    "outer": jones_harris.RACE_OUTER,
    "inner": jones_harris.RACE_INNER,
    "hybrid": jones_harris.RACE_HYBRID,
    "traction": jones_harris.RACE_TRACTION,
}
# rad: the thrust-side check refuses loaded inner contacts below +1e-8 rad. A radial load without thrust puts
# the loaded balls of a free single angular-contact bearing at the groove bottom (angle 0, returned to the
# solver's rounding, ~1e-12 rad of either sign), where nothing locates the ring axially and it is nearly free
# to tilt: refused every time, not by the sign of a rounding error. Any thrust lifts the angles far above it.
SHOULDER_ANGLE_TOL = 1e-8
# readings of the hybrid model's gyroscopic-moment share (Python API only, for sensitivity studies;
# the FMUs use 'spin_moments'): docs/quasistatic.md section 2, tests/validation/test_quasistatic_literature.py
HYBRID_SPLITS = {
    "spin_moments": jones_harris.RACE_HYBRID,
    "outer": jones_harris.RACE_HYBRID_OUTER_SPLIT,
    "inner": jones_harris.RACE_HYBRID_INNER_SPLIT,
    "equal": jones_harris.RACE_HYBRID_EQUAL_SPLIT,
    "controlling_race": jones_harris.RACE_HYBRID_CONTROLLING,
}
_PARAMETERS = {v.name: v for v in QUASI_STATIC_PARAMETERS}


class SolverError(InputError):
    """The equilibrium could not be found (message says why and for which inputs)."""


class QuasiStaticModel:
    """Quasi-static 5-DOF bearing (Jones/Harris, docs/quasistatic.md) with film, capacitance and Houpert losses.

    bearing, lubricant: catalogue name or TOML path; scene: Scene with fidelity 'quasi_static';
    Pd: diametral clearance (m) overriding the bearing file (None: the file's), within
        -(f_i + f_o - 1) D <= Pd <= (f_i + f_o - 1) D (free contact angle up to 60 deg);
    race_control: 'outer' | 'inner' | 'hybrid' | 'traction' (default: the scene's); 'traction' takes no hypothesis:
        each ball's kinematics follow from its balance with the lubricant's traction curve (kernels.ball_traction);
    hybrid_split: with race_control 'hybrid', how the gyroscopic moment is shared between the races:
        'spin_moments' (default, lam_i = 2C/(1+C)); 'outer', 'inner', 'equal' and 'controlling_race'
        are the other readings of Rabreau's lost Table 1, kept for sensitivity studies (HYBRID_SPLITS);
    lubrication: the lubrication method (docs/lubrication_method.md) at its default settings, overriding the scene's
        for the physics (None: the scene's, with its settings); the outputs stay those of the scene (a flooded
        scene has no phi_* or drag outputs; a method's scene run flooded reports the factors 1 and no drag);
    F_preload: fixed_axial drive only, axial preload (N, >= 0) set at assembly (at rest, no thermal
        change): the model holds the axial approach z0 (m) that carries it, and the input z (and
        dz_thermal) is added to z0. 0 (default) = z is the axial approach itself.
    film_tables: directory of the film tables an FMU carries (models.film_table); None = this machine's cache.
    """

    def __init__(
        self,
        bearing="B7214C",
        lubricant="iso_vg68_mineral",
        scene=None,
        Pd=None,
        race_control=None,
        F_preload=0.0,
        hybrid_split="spin_moments",
        lubrication=None,
        film_tables=None,
    ):
        self.scene = (scene or Scene(name="quasi_static", fidelity="quasi_static")).validate()
        self.film_tables = film_tables
        if self.scene.fidelity != "quasi_static":
            raise InputError(
                f"scene '{self.scene.name}' has fidelity {self.scene.fidelity!r}: QuasiStaticModel needs 'quasi_static'"
            )
        self.bearing = load_bearing(bearing)
        self.lubricant = load_lubricant(lubricant)
        b = self.bearing
        self.Pd = b.Pd if Pd is None else float(Pd)
        check_clearance(self.Pd, b, Pd is not None)
        self.lubrication = self.scene.lubrication if lubrication is None else lubrication
        if self.lubrication not in LUBRICATION_METHODS:
            raise InputError(f"lubrication = {self.lubrication!r} is not allowed: allowed {list(LUBRICATION_METHODS)}")
        self.race_control = self.scene.race_control if race_control is None else race_control
        if self.race_control not in RACE_CONTROLS:
            raise InputError(f"race_control = {self.race_control!r} is not allowed: allowed {list(RACE_CONTROLS)}")
        if hybrid_split not in HYBRID_SPLITS:
            raise InputError(f"hybrid_split = {hybrid_split!r}: allowed {list(HYBRID_SPLITS)}")
        self.hybrid_split = hybrid_split
        self.control = np.array(DRIVE_CONTROL[self.scene.drive], dtype=float)
        self.omega_max = DM_N_LIMIT / (b.dm * 1e3) * 2.0 * math.pi / 60.0
        check_roughness(b.Ra_inner, b.Ra_outer, b.Ra_ball, b.path)  # the reader's check, for a Bearing made by hand
        self.qs, self.cp = self._pack()
        self.groove = (b.f_i + b.f_o - 1.0) * b.D
        self.load_limit = self._load_limit()
        self._allocate(b.Z)
        self.F_preload = float(F_preload)
        if self.F_preload and self.scene.drive != "fixed_axial":
            raise InputError(
                f"F_preload = {F_preload} N needs drive = 'fixed_axial' (scene '{self.scene.name}' "
                f"has drive {self.scene.drive!r})"
            )
        _PARAMETERS["F_preload"].check(
            self.F_preload,
            0.0,
            self.load_limit,
            f"the upper bound is the material limit of {named_bearing(self.bearing)}: p_max = 6 GPa with the load on "
            "all balls",
        )
        self.z0 = self.axial_approach(self.F_preload) if self.F_preload else 0.0
        self._plan_variables()

    def _allocate(self, Z):
        """The solver's arrays for Z balls, the outputs at rest and the watches that warn once per entry."""
        self.d = np.zeros(5)
        self.X = np.zeros((jones_harris.X_SIZE, Z))
        self.F = np.zeros(5)
        self.K = np.zeros((5, 5))
        self.balls = np.zeros((jones_harris.BQ_SIZE, Z))
        self.per_contact = np.zeros((ck.PC_SIZE, Z))
        self.out = np.zeros(ck.CO_SIZE)
        self.out[ck.CO_PHI_ISH_I : ck.CO_PHI_RS_O + 1] = 1.0  # a flooded run of a method's scene: factors 1
        self._losses = np.zeros(TL_SIZE)
        self.status = (jones_harris.QS_OK, 0, 0.0)
        self.warnings = []
        self._oil_watch = OilTemperatureWatch(self.lubricant)
        self._lubrication_watch = LubricationWatch(self.lubrication_numbers, self.lubricant)
        # shoulder truncation of the contact ellipses (kernels.truncation), the races truncated at the last
        # evaluation (a warning is logged on entry only)
        self._trunc = np.zeros(tk.TR_SIZE)
        self._truncated = [0.0, 0.0]  # per race the truncated fraction at its last warning (0: not truncated)
        self._friction = FrictionWatch(self.race_control, self.lubricant.traction_limit, self.lubricant.name)

    def _plan_variables(self):
        """The scene's inputs and outputs, where each output comes from (kernels.bearing_outputs codes) and where
        update() finds each input in its list u (positions resolved once, not a dict per step)."""
        self.inputs = select(QUASI_STATIC_INPUTS, self.scene)
        self.input_names = tuple(v.name for v in self.inputs)
        self._input_starts = {v.name: v.start for v in self.inputs}
        self.outputs = select(QUASI_STATIC_OUTPUTS, self.scene)
        self.output_names = tuple(v.name for v in self.outputs)
        self.values = np.zeros(len(self.outputs))  # outputs of the last evaluation, in self.outputs order
        # where each output slot comes from, as the codes of kernels.bearing_outputs
        codes = {
            "out": bo.SRC_OUT,
            "d": bo.SRC_D,
            "F": bo.SRC_F,
            "K": bo.SRC_K,
            "ball_set": bo.SRC_BALL_SET,
            "trunc": bo.SRC_TRUNC,
        }
        # the rating-life slots are filled after the output kernel (_collect): it copies a placeholder there
        sourced = [(codes[v.source[0]], v.source[1]) if v.source[0] in codes else (bo.SRC_OUT, 0) for v in self.outputs]
        self._source = np.array([code for code, _ in sourced], dtype=np.int64)
        self._index = np.array([index for _, index in sourced], dtype=np.int64)
        self._life_slots = np.array([k for k, v in enumerate(self.outputs) if v.source[0] == "life"], dtype=np.int64)
        self._life_index = np.array([v.source[1] for v in self.outputs if v.source[0] == "life"], dtype=np.int64)
        self._life = np.zeros(rl.LO_SIZE)
        self._life_parameters = self._rating_parameters() if self.scene.life else np.zeros(rl.LP_SIZE)
        self._K_flat = self.K.reshape(-1)  # a view: the solver writes K in place
        self._summary = np.zeros(bo.BS_SIZE)
        self._load_controlled = tuple(bool(c) for c in self.control)  # per DOF, as plain booleans
        position = {name: k for k, name in enumerate(self.input_names)}
        self._u_omega, self._u_T_oil = position["omega"], position["T_oil"]
        self._u_dPd, self._u_dz = position.get("dPd_thermal"), position.get("dz_thermal")
        self._u_loads = tuple((i, position[LOAD_NAMES[i]]) for i in range(5) if self._load_controlled[i])
        self._u_dofs = tuple((i, position[DOF_NAMES[i]]) for i in range(5) if not self._load_controlled[i])
        self._applied = np.zeros(5)  # the applied loads of the step (0 on displacement-driven DOFs)
        self._limits = self._input_limits()

    def _input_limits(self):
        """The allowed range of each input: the declared one narrowed by this bearing's limits (d_m n, material
        load limit, groove clearance A for imposed displacements, 0.02 D for thermal changes)."""
        narrowed = {"omega": (-self.omega_max, self.omega_max, f"d_m n <= {DM_N_LIMIT:.0e} mm.rpm")}
        for i, name in enumerate(LOAD_NAMES):
            limit = self.load_limit * (1.0 if i < 3 else 0.5 * self.bearing.dm)
            narrowed[name] = (-limit, limit, MATERIAL_LIMIT)
        for i, name in enumerate(DOF_NAMES):
            if i >= 3:
                narrowed[name] = (-TILT_LIMIT, TILT_LIMIT, "")
            else:
                limit = DISPLACEMENT_LIMIT * self.groove
                narrowed[name] = (-limit, limit, "|d| <= 0.5 (f_i + f_o - 1) D: beyond it past any material limit")
        limit = 0.02 * self.bearing.D
        for name in ("dPd_thermal", "dz_thermal"):
            narrowed[name] = (-limit, limit, "|value| <= 0.02 D")
        return InputLimits(self.inputs, narrowed)

    # -- set-up --------------------------------------------------------------------------------
    def _pack(self):
        b, s = self.bearing, self.scene
        rc = race_contacts(b, s, self.Pd)
        Rx_i, Ry_i, Rx_o, Ry_o, ci, co, E_red = rc.Rx_i, rc.Ry_i, rc.Rx_o, rc.Ry_o, rc.ci, rc.co, rc.E_red
        self._truncation_parameters = truncation_parameters(b, rc, self.Pd)
        qs = np.zeros(jones_harris.QS_SIZE)
        qs[jones_harris.QS_Z] = b.Z
        qs[jones_harris.QS_D] = b.D
        qs[jones_harris.QS_DM] = b.dm
        qs[jones_harris.QS_FI] = b.f_i
        qs[jones_harris.QS_FO] = b.f_o
        qs[jones_harris.QS_PD] = self.Pd
        qs[jones_harris.QS_ANGULAR] = 1.0 if b.kind == "angular_contact" else 0.0
        spring = rl.iso16281_spring_constant if s.spring_constant == "iso_ts_16281" else hertz_stiffness
        qs[jones_harris.QS_K_I] = spring(Rx_i, Ry_i, E_red, *ci)
        qs[jones_harris.QS_K_O] = spring(Rx_o, Ry_o, E_red, *co)
        qs[jones_harris.QS_M_BALL] = ball_mass(b.D, b.ball.rho)
        qs[jones_harris.QS_RACE] = (
            HYBRID_SPLITS[self.hybrid_split] if self.race_control == "hybrid" else RACE_CODES[self.race_control]
        )
        qs[jones_harris.QS_CENTRIFUGAL] = 1.0 if s.centrifugal else 0.0
        qs[jones_harris.QS_GYROSCOPIC] = 1.0 if s.gyroscopic else 0.0
        # hybrid law: C = Q_i a_i E_i / (Q_o a_o E_o); a ~ Q^(1/3) gives C = c_hyb (Q_i/Q_o)^(4/3)
        a_i = hertz_contact(1.0, Rx_i, Ry_i, E_red, *ci)[0]
        a_o = hertz_contact(1.0, Rx_o, Ry_o, E_red, *co)[0]
        qs[jones_harris.QS_C_HYB] = a_i * ci[1] / (a_o * co[1])
        qs[jones_harris.QS_TOL] = s.tolerance
        qs[jones_harris.QS_MAXIT] = s.max_iterations
        qs[jones_harris.QS_STIFFNESS] = 1.0 if s.stiffness else 0.0
        self._traction = self.race_control == "traction"
        write_blocks(qs, ((jones_harris.QS_TRACTION, traction_block(b, s, rc, self.lubricant, self._traction)),))
        cp = np.zeros(ck.CP_SIZE)
        pack(cp, ck, "CP_", contact_terms(b, s, rc))
        cp[ck.CP_D] = b.D
        cp[ck.CP_TORQUE] = 1.0 if s.torque else 0.0
        cp[ck.CP_DM] = b.dm
        if self.lubrication != s.lubrication:  # the parameter's method at its defaults
            s = replace(s, lubrication=self.lubrication, oil_level=None, inlet_oil_layer=None, cavity_oil_fraction=None)
        self.lubrication_numbers = Lubrication(s, b.D, b.dm)
        write_blocks(
            cp,
            (
                (ck.CP_FILM_TABLE, film_table_array(b, self.lubricant, s.film_correction, self.film_tables)),
                (ck.CP_LUBRICATION_BLOCK, lubrication_block(self.lubrication_numbers, s.torque)),
                (ck.CP_CAPACITANCE_BLOCK, capacitance_block(s)),
            ),
        )
        return qs, cp

    def _rating_parameters(self):
        """kernels.rating_life LP_* array. The ratings are those of the bearing's design: a deep-groove bearing at
        the nominal angle 0 (radial contact), an angular-contact bearing at the nominal angle of its file (the
        free contact angle of the file's clearance, which the file's angle gives; a Pd override, e.g. a
        preload, changes the load distribution, not the rating). Taken from the clearance, the angle is the
        same bit for bit whether the file gives the angle or the equivalent clearance."""
        b = self.bearing
        angular = b.kind == "angular_contact"
        alpha = free_contact_angle(b.D, b.f_i, b.f_o, b.Pd) if angular else 0.0
        lp = np.zeros(rl.LP_SIZE)
        rl.rating_parameters(1.0 if angular else 0.0, b.Z, b.D, b.dm, b.f_i, b.f_o, alpha, lp)
        return lp

    def _load_limit(self):
        """Largest admissible load (N): all Z balls at the contact load giving p_max = P_MAX_ERROR."""
        cp = self.cp
        contacts = [
            [cp[key + o] for key in (ck.CP_RX_I, ck.CP_RY_I, ck.CP_K_I, ck.CP_EE_I, ck.CP_KK_I)] for o in (0, 5)
        ]
        return material_load_limit(self.bearing.Z, cp[ck.CP_E_RED], contacts)

    def axial_approach(self, F_axial):
        """Axial approach z (m) at which this bearing alone carries the axial load F_axial (N) at rest,
        with no thermal change (the assembly offset of a fixed preload)."""
        Z = self.bearing.Z
        d = np.zeros(5)
        axial = np.array([0.0, 0.0, 1.0, 0.0, 0.0])
        status, _, res = jones_harris.solve_quasistatic(
            F_axial * axial,
            axial,
            d,
            self.qs,
            0.0,
            0.0,
            np.zeros((2, Z)),
            np.zeros(5),
            np.zeros((5, 5)),
            np.zeros((jones_harris.BQ_SIZE, Z)),
        )
        if status != jones_harris.QS_OK:
            raise SolverError(
                f"bearing '{self.bearing.name}': axial position under F = {F_axial} N at rest not "
                f"found (status {status}, residual {res:.3g} N)"
            )
        return float(d[2])

    # -- evaluation ----------------------------------------------------------------------------
    def check_inputs(self, values):
        """Raise InputError naming the first input (values: name -> SI value) outside its allowed range."""
        self._limits.check([values[name] for name in self.input_names])

    def evaluate(self, **values):
        """Outputs (dict name -> SI value) for the inputs of self.inputs (missing ones take their start
        value: 0, T_oil 313.15 K).

        Raises InputError for inputs out of range or loads beyond the material limit, SolverError
        when no equilibrium is found; fills self.warnings (p_max above the ISO 76 limit)."""
        starts = self._input_starts
        self.update([values.get(name, starts[name]) for name in self.input_names])
        return self.as_dict()

    def as_dict(self):
        """The outputs of the last evaluation as a dict name -> SI value (integers for integer outputs)."""
        return outputs_as_dict(self.outputs, self.values)

    def update(self, u):
        """Evaluate for the input values u in self.inputs order (SI) and fill self.values (self.outputs
        order); returns self.values. Raises as evaluate()."""
        self._limits.check(u)
        omega = float(u[self._u_omega])
        applied = self._applied
        for i, k in self._u_loads:
            applied[i] = u[k]
        for i, k in self._u_dofs:
            self.d[i] = u[k]
        if not self.control[2]:
            self.d[2] += self.z0 + (0.0 if self._u_dz is None else float(u[self._u_dz]))
        dPd = 0.0 if self._u_dPd is None else float(u[self._u_dPd])
        if self._traction:  # the film's traction at the oil temperature
            eta, xi, _ = lubricant_state(float(u[self._u_T_oil]), self.lubricant.array)
            self.qs[jones_harris.QS_TRACTION + bt.TR_ETA] = eta
            self.qs[jones_harris.QS_TRACTION + bt.TR_XI] = xi
        self._solve(applied, dPd, omega, u)
        ck.contact_outputs(
            omega,
            float(u[self._u_T_oil]),
            self.cp,
            self.lubricant.array,
            self.balls,
            self.out,
            self.per_contact,
            self._losses,
        )
        # the contact ellipses against the shoulders (an output: nothing of the solution changes)
        tk.race_truncation(
            self.balls, jones_harris.BQ_Q_I, self.balls, jones_harris.BQ_A_I, self._truncation_parameters, self._trunc
        )
        return self._collect(omega, u)

    def _shown(self, u):
        """The inputs u as 'name = value unit' for a message."""
        return ", ".join(f"{v.name} = {u[k]:.6g} {v.unit}" for k, v in enumerate(self.inputs))

    def _solve(self, applied, dPd, omega, u):
        d_start = self.d.copy()
        X_start = self.X.copy()
        status, iters, res = jones_harris.solve_quasistatic(
            applied, self.control, self.d, self.qs, dPd, omega, self.X, self.F, self.K, self.balls
        )
        if status != jones_harris.QS_OK:  # the warm start can be far off after a big input jump: retry cold
            self.d[:] = np.where(self.control > 0.5, 0.0, d_start)
            self.X[:] = 0.0
            status, more, res = jones_harris.solve_quasistatic(
                applied, self.control, self.d, self.qs, dPd, omega, self.X, self.F, self.K, self.balls
            )
            iters += more
        self.status = (status, iters, res)
        if status != jones_harris.QS_OK:
            self.d[:] = d_start
            self.X[:] = X_start
            self._refuse_without_thrust(applied, u)
            self._refuse_beyond_the_groove_centre(res, u)
            reason = {
                jones_harris.QS_NOT_CONVERGED: f"no convergence in {self.scene.max_iterations} iterations",
                jones_harris.QS_BALL_NOT_CONVERGED: "a ball equilibrium did not converge",
                jones_harris.QS_NOT_FINITE: "the iteration produced a non-finite value",
            }[status]
            raise SolverError(
                f"quasi-static equilibrium not found ({reason}, load residual {res:.3g} N) for {self._shown(u)}"
            )
        if self.bearing.kind == "angular_contact":
            self._check_thrust_side(d_start, X_start, u)
        try:
            self._friction.refuse_friction_alone(self.balls, applied, self.control, lambda: self._shown(u))
        except InputError:
            self.d[:] = d_start
            self.X[:] = X_start
            raise

    def _refuse_without_thrust(self, applied, u):
        """An equilibrium not found for a single angular-contact bearing whose thrust is load-controlled and not
        positive, under a radial load or moment: the physical reason, not the solver's. With F_z <= 0 the axial
        balance sum Q sin(alpha) = F_z leaves loaded balls at the groove bottom or beyond (_check_thrust_side):
        a state the bearing cannot take, and nearly free to slide and tilt, where the solver may also stall."""
        if self.bearing.kind != "angular_contact" or not self.control[2] or applied[2] > 0.0:
            return
        if not any(applied[i] != 0.0 for i in (0, 1, 3, 4) if self.control[i]):
            return
        raise InputError(
            f"bearing '{self.bearing.name}' is a single-row angular-contact bearing: it carries thrust in +z only, "
            f"and a radial load or moment with F_z = {applied[2]:.6g} N needs its missing shoulder, or leaves its "
            f"balls at the groove bottom with nothing to locate it axially (no equilibrium found there). Carry the "
            f"reverse thrust, or the thrust a radial load needs, with a second bearing or a preload "
            f"(bearing_fmu.models.pair). Allowed: F_z > 0 with a radial load or moment. Inputs: {self._shown(u)}"
        )

    def _refuse_beyond_the_groove_centre(self, res, u):
        """An equilibrium not found where the ring has crossed so much of its clearance that a ball lies beyond the
        centre of curvature of its inner groove (inner contact angle beyond 90 deg, self.balls: the solver's last
        state): the physical reason, not the solver's. There the model's full-circle inner groove closes on the
        ball from behind, a contact the ring does not have, and the ball's state jumps between that contact and
        none (docs/quasistatic.md section 3): the loads have no continuous equilibrium to converge to."""
        cos_inner = np.cos(self.balls[jones_harris.BQ_A_I])
        if not np.all(np.isfinite(cos_inner)) or cos_inner.min() > 0.0:
            return
        j = int(np.argmin(cos_inner))
        b = self.bearing
        raise SolverError(
            f"quasi-static equilibrium not found (load residual {res:.3g} N): under these loads the inner ring of "
            f"bearing '{b.name}' (P_d = {self.Pd:.4g} m, free contact angle "
            f"{math.degrees(free_contact_angle(b.D, b.f_i, b.f_o, self.Pd)):.3g} deg) crosses so much of its "
            f"clearance that ball {j} lies beyond the centre of curvature of its inner groove (inner contact angle "
            f"{math.degrees(self.balls[jones_harris.BQ_A_I, j]):.4g} deg): there the model's full-circle groove "
            f"would press it from behind, a contact the ring does not have, and no equilibrium of the model "
            f"describes the bearing. Allowed: loads and clearances that keep every inner contact angle below 90 deg "
            f"(less clearance, more thrust or less radial load or moment). Inputs: {self._shown(u)}"
        )

    def _check_thrust_side(self, d_start, X_start, u):
        """Refuse a solution that needs the shoulder a single-row angular-contact bearing does not have, or that
        leaves its loaded balls at the groove bottom (a radial load without thrust: no axial location).

        The kernel's grooves are full circles; the bearing's inner ring has its thrust shoulder on the side of
        positive contact angles only (z = 0 where the balls touch it at the free angle). A loaded inner contact
        at a negative angle would be a ball pressed on the missing shoulder: the load (a reverse thrust, or a
        radial load or moment with too little thrust) must be carried by another bearing or a preload
        (models.pair, or a second bearing FMU)."""
        balls = self.balls
        # the usual case: no inner contact at or below the groove bottom (a list's min is a fraction of numpy's fixed
        # cost for a few dozen balls; NaN never passes)
        if min(balls[jones_harris.BQ_A_I].tolist()) >= SHOULDER_ANGLE_TOL:
            return
        wrong = (balls[jones_harris.BQ_Q_I] > 0.0) & (balls[jones_harris.BQ_A_I] < SHOULDER_ANGLE_TOL)
        if not wrong.any():
            return
        j = int(np.argmax(np.where(wrong, balls[jones_harris.BQ_Q_I], -1.0)))
        self.d[:] = d_start
        self.X[:] = X_start
        shown = self._shown(u)
        raise InputError(
            f"bearing '{self.bearing.name}' is a single-row angular-contact bearing: it carries thrust in +z only, "
            f"and these loads need its missing shoulder, or leave its balls at the groove bottom with nothing to "
            f"locate it axially (ball {j} would carry {balls[jones_harris.BQ_Q_I, j]:.4g} N at a contact angle of "
            f"{math.degrees(balls[jones_harris.BQ_A_I, j]):.3g} deg). Carry the reverse thrust, or the thrust a "
            f"radial load needs, with a second bearing or a preload (bearing_fmu.models.pair). Allowed: loads with "
            f"which every loaded ball touches the inner ring at a contact angle above {SHOULDER_ANGLE_TOL:g} rad. "
            f"Inputs: {shown}"
        )

    def _collect(self, omega, u):
        """Fill self.values from the solver's and the contact kernel's arrays (declaration order)."""
        out = self.out
        self.warnings = pressure_warnings(out[ck.CO_PMAX], "the loads") + self._oil_watch.warnings(u[self._u_T_oil])
        bad = bo.quasi_static_outputs(
            self.balls,
            omega,
            int(self.status[1]),
            out,
            self.d,
            self.F,
            self._K_flat,
            self._trunc,
            self._source,
            self._index,
            self._summary,
            self.values,
        )
        if self.scene.life:
            F, balls = self.F, self.balls
            rl.rating_life(
                balls[jones_harris.BQ_Q_I],
                balls[jones_harris.BQ_Q_O],
                math.hypot(F[0], F[1]),
                abs(F[2]),
                omega,
                self._life_parameters,
                self._life,
            )
            self.values[self._life_slots] = self._life[self._life_index]
        if bad >= 0:
            raise SolverError(
                f"output {self.output_names[bad]} is not finite ({self.values[bad]}) for {self._shown(u)}: "
                f"please report this case"
            )
        self.warnings += truncation_warnings(
            self._truncation_parameters,
            self._trunc,
            self.balls,
            jones_harris.BQ_Q_I,
            self.balls,
            jones_harris.BQ_A_I,
            self._truncated,
        )
        summary = self._summary
        inner = summary[bo.BS_ALPHA_I] if out[ck.CO_QMAX_I] > 0.0 else None
        mu_required = (summary[bo.BS_MU_REQ_I], summary[bo.BS_MU_REQ_O])
        self.warnings += self._friction.warnings(mu_required, inner, self.balls, u)
        self.warnings += self._lubrication_watch.warnings(omega, (out[ck.CO_PHI_RS_I], out[ck.CO_PHI_RS_O]))
        return self.values

    # -- state (FMU get/set state, rollback) ---------------------------------------------------
    def get_state(self):
        """Solver state as plain lists (JSON-serialisable): displacements, ball states, the races whose contact
        ellipse was truncated (their warning is logged on entry only) and the friction watch's state."""
        return {
            "d": self.d.tolist(),
            "X": self.X.tolist(),
            "truncated": list(self._truncated),
            "friction": self._friction.state(),
        }

    def set_state(self, state):
        self.d[:] = state["d"]
        self.X[:] = state["X"]
        self._truncated[:] = state.get("truncated", (0.0, 0.0))
        self._friction.set_state(state.get("friction", {}))


DRIVE_WORDS = {
    "load": "loads in, displacements out",
    "displacement": "displacements in, reaction loads out",
    "fixed_axial": "fixed axial position (fixed preload): axial reaction out",
}


def reference_inputs(scene):
    """The quasi-static FMU's reference experiment (SI): the B7214C at 40 C, 0-10 000 rpm in steps of 500 rpm,
    at 800 N axial and 500 N radial (load drive), at z = 20 um, x = 2 um (displacement drive) or with 500 N radial
    at 5 um beyond the 800 N assembly offset (fixed_axial drive)."""
    speeds = [n * 2.0 * math.pi / 60.0 for n in range(0, 10001, 500)]
    if scene.drive == "displacement":
        return [{"omega": w, "x": 2e-6, "z": 20e-6, "T_oil": 313.15} for w in speeds]
    if scene.drive == "fixed_axial":  # assembly offset of the FMU's default F_preload, 5 um tighter
        return [{"omega": w, "F_x": 500.0, "z": 5e-6, "T_oil": 313.15} for w in speeds]
    return [{"omega": w, "F_x": 500.0, "F_z": 800.0, "T_oil": 313.15} for w in speeds]


def build_options(scene):
    """The reference model's assembly preload: the Rabreau rig's 800 N in a fixed-preload scene, none otherwise."""
    return {"F_preload": DEFAULT_FIXED_PRELOAD} if scene.drive == "fixed_axial" else {}


FIDELITY = Fidelity(
    name="quasi_static",
    model=QuasiStaticModel,
    parameters=QUASI_STATIC_PARAMETERS,
    choices=("bearing", "lubricant", "race_control"),
    reference_step=0.1,
    reference_inputs=reference_inputs,
    summary=lambda scene: f"quasi-static bearing, {DRIVE_WORDS[scene.drive]}",
    build_options=build_options,
)
