"""SpindleThermalModel: facade of the lumped thermal spindle (docs/spindle_thermal.md).

Reads a spindle TOML (a catalogue name in spindle/thermal/params/ or a path), packs it into the arrays of
spindle.thermal.network, advances the temperatures with the exact exponential update (default) or backward
Euler, and turns temperatures into thermal/centrifugal changes of bearing clearance and axial
interference. Inputs and outputs are SI and declared once in spindle.thermal.declarations: the model
fills a preallocated output array in that order and the FMU class registers its FMI variables from the
same declarations. No scipy import on this path (a pythonfmu FMU that loads scipy's compiled libraries
first can make its host abort at exit, spindle.cosim.master): the eigendecomposition is numpy's.
"""

import math
from dataclasses import dataclass, replace
from pathlib import Path

import numpy as np

from bearing_fmu_common.bearing_file import check_ring_sections, clearance_limits, read_bearing
from bearing_fmu_common.paramfile import ParameterError, Spec, checked_value, read_toml, resolve_toml
from bearing_fmu_common.variables import THERMAL_SHIFT_MAX, InputError

from . import network as nk
from .declarations import (
    AXIAL,
    AXIAL_FLOAT_MAX,
    DEFAULT_SPINDLE,
    EXPANSION,
    INTEGRATORS,
    RING_DIMENSIONS,
    T_MAX,
    T_MIN,
    dimension_declarations,
    input_declarations,
    output_declarations,
)

CATALOGUE = Path(__file__).resolve().parent / "params"
# The bearing catalogue the networks' [[bearing]] entries name: the bearing_fmu package's beside this
# one (source tree, installed package), or the copy the thermal FMU carries instead of that package
BEARING_CATALOGUES = (
    Path(__file__).resolve().parent / "bearings",
    Path(__file__).resolve().parents[2] / "bearing_fmu" / "params" / "bearings",
)
ARRANGEMENT_SIGN = {"X": 1.0, "O": -1.0}
# Admissible inputs: the declared ranges (spindle.thermal.declarations); anything outside is reported,
# never integrated into NaN
SUBSTEPS_MAX = 100000


class SpindleInputError(InputError):
    """An input of the thermal spindle is outside its allowed range (the message names it and the range)."""


# ---------------------------------------------------------------------------------------------- TOML
def network_path(name_or_path):
    """Path of a spindle network TOML file from its catalogue name or path."""
    return _resolve(name_or_path)


def _resolve(name_or_path):
    return resolve_toml(name_or_path, CATALOGUE, "spindle")


def bearing_catalogue():
    """The folder of the bearing catalogue (BEARING_CATALOGUES: the first that exists)."""
    for folder in BEARING_CATALOGUES:
        if folder.is_dir():
            return folder
    return BEARING_CATALOGUES[-1]


def load_ring_bearing(name_or_path):
    """The bearing (bearing_fmu_common.bearing_file.Bearing) of a network's [[bearing]] entry: a catalogue
    name or a bearing file path."""
    return read_bearing(resolve_toml(name_or_path, bearing_catalogue(), "bearing"))


def _quantity(table, key, unit, where, low=0.0, high=math.inf, low_open=True):
    """Checked value of `table[key]` = { value, unit, source [, estimated] } (where: for messages): the bearing
    and lubricant files' check, one key deep."""
    return checked_value(table, key, Spec(unit, low, high, low_open), where)


# link kind -> (code, [(TOML key, unit)] in the order of the kernel's parameter row)
LINK_KINDS = {
    "conductance": (nk.LINK_CONDUCTANCE, [("G", "W/K")]),
    "shell": (nk.LINK_SHELL, [("conductivity", "W/m/K"), ("length", "m"), ("r_inner", "m"), ("r_outer", "m")]),
    "contact": (nk.LINK_CONTACT, [("h_c", "W/m^2/K"), ("area", "m^2")]),
    "convection": (nk.LINK_CONVECTION, [("h", "W/m^2/K"), ("area", "m^2")]),
    "rotating_shaft": (nk.LINK_ROTATING_SHAFT, [("diameter", "m"), ("area", "m^2")]),
    "advection": (nk.LINK_ADVECTION, [("mass_flow", "kg/s"), ("specific_heat", "J/kg/K")]),
}


