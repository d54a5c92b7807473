"""Every input, output and parameter of the thermal spindle FMUs, declared once.

The variables follow the network (node names, heat inputs, boundaries and bearings of the spindle
TOML), so they are declared as rules expanded for a network. SpindleThermalModel fills its output
array in the order of output_declarations(), the FMU class (spindle.thermal.fmu) registers its FMI
variables from the same declarations, and fmus/<Name>.md is generated from them (spindle.all_fmus).
"""

from bearing_fmu_common.bearing_file import (
    BALL_DIAMETER_MIN,
    BALL_RING_MODULUS,
    GROOVE_MAX,
    INNER_DIAMETER_MAX,
    PITCH_DIAMETER_MIN,
)
from bearing_fmu_common.paramfile import ParameterError
from bearing_fmu_common.variables import LOAD_MAX, OMEGA_MAX, THERMAL_SHIFT_MAX, Variable

T_START = 293.15  # K, start value of the temperature inputs of the FMU (20 C, the default assembly temperature)
DEFAULT_SPINDLE = "b7214c_x_pair"
INTEGRATORS = ("exponential", "implicit_euler")

# Allowed ranges of the inputs and parameters (FMI min/max; spindle.thermal.model refuses anything outside):
HEAT_MAX = 1e7  # W: |heat input|, far beyond any spindle bearing or motor loss (kW)
T_MIN, T_MAX = 150.0, 1000.0  # K: temperatures (boundaries, T_initial)
T_LIMITS = (
    "the network's properties (conductivities, expansion coefficient) are room-temperature constants: "
    "meaningless below 150 K, and 1000 K is past the austenite transformation of bearing steel"
)
K_AXIAL_MAX = 1e11  # N/m: 100 x the axial stiffness of the stiffest spindle bearing sets (~1e9 N/m)
# a bore of 0.05 mm (below a 0.5 mm pitch circle's 0.1 mm balls), bearing centres 1 mm apart (two of the smallest
# bearings side by side): the declared ends a network can take (a bore and a spacing must be > 0)
BORE_MIN = 5e-5
SPACING_MIN = 1e-3
AXIAL_FLOAT_MAX = THERMAL_SHIFT_MAX  # m: |axial float| of the shaft; a bearing FMU refuses |dz_thermal| beyond it


NETWORK_FROM_FILE = Variable(
    "network_from_file",
    "",
    "true: the network's thermo-mechanical dimensions come from the file named by spindle (its bearings' files); "
    "false: from the parameters bearing_<k>.*, expansion.* and axial.* (the nodes and links stay the file's)",
    "boolean",
    start=True,
)
# The network's main dimensions: what turns temperatures into the clearance and preload outputs. Per bearing k
# (its [[bearing]] entry, the bearing file it names): (name, unit, key of the network's bearing entry,
# description, min, max); then the [expansion] and [axial] values. Ranges: those of the files' readers (the bearing
# file's are bearing_fmu_common.bearing_file's, as the bearing FMUs declare them), closed where those are open
# (model.with_dimensions refuses a 0 that the file would refuse).
RING_DIMENSIONS = (
    ("D", "m", "D", "ball diameter (< d_m)", BALL_DIAMETER_MIN, 1.0),
    ("d_m", "m", "dm", "pitch diameter", PITCH_DIAMETER_MIN, 10.0),
    (
        "Pd", "m", "Pd",
        "diametral clearance at assembly (negative = preload), |Pd| <= (f_i + f_o - 1) D with the bearing file's "
        "conformities; grooves d_m -+ (D + Pd/2)",
        -GROOVE_MAX, GROOVE_MAX,
    ),
    ("bore", "m", "bore", "bore diameter (below the inner groove bottom)", BORE_MIN, INNER_DIAMETER_MAX),
    (
        "E_ring", "Pa", "E", "Young's modulus of the rings (centrifugal growth; steels and ceramics)",
        BALL_RING_MODULUS.low, BALL_RING_MODULUS.high,
    ),
    ("nu_ring", "1", "nu", "Poisson's ratio of the rings", 0.0, 0.5),
    ("rho_ring", "kg/m^3", "rho", "density of the rings", 100.0, 30000.0),
)  # fmt: skip
EXPANSION = (
    ("expansion.T_ref", "K", "T_ref", "assembly temperature: the dimensions are those at it", T_MIN, T_MAX),
    ("expansion.alpha_bearing", "1/K", "alpha_bearing", "thermal expansion coefficient of rings and balls", 0.0, 1e-3),
)  # fmt: skip
AXIAL = (
    ("axial.spacing", "m", "spacing", "distance between the bearing centres", SPACING_MIN, 10.0),
    ("axial.alpha_shaft", "1/K", "alpha_shaft", "thermal expansion coefficient of the shaft", 0.0, 1e-3),
    ("axial.alpha_housing", "1/K", "alpha_housing", "thermal expansion coefficient of the housing", 0.0, 1e-3),
)


DIMENSION_LIMITS = (
    "the range the network and bearing files accept, closed at a value a bearing can take where theirs is open; in "
    "use also D < d_m, |Pd| <= (f_i + f_o - 1) D and bore < d_m - D - max(Pd, 0)/2 "
    "(spindle.thermal.model.with_dimensions)"
)


