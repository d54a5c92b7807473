"""Every input, output and parameter of the bearing fidelities, declared once.

The facades (analytic.AnalyticModel, quasi_static.QuasiStaticModel, dem.DemModel) fill their output arrays in the
order declared here, the FMU classes (bearing_fmu.fmu) register their FMI variables from these
declarations, and the variable lists of fmus/<Name>.md and of the README are generated from them
(bearing_fmu.build.variables_markdown). A declaration says which scene option enables it (`option`,
`drives`) and where its value comes from (`source`: a slot of a kernel's output array or of the
solver's arrays; none = computed by the facade).

Source arrays: "out" is the kernel's output array (radial_bearing.O_* for the analytic fidelity,
contacts.CO_* for the quasi-static one); "d", "F" and "K" are the quasi-static solver's
displacements, reactions and stiffness matrix (K flattened row by row); "ball_set" is the summary of
the ball set (bearing_outputs.BS_*: most loaded ball, cage speed, iterations). DEM fidelity: "out",
"ring" and "status" are the ball-dynamics output, inner-ring and monitor-status arrays
(kernels.ball_dynamics.state O_*, R_*, ST_*), "K" the facade's condensed stiffness (row by row), "freq" the
facade's defect frequencies (FTF, BPFO, BPFI, BSF, kernels.geometry.pass_frequencies).
"life" (analytic and quasi-static fidelities) is the rating-life array (kernels.rating_life LO_*).
"""

import math
from dataclasses import replace

from bearing_fmu_common.variables import Variable

from ..kernels import bearing_outputs as bo
from ..kernels import contact_outputs as ck
from ..kernels import radial_bearing
from ..kernels import rating_life as rl
from ..kernels import truncation as tk
from ..kernels.ball_dynamics import state as ds
from ..scene import LUBRICATION_METHODS, RACE_CONTROLS
from .dem_settings import DEM_SETTINGS
from .file_parameters import bearing_parameters
from .limits import (
    GROOVE_MAX,
    LOAD_LIMITS,
    LOAD_MAX,
    MOMENT_MAX,
    OMEGA_LIMITS,
    OMEGA_MAX,
    T_OIL_LIMITS,
    T_OIL_RANGE,
    THERMAL_SHIFT_MAX,
    TILT_LIMIT,
)

T_OIL_START = 313.15  # K (40 C): every other input starts at 0 (at rest, unloaded, centred)
DEFAULT_FIXED_PRELOAD = 800.0  # N, Rabreau et al. 2018 rig (fixed_axial scenes only)

# Allowed ranges (min, max) of inputs and parameters: the static bounds of models.limits, each with its reason;
# the models narrow them at run time where the limit depends on the bearing (the message states the narrower range).
OMEGA = Variable(
    "omega",
    "rad/s",
    "inner-ring angular speed about the bearing axis (outer ring fixed); |omega| <= d_m n limit",
    min=-OMEGA_MAX,
    max=OMEGA_MAX,
    limits=OMEGA_LIMITS,
)
T_OIL = Variable(
    "T_oil",
    "K",
    "oil temperature (viscosity, pressure-viscosity, density)",
    start=T_OIL_START,
    min=T_OIL_RANGE[0],
    max=T_OIL_RANGE[1],
    limits=T_OIL_LIMITS,
)
PD_FROM_FILE = Variable(
    "Pd_from_file",
    "",
    "true: diametral clearance from the bearing file; false: from the parameter Pd",
    "boolean",
    start=True,
)
PD = Variable(
    "Pd",
    "m",
    "diametral clearance used when Pd_from_file is false (negative = preload), |Pd| <= (f_i + f_o - 1) D",
    start=0.0,
    min=-GROOVE_MAX,
    max=GROOVE_MAX,
    limits="static bound: the groove clearance of a 0.25 m ball; |Pd| <= (f_i + f_o - 1) D of the bearing applies",
)
BEARING_NAME = "bearing catalogue name ({}) or path of a bearing TOML file"
LUBRICANT_NAME = "lubricant catalogue name or path of a lubricant TOML file"
LAMBDA = "film parameter h_min/sigma, minimum over loaded {} contacts (0 if none)"
H_MIN = "minimum film thickness, minimum over loaded {} contacts"
REGIME = "lubrication regime of the worst contact: 0 boundary, 1 mixed, 2 full film"
# rating life (scene option `life`, docs/rating_life.md); 1e30 = no fatigue (unloaded, or at rest for hours)
LIFE_OUTPUTS = (
    Variable(
        "L10",
        "1",
        "basic rating life L10 (90 % reliability), revolutions: ISO 281, C_r from the geometry, P = X F_r + Y F_a "
        "(tilting moments not included); 1e30 = unloaded",
        option="life",
        source=("life", rl.LO_L10),
    ),
    Variable(
        "L10_h", "h", "L10 in hours at the current speed (1e30 at rest)", option="life", source=("life", rl.LO_L10_H)
    ),
    Variable(
        "L10r",
        "1",
        "reference rating life L10r (90 % reliability), revolutions, from the computed contact loads of every "
        "ball (ISO/TS 16281 manner: moments and clearance included); 1e30 = unloaded",
        option="life",
        source=("life", rl.LO_L10R),
    ),
    Variable(
        "L10r_h",
        "h",
        "L10r in hours at the current speed (1e30 at rest)",
        option="life",
        source=("life", rl.LO_L10R_H),
    ),
)
CAPACITANCE = "electrical capacitance of the bearing (balls in parallel)"
# shoulder truncation of the contact ellipse (kernels.truncation; the shoulders of the bearing file)
TRUNCATION = (
    "part of the contact ellipse's major axis beyond the {0} ring's shoulder edge, in semi-major axes, for the "
    "most truncated loaded {0} contact{1}: 0 none, 1 the contact centre on the edge, 2 the whole ellipse beyond; "
    "a warning is logged on entry (load, stresses and film are computed as if the groove went on)"
)