@dataclass
class Network:
    """A spindle network packed for the kernels (all SI)."""

    name: str
    path: str
    nodes: tuple  # node names
    C: np.ndarray  # capacities (J/K)
    boundaries: tuple  # boundary names
    boundary_inputs: tuple  # input name giving each boundary's temperature
    links: tuple  # (name, kind name) per link
    kinds: np.ndarray  # int64 link codes
    par: np.ndarray  # (n_links, PAR_SIZE)
    ends_i: np.ndarray  # int64, node index or n + boundary index
    ends_j: np.ndarray
    heat_names: tuple  # heat input names
    heat_text: tuple  # their descriptions
    dist: np.ndarray  # (n_nodes, n_heat) fraction of each input going to each node
    T_ref: float  # assembly temperature (K)
    alpha_bearing: float  # expansion coefficient of rings and balls (1/K)
    bearings: tuple  # dicts: inner_ring, outer_ring, ball_oil (node indices), d_i, d_o, D, a, E, nu, rho
    axial: dict | None  # s_arr, spacing, alpha_shaft, alpha_housing, shaft, housing (indices), axial_float


def _bearing_entry(entry, index, node_index, where):
    where = f"{where} [[bearing]] #{index}"
    nodes = {}
    for role in ("inner_ring", "outer_ring", "ball_oil"):
        name = entry.get(role)
        if name not in node_index:
            raise ParameterError(f"{where}: '{role}' = {name!r} is not a node ({', '.join(node_index)})")
        nodes[role] = node_index[name]
    b = load_ring_bearing(entry.get("bearing", ""))  # its reader checks the bore against the groove
    if b.bore is None:
        raise ParameterError(f"{b.path} [geometry]: missing key 'bore' (m)")
    ring = ring_dimensions(b.D, b.dm, b.Pd, b.bore, b.ring.E, b.ring.nu, b.ring.rho)
    # the conformities stay the file's: with the ball diameter they bound the clearance (clearance_limits)
    return dict(name=b.name, **ring, f_i=b.f_i, f_o=b.f_o, **nodes)


def ring_dimensions(D, dm, Pd, bore, E, nu, rho):
    """A bearing's entries of Network.bearings from its ball diameter D, pitch diameter dm, diametral clearance Pd
    and bore (m) and its rings' modulus E (Pa), Poisson ratio nu and density rho (kg/m^3): the groove diameters
    d_i, d_o with P_d = d_o - d_i - 2 D (Harris) and the bore radius a."""
    d_i = dm - D - 0.5 * Pd
    d_o = dm + D + 0.5 * Pd
    return dict(D=D, dm=dm, Pd=Pd, bore=bore, d_i=d_i, d_o=d_o, a=0.5 * bore, E=E, nu=nu, rho=rho)


def load_spindle(name_or_path):
    """Network from a catalogue name ('b7214c_x_pair') or a TOML path; validated (docs/spindle_thermal.md)."""
    path = _resolve(name_or_path)
    doc = read_toml(path, "spindle")
    where = str(path)
    nodes, C, boundaries, b_inputs = _nodes_and_boundaries(doc, where)
    everything = nodes + boundaries
    if not nodes or not boundaries or len(set(everything)) != len(everything):
        raise ParameterError(f"{where}: needs >= 1 [[node]] and >= 1 [[boundary]], all names distinct")
    index = {name: i for i, name in enumerate(everything)}
    n = len(nodes)
    node_index = {name: i for i, name in enumerate(nodes)}

    air = doc.get("air", {})
    links, kinds, par, ends_i, ends_j = [], [], [], [], []
    for k, entry in enumerate(doc.get("link", [])):
        label, kind, code, row, i, j = _link(entry, k, index, everything, n, air, where)
        links.append((label, kind))
        kinds.append(code)
        par.append(row)
        ends_i.append(i)
        ends_j.append(j)
    _check_paths(nodes, n, ends_i, ends_j, kinds, where)
    heat_names, heat_text, columns = _heat_inputs(doc, nodes, node_index, b_inputs, where)

    exp = doc.get("expansion", {})
    T_ref = _quantity(exp, "T_ref", "K", f"{where} [expansion]", high=T_MAX)
    alpha_b = _quantity(exp, "alpha_bearing", "1/K", f"{where} [expansion]", low=0.0, high=1e-3, low_open=False)
    bearings = tuple(_bearing_entry(e, k + 1, node_index, where) for k, e in enumerate(doc.get("bearing", [])))
    axial = _axial(doc.get("axial"), node_index, len(bearings), where)
    return Network(
        name=str(doc.get("meta", {}).get("name", path.stem)),
        path=str(path),
        nodes=tuple(nodes),
        C=np.array(C),
        boundaries=tuple(boundaries),
        boundary_inputs=tuple(b_inputs),
        links=tuple(links),
        kinds=np.array(kinds, dtype=np.int64),
        par=np.array(par).reshape(len(par), nk.PAR_SIZE),
        ends_i=np.array(ends_i, dtype=np.int64),
        ends_j=np.array(ends_j, dtype=np.int64),
        heat_names=tuple(heat_names),
        heat_text=tuple(heat_text),
        dist=np.array(columns).T.reshape(n, len(columns)),
        T_ref=T_ref,
        alpha_bearing=alpha_b,
        bearings=bearings,
        axial=axial,
    )


