"""Shaft parameter files (TOML, docs/shaft.md "Parameter file"): sections, materials, disks, seats, tool tip.

Every physical value is an inline table { value, unit, source [, estimated] } (bearing_fmu_common.paramfile).
Positions are axial coordinates z (m) from the shaft's first end (the nose); nodes are put at the ends of the
sections and at their equal subdivisions, and every disk, seat and the tool tip must sit on a node.
"""

from dataclasses import dataclass, replace
from pathlib import Path

import numpy as np

from bearing_fmu_common.paramfile import ParameterError, Spec, checked_value, read_toml, resolve_toml

CATALOGUE = Path(__file__).resolve().parent / "params"
DEFAULT_SHAFT = "rabreau_b7214c"
NODE_TOLERANCE = 1e-9  # m: a disk, seat or tool tip this close to a node is on it
ELEMENTS_MAX = 200  # per section: beyond it the eigen-solution, not the element, limits the accuracy

LENGTH = Spec("m", 0.0, 10.0, low_open=True)
DIAMETER = Spec("m", 0.0, 2.0, low_open=True)
BORE = Spec("m", 0.0, 2.0)
POSITION = Spec("m", 0.0, 10.0)
BEARING_AXES = {"+z": 1, "-z": -1}
MATERIAL = {
    "youngs_modulus": Spec("Pa", 1e9, 1e12),
    "density": Spec("kg/m^3", 100.0, 30000.0),
}
POISSON = Spec("-", 0.0, 0.5, low_open=True)
SHEAR_MODULUS = Spec("Pa", 1e8, 1e12)
DISK = {
    "mass": Spec("kg", 0.0, 1e4),
    "polar_inertia": Spec("kg.m^2", 0.0, 1e3),
    "diametral_inertia": Spec("kg.m^2", 0.0, 1e3),
}
SECTION = {"length": LENGTH, "outer_diameter": DIAMETER, "inner_diameter": BORE}
# The numbers of a shaft file per table, each with its reader's range (shaft_numbers, shaft_with_numbers): what the
# shaft FMUs also take as numeric parameters. The rest is the file's structure (how many entries and their order, the
# sections' elements and materials, the positions, the seats' bearing_axis): it makes the model's degrees of freedom.
NUMBERS = {
    "material": {
        "youngs_modulus": MATERIAL["youngs_modulus"],
        "poisson_ratio": POISSON,
        "density": MATERIAL["density"],
    },
    "section": SECTION,
    "disk": DISK,
}


@dataclass(frozen=True)
class ShaftFile:
    """A shaft file packed for the kernels: node positions (m), element rows (E, G, rho, kappa placeholder 0,
    L, outer and inner diameter; the facade fills kappa), Poisson's ratios per element, disk rows (node, mass,
    polar and diametral inertia), seat nodes, names and bearing axes, and the tool-tip node."""

    path: Path
    name: str
    z: np.ndarray
    elements: np.ndarray
    poisson: np.ndarray
    disks: np.ndarray
    disk_names: tuple
    seat_nodes: tuple
    seat_names: tuple
    seat_axes: tuple  # per seat +1 or -1: the bearing model's z axis along or against the shaft's z
    tip_node: int


def shaft_path(name_or_path):
    """Path of a shaft TOML file from its catalogue name (spindle/shaft/params/) or its path."""
    return resolve_toml(name_or_path, CATALOGUE, "shaft")


def file_name(table, index, key):
    """How a refusal names a value of the file: its table, the entry's index (from 0) and its key, section[1].length."""
    return f"{table}[{index}].{key}"


def _checked(entry, key, spec, path, name, required=True):
    """checked_value of `key` in an entry of a table, a refusal naming the value `name` (file_name or what the caller
    calls it: an FMU parameter)."""
    try:
        return checked_value(entry, key, spec, path, required=required)
    except ParameterError as exc:
        raise ParameterError(str(exc).replace(f"'{key}'", name, 1)) from None