def truncation_outputs(source, words=""):
    """truncation_inner, truncation_outer (-) from the array named `source` (kernels.truncation TR_* slots);
    `words` says when they are evaluated."""
    return tuple(
        Variable(f"truncation_{race}", "1", TRUNCATION.format(race, words), source=(source, slot))
        for race, slot in (("inner", tk.TR_INNER), ("outer", tk.TR_OUTER))
    )


# lubrication method (scene option `lubrication`, docs/lubrication_method.md)
PHI_ISH = (
    "inlet-shear-heating film factor of the most loaded {} contact (Gupta et al. 1992 thermal reduction; 1 = "
    "isothermal): h_c, h_min (and Lambda, regime, mu) are the flooded films times it"
)
PHI_RS = (
    "starvation (kinematic replenishment) factor of the central film of the most loaded {} contact (Hamrock & "
    "Dowson 1977, inlet meniscus from the method's inlet oil layer; 1 = fully flooded)"
)
TORQUE_DRAG = (
    "drag torque of the balls in the oil or oil-air mixture = P_drag/|omega| (Harris ball drag, sphere C_D(Re))"
)
P_DRAG = "drag power of the balls in the oil or oil-air mixture (heats the oil{})"


def lubrication_outputs(source, phi_slots, drag_slots, words=""):
    """phi_ish_inner, phi_ish_outer, phi_rs_inner, phi_rs_outer (option lubricated) and torque_drag, P_drag
    (option drag) from the array named `source`."""
    phis = tuple(
        Variable(f"{name}_{race}", "1", text.format(race), option="lubricated", source=(source, slot))
        for (name, text), slots in zip((("phi_ish", PHI_ISH), ("phi_rs", PHI_RS)), phi_slots)
        for race, slot in zip(("inner", "outer"), slots)
    )
    torque_slot, power_slot = drag_slots
    return phis + (
        Variable("torque_drag", "N.m", TORQUE_DRAG, option="drag", source=(source, torque_slot)),
        Variable("P_drag", "W", P_DRAG.format(words), option="drag", source=(source, power_slot)),
    )


def film_and_load_outputs(slots, outer_words=""):
    """The film parameter, minimum film, regime, capacitance and largest contact loads of a static fidelity, from the
    slots of its output array "out": Lambda, h_min (inner, outer), regime, C_bearing, Q_max (inner, outer)."""
    lambda_i, lambda_o, h_min_i, h_min_o, regime, capacitance, q_max_i, q_max_o = slots
    return (
        Variable("Lambda_inner", "1", LAMBDA.format("inner"), source=("out", lambda_i)),
        Variable("Lambda_outer", "1", LAMBDA.format("outer"), source=("out", lambda_o)),
        Variable("h_min_inner", "m", H_MIN.format("inner"), source=("out", h_min_i)),
        Variable("h_min_outer", "m", H_MIN.format("outer"), source=("out", h_min_o)),
        Variable("regime", "1", REGIME, "integer", source=("out", regime)),
        Variable("C_bearing", "F", CAPACITANCE, option="capacitance", source=("out", capacitance)),
        Variable("Q_max_inner", "N", "largest inner contact load", source=("out", q_max_i)),
        Variable("Q_max_outer", "N", "largest outer contact load" + outer_words, source=("out", q_max_o)),
    )


H_C = "central film thickness of the most loaded {} contact (0 if none; what capacitance film measurements report)"
# speeds: every angular speed is about the bearing axis in the fixed frame (outer ring) unless it says otherwise
BALL_CAGE = (
    "ball angular speed relative to the cage (the frame turning at omega_cage), magnitude, {}; BSF = this / 2 pi"
)
FREQUENCIES = (
    ("FTF", "fundamental train frequency: cage turns per second, |omega_cage| / 2 pi"),
    ("BPFO", "ball pass frequency, outer race: balls passing a point of the outer ring per second, Z FTF"),
    ("BPFI", "ball pass frequency, inner race: balls passing a point of the inner ring per second, "
     "Z |omega - omega_cage| / 2 pi"),
    ("BSF", "ball spin frequency: ball turns relative to the cage per second, omega_ball_cage / 2 pi (a ball "
     "defect strikes the races at 2 BSF)"),
)  # fmt: skip


