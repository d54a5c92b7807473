"""Every input, output and parameter of SpindleShaft.fmu, declared once.

The seat inputs follow the shaft file (one 5x5 stiffness and one radial damping per [[seat]]), so they are declared
as rules expanded for a shaft. spindle.shaft.stepper fills its outputs in the order of output_declarations(), the FMU
class (spindle.shaft.fmu) registers its FMI variables from the same declarations, and fmus/SpindleShaft.md is
generated from them (spindle.all_fmus).
"""

from bearing_fmu_common.variables import Variable

from .model import N_FREQUENCIES, OMEGA_MAX, SEAT_MATRIX_MAX

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


def parameter_declarations(shaft, seat_names):
    """The FMU's parameters: `shaft` (start: the file it was built with, whose seats are `seat_names`), then per
    seat whether its outer ring floats axially, and the inputs' change below which a step keeps its outputs."""
    out = [
        Variable(
            "shaft",
            "",
            "shaft: catalogue name or path of a shaft TOML file (docs/shaft.md)",
            "string",
            start=shaft,
        )
    ]
    out.append(
        Variable(
            "tolerance",
            "1",
            "relative change of the seats' K and damping (Frobenius norm over the seats) and of omega since the last "
            "solution below which a step keeps the last outputs; 0: every step solves (docs/shaft.md, The warm-up)",
            start=0.0,
            min=0.0,
            max=TOLERANCE_MAX,
            limits="0 solves every step; above 0.1 the kept outputs could lag the seats by several per cent",
        )
    )
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
    return tuple(out)


def _seat_inputs(seat, name):
    """The 25 stiffness entries and the radial damping of seat `seat` (1-based) named `name` in the shaft file."""
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


def input_declarations(shaft_file):
    """Inputs of a shaft (spindle.shaft.params.ShaftFile): the speed, then per seat its K entries and damping."""
    out = [
        Variable(
            "omega",
            "rad/s",
            "shaft angular speed (gyroscopic coupling of the modes)",
            min=0.0,
            max=OMEGA_MAX,
            limits="above any spindle's speed (95 500 rpm); >= 0: the model's spin sense is +z",
        )
    ]
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