def _materials(doc, path, name=file_name):
    materials = {}
    for i, entry in enumerate(doc.get("material", [])):
        name_i = entry.get("name", f"material[{i}]")
        values = {key: _checked(entry, key, spec, path, name("material", i, key)) for key, spec in MATERIAL.items()}
        nu = _checked(entry, "poisson_ratio", POISSON, path, name("material", i, "poisson_ratio"), required=False)
        G = _checked(entry, "shear_modulus", SHEAR_MODULUS, path, name("material", i, "shear_modulus"), required=False)
        if (nu is None) == (G is None):
            raise ParameterError(f"{path}: material '{name_i}' needs exactly one of poisson_ratio and shear_modulus")
        if nu is None:
            nu = values["youngs_modulus"] / (2.0 * G) - 1.0
            if not 0.0 < nu <= 0.5:
                raise ParameterError(f"{path}: material '{name_i}': E / (2 G) - 1 = {nu} is outside ]0, 0.5]")
        else:
            G = values["youngs_modulus"] / (2.0 * (1.0 + nu))
        materials[name_i] = (values["youngs_modulus"], G, values["density"], nu)
    return materials


def _sections(doc, path, materials, name=file_name):
    """(node positions, element rows, Poisson's ratio per element) from the [[section]] list; `name` names a value
    in a refusal (file_name)."""
    z, rows, nus = [0.0], [], []
    if not doc.get("section"):
        raise ParameterError(f"{path}: no [[section]]: a shaft needs at least one section")
    for i, sec in enumerate(doc["section"]):
        where = f"section[{i}] ('{sec.get('name', '')}')"
        length, d_o, d_i = (_checked(sec, key, spec, path, name("section", i, key)) for key, spec in SECTION.items())
        n = sec.get("elements", 1)
        if isinstance(n, bool) or not isinstance(n, int) or not 1 <= n <= ELEMENTS_MAX:
            raise ParameterError(f"{path}: {where}: elements = {n!r} must be an integer in [1, {ELEMENTS_MAX}]")
        if d_i >= d_o:
            inner, outer = name("section", i, "inner_diameter"), name("section", i, "outer_diameter")
            raise ParameterError(
                f"{path}: {inner} = {d_i} m must be below {outer} = {d_o} m (section '{sec.get('name', '')}'); "
                f"allowed: an inner diameter in [0, {d_o}[ m"
            )
        if sec.get("material") not in materials:
            raise ParameterError(f"{path}: {where}: material {sec.get('material')!r} is not one of {sorted(materials)}")
        E, G, rho, nu = materials[sec["material"]]
        for _ in range(n):
            z.append(z[-1] + length / n)
            rows.append((E, G, rho, 0.0, length / n, d_o, d_i))
            nus.append(nu)
    return np.array(z), np.array(rows), np.array(nus)


def _node_at(z, position, what, path):
    node = int(np.argmin(np.abs(z - position)))
    if abs(z[node] - position) > NODE_TOLERANCE:
        raise ParameterError(
            f"{path}: {what} at z = {position} m is on no node (nearest node at {z[node]:.6g} m): "
            "subdivide the sections so that a node falls on it"
        )
    return node


def _bearing_axis(seat, name, path):
    """+1 or -1 from a seat's `bearing_axis` ("+z" or "-z", default "+z"): whether the bearing model's own z axis
    (its F_z and the third row and column of its K) points along the shaft's z (nose to rear) or against it."""
    axis = seat.get("bearing_axis", "+z")
    if axis not in BEARING_AXES:
        raise ParameterError(
            f"{path}: seat '{name}': bearing_axis = {axis!r} is not allowed; allowed {list(BEARING_AXES)} (the "
            "bearing model's z axis along the shaft's z, from the nose to the rear, or against it)"
        )
    return BEARING_AXES[axis]


def _disk_numbers(doc, path, name=file_name):
    """(mass, polar inertia, diametral inertia) of each [[disk]]; `name` names a value in a refusal (file_name)."""
    return [
        tuple(_checked(d, key, spec, path, name("disk", i, key)) for key, spec in DISK.items())
        for i, d in enumerate(doc.get("disk", []))
    ]