def frequency_outputs(sources, words):
    """The defect-frequency outputs (Hz), each from sources[name], their basis said by `words`."""
    return tuple(Variable(name, "Hz", f"{text} ({words})", source=sources[name]) for name, text in FREQUENCIES)


# -- analytic fidelity ------------------------------------------------------------------------------
ANALYTIC_INPUTS = (
    OMEGA,
    Variable(
        "F_y",
        "N",
        "radial load on the inner ring along +y, the line of ball 1 (docs/conventions.md)",
        min=-LOAD_MAX,
        max=LOAD_MAX,
        limits=LOAD_LIMITS,
    ),
    T_OIL,
)

ANALYTIC_OUTPUTS = (
    *film_and_load_outputs(
        (
            radial_bearing.O_LAMBDA_I,
            radial_bearing.O_LAMBDA_O,
            radial_bearing.O_HMIN_I,
            radial_bearing.O_HMIN_O,
            radial_bearing.O_REGIME,
            radial_bearing.O_C_BEARING,
            radial_bearing.O_QMAX_I,
            radial_bearing.O_QMAX_O,
        ),
        " (includes centrifugal force)",
    ),
    Variable("p_max", "Pa", "largest Hertz contact pressure", source=("out", radial_bearing.O_PMAX)),
    *truncation_outputs("trunc", " (contacts at the groove bottom)"),
    Variable(
        "omega_cage",
        "rad/s",
        "cage angular speed in the fixed frame (pure rolling, sign of omega)",
        source=("out", radial_bearing.O_OMEGA_CAGE),
    ),
    Variable(
        "omega_ball",
        "rad/s",
        "ball spin speed about its own axis in the fixed frame (pure rolling, sign of omega); the spin relative "
        "to the cage is omega_ball_cage",
        source=("out", radial_bearing.O_OMEGA_BALL),
    ),
    Variable(
        "omega_ball_cage", "rad/s", BALL_CAGE.format("pure rolling"), source=("out", radial_bearing.O_OMEGA_BALL_CAGE)
    ),
    *frequency_outputs(
        {
            "FTF": ("out", radial_bearing.O_FTF),
            "BPFO": ("out", radial_bearing.O_BPFO),
            "BPFI": ("out", radial_bearing.O_BPFI),
            "BSF": ("out", radial_bearing.O_BSF),
        },
        "pure rolling",
    ),
    Variable("h_c_inner", "m", H_C.format("inner"), source=("out", radial_bearing.O_HC_I)),
    Variable("h_c_outer", "m", H_C.format("outer"), source=("out", radial_bearing.O_HC_O)),
    Variable(
        "n_loaded", "1", "number of balls loaded on both races", "integer", source=("out", radial_bearing.O_N_LOADED)
    ),
    *lubrication_outputs(
        "out",
        (
            (radial_bearing.O_PHI_ISH_I, radial_bearing.O_PHI_ISH_O),
            (radial_bearing.O_PHI_RS_I, radial_bearing.O_PHI_RS_O),
        ),
        (radial_bearing.O_TORQUE_DRAG, radial_bearing.O_P_DRAG),
    ),
    Variable("y", "m", "radial displacement of the inner ring along F_y"),  # signed radial approach
    Variable("epsilon", "1", "load parameter eps = (1 - P_d/(2 delta_r))/2, capped at 1e6 (centred preloaded ring)"),
    *LIFE_OUTPUTS,
)

DEEP_GROOVE_ONLY = (
    "the analytic fidelity models radially loaded deep-groove bearings (kind 0, contact angle 0); the quasi-static "
    "and DEM fidelities model the others"
)


def deep_groove_only(parameters):
    """`parameters` with bearing_data.kind and bearing_data.alpha0 declared [0, 0]: the only bearing the analytic
    fidelity models (analytic.models_bearing), so that the declared range is the range it accepts."""
    names = ("bearing_data.kind", "bearing_data.alpha0")
    return tuple(
        replace(v, max=0 if v.kind == "integer" else 0.0, limits=DEEP_GROOVE_ONLY) if v.name in names else v
        for v in parameters
    )


ANALYTIC_PARAMETERS = (
    Variable("bearing", "", BEARING_NAME.format("6208, 6306"), "string", start="6208"),
    Variable("lubricant", "", LUBRICANT_NAME, "string", start="guessasma_oil"),
    PD_FROM_FILE,
    PD,
    # the numeric bearing and lubricant (models.file_parameters)
    *deep_groove_only(bearing_parameters("6208", "guessasma_oil")),
)

# -- quasi-static fidelity --------------------------------------------------------------------------
DOF_NAMES = ("x", "y", "z", "theta_x", "theta_y")
DOF_UNITS = ("m", "m", "m", "rad", "rad")
LOAD_NAMES = ("F_x", "F_y", "F_z", "M_x", "M_y")
LOAD_UNITS = ("N", "N", "N", "N.m", "N.m")
DOF_WORDS = (
    "radial displacement along x",
    "radial displacement along y",
    "axial displacement",
    "tilt about x",
    "tilt about y",
)
LOAD_WORDS = ("radial force along x", "radial force along y", "axial force", "moment about x", "moment about y")
# which DOFs are load-controlled (1) for each drive (scene option)
DRIVE_CONTROL = {"load": (1, 1, 1, 1, 1), "displacement": (0, 0, 0, 0, 0), "fixed_axial": (1, 1, 0, 1, 1)}


