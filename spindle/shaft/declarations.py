"""Every input, output and parameter of SpindleShaft.fmu, declared once.

The seat inputs follow the shaft file (one 5x5 stiffness and one radial damping per [[seat]]), so they are declared
as rules expanded for a shaft, and so are the numeric parameters shaft_data.* (the shaft file's numbers, for masters
that set no String parameter). spindle.shaft.stepper fills its outputs in the order of output_declarations(), the FMU
class (spindle.shaft.fmu) registers its FMI variables from the same declarations, and fmus/SpindleShaft.md is
generated from them (spindle.all_fmus).
"""

from bearing_fmu_common.variables import Variable

from .model import N_FREQUENCIES, OMEGA_MAX, SEAT_MATRIX_MAX
from .params import NUMBERS, shaft_numbers
from .transient import FORCE_MAX, GAMMA_RANGE, SUBSTEPS_MAX

DOF_WORDS = "(F_x, F_y, F_z, M_x, M_y)", "(x, y, z, theta_x, theta_y)"
SEAT_LIMITS = "orders of magnitude above any bearing's stiffness; a diagonal entry is >= 0 (a bearing resists motion)"
DAMPING_MIN, DAMPING_MAX = 1.0, 1.0e8  # N.s/m
TOLERANCE_MAX = 0.1  # relative change of the inputs below which outputs are kept
DAMPING_LIMITS = (
    "> 0: an undamped shaft has an infinite receptance peak; 1e8 N.s/m is far above a bearing's or a squeeze film's"
)
# Start value of each seat's K: the quasi-static Bearing.fmu's K[i,j] at its reference point (B7214C, 10 000 rpm,
# F_x = 500 N, F_z = 800 N, fmus/Bearing_ref.csv last row), to 4 digits, at both seats, so that the FMU runs with no
# connection; row i = dF_i, column j = d_j, as the bearing FMUs' outputs.
K_START = (
    (1.394e8, 20.53, 1.893e7, -1.502, -1.645e6),
    (20.53, 8.278e7, -62.44, 1.223e6, 1.502),
    (1.944e7, -63.27, 2.145e7, -0.6099, -1.155e5),
    (-1.504, 1.180e6, -0.6099, 2.386e4, 0.02222),
    (-1.603e6, 1.504, -1.155e5, 0.02222, 2.777e4),
)
C_START = 2000.0  # N.s/m: radial damping of an angular-contact spindle bearing, 1e3-1e4 N.s/m in measurements
WHIRL_TEXT = "+1 forward, -1 backward, 2 axial, 0 none (at rest, or a planar shape)"


def stiffness_unit(i, j):
    """Unit of dF_i/dd_j (0-based): N/m between forces and translations, N.m (per rad) between moments and tilts,
    N across."""
    return ("N/m", "N")[i >= 3] if j < 3 else ("N", "N.m")[i >= 3]


def seat_stiffness_name(seat, i, j):
    """FMI name of seat `seat`'s (1-based) stiffness entry dF_i/dd_j (0-based i, j): K_<seat>[i+1,j+1], the entry a
    master connects from the bearing FMU's K[i+1,j+1]."""
    return f"K_{seat}[{i + 1},{j + 1}]"


SHAFT_FROM_FILE = Variable(
    "shaft_from_file",
    "",
    "true: the shaft's numbers come from the file named by shaft; false: from the parameters shaft_data.* on that "
    "file's structure (its sections' elements and materials, its disks, seats and tool tip on their nodes)",
    "boolean",
    start=True,
)
# The shaft file's numbers as parameters (params.NUMBERS), per entry k (1-based) of its [[material]], [[section]] and
# [[disk]] tables: key -> (description, min, max, why). The ranges are a spindle's: inside the reader's (params.py)
# and closed where its bounds are open; at their ends the default shaft still runs (its elastic modes stay apart from
# its rigid-body ones: a section of 2 m, a diameter of 5 mm or 1 m, a disk of 100 kg.m^2 on it, one at a time).
SHAFT_NUMBERS = {
    "youngs_modulus": ("Young's modulus", 1e9, 1e12, "polymers to diamond"),
    "poisson_ratio": ("Poisson's ratio", 0.01, 0.5, "the file's ]0, 0.5], closed at 0.01 (below beryllium's 0.03)"),
    "density": ("density", 100.0, 30000.0, "foams to beyond osmium"),
    "length": ("length", 1e-3, 2.0, "a shoulder's width to a long spindle's section (the file's: up to 10 m)"),
    "outer_diameter": ("outer diameter", 5e-3, 1.0, "a small grinding spindle's shaft to a large machine's"),
    "inner_diameter": ("inner diameter (0: solid)", 0.0, 1.0, "as the outer diameter; in use below it (file check)"),
    "mass": ("mass", 0.0, 1e3, "none to a large grinding wheel's"),
    "polar_inertia": ("polar moment of inertia", 0.0, 100.0, "1 t at a radius of 0.45 m: m r^2 / 2"),
    "diametral_inertia": ("diametral moment of inertia", 0.0, 100.0, "as the polar moment"),
}