def _nodes_and_boundaries(doc, where):
    """The [[node]] names and heat capacities (J/K) and the [[boundary]] names and input names of a network."""
    nodes, C = [], []
    for k, entry in enumerate(doc.get("node", [])):
        name = entry.get("name")
        if not isinstance(name, str) or not name.isidentifier():
            raise ParameterError(f"{where}: [[node]] #{k + 1} needs a name (letters, digits, _)")
        nodes.append(name)
        C.append(_quantity(entry, "capacity", "J/K", f"{where} node '{name}'"))
    boundaries, b_inputs = [], []
    for k, entry in enumerate(doc.get("boundary", [])):
        name, inp = entry.get("name"), entry.get("input")
        if not isinstance(name, str) or not isinstance(inp, str) or not inp.isidentifier():
            raise ParameterError(f"{where}: [[boundary]] #{k + 1} needs a name and an input name")
        boundaries.append(name)
        b_inputs.append(inp)
    return nodes, C, boundaries, b_inputs


def _link(entry, k, index, everything, n, air, where):
    """One [[link]] (the k-th): its label, kind, kernel code, parameter row and its ends (node first)."""
    between = entry.get("between")
    lw = f"{where} [[link]] #{k + 1} {between}"
    if (
        not isinstance(between, list)
        or len(between) != 2
        or between[0] == between[1]
        or any(e not in index for e in between)
    ):
        raise ParameterError(f"{lw}: 'between' must name two different nodes/boundaries of {everything}")
    i, j = index[between[0]], index[between[1]]
    if i >= n and j >= n:
        raise ParameterError(f"{lw}: a link between two boundaries has no effect on the network")
    if i >= n:
        i, j = j, i  # node first
    kind = entry.get("kind")
    if kind == "convection" and entry.get("correlation") == "rotating_shaft":
        kind = "rotating_shaft"
    elif kind == "convection" and "correlation" in entry:
        raise ParameterError(f"{lw}: correlation = {entry['correlation']!r}, allowed: 'rotating_shaft'")
    if kind not in LINK_KINDS:
        raise ParameterError(
            f"{lw}: kind = {kind!r}, allowed: {', '.join(k for k in LINK_KINDS if k != 'rotating_shaft')}"
        )
    if kind == "advection" and j < n:
        raise ParameterError(f"{lw}: an advection link carries a flow from a boundary (inlet) to a node")
    code, keys = LINK_KINDS[kind]
    row = np.zeros(nk.PAR_SIZE)
    for q, (key, unit) in enumerate(keys):
        row[q] = _quantity(entry, key, unit, lw)
    if kind == "shell" and not row[3] > row[2]:
        raise ParameterError(f"{lw}: r_outer = {row[3]} m must exceed r_inner = {row[2]} m")
    if kind == "rotating_shaft":
        row[2] = _quantity(air, "conductivity", "W/m/K", f"{where} [air]")
        row[3] = _quantity(air, "kinematic_viscosity", "m^2/s", f"{where} [air]")
        row[4] = _quantity(air, "prandtl", "-", f"{where} [air]")
    return entry.get("name", f"{between[0]}--{between[1]}"), kind, code, row, i, j


def _heat_inputs(doc, nodes, node_index, b_inputs, where):
    """The [[heat_input]] names, descriptions and their split over the nodes (a column of fractions each)."""
    n = len(nodes)
    heat_names, heat_text, columns = [], [], []
    for entry in doc.get("heat_input", []):
        name, split = entry.get("name"), entry.get("split")
        hw = f"{where} [[heat_input]] '{name}'"
        if (
            not isinstance(name, str)
            or not name.isidentifier()
            or name in heat_names
            or name in b_inputs
            or name == "omega"
        ):
            raise ParameterError(f"{hw}: needs a unique name (letters, digits, _)")
        if not isinstance(split, dict) or not split or any(t not in node_index for t in split):
            raise ParameterError(f"{hw}: 'split' must map node names ({', '.join(nodes)}) to fractions")
        col = np.zeros(n)
        for target, frac in split.items():
            if isinstance(frac, bool) or not isinstance(frac, (int, float)) or not 0.0 < frac <= 1.0:
                raise ParameterError(f"{hw}: fraction to '{target}' = {frac!r} must be in ]0, 1]")
            col[node_index[target]] = frac
        if abs(col.sum() - 1.0) > 1e-12:
            raise ParameterError(f"{hw}: fractions sum to {col.sum()}, must sum to 1")
        if "source" not in entry:
            raise ParameterError(f"{hw}: has no 'source'")
        heat_names.append(name)
        heat_text.append(str(entry.get("description", f"heat input {name}")))
        columns.append(col)

    return heat_names, heat_text, columns