def _drives(dof, controlled):
    """The drives in which DOF `dof` is load-controlled (controlled=1) or imposed (0)."""
    return tuple(drive for drive, control in DRIVE_CONTROL.items() if control[dof] == controlled)


DISPLACEMENT_LIMIT = 0.5  # x the groove clearance A (m): beyond it the Hertz loads pass any material limit
DISPLACEMENT_LIMITS = (
    "static bound; |d| <= 0.5 (f_i + f_o - 1) D of the bearing applies (beyond: past any material limit)"
)
TILT_LIMITS = "over 3 x the largest misalignment ball-bearing catalogues permit (10 arcmin = 2.9 mrad)"


def _load_range(i):
    """min, max and reason of the applied load of DOF i (forces, then moments)."""
    bound = LOAD_MAX if i < 3 else MOMENT_MAX
    return dict(min=-bound, max=bound, limits=LOAD_LIMITS)


def _displacement_range(i):
    """min, max and reason of the imposed displacement of DOF i (translations, then tilts)."""
    if i >= 3:
        return dict(min=-TILT_LIMIT, max=TILT_LIMIT, limits=TILT_LIMITS)
    bound = DISPLACEMENT_LIMIT * GROOVE_MAX
    return dict(min=-bound, max=bound, limits=DISPLACEMENT_LIMITS)


def _dof_inputs():
    out = []
    for i in range(5):
        out.append(
            Variable(
                LOAD_NAMES[i],
                LOAD_UNITS[i],
                f"applied {LOAD_WORDS[i]} on the inner ring",
                drives=_drives(i, 1),
                **_load_range(i),
            )
        )
        imposed = f"imposed {DOF_WORDS[i]} of the inner ring relative to the outer ring"
        if i == 2:  # a fixed preload adds the assembly offset to the imposed axial position
            out.append(
                Variable(DOF_NAMES[i], DOF_UNITS[i], imposed, drives=("displacement",), **_displacement_range(i))
            )
            out.append(
                Variable(
                    DOF_NAMES[i],
                    DOF_UNITS[i],
                    f"{imposed} (added to the assembly offset z0 of the parameter F_preload)",
                    drives=("fixed_axial",),
                    **_displacement_range(i),
                )
            )
        else:
            out.append(Variable(DOF_NAMES[i], DOF_UNITS[i], imposed, drives=_drives(i, 0), **_displacement_range(i)))
    return out


THERMAL_SHIFT = dict(
    min=-THERMAL_SHIFT_MAX,
    max=THERMAL_SHIFT_MAX,
    limits="static bound (thermal growth of spindle bearings: micrometres); |value| <= 0.02 D of the bearing applies",
)


# where z is imposed (the quasi-static fidelity with thermal_inputs, and the DEM with a prescribed ring)
DZ_THERMAL = Variable(
    "dz_thermal",
    "m",
    "imposed axial shift of the inner ring from thermal growth, added to z (fixed preload)",
    option="thermal_inputs",
    drives=_drives(2, 0),
    **THERMAL_SHIFT,
)

QUASI_STATIC_INPUTS = (
    OMEGA,
    *_dof_inputs(),
    T_OIL,
    Variable(
        "dPd_thermal",
        "m",
        "change of diametral clearance from thermal and centrifugal growth (added to Pd, negative = tighter)",
        option="thermal_inputs",
        **THERMAL_SHIFT,
    ),
    DZ_THERMAL,
)


def _stiffness_unit(i, j):
    """Unit of dF_i/dd_j: N/m, N (force per rad or moment per m) or N.m/rad (shown as N.m)."""
    force_i, length_j = i < 3, j < 3
    if force_i and length_j:
        return "N/m"
    if force_i or length_j:
        return "N"
    return "N.m"


def stiffness_name(i, j):
    """FMI name of the stiffness entry dF_i/dd_j (0-based i, j): K[i+1,j+1]."""
    return f"K[{i + 1},{j + 1}]"


def _dof_outputs():
    """Per DOF, in DOF order: its equilibrium value where it is load-controlled, its reaction where imposed."""
    out = []
    for i in range(5):
        out.append(
            Variable(
                DOF_NAMES[i],
                DOF_UNITS[i],
                f"{DOF_WORDS[i]} of the inner ring at equilibrium",
                drives=_drives(i, 1),
                source=("d", i),
            )
        )
        out.append(
            Variable(
                LOAD_NAMES[i],
                LOAD_UNITS[i],
                f"reaction: {LOAD_WORDS[i]} the balls exert (= the load needed to hold the imposed position)",
                drives=_drives(i, 0),
                source=("F", i),
            )
        )
    return out