def number_name(table, index, key):
    """FMI name of the number `key` of entry `index` (0-based, as in params.shaft_numbers) of the shaft file's
    table: shaft_data.<table>_<index + 1>.<key>, e.g. shaft_data.section_2.outer_diameter."""
    return f"shaft_data.{table}_{index + 1}.{key}"


def number_declarations(shaft):
    """shaft_from_file and the numbers of the shaft file `shaft` as parameters, their start values the file's."""
    out = [SHAFT_FROM_FILE]
    for table, index, entry, key, value in shaft_numbers(shaft):
        text, low, high, why = SHAFT_NUMBERS[key]
        out.append(
            Variable(
                number_name(table, index, key),
                {"-": "1"}.get(NUMBERS[table][key].unit, NUMBERS[table][key].unit),  # FMI's dimensionless unit
                f"{table} {index + 1} ('{entry}'): {text}",
                start=value,
                min=min(low, value),  # a file beyond a spindle's range still runs its own numbers
                max=max(high, value),
                limits=f"{why}; within the shaft file's range",
            )
        )
    return tuple(out)


def _shaft_parameter(shaft):
    return Variable(
        "shaft", "", "shaft: catalogue name or path of a shaft TOML file (docs/shaft.md)", "string", start=shaft
    )


def parameter_declarations(shaft, seat_names):
    """The FMU's parameters: `shaft` (start: the file it was built with, whose seats are `seat_names`), the inputs'
    change below which a step keeps its outputs, per seat whether its outer ring floats axially, then the shaft
    file's numbers (number_declarations)."""
    out = [
        _shaft_parameter(shaft),
        Variable(
            "tolerance",
            "1",
            "relative change of the seats' K and damping (Frobenius norm over the seats) and of omega since the last "
            "solution below which a step keeps the last outputs; 0: every step solves (docs/shaft.md, The warm-up)",
            start=0.0,
            min=0.0,
            max=TOLERANCE_MAX,
            limits="0 solves every step; above 0.1 the kept outputs could lag the seats by several per cent",
        ),
    ]
    for seat, name in enumerate(seat_names, start=1):
        out.append(
            Variable(
                f"floating_{seat}",
                "",
                f"seat {seat} ('{name}'): true if the bearing's outer ring floats axially under a constant preload "
                "force (springs or an actuator): the bearing then carries no axial stiffness (its z row and column "
                "condensed out); false if the ring is held axially (fixed preload or the locating bearing)",
                "boolean",
                start=False,
            )
        )
    return (*out, *number_declarations(shaft))


def _stiffness_inputs(seat, name):
    """The 25 stiffness entries of seat `seat` (1-based) named `name` in the shaft file."""
    out = []
    for i in range(5):
        for j in range(5):
            unit = stiffness_unit(i, j)
            out.append(
                Variable(
                    seat_stiffness_name(seat, i, j),
                    unit,
                    f"seat {seat} ('{name}'): bearing stiffness dF_{i + 1}/dd_{j + 1}, (F) = {DOF_WORDS[0]}, (d) = "
                    f"{DOF_WORDS[1]}: connect the bearing FMU's K[{i + 1},{j + 1}]",
                    start=K_START[i][j],
                    min=0.0 if i == j else -SEAT_MATRIX_MAX,
                    max=SEAT_MATRIX_MAX,
                    limits=SEAT_LIMITS,
                    nominal={"N/m": 1e8, "N": 1e6, "N.m": 1e4}[unit],
                )
            )
    return out


def _seat_inputs(seat, name):
    """The 25 stiffness entries and the radial damping of seat `seat` (1-based) named `name` in the shaft file."""
    out = _stiffness_inputs(seat, name)
    out.append(
        Variable(
            f"c_{seat}",
            "N.s/m",
            f"seat {seat} ('{name}'): viscous damping of the bearing in x and y",
            start=C_START,
            min=DAMPING_MIN,
            max=DAMPING_MAX,
            limits=DAMPING_LIMITS,
            nominal=1e3,
        )
    )
    return out