def _check_paths(nodes, n, ends_i, ends_j, kinds, where):
    """Raise unless every node reaches a boundary through links whose conductance does not vanish at rest
    (the rotating-shaft correlation gives G = 0 at omega = 0, so it does not count)."""
    reached, frontier = set(), []
    adjacency = {i: set() for i in range(n)}
    for i, j, code in zip(ends_i, ends_j, kinds):
        if code == nk.LINK_ROTATING_SHAFT:
            continue
        if j >= n:
            frontier.append(i)
        else:
            adjacency[i].add(j)
            adjacency[j].add(i)
    while frontier:
        i = frontier.pop()
        if i not in reached:
            reached.add(i)
            frontier.extend(adjacency[i] - reached)
    for i, name in enumerate(nodes):
        if i not in reached:
            raise ParameterError(
                f"{where}: node {name} has no conductive path to a boundary: steady state undefined "
                f"(the rotating-shaft convection vanishes at rest and does not count)"
            )


def _axial(section, node_index, n_bearings, where):
    if section is None:
        return None
    aw = f"{where} [axial]"
    if n_bearings != 2:
        raise ParameterError(f"{aw}: the axial interference is defined for a pair: needs exactly 2 [[bearing]]")
    arrangement = section.get("arrangement")
    if arrangement not in ARRANGEMENT_SIGN:
        raise ParameterError(f"{aw}: arrangement = {arrangement!r}, allowed: 'X' (face-to-face), 'O' (back-to-back)")
    out = dict(arrangement=arrangement, s_arr=ARRANGEMENT_SIGN[arrangement])
    for role in ("shaft", "housing"):
        if section.get(role) not in node_index:
            raise ParameterError(f"{aw}: '{role}' = {section.get(role)!r} is not a node")
        out[role] = node_index[section[role]]
    out["spacing"] = _quantity(section, "spacing", "m", aw, high=10.0)
    out["alpha_shaft"] = _quantity(section, "alpha_shaft", "1/K", aw, low=0.0, high=1e-3, low_open=False)
    out["alpha_housing"] = _quantity(section, "alpha_housing", "1/K", aw, low=0.0, high=1e-3, low_open=False)
    flt = section.get("axial_float", False)
    if not isinstance(flt, bool):
        raise ParameterError(f"{aw}: axial_float = {flt!r} must be true or false")
    out["axial_float"] = flt
    return out


def with_dimensions(net, values):
    """`net` with its main dimensions (spindle.thermal.declarations.dimension_rows) replaced by `values` (FMI name
    -> value; the parameter network_from_file false): each checked against its declared range, and the ring
    geometry as a bearing file's (0 < D < d_m, |Pd| <= (f_i + f_o - 1) D with the file's conformities, 0 < bore
    below the inner groove bottom: bearing_fmu_common.bearing_file.check_ring_sections, spacing > 0). A refusal
    names the parameter."""
    for var in dimension_declarations(net)[1:]:
        var.check(values[var.name])
    bearings = []
    for k, b in enumerate(net.bearings, start=1):
        ring = {key: values[f"bearing_{k}.{name}"] for name, _, key, *_ in RING_DIMENSIONS}
        geometry = ring_dimensions(ring["D"], ring["dm"], ring["Pd"], ring["bore"], ring["E"], ring["nu"], ring["rho"])
        if not 0.0 < ring["D"] < ring["dm"]:
            raise ParameterError(
                f"bearing_{k}.D = {ring['D']} m must be > 0 and below bearing_{k}.d_m = {ring['dm']} m"
            )
        low, high = clearance_limits(ring["D"], b["f_i"], b["f_o"])
        if not low <= ring["Pd"] <= high:
            raise ParameterError(
                f"bearing_{k}.Pd = {ring['Pd']} m is outside the allowed range [{low:.4g}, {high:.4g}] m "
                f"(|Pd| <= (f_i + f_o - 1) D with bearing_{k}.D = {ring['D']} m and the conformities f_i = {b['f_i']}, "
                f"f_o = {b['f_o']} of bearing '{b['name']}': free contact angle up to 60 deg, as in the bearing FMUs)"
            )
        if not ring["bore"] > 0.0:
            raise ParameterError(f"bearing_{k}.bore = {ring['bore']} m must be > 0")
        names = {key: f"bearing_{k}.{key}" for key in ("bore", "D", "d_m", "Pd")}
        check_ring_sections(ring["D"], ring["dm"], ring["Pd"], bore=ring["bore"], names=names)
        bearings.append({**b, **geometry})
    axial = net.axial and {**net.axial, **{key: values[name] for name, _, key, *_ in AXIAL}}
    if axial and not axial["spacing"] > 0.0:
        raise ParameterError(f"axial.spacing = {axial['spacing']} m must be > 0")
    expansion = {key: values[name] for name, _, key, *_ in EXPANSION}
    return replace(net, bearings=tuple(bearings), axial=axial, **expansion)