QUASI_STATIC_OUTPUTS = (
    *_dof_outputs(),
    *(
        Variable(
            stiffness_name(i, j),
            _stiffness_unit(i, j),
            f"stiffness dF_{i + 1}/dd_{j + 1}, (F) = (F_x, F_y, F_z, M_x, M_y), "
            f"(d) = (x, y, z, theta_x, theta_y), ball equilibrium condensed",
            option="stiffness",
            source=("K", 5 * i + j),
        )
        for i in range(5)
        for j in range(5)
    ),
    Variable(
        "torque",
        "N.m",
        "friction torque = P_loss/|omega| (0 at rest): Houpert components and the drag of the lubrication method",
        option="torque",
        source=("out", ck.CO_TORQUE),
    ),
    Variable(
        "P_loss",
        "W",
        "total power loss of the contacts and of the drag of the balls",
        option="torque",
        source=("out", ck.CO_P_LOSS),
    ),
    Variable(
        "Q_inner_ring",
        "W",
        "heat to the inner ring (losses of the inner contacts, half the drag)",
        option="torque",
        source=("out", ck.CO_Q_INNER_RING),
    ),
    Variable(
        "Q_outer_ring",
        "W",
        "heat to the outer ring (losses of the outer contacts, half the drag)",
        option="torque",
        source=("out", ck.CO_Q_OUTER_RING),
    ),
    *lubrication_outputs(
        "out",
        ((ck.CO_PHI_ISH_I, ck.CO_PHI_ISH_O), (ck.CO_PHI_RS_I, ck.CO_PHI_RS_O)),
        (ck.CO_TORQUE_DRAG, ck.CO_P_DRAG),
        ": half to each ring, in Q_inner_ring and Q_outer_ring",
    ),
    *film_and_load_outputs(
        (
            ck.CO_LAMBDA_I,
            ck.CO_LAMBDA_O,
            ck.CO_HMIN_I,
            ck.CO_HMIN_O,
            ck.CO_REGIME,
            ck.CO_C_BEARING,
            ck.CO_QMAX_I,
            ck.CO_QMAX_O,
        )
    ),
    Variable(
        "p_max", "Pa", "largest Hertz contact pressure (warning logged above 4.2 GPa)", source=("out", ck.CO_PMAX)
    ),
    Variable("alpha_inner", "rad", "inner contact angle of the most loaded ball", source=("ball_set", bo.BS_ALPHA_I)),
    Variable("alpha_outer", "rad", "outer contact angle of the most loaded ball", source=("ball_set", bo.BS_ALPHA_O)),
    *(
        Variable(
            f"mu_required_{race}",
            "1",
            f"largest traction coefficient the race-control hypothesis asks of an {race} contact (its share of the "
            f"balls' gyroscopic moment over the contact load; a warning is logged above the lubricant's limiting "
            f"traction coefficient); 0 under race_control = traction, whose forces are the traction curve's",
            source=("ball_set", slot),
        )
        for race, slot in (("inner", bo.BS_MU_REQ_I), ("outer", bo.BS_MU_REQ_O))
    ),
    *truncation_outputs("trunc"),
    Variable(
        "omega_cage",
        "rad/s",
        "cage speed in the fixed frame: orbital speed of the balls, mean weighted by inner load",
        source=("ball_set", bo.BS_CAGE),
    ),
    Variable(
        "omega_ball",
        "rad/s",
        "ball angular speed in the fixed frame (most loaded ball, spin and orbital motion, sign of omega); the spin "
        "relative to the cage is omega_ball_cage",
        source=("ball_set", bo.BS_BALL),
    ),
    Variable(
        "omega_ball_cage",
        "rad/s",
        BALL_CAGE.format("most loaded ball, operating contact angles and race control"),
        source=("ball_set", bo.BS_BALL_CAGE),
    ),
    *frequency_outputs(
        {name: ("ball_set", getattr(bo, f"BS_{name}")) for name, _ in FREQUENCIES},
        "solved cage speed and the most loaded ball's spin",
    ),
    Variable("h_c_inner", "m", H_C.format("inner"), source=("out", ck.CO_HC_I)),
    Variable("h_c_outer", "m", H_C.format("outer"), source=("out", ck.CO_HC_O)),
    Variable("n_loaded", "1", "number of balls loaded on both races", "integer", source=("out", ck.CO_N_LOADED)),
    Variable(
        "iterations",
        "1",
        "work of the last solve: bearing evaluations after the first (trust-region trials of the Newton iteration)",
        "integer",
        source=("ball_set", bo.BS_ITERATIONS),
    ),
    *LIFE_OUTPUTS,
)


def mode_parameter(string, what, choices):
    """The Integer <string>_mode that stands for the String parameter `string` in masters without String
    parameters: -1 (default) = the String, 0 .. len(choices) - 1 = that choice, which then wins."""
    return Variable(
        f"{string}_mode",
        "1",
        f"{what} as a number, for masters without String parameters: -1 = the parameter {string}, "
        + ", ".join(f"{code} = {name}" for code, name in enumerate(choices)),
        "integer",
        start=-1,
        min=-1,
        max=len(choices) - 1,
    )