def _omega_input(words):
    return Variable(
        "omega",
        "rad/s",
        f"shaft angular speed ({words})",
        min=0.0,
        max=OMEGA_MAX,
        limits="above any spindle's speed (95 500 rpm); >= 0: the model's spin sense is +z",
    )


def input_declarations(shaft_file):
    """Inputs of a shaft (spindle.shaft.params.ShaftFile): the speed, then per seat its K entries and damping."""
    out = [_omega_input("gyroscopic coupling of the modes")]
    for seat, name in enumerate(shaft_file.seat_names, start=1):
        out += _seat_inputs(seat, name)
    return tuple(out)


def output_declarations():
    """Outputs: the first six natural frequencies with their whirl and damping ratio, the tool tip's static and peak
    compliance, the first two forward critical speeds."""
    modes = range(1, N_FREQUENCIES + 1)
    out = [Variable(f"f_{k}", "Hz", f"damped natural frequency of elastic mode {k} at speed omega") for k in modes]
    out += [Variable(f"whirl_{k}", "1", f"whirl of mode {k}: {WHIRL_TEXT}", kind="integer") for k in modes]
    out += [Variable(f"zeta_{k}", "1", f"damping ratio of mode {k}: -Re(lambda)/|lambda|") for k in modes]
    out += [
        Variable("compliance_radial", "m/N", "static x deflection of the tool tip under a unit x force there"),
        Variable("compliance_axial", "m/N", "static z deflection of the tool tip under a unit z force there"),
        Variable("peak_compliance", "m/N", "largest |H_xx| of the tool tip's receptance (x force, x motion)"),
        Variable("peak_frequency", "Hz", "frequency of peak_compliance"),
    ]
    out += [
        Variable(
            f"critical_speed_{k}",
            "rad/s",
            f"synchronous forward critical speed {k}; recomputed only when a seat's K or c changed by more than a "
            "relative 1e-9 since its last computation (a second eigenproblem), else the last value",
        )
        for k in (1, 2)
    ]
    return tuple(out)


# ---------------------------------------------------------------------------------------------------------------------
# SpindleShaftTransient.fmu: the time-domain mode (spindle.shaft.transient, docs/shaft.md "Time-domain mode"). Each
# seat's variables are the bearing FMU's names with the seat's number appended (F_x -> F_x_1, x -> x_1, K[i,j] ->
# K_1[i,j]), so that a run file connects bearing_1.F_x -> shaft.F_x_1 and shaft.x_1 -> bearing_1.x.
FORCE_NAMES = ("F_x", "F_y", "F_z", "M_x", "M_y")
FORCE_UNITS = ("N", "N", "N", "N.m", "N.m")
MOTION_NAMES = ("x", "y", "z", "theta_x", "theta_y")
MOTION_UNITS = ("m", "m", "m", "rad", "rad")
RATE_UNITS = ("m/s", "m/s", "m/s", "rad/s", "rad/s")
MOTION_WORDS = ("displacement along x", "displacement along y", "axial displacement", "tilt about x", "tilt about y")
# the shaft's own damping at a seat (radial x and y, axial z, tilt theta_x and theta_y): its start values are those
# of the coupling's example in docs/shaft.md (a bearing's radial damping, 1e3-1e4 N.s/m in measurements)
SEAT_DAMPING = (("radial", "N.s/m", 2000.0, DAMPING_MAX), ("axial", "N.s/m", 2000.0, DAMPING_MAX))
SEAT_DAMPING += (("tilt", "N.m.s/rad", 0.2, 1.0e4),)
# Newmark's gamma of the FMU: 0.6 damps unresolved modes to 0.82 of their amplitude per step; the shaft on two DEM
# bearings (runs/shaft_transient_dem.toml) grows at 0.5 and settles at 0.55 and 0.6 (docs/shaft.md)
NEWMARK_GAMMA = 0.6
SEAT_DAMPING_LIMITS = "0: none; the upper end is far above a bearing's or a squeeze film's damping"
FORCE_LIMITS = "far above a spindle bearing's load limit"