def read_shaft(name_or_path):
    """The shaft file (catalogue name or path) read, checked and packed (ShaftFile)."""
    path = shaft_path(name_or_path)
    doc = read_toml(path)
    materials = _materials(doc, path)
    z, elements, poisson = _sections(doc, path, materials)
    disks, disk_names = [], []
    for i, (d, numbers) in enumerate(zip(doc.get("disk", []), _disk_numbers(doc, path), strict=True)):
        name = d.get("name", f"disk[{i}]")
        node = _node_at(z, checked_value(d, "position", POSITION, path), f"disk '{name}'", path)
        disks.append((node, *numbers))
        disk_names.append(name)
    seat_nodes, seat_names, seat_axes = [], [], []
    for i, s in enumerate(doc.get("seat", [])):
        name = s.get("name", f"seat[{i}]")
        seat_nodes.append(_node_at(z, checked_value(s, "position", POSITION, path), f"seat '{name}'", path))
        seat_names.append(name)
        seat_axes.append(_bearing_axis(s, name, path))
    if len(set(seat_nodes)) != len(seat_nodes):
        raise ParameterError(f"{path}: two seats on one node ({seat_names}): give one seat per bearing node")
    tip = _node_at(z, checked_value(doc, "tool_tip.position", POSITION, path), "tool_tip", path)
    return ShaftFile(
        path=path,
        name=doc.get("meta", {}).get("name", path.stem),
        z=z,
        elements=elements,
        poisson=poisson,
        disks=np.array(disks, dtype=float).reshape(-1, 4),
        disk_names=tuple(disk_names),
        seat_nodes=tuple(seat_nodes),
        seat_names=tuple(seat_names),
        seat_axes=tuple(seat_axes),
        tip_node=tip,
    )


def _numbers(doc, path):
    """(table, index, entry name, key, value) of each number of a read file (NUMBERS), a material's Poisson's ratio
    the reader's (derived from its shear modulus where the file gives that)."""
    poisson = {name: nu for name, (*_, nu) in _materials(doc, path).items()}
    rows = []
    for table, keys in NUMBERS.items():
        for i, entry in enumerate(doc.get(table, [])):
            name = entry.get("name", f"{table}[{i}]")
            for key in keys:
                value = poisson[name] if key == "poisson_ratio" else entry[key]["value"]
                rows.append((table, i, name, key, float(value)))
    return rows


def shaft_numbers(name_or_path):
    """The numbers of a shaft file (catalogue name or path), checked by read_shaft: per table of NUMBERS in the
    file's order, (table, index from 0, entry name, key, value in the unit of NUMBERS)."""
    path = read_shaft(name_or_path).path
    return _numbers(read_toml(path), path)


def _counts(keys):
    """How many entries of each table the numbers' keys (table, index, key) hold: 'material 1, section 5, disk 2'."""
    return ", ".join(f"{table} {len({i for t, i, _ in keys if t == table})}" for table in NUMBERS)


def shaft_with_numbers(name_or_path, numbers, name=file_name):
    """The shaft file (catalogue name or path) with its numbers replaced by `numbers` ((table, index, key) -> value,
    the keys of shaft_numbers), checked by the reader's own checks on them (ranges, inner below outer diameter). The
    structure stays the file's: the sections' elements and materials, the seats' bearing axes and the disks, seats and
    tool tip on the nodes the file puts them on, wherever the new lengths move those nodes. `name(table, index, key)`
    names a value in a refusal (file_name; an FMU passes its parameters' names)."""
    shaft = read_shaft(name_or_path)
    doc = read_toml(shaft.path)
    given = {(table, i, key) for table, i, _, key, _ in _numbers(doc, shaft.path)}
    if set(numbers) != given:
        raise ParameterError(
            f"{shaft.path}: the numbers given are those of a shaft with the entries {_counts(numbers)}; the file has "
            f"{_counts(given)}: allowed, a file with as many materials, sections and disks"
        )
    for (table, i, key), value in numbers.items():
        entry = doc[table][i]
        if key == "poisson_ratio":
            entry.pop("shear_modulus", None)
        entry[key] = {"value": value, "unit": NUMBERS[table][key].unit, "source": name(table, i, key)}
    z, elements, poisson = _sections(doc, shaft.path, _materials(doc, shaft.path, name), name)
    disks = shaft.disks.copy()
    disks[:, 1:] = np.array(_disk_numbers(doc, shaft.path, name), dtype=float).reshape(-1, 3)
    return replace(shaft, z=z, elements=elements, poisson=poisson, disks=disks)