QUASI_STATIC_PARAMETERS = (
    Variable("bearing", "", BEARING_NAME.format("6208, 6306, B7214C"), "string", start="B7214C"),
    Variable("lubricant", "", LUBRICANT_NAME, "string", start="iso_vg68_mineral"),
    PD_FROM_FILE,
    PD,
    Variable(
        "race_control",
        "",
        "ball race-control hypothesis: outer | inner | hybrid (Rabreau 2018)",
        "string",
        start=None,  # the scene's race_control
        choices=RACE_CONTROLS,
    ),
    Variable(
        "lubrication",
        "",
        "lubrication method (docs/lubrication_method.md): " + " | ".join(LUBRICATION_METHODS) + ", at its default "
        "settings; default: the scene's. Torque, heat and films follow it; its own outputs (phi_*, torque_drag, "
        "P_drag) exist when the scene names a method other than flooded",
        "string",
        start=None,  # the scene's lubrication
        choices=LUBRICATION_METHODS,
    ),
    mode_parameter("race_control", "race control", RACE_CONTROLS),
    mode_parameter("lubrication", "lubrication method", LUBRICATION_METHODS),
    Variable(
        "F_preload",
        "N",
        "axial preload set at assembly (at rest, no thermal change; default: the Rabreau rig's 800 N); the "
        "input z is added to the axial approach that carries it. 0 = z is the axial approach itself",
        drives=("fixed_axial",),  # only a fixed-preload bearing has an assembly offset
        start=DEFAULT_FIXED_PRELOAD,
        min=0.0,
        max=LOAD_MAX,
        limits="below the bearing's material limit (p_max = 6 GPa with the load on all balls)",
    ),
    *bearing_parameters("B7214C", "iso_vg68_mineral"),
)

# -- DEM fidelity (ball dynamics, docs/dem.md) ------------------------------------------------------
# Same names, units and meaning as the quasi-static load-driven FMU where they apply. One doStep
# integrates the communication step H: the speed goes linearly from its value at the previous
# communication point to the input (a first-order hold: no speed jump at a point), loads, oil
# temperature and clearance change are held. Loads, film, angles and positions are end-of-step values;
# the power outputs and the capacitance are means over the step (the energy dissipated in the contacts
# divided by H; the capacitance integrated over the DEM steps divided by H) or, with the parameter
# average_outputs false, their values at the step's last DEM step.
DEM_REFRESH_INTERVAL = 40e-6  # s, default simulated time between two tribology refreshes (docs/reports/dem_steps.md)
DEM_REFRESH_MAX = 1e-3  # s, longest refresh interval (models.dem.DemModel checks it)
# s, longest fixed DEM time step (models.dem.DemModel checks it): the stability limit of a lightly loaded bearing.
# Measured with 4 steps of 0.5 ms: the 6208 runs at 10 us under 100 N (radial at rest or at 500 rad/s, axial at
# 500 rad/s) but not at 15 us; under 3 kN at 500 rad/s it needs 3.3 us or less; the B7214C runs at 20 us under
# 100 N; above about 20 us only an unloaded bearing runs
DEM_DT_MAX = 1e-5
# s, shortest fixed DEM time step: far below any step a bearing needs (the automatic step's smallest measured, the
# B7214C's cold full film, is 0.26 us), and it keeps a call's step count a machine integer
DEM_DT_MIN = 1e-9
_BY_NAME = {v.name: v for v in QUASI_STATIC_INPUTS + QUASI_STATIC_OUTPUTS if not v.drives or "load" in v.drives}
_BY_NAME_PARAMETERS = {v.name: v for v in QUASI_STATIC_PARAMETERS}
DEM_OUTPUT_WORDS = (
    "mean over the communication step (energy dissipated in the contacts / H; at the step's end when "
    "average_outputs is false)"
)


def _dem_output(name, source, description=None, option=""):
    """The quasi-static output `name` with the DEM's source (and description where the meaning differs)."""
    var = _BY_NAME[name]
    return replace(var, source=source, option=option, description=description or var.description)


# the prescribed ring (DemModel drive = "displacement"): its displacement, tilts and their rates at the end of each
# call. The rates' bound: the largest displacement or tilt vibrating at PATH_RATE_FREQUENCY, beyond the ball-pass
# frequencies of any bearing that the DEM's steps resolve
PATH_RATE_FREQUENCY = 1e4  # Hz
DOF_RATE_UNITS = ("m/s", "m/s", "m/s", "rad/s", "rad/s")
PATH_RATE_LIMITS = "the largest displacement (tilt) vibrating at 10 kHz"


def _path_inputs():
    """x ... theta_y and their rates x_rate ... theta_y_rate, each at the end of the call (the ring follows the cubic
    from its current state to them)."""
    out = [
        Variable(
            name,
            unit,
            f"imposed {words} of the inner ring at the end of the step (the ring follows the cubic from its state "
            "to it and its rate)",
            drives=("displacement",),
            **_displacement_range(i),
        )
        for i, (name, unit, words) in enumerate(zip(DOF_NAMES, DOF_UNITS, DOF_WORDS))
    ]
    for i in range(5):
        bound = _displacement_range(i)["max"] * 2.0 * math.pi * PATH_RATE_FREQUENCY
        out.append(
            Variable(
                f"{DOF_NAMES[i]}_rate",
                DOF_RATE_UNITS[i],
                f"rate of the imposed {DOF_WORDS[i]} of the inner ring at the end of the step",
                min=-bound,
                max=bound,
                limits=PATH_RATE_LIMITS,
                nominal=1e-3 if i < 3 else 1.0,
                drives=("displacement",),
            )
        )
    return tuple(out)