def transient_parameter_declarations(shaft, seat_names):
    """SpindleShaftTransient.fmu's parameters: `shaft`, the Newmark substeps per communication step and gamma,
    whether the bearings' K is used over a step, per seat the shaft's own damping there, then the shaft file's numbers
    (number_declarations)."""
    out = [
        _shaft_parameter(shaft),
        Variable(
            "substeps",
            "",
            "Newmark steps per communication step (the seat forces are held over the step, so more substeps only "
            "resolve the shaft's own motion)",
            "integer",
            start=1,
            min=1,
            max=SUBSTEPS_MAX,
            limits="1e5 steps of a 27-dof model per communication step is seconds of work",
        ),
        Variable(
            "newmark_gamma",
            "1",
            "Newmark's gamma of the time integration (beta = (gamma + 1/2)^2 / 4): 0.5 the average acceleration, "
            "without numerical damping; above it the modes the step does not resolve are damped, their amplitude "
            "multiplied per step by at most (3/2 - gamma) / (gamma + 1/2), and a resolved mode gains a damping ratio "
            "of about (gamma - 1/2) omega h / 2. The start value damps the seat modes a bearing's contact vibration "
            "excites (BearingDEMDisp.fmu; docs/shaft.md)",
            start=NEWMARK_GAMMA,
            min=GAMMA_RANGE[0],
            max=GAMMA_RANGE[1],
            limits="below 0.5 the scheme is unstable; 1 is the family's most damping member",
        ),
        Variable(
            "implicit_coupling",
            "",
            "true: each seat's force over a step is the held force plus K_<seat> (d(t) - d_start), integrated "
            "implicitly with the shaft (stable whatever the step for a linear bearing); false: the force is held "
            "and the K inputs are not used (stable below 2 c / k, docs/shaft.md)",
            "boolean",
            start=True,
        ),
    ]
    for seat, name in enumerate(seat_names, start=1):
        for kind, unit, start, high in SEAT_DAMPING:
            dofs = {"radial": "x and y", "axial": "z", "tilt": "theta_x and theta_y"}[kind]
            out.append(
                Variable(
                    f"c_{kind}_{seat}",
                    unit,
                    f"seat {seat} ('{name}'): the shaft's own viscous damping at the seat in {dofs} (a bearing "
                    "driven by displacement carries none)",
                    start=start,
                    min=0.0,
                    max=high,
                    limits=SEAT_DAMPING_LIMITS,
                )
            )
    return (*out, *number_declarations(shaft))


def _force_inputs(suffix, words, start=0.0):
    return [
        Variable(
            f"{name}_{suffix}",
            unit,
            f"{words}: {name}",
            start=start,
            min=-FORCE_MAX,
            max=FORCE_MAX,
            limits=FORCE_LIMITS,
            nominal=1e3 if unit == "N" else 10.0,
        )
        for name, unit in zip(FORCE_NAMES, FORCE_UNITS, strict=True)
    ]


def transient_input_declarations(shaft_file):
    """Inputs of SpindleShaftTransient.fmu: the speed, per seat the bearing's reaction (F_x ... M_y) and K, then the
    external force on the tool tip."""
    out = [_omega_input("gyroscopic term; a change between steps keeps the state")]
    for seat, name in enumerate(shaft_file.seat_names, start=1):
        out += _force_inputs(
            seat,
            f"seat {seat} ('{name}'): the bearing's reaction in its own frame, the load on its inner ring that holds "
            "it at the seat's displacement (the shaft receives its reverse); connect the bearing FMU's output",
        )
        out += _stiffness_inputs(seat, name)
    out += _force_inputs("tip", "external force on the tool tip, shaft's frame, on the shaft")
    return tuple(out)


def transient_output_declarations(shaft_file):
    """Outputs: per seat the inner ring's displacement and tilts and their rates in the bearing's frame (relative to
    the outer ring, fixed to the housing), then the tool tip's displacement (shaft's frame)."""
    out = []
    for seat, name in enumerate(shaft_file.seat_names, start=1):
        where = f"seat {seat} ('{name}'): inner ring's"
        out += [
            Variable(f"{m}_{seat}", u, f"{where} {w}, bearing's frame: connect to the bearing FMU's {m}")
            for m, u, w in zip(MOTION_NAMES, MOTION_UNITS, MOTION_WORDS, strict=True)
        ]
        out += [
            Variable(f"{m}_rate_{seat}", u, f"{where} rate of its {w}, bearing's frame")
            for m, u, w in zip(MOTION_NAMES, RATE_UNITS, MOTION_WORDS, strict=True)
        ]
    out += [
        Variable(f"{m}_tip", u, f"tool tip's {w}, shaft's frame")
        for m, u, w in zip(MOTION_NAMES, MOTION_UNITS, MOTION_WORDS, strict=True)
    ]
    return tuple(out)