def dimension_rows(net):
    """(FMI name, unit, description, min, max, value in `net`) of each main dimension of a network."""
    rows = [
        (f"bearing_{k}.{name}", unit, f"bearing {k} ({b['name']}): {text}", low, high, b[key])
        for k, b in enumerate(net.bearings, start=1)
        for name, unit, key, text, low, high in RING_DIMENSIONS
    ]
    rows += [(name, unit, text, low, high, getattr(net, key)) for name, unit, key, text, low, high in EXPANSION]
    if net.axial:
        rows += [(name, unit, text, low, high, net.axial[key]) for name, unit, key, text, low, high in AXIAL]
    return rows


def dimension_declarations(net):
    """network_from_file and the main dimensions of `net` as parameters, their start values `net`'s."""
    return (
        NETWORK_FROM_FILE,
        *(
            Variable(name, unit, text, start=value, min=low, max=high, limits=DIMENSION_LIMITS)
            for name, unit, text, low, high, value in dimension_rows(net)
        ),
    )


def parameter_declarations(network=DEFAULT_SPINDLE, net=None):
    """The FMU's parameters; `network` is the start value of `spindle` (the network it was built with), `net`
    that network loaded (spindle.thermal.model.load_spindle): its main dimensions are the start values of
    theirs."""
    return (
        Variable(
            "spindle", "", "spindle network: catalogue name or path of a spindle TOML file", "string", start=network
        ),
        Variable(
            "integrator",
            "",
            "exponential (exact for inputs held over the step) | implicit_euler",
            "string",
            start="exponential",
            choices=INTEGRATORS,
        ),
        Variable(
            "T_initial",
            "K",
            f"initial temperature of every node; 0 = the ambient temperature input, else in [{T_MIN:g}, {T_MAX:g}] K",
            start=0.0,
            min=0.0,
            max=T_MAX,
            limits=f"0 (= the ambient input) or [{T_MIN:g}, {T_MAX:g}] K: {T_LIMITS}",
        ),
        *dimension_declarations(net),
    )


def input_declarations(net, axial_float):
    """Inputs of a network (spindle.thermal.model.Network): heat inputs (W), shaft speed, boundary
    temperatures and, with axial_float, the axial reaction and stiffness of each bearing of the pair."""
    heat = dict(min=-HEAT_MAX, max=HEAT_MAX, limits="far beyond any spindle bearing or motor loss")
    out = [Variable(name, "W", text, **heat) for name, text in zip(net.heat_names, net.heat_text)]
    out.append(
        Variable(
            "omega",
            "rad/s",
            "shaft angular speed (rotating-shaft convection, centrifugal growth)",
            min=-OMEGA_MAX,
            max=OMEGA_MAX,
            limits="beyond any spindle; the bearing FMUs' static bound",
        )
    )
    out += [
        Variable(name, "K", f"temperature of the boundary '{b}'", start=T_START, min=T_MIN, max=T_MAX, limits=T_LIMITS)
        for name, b in zip(net.boundary_inputs, net.boundaries)
    ]
    if axial_float:
        for k in (1, 2):
            out.append(
                Variable(
                    f"F_axial_{k}",
                    "N",
                    f"axial reaction of bearing {k} (axial float)",
                    min=-LOAD_MAX,
                    max=LOAD_MAX,
                    limits="the bearing FMUs' static load bound",
                )
            )
        for k in (1, 2):
            out.append(
                Variable(
                    f"K_axial_{k}",
                    "N/m",
                    f"axial stiffness of bearing {k} (axial float), >= 0",
                    min=0.0,
                    max=K_AXIAL_MAX,
                    limits="100 x the axial stiffness of the stiffest spindle bearing sets",
                )
            )
    return tuple(out)


def output_declarations(net):
    """Outputs of a network: node temperatures, ring and oil temperatures and clearance change per
    bearing, the pair's axial interference (with an [axial] section), heat balance."""
    out = [Variable(f"T_{name}", "K", f"temperature of node '{name}'") for name in net.nodes]
    names = {v.name for v in out}
    for k, b in enumerate(net.bearings, start=1):
        for alias, role, text in (
            (f"T_inner_ring_{k}", "inner_ring", "inner ring"),
            (f"T_outer_ring_{k}", "outer_ring", "outer ring"),
            (f"T_oil_{k}", "ball_oil", "balls and oil"),
        ):
            if alias in names:  # a node already carries this name: it is that node's output
                if alias != f"T_{net.nodes[b[role]]}":
                    raise ParameterError(
                        f"{net.path}: output {alias} would name node '{alias[2:]}' and "
                        f"bearing {k}'s {role} '{net.nodes[b[role]]}': rename the node"
                    )
                continue
            out.append(Variable(alias, "K", f"temperature of bearing {k}'s {text} (node '{net.nodes[b[role]]}')"))
            names.add(alias)
        out.append(
            Variable(
                f"dPd_thermal_{k}",
                "m",
                f"change of bearing {k}'s diametral clearance from thermal and centrifugal growth (negative = tighter)",
            )
        )
    if net.axial:
        out.append(
            Variable(
                "dz_thermal",
                "m",
                "change of the pair's axial interference from shaft vs housing growth (> 0 tightens both bearings)",
            )
        )
        for k in (1, 2):
            out.append(
                Variable(
                    f"dz_thermal_{k}",
                    "m",
                    f"change of bearing {k}'s local axial approach (dz_thermal/2 {'+' if k == 1 else '-'} axial float)",
                )
            )
    out += [
        Variable("P_in", "W", "sum of the heat inputs"),
        Variable("P_out", "W", "heat flowing into the boundaries at the current temperatures"),
        Variable("E_stored", "J", "heat stored since initialisation: sum of C (T - T_initial)"),
    ]
    return tuple(out)