DEM_PATH_INPUTS = _path_inputs()

# the DEM's inputs in both drives: the loads (drive "load", the load-driven DEM's own F_x ... M_y) or the ring's path
# (drive "displacement"), in the order DemModel.update() takes them
DEM_INPUTS = (
    OMEGA,
    *(replace(_BY_NAME[name], drives=("load",)) for name in LOAD_NAMES),
    *DEM_PATH_INPUTS,
    T_OIL,
    replace(_BY_NAME["dPd_thermal"], option=""),  # the DEM always has it
    # a prescribed ring always has it (a shaft's seat motion starts from 0: this offset gives its axial preload
    # position); a load-driven ring has no imposed z
    replace(
        DZ_THERMAL,
        option="",
        drives=("displacement",),
        description="imposed axial shift of the inner ring from thermal growth or preload, added to z at the end "
        "of the step (not to z_rate: a constant offset)",
    ),
)
DEM_LOAD_INPUTS = tuple(v for v in DEM_INPUTS if "load" in (v.drives or ("load",)))

DEM_OUTPUTS = (
    *(
        _dem_output(
            name,
            ("out", ds.O_X + i),
            f"{DOF_WORDS[i]} of the inner ring at the end of the step (its mean over the step with "
            "average_state_outputs)",
        )
        for i, name in enumerate(("x", "y", "z"))
    ),
    *(
        _dem_output(name, ("ring", ds.R_TH + i), f"{DOF_WORDS[3 + i]} of the inner ring at the end of the step")
        for i, name in enumerate(("theta_x", "theta_y"))
    ),
    *(
        Variable(
            LOAD_NAMES[i],
            LOAD_UNITS[i],
            f"reaction: {LOAD_WORDS[i]} that holds the inner ring on its imposed path (minus the balls' force"
            f"{' and moment about its centre' if i >= 3 else ''}), mean over the communication step",
            drives=("displacement",),
            source=("reaction", i),
        )
        for i in range(5)
    ),
    *(
        _dem_output(
            stiffness_name(i, j),
            ("K", 5 * i + j),
            f"stiffness dF_{i + 1}/dd_{j + 1} at the end of the step, (F) = (F_x, F_y, F_z, M_x, M_y), "
            f"(d) = (x, y, z, theta_x, theta_y), contact tangent stiffnesses with each ball's inner and outer "
            f"contact in series (docs/dem.md)",
            option="stiffness",
        )
        for i in range(5)
        for j in range(5)
    ),
    _dem_output("torque", ("out", ds.O_TORQUE), f"friction torque = P_loss/|omega| (0 at rest), {DEM_OUTPUT_WORDS}"),
    _dem_output("P_loss", ("out", ds.O_P_LOSS), f"total power loss of the contacts, {DEM_OUTPUT_WORDS}"),
    _dem_output(
        "Q_inner_ring", ("out", ds.O_Q_INNER_RING), f"heat to the inner ring (inner contacts), {DEM_OUTPUT_WORDS}"
    ),
    _dem_output(
        "Q_outer_ring", ("out", ds.O_Q_OUTER_RING), f"heat to the outer ring (outer contacts), {DEM_OUTPUT_WORDS}"
    ),
    _dem_output("Lambda_inner", ("out", ds.O_LAMBDA_I)),
    _dem_output("Lambda_outer", ("out", ds.O_LAMBDA_O)),
    _dem_output("h_min_inner", ("out", ds.O_HMIN_I)),
    _dem_output("h_min_outer", ("out", ds.O_HMIN_O)),
    _dem_output("regime", ("out", ds.O_REGIME)),
    _dem_output(
        "C_bearing",
        ("out", ds.O_C_BEARING),
        f"{CAPACITANCE}, mean over the communication step (at its end when average_outputs is false; "
        "contact capacitances of the tribology refreshes)",
        option="capacitance",
    ),
    _dem_output(
        "Q_max_inner",
        ("out", ds.O_QMAX_I),
        "largest inner contact load at the end of the step (with average_state_outputs: its mean over the step)",
    ),
    _dem_output(
        "Q_max_outer",
        ("out", ds.O_QMAX_O),
        "largest outer contact load at the end of the step (with average_state_outputs: its mean over the step)",
    ),
    _dem_output(
        "p_max",
        ("out", ds.O_PMAX),
        "largest Hertz contact pressure of a loaded contact at the last refresh (or its mean over the step's "
        "refreshes with average_state_outputs)",
    ),
    _dem_output("alpha_inner", ("out", ds.O_ALPHA_I), "inner contact angle of the most loaded ball (end of step)"),
    _dem_output("alpha_outer", ("out", ds.O_ALPHA_O), "outer contact angle of the most loaded ball (end of step)"),
    *truncation_outputs("trunc", " at the end of the step"),
    _dem_output(
        "omega_cage",
        ("out", ds.O_OMEGA_CAGE),
        "cage speed in the fixed frame: mean orbital speed of the balls over the step (slip solved dynamically)",
    ),
    _dem_output(
        "omega_ball",
        ("out", ds.O_OMEGA_BALL),
        "angular speed of the most loaded ball in the fixed frame (end of step, sign of omega); the spin relative "
        "to the cage is omega_ball_cage",
    ),
    _dem_output(
        "omega_ball_cage",
        ("out", ds.O_OMEGA_BALL_REL),
        BALL_CAGE.format("most loaded ball at the end of the step, relative to the step's mean cage speed"),
    ),
    *frequency_outputs(
        {name: ("freq", k) for k, (name, _) in enumerate(FREQUENCIES)},
        "cage speed of the step and omega at its end: slip solved dynamically",
    ),
    _dem_output("h_c_inner", ("out", ds.O_HC_I), f"{H_C.format('inner')}, at the last refresh of the step"),
    _dem_output("h_c_outer", ("out", ds.O_HC_O), f"{H_C.format('outer')}, at the last refresh of the step"),
    _dem_output("n_loaded", ("out", ds.O_N_LOADED), "number of balls loaded on both races (end of step)"),
    Variable(
        "cage_slip",
        "1",
        "cage slip 1 - omega_cage / (pure-rolling cage speed): the mean orbital speed at which the balls loaded "
        "on both races would roll without sliding at their current contact points and spin axes (0 at rest)",
        source=("out", ds.O_CAGE_SLIP),
    ),
    Variable(
        "SRR_max",
        "1",
        "largest slide-to-roll ratio of a loaded contact at the last refresh",
        source=("out", ds.O_SRR_MAX),
    ),
    Variable(
        "monitor_status",
        "1",
        "stability monitor of the last doStep: 0 ok, 1 non-finite force, 2 penetration beyond the material "
        "limit, 3 energy growth, 4 tangential chatter, 5 normal damping beyond the step (codes 1-5 come with "
        "fmi2Discard); 6 the inner ring whirls: a self-excited orbit of the ring on its support, the step succeeds "
        "and an fmi2Warning names the orbit at its onset (docs/dem.md, Ring support)",
        "integer",
        source=("status", ds.ST_CODE),
    ),
)