def _admissible(var):
    """(low, high, allowed range as text) of an input: its declared range (spindle.thermal.declarations);
    admissible means low <= x <= high, which also refuses NaN; the text is for messages."""
    return var.min, var.max, f"{var.range_text()} ({var.limits})"


# --------------------------------------------------------------------------------------------- model
class SpindleThermalModel:
    """Lumped thermal spindle (docs/spindle_thermal.md): temperatures, clearance and axial-interference changes.

    spindle: catalogue name (spindle/thermal/params/<name>.toml) or TOML path; integrator: 'exponential'
    (exact for inputs held over the step, default) | 'implicit_euler' (backward Euler, `substeps` >= 1
    equal sub-steps per step); T_initial (K): start temperature of every node (default: the T_ambient
    input, or the first boundary's input, at initialize()); axial_float: None = as the TOML's
    [axial] section says, True/False overrides it (the fixed-preload FMU is built with True);
    dimensions: None = the network's main dimensions (its file and its bearings' files), else their values by
    FMI name (with_dimensions; the FMU parameter network_from_file false).
    Inputs missing from a call keep their previous value (defaults: heats 0 W, omega 0, temperatures
    T_ref, forces 0 N, stiffnesses 0 N/m), like FMU inputs.
    """

    def __init__(
        self,
        spindle=DEFAULT_SPINDLE,
        integrator="exponential",
        substeps=1,
        T_initial=None,
        axial_float=None,
        dimensions=None,
    ):
        if integrator not in INTEGRATORS:
            raise SpindleInputError(f"integrator = {integrator!r}: allowed {list(INTEGRATORS)}")
        if (
            isinstance(substeps, bool)
            or not isinstance(substeps, (int, np.integer))
            or not 1 <= substeps <= SUBSTEPS_MAX
        ):
            raise SpindleInputError(f"substeps = {substeps!r} must be a whole number in [1, {SUBSTEPS_MAX}]")
        if T_initial is not None and not (T_MIN <= T_initial <= T_MAX):  # a NaN fails the test
            raise SpindleInputError(
                f"T_initial = {T_initial} K is outside the allowed range [{T_MIN:g}, {T_MAX:g}] K (None or, in the "
                f"FMU, 0 = the ambient input)"
            )
        self.net = net = load_spindle(spindle)
        if dimensions is not None:
            self.net = net = with_dimensions(net, dimensions)
        self.integrator = integrator
        self.substeps = int(substeps)
        self.T_initial = None if T_initial is None else float(T_initial)
        self.axial_float = bool(net.axial and net.axial["axial_float"]) if axial_float is None else bool(axial_float)
        if self.axial_float and not net.axial:
            raise SpindleInputError(f"axial_float = true needs an [axial] section in spindle '{spindle}'")
        self.inputs = input_declarations(net, self.axial_float)
        self.input_names = tuple(v.name for v in self.inputs)
        self.outputs = output_declarations(net)
        self.output_names = tuple(v.name for v in self.outputs)
        self.values = np.zeros(len(self.outputs))  # outputs at the current state, in self.outputs order
        self._next = np.zeros(len(self.outputs))  # outputs of a step before they are accepted
        self._position = {name: k for k, name in enumerate(self.input_names)}
        self._checks = [(v.name, v.unit, *_admissible(v)) for v in self.inputs]
        self._tables()
        self._u = [net.T_ref if v.unit == "K" else 0.0 for v in self.inputs]  # held inputs, self.inputs order
        self._cache_omega = None
        self._op = None
        self.T = None  # node temperatures (K); None until initialize()
        self.T0 = None  # initial node temperatures (K) for E_stored
        self.s = 0.0  # axial float of the shaft (m)
        self.time = 0.0  # s

    def _tables(self):
        """Index and parameter tables of the step and output kernels (spindle.thermal.network)."""
        net, position = self.net, self._position
        slot = {name: k for k, name in enumerate(self.output_names)}
        self._heat_at = np.array([position[name] for name in net.heat_names], dtype=np.int64)
        self._boundary_at = np.array([position[name] for name in net.boundary_inputs], dtype=np.int64)
        self._bearing_par = np.array(
            [[b["rho"], b["E"], b["nu"], b["a"], b["d_i"], b["d_o"], b["D"]] for b in net.bearings], dtype=float
        ).reshape(len(net.bearings), 7)
        self._clearance_limits = self._clearance_output_limits(slot)
        self._bearing_idx = np.array(
            [
                [b["inner_ring"], b["outer_ring"], b["ball_oil"]]
                + [slot[f"{kind}_{k}"] for kind in ("T_inner_ring", "T_outer_ring", "T_oil", "dPd_thermal")]
                for k, b in enumerate(net.bearings, start=1)
            ],
            dtype=np.int64,
        ).reshape(len(net.bearings), 7)
        ax = net.axial
        self._par = np.array(
            [net.alpha_bearing, net.T_ref]
            + ([ax["s_arr"], ax["alpha_shaft"], ax["alpha_housing"], ax["spacing"]] if ax else [0.0] * 4)
        )
        self._idx = np.array(
            (
                [ax["shaft"], ax["housing"], slot["dz_thermal"], slot["dz_thermal_1"], slot["dz_thermal_2"]]
                if ax
                else [-1] * 5
            )
            + [slot["P_in"], slot["P_out"], slot["E_stored"], position["omega"]],
            dtype=np.int64,
        )
        if self.axial_float:
            self._axial_at = tuple(position[name] for name in ("F_axial_1", "F_axial_2", "K_axial_1", "K_axial_2"))

    def _clearance_output_limits(self, slot):
        """Per bearing (output slot of dPd_thermal_k, low, high, why): the range dPd_thermal_k may take, that of the
        bearing FMUs' input dPd_thermal for this bearing: |dPd| <= THERMAL_SHIFT_MAX and P_d + dPd within the
        groove clearance, |P_d + dPd| <= (f_i + f_o - 1) D (bearing_fmu_common.bearing_file.clearance_limits)."""
        rows = []
        for k, b in enumerate(self.net.bearings, start=1):
            low, high = clearance_limits(b["D"], b["f_i"], b["f_o"])
            why = (
                f"|dPd_thermal_{k}| <= {THERMAL_SHIFT_MAX:g} m and Pd + dPd_thermal_{k} within [{low:.4g}, "
                f"{high:.4g}] m with Pd = {b['Pd']} m: the bearing FMUs' input dPd_thermal, |Pd + dPd| <= "
                "(f_i + f_o - 1) D"
            )
            rows.append(
                (
                    slot[f"dPd_thermal_{k}"],
                    max(-THERMAL_SHIFT_MAX, low - b["Pd"]),
                    min(THERMAL_SHIFT_MAX, high - b["Pd"]),
                    why,
                )
            )
        return tuple(rows)

    def _check_clearance_outputs(self, values, u):
        """Raise SpindleInputError if a bearing's clearance change in `values` (outputs for the inputs u) leaves the
        range of _clearance_output_limits: growth no bearing survives (a ring turning too fast for its modulus, or
        temperatures beyond any spindle's), which the bearing FMU fed with it would refuse."""
        for k, (at, low, high, why) in enumerate(self._clearance_limits, start=1):
            if not low <= values[at] <= high:  # a NaN fails too
                omega = u[self._idx[nk.LS_OMEGA]]
                raise SpindleInputError(
                    f"dPd_thermal_{k} = {values[at]} m (thermal and centrifugal growth at omega = {omega} rad/s and "
                    f"the network's temperatures, of the rings of {self._ring_parameters(k)}) is outside the allowed "
                    f"range [{low:.4g}, {high:.4g}] m ({why}); state left unchanged"
                )

    def _ring_parameters(self, k):
        """The FMU parameters that set bearing k's growth, with their values (a refused growth names them)."""
        b = self.net.bearings[k - 1]
        rings = ", ".join(
            f"bearing_{k}.{name} = {b[key]}" + ("" if unit == "1" else f" {unit}")
            for name, unit, key, *_ in RING_DIMENSIONS
            if name != "Pd"
        )
        return f"{rings} and expansion.alpha_bearing = {self.net.alpha_bearing} 1/K"

    @property
    def parameters(self):
        """Summary of the network (for documentation): nodes, boundaries, links (G at rest), inputs, bearings."""
        net = self.net
        G0 = nk.link_conductances(net.kinds, net.par, 0.0)
        names = net.nodes + net.boundaries
        return {
            "name": net.name,
            "path": net.path,
            "integrator": self.integrator,
            "substeps": self.substeps,
            "nodes": {name: float(c) for name, c in zip(net.nodes, net.C)},
            "boundaries": dict(zip(net.boundaries, net.boundary_inputs)),
            "links": [
                {"name": ln, "kind": kind, "between": (names[i], names[j]), "G_at_rest": float(g)}
                for (ln, kind), i, j, g in zip(net.links, net.ends_i, net.ends_j, G0)
            ],
            "heat_inputs": {
                name: {net.nodes[i]: float(f) for i, f in enumerate(net.dist[:, q]) if f}
                for q, name in enumerate(net.heat_names)
            },
            "T_ref": net.T_ref,
            "alpha_bearing": net.alpha_bearing,
            "bearings": [
                {key: (net.nodes[v] if key in ("inner_ring", "outer_ring", "ball_oil") else v) for key, v in b.items()}
                for b in net.bearings
            ],
            "axial": None
            if net.axial is None
            else {key: (net.nodes[v] if key in ("shaft", "housing") else v) for key, v in net.axial.items()},
        }

    # ---------------------------------------------------------------- inputs
    def _merge(self, inputs):
        """Current inputs (a list in self.inputs order) updated with `inputs` (dict name -> value), validated
        (SpindleInputError names the first bad one)."""
        u = list(self._u)
        for name, value in inputs.items():
            if name not in self._position:
                raise SpindleInputError(f"unknown input '{name}'; inputs: {', '.join(self.input_names)}")
            try:
                u[self._position[name]] = float(value)
            except (TypeError, ValueError):
                raise SpindleInputError(f"{name} = {value!r} is not a number") from None
        self._check(u)
        return u

    def _check(self, u):
        """Raise SpindleInputError naming the first input of u (self.inputs order) outside its range."""
        for x, (name, unit, low, high, allowed) in zip(u, self._checks):
            if not low <= x <= high:
                raise SpindleInputError(f"{name} = {x} {unit} is outside the allowed range {allowed}")

    def _vectors(self, u):
        """(node heats P (W), boundary temperatures T_b (K), sum of the heat inputs (W)) of the inputs u."""
        u = np.asarray(u, dtype=float)
        return nk.heat_vector(u, self._heat_at, self.net.dist), u[self._boundary_at], float(u[self._heat_at].sum())

    def _operator(self, omega):
        """Conductances, L, B, Cholesky factor of L and (exponential) eigen data at omega; cached per omega."""
        if self._cache_omega == omega:
            return self._op
        net = self.net
        G = nk.link_conductances(net.kinds, net.par, omega)
        L, B = nk.assemble(len(net.nodes), len(net.boundaries), net.ends_i, net.ends_j, G)
        R = nk.cholesky(L)
        if not np.all(np.isfinite(R)):
            raise SpindleInputError(
                f"the conductance matrix at omega = {omega} rad/s is singular: some node has no path to a boundary"
            )
        op = {"G": G, "L": L, "B": B, "R": R}
        if self.integrator == "exponential":
            sqrt_c = np.sqrt(net.C)
            lam, V = np.linalg.eigh(L / np.outer(sqrt_c, sqrt_c))  # S = C^-1/2 L C^-1/2, symmetric
            op.update(sqrt_c=sqrt_c, lam=np.ascontiguousarray(lam), V=np.ascontiguousarray(V))
        self._cache_omega, self._op = omega, op
        return op

    # ---------------------------------------------------------------- API
    def initialize(self, **inputs):
        """Set inputs, all nodes to T_initial (default: T_ambient, else the first boundary input), s = 0, time = 0."""
        u = self._merge(inputs)
        T = np.full(len(self.net.nodes), self._start_temperature(u))
        values = np.zeros(len(self.outputs))
        self._outputs(T, u, values, 0.0, T)
        self._check_clearance_outputs(values, u)
        self._u = u
        self.T, self.T0 = T, T.copy()
        self.s, self.time = 0.0, 0.0
        self.values[:] = values
        return self.outputs_values()

    def _start_temperature(self, u):
        if self.T_initial is not None:
            return self.T_initial
        return u[self._position["T_ambient"] if "T_ambient" in self._position else self._boundary_at[0]]

    def step(self, h, **inputs):
        """Advance h seconds (> 0) with `inputs` held over the step; returns the outputs (dict name -> SI)."""
        self.advance(h, **inputs)
        return self.outputs_values()

    def advance(self, h, **inputs):
        """step() without building the output dict: the outputs are in self.values (self.outputs order)."""
        if self.T is None:
            self.initialize()
        self.update(h, self._merge(inputs))

    def update(self, h, u):
        """Advance h seconds (> 0) with the input values u (SI, self.inputs order: all of them) held over the
        step; fills self.values (self.outputs order) and returns it. The FMU's path: no dict, no copy of
        the outputs."""
        if self.T is None:
            self.initialize()
        if isinstance(h, bool) or not isinstance(h, (int, float)) or not (math.isfinite(h) and h > 0.0):
            raise SpindleInputError(f"step size h = {h!r} s must be a finite number > 0")
        self._check(u)
        u_vec = np.array(u, dtype=float)
        op = self._operator(u[self._idx[nk.LS_OMEGA]])
        if self.integrator == "exponential":
            T = nk.exponential_update(
                self.T,
                u_vec,
                self._heat_at,
                self._boundary_at,
                self.net.dist,
                op["B"],
                op["R"],
                op["sqrt_c"],
                op["V"],
                op["lam"],
                float(h),
            )
        else:
            P, Tb, _ = self._vectors(u_vec)
            f = nk.source_vector(op["B"], Tb, P)
            T = nk.implicit_euler_step(self.net.C, op["L"], f, self.T, float(h), self.substeps)
        if not (T.min() > 0.0 and T.max() < math.inf):  # a NaN fails both comparisons
            bad = np.flatnonzero(~(np.isfinite(T) & (T > 0.0)))
            raise SpindleInputError(
                f"node {self.net.nodes[bad[0]]} would reach T = {T[bad[0]]} K (non-physical) "
                f"with these heat inputs; state left unchanged"
            )
        s = self.s
        if self.axial_float:
            F_1, F_2, K_1, K_2 = (u[k] for k in self._axial_at)
            if K_1 > 0.0 and K_2 > 0.0:
                # rigid shaft floats until both bearings carry the same axial force (one Newton step on F_1 - F_2)
                s = self.s + (F_2 - F_1) / (K_1 + K_2)
                if not abs(s) <= AXIAL_FLOAT_MAX:
                    shown = ", ".join(
                        f"{n} = {v}"
                        for n, v in zip(("F_axial_1", "F_axial_2", "K_axial_1", "K_axial_2"), (F_1, F_2, K_1, K_2))
                    )
                    raise SpindleInputError(
                        f"{shown} give an axial float s = {s} m, outside the allowed range [{-AXIAL_FLOAT_MAX:g}, "
                        f"{AXIAL_FLOAT_MAX:g}] m (a bearing FMU refuses dz_thermal beyond it); state left unchanged"
                    )
        self._outputs(T, u_vec, self._next, s)
        self._check_clearance_outputs(self._next, u)
        self.s = s
        self._u, self.T = [float(x) for x in u], T
        self.time += float(h)
        self.values[:] = self._next
        return self.values

    def outputs_values(self):
        """Outputs (dict name -> float, SI) at the current state."""
        if self.T is None:
            self.initialize()
        return dict(zip(self.output_names, self.values.tolist()))

    def steady_state(self, **inputs):
        """Outputs at the steady state for `inputs` (merged with the current ones), by a direct solve of
        L T = B T_b + P. The model state is not changed."""
        u = self._merge(inputs)
        op = self._operator(u[self._idx[nk.LS_OMEGA]])
        P, Tb, _ = self._vectors(u)
        values = np.zeros(len(self.outputs))
        self._outputs(nk.cholesky_solve(op["R"], nk.source_vector(op["B"], Tb, P)), u, values)
        self._check_clearance_outputs(values, u)
        return dict(zip(self.output_names, values.tolist()))

    def time_constants(self, omega=0.0):
        """Time constants 1/lambda (s) of the network at omega (rad/s), slowest first (generalised
        eigenvalues of L x = lambda C x)."""
        sqrt_c = np.sqrt(self.net.C)
        L = nk.assemble(
            len(self.net.nodes),
            len(self.net.boundaries),
            self.net.ends_i,
            self.net.ends_j,
            nk.link_conductances(self.net.kinds, self.net.par, float(omega)),
        )[0]
        return 1.0 / np.linalg.eigvalsh(L / np.outer(sqrt_c, sqrt_c))

    def get_state(self):
        """Complete state as plain values (JSON-serialisable): temperatures, initial temperatures, axial
        float s, time and the held inputs."""
        if self.T is None:
            self.initialize()
        return {
            "T": self.T.tolist(),
            "T0": self.T0.tolist(),
            "s": self.s,
            "time": self.time,
            "inputs": dict(zip(self.input_names, self._u)),
        }

    def set_state(self, state):
        n = len(self.net.nodes)
        T, T0 = np.array(state["T"], dtype=float), np.array(state["T0"], dtype=float)
        if T.shape != (n,) or T0.shape != (n,):
            raise SpindleInputError(f"state holds {T.size} temperatures, the network has {n} nodes")
        self._u = self._merge(state["inputs"])
        self.T, self.T0 = T, T0
        self.s, self.time = float(state["s"]), float(state["time"])
        self._outputs(self.T, self._u, self.values)

    # ---------------------------------------------------------------- outputs
    def _outputs(self, T, u, values, s=None, T0=None):
        """Fill `values` (self.outputs order) with the outputs for node temperatures T and inputs u, the shaft's
        axial float s (m) and the initial temperatures T0 (K) (None: the model's)."""
        u = np.asarray(u, dtype=float)
        if T0 is None:
            T0 = self.T0 if self.T0 is not None else np.full(len(T), self._start_temperature(u))
        net = self.net
        nk.network_outputs(
            T,
            T0,
            u,
            self.s if s is None else s,
            self._heat_at,
            self._boundary_at,
            net.C,
            net.ends_i,
            net.ends_j,
            self._operator(float(u[self._idx[nk.LS_OMEGA]]))["G"],
            self._bearing_par,
            self._bearing_idx,
            self._par,
            self._idx,
            values,
        )