def _average_state_outputs():
    """The parameter average_state_outputs of each drive: a prescribed ring's x ... theta_y are inputs, and its
    reaction loads are always means over the step."""
    refreshes = (
        "Q_max_*, p_max, Lambda_*, h_min_*, h_c_* means over its tribology refreshes (for masters that sample slower "
        "than the ball pass); false: their values at the end of the step"
    )
    words = {
        "load": f"true: x, y, z, theta_x, theta_y are means over the communication step's DEM steps and {refreshes}",
        "displacement": "true: Q_max_*, p_max, Lambda_*, h_min_*, h_c_* are means over the communication step's "
        "tribology refreshes (for masters that sample slower than the ball pass); false: their values at the end of "
        "the step (the reaction loads F_x ... M_y are means over the step either way)",
    }
    return tuple(
        Variable("average_state_outputs", "", text, "boolean", start=False, drives=(drive,))
        for drive, text in words.items()
    )


DEM_PARAMETERS = (
    replace(_BY_NAME_PARAMETERS["bearing"], start="6208"),
    replace(_BY_NAME_PARAMETERS["lubricant"], start="guessasma_oil"),
    _BY_NAME_PARAMETERS["Pd_from_file"],
    _BY_NAME_PARAMETERS["Pd"],
    Variable(
        "dt",
        "s",
        "DEM time step, 0 = automatic (half the stability limit of the stiffest pair); <= 1e-5 s",
        min=0.0,
        max=DEM_DT_MAX,
        limits="0 = automatic (follows the loads and the film), else at least 1e-9 s; a fixed step above the "
        "stability limit of the bearing at the step's loads is stopped by the monitor (fmi2Discard) with a step "
        "that works there and dt = 0 suggested; 1e-5 s is the stability limit of the 6208 under 100 N (a few us "
        "under its rated loads), and above it only an unloaded bearing runs",
    ),
    Variable(
        "refresh_interval",
        "s",
        "simulated time between two tribology refreshes (film, friction, damping, capacitance), [0, 1e-3] s; "
        "0 = at every DEM step",
        start=DEM_REFRESH_INTERVAL,
        min=0.0,
        max=DEM_REFRESH_MAX,
        limits="0 = every DEM step (as any interval shorter than the step); beyond 1 ms the film and friction lag "
        "the ball motion (docs/reports/dem_steps.md)",
    ),
    Variable(
        "average_outputs",
        "",
        "true: torque, P_loss, Q_inner_ring, Q_outer_ring and C_bearing are means over the communication step; "
        "false: their values at the step's last DEM step",
        "boolean",
        start=True,
    ),
    *_average_state_outputs(),
    # the numeric settings (models.dem_settings): traction_limit and the ring's support
    *(setting.parameter() for setting in DEM_SETTINGS),
    *bearing_parameters("6208", "guessasma_oil"),
)
