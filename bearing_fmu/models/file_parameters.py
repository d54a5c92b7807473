"""The values of a bearing file and of a lubricant file as numeric FMU parameters (docs/parameters.md,
"Numeric parameters").

A master that imports no String parameter (OMSimulator) or shows only Real, Integer and Boolean ones in its
dialogs cannot choose a bearing by name: every value of a bearing file and of a lubricant file is therefore
also a numeric parameter (`bearing_data.*`, `lubricant_data.*`). The Boolean `bearing_from_file`
(`lubricant_from_file`) says which of the two is in effect, as `Pd_from_file` does for the clearance:
true (default) = the catalogue entry or TOML file named by the String `bearing` (`lubricant`), false = the
numeric parameters. A master that writes every start value at initialisation therefore changes nothing.

Each `Quantity` ties one parameter (a Variable: FMI name, SI unit, description, declared range) to the key
of the file it stands for. From the parameters' values `document()` makes the nested tables a file would
parse to, and the file's own reader (bearing_from_document, lubricant_from_document) builds the set from
them: a numeric set is checked, and packed for the kernels, exactly as the same values in a file are. A
refusal names the parameter, not the file key. `file_values()` reads a file's values as the parameters'
values: the start values of an FMU are those of its default (or configured) bearing and lubricant.
"""

from dataclasses import dataclass, replace

from bearing_fmu_common.paramfile import ParameterError, read_toml
from bearing_fmu_common.variables import Variable

from ..params import (
    ALPHA_MAX,
    BALL_DIAMETER_MIN,
    BALL_RING_MODULUS,
    CONFORMITY_MIN,
    GROOVE_MAX,
    INNER_DIAMETER_MAX,
    PITCH_DIAMETER_MIN,
    ROUGHNESS,
    TRACTION_LIMIT_DEFAULT,
    TRACTION_SLIP_DEFAULT,
    _resolve,
    bearing_from_document,
    load_bearing,
    lubricant_from_document,
)

BEARING_PREFIX = "bearing_data."
LUBRICANT_PREFIX = "lubricant_data."


@dataclass(frozen=True)
class Quantity:
    """One numeric parameter and the file key it stands for.

    variable: the FMI parameter (its start is the default file's value, set by with_starts);
    key: the dotted key of the file ('geometry.ball_diameter');
    file_unit: the unit the file writes ('-' for dimensionless); None for a choice written as text;
    choices: the texts an Integer parameter codes (0, 1, ...), e.g. the file's 'model' entries;
    absent: the parameter value that means 'not given' (the key is left out: the file's default applies);
    used_when: (name of a choice parameter, its code): the key is given only with that choice (the constants
        of one viscosity, pressure-viscosity or density law); () = always.
    """

    variable: Variable
    key: str
    file_unit: str = None
    choices: tuple = ()
    absent: float = None
    used_when: tuple = ()
    default: object = None  # the value when a file gives none and `absent` does not apply


FILE_LIMITS = (
    "the range of the {} file's value (docs/parameters.md), closed at a value some set can take where the file's "
    "bound is open, 0 included where 0 means not given or unused; "
    "in use, the file's own checks apply (open bounds, d_m > D, the balls fit, clearance and angle agree, the rings' "
    "sections and width, a rough race, the cage balls fit)"
)


def _real(name, unit, key, description, low, high, **kwargs):
    """A Real quantity; its file unit is its unit ('-' for a dimensionless '1')."""
    limits = kwargs.pop("limits", FILE_LIMITS.format(name.split("_data.")[0]))
    variable = Variable(name, unit, description, min=low, max=high, limits=limits)
    return Quantity(variable, key, "-" if unit == "1" else unit, **kwargs)


def _choice(name, key, choices, description, default):
    """An Integer quantity coding the file's text entry `key` as 0, 1, ... (the order of `choices`)."""
    codes = ", ".join(f"{k} = {text}" for k, text in enumerate(choices))
    variable = Variable(name, "1", f"{description}: {codes}", "integer", start=0, min=0, max=len(choices) - 1)
    return Quantity(variable, key, choices=choices, default=default)


def _optional(name, unit, key, description, high):
    """A Real quantity a file may leave out: 0 = not given (the reader's default or estimate applies)."""
    return _real(
        name, unit, key, f"{description} (0 = not given: {OPTIONAL[key.split('.')[0]]})", 0.0, high, absent=0.0
    )


OPTIONAL = {"geometry": "estimated, docs/parameters.md", "material": "the DEM's default", "cage": "no cage balls"}
B = BEARING_PREFIX
CLEARANCE_LIMITS = (
    "static bound: the groove clearance of a 0.25 m ball; |Pd| <= (f_i + f_o - 1) D of the bearing applies"
)
SHOULDERS = (
    ("shoulder_inner", "inner_shoulder_diameter", "inner ring, thrust side"),
    ("shoulder_outer", "outer_shoulder_diameter", "outer ring, thrust side"),
    ("shoulder_inner_back", "inner_back_shoulder_diameter", "inner ring, back side"),
    ("shoulder_outer_back", "outer_back_shoulder_diameter", "outer ring, back side"),
)
ROUGHNESS_RULE = " (a race's Ra or the balls' Ra > 0: Lambda = h_min / sigma needs sigma > 0)"
# the bearing file's values (docs/parameters.md, bearing file); ranges are those the bearing file's reader
# accepts, closed at a value some bearing takes where the reader's bound is open (bearing_file.BALL_DIAMETER_MIN ...)
BEARING_QUANTITIES = (
    _choice(B + "kind", "meta.kind", ("deep_groove", "angular_contact"), "bearing kind", "deep_groove"),
    _real(B + "D", "m", "geometry.ball_diameter", "ball diameter", BALL_DIAMETER_MIN, 1.0),
    _real(B + "d_m", "m", "geometry.pitch_diameter", "pitch diameter (> D)", PITCH_DIAMETER_MIN, 10.0),
    _real(B + "f_i", "1", "geometry.inner_conformity", "inner groove conformity r_i / D", CONFORMITY_MIN, 1.0),
    _real(B + "f_o", "1", "geometry.outer_conformity", "outer groove conformity r_o / D", CONFORMITY_MIN, 1.0),
    Quantity(Variable(B + "Z", "1", "number of balls", "integer", min=3, max=200), "geometry.n_balls", "-"),
    _real(
        B + "Pd",
        "m",
        "geometry.diametral_clearance",
        "diametral clearance of the bearing (negative = preload), |Pd| <= (f_i + f_o - 1) D; in effect when "
        "Pd_from_file is true (else the parameter Pd)",
        -GROOVE_MAX,
        GROOVE_MAX,
        limits=CLEARANCE_LIMITS,
    ),
    _real(
        B + "alpha0",
        "rad",
        "geometry.contact_angle",
        "nominal contact angle; for an angular-contact bearing (or an angle > 0) it must match the free contact angle "
        "of bearing_data.Pd, arccos(1 - Pd / (2 (f_i + f_o - 1) D)), to 0.05 deg",
        0.0,
        ALPHA_MAX,
    ),
    _optional(
        B + "bore",
        "m",
        "geometry.bore",
        "bore diameter, below the inner groove bottom (the DEM's inner-ring mass)",
        INNER_DIAMETER_MAX,
    ),
    _optional(
        B + "outer_diameter", "m", "geometry.outer_diameter", "outer diameter, above the outer groove bottom", 10.0
    ),
    _optional(
        B + "width",
        "m",
        "geometry.width",
        "ring width, at least each ring's groove width between its lands (the DEM's inner-ring mass)",
        10.0,
    ),
    *(
        _optional(
            B + name,
            "m",
            f"geometry.{key}",
            f"land (shoulder) diameter, {words}",
            INNER_DIAMETER_MAX if "inner" in name else 10.0,
        )
        for name, key, words in SHOULDERS
    ),
    *(
        quantity
        for part, words in (("ball", "balls"), ("ring", "rings"))
        for quantity in (
            _real(
                f"{B}E_{part}",
                "Pa",
                f"material.{part}.E",
                f"Young's modulus of the {words} (steels and ceramics)",
                BALL_RING_MODULUS.low,
                BALL_RING_MODULUS.high,
            ),
            _real(f"{B}nu_{part}", "1", f"material.{part}.nu", f"Poisson's ratio of the {words}", 0.0, 0.5),
            _real(f"{B}rho_{part}", "kg/m^3", f"material.{part}.rho", f"density of the {words}", 100.0, 30000.0),
        )
    ),
    _optional(B + "E_cage", "Pa", "material.cage.E", "Young's modulus of the cage", 1e13),
    _optional(B + "nu_cage", "1", "material.cage.nu", "Poisson's ratio of the cage", 0.5),
    _optional(B + "rho_cage", "kg/m^3", "material.cage.rho", "density of the cage", 30000.0),
    *(
        _real(
            B + name,
            "m",
            f"surface.{key}",
            f"roughness Ra of the {words}{ROUGHNESS_RULE}",
            ROUGHNESS.low,
            ROUGHNESS.high,
        )
        for name, key, words in (
            ("Ra_inner", "inner_race_Ra", "inner race"),
            ("Ra_outer", "outer_race_Ra", "outer race"),
            ("Ra_ball", "ball_Ra", "balls"),
        )
    ),
    _optional(
        B + "cage_ball_radius",
        "m",
        "cage.ball_radius",
        "radius of the DEM's cage balls, at most d_m sin(pi / (2 Z)) - D/2 (touching both balls)",
        1.0,
    ),
    _optional(B + "cage_mass", "kg", "cage.mass", "mass of the whole cage", 1e3),
)

L = LUBRICANT_PREFIX
VISCOSITY_MODEL, PIEZO_MODEL, DENSITY_MODEL = L + "viscosity_model", L + "pressure_viscosity_model", L + "density_model"
# the constants of each law: (name, unit, file key, description, low, high); a law's constants are given to the
# reader only when it is chosen, and are 0 when it is not (temperatures are declared from 0 K for that reason;
# the reader's range applies in use)
LAWS = {
    (VISCOSITY_MODEL, 0): (("eta", "Pa.s", "viscosity.dynamic_viscosity", "dynamic viscosity", 0.0, 1e4),),
    (VISCOSITY_MODEL, 1): (
        ("nu_1", "m^2/s", "viscosity.nu_1", "kinematic viscosity at T_1", 0.0, 1.0),
        ("T_1", "K", "viscosity.T_1", "temperature of nu_1 (below T_2, at most 700 K)", 0.0, 699.0),
        ("nu_2", "m^2/s", "viscosity.nu_2", "kinematic viscosity at T_2 > T_1 (below nu_1, at most 1)", 0.0, 0.999),
        ("T_2", "K", "viscosity.T_2", "temperature of nu_2", 0.0, 700.0),
    ),
    (VISCOSITY_MODEL, 2): (
        ("mu_G", "Pa.s", "viscosity.mu_G", "viscosity at the glass transition", 0.0, 1e20),
        ("T_g0", "K", "viscosity.T_g0", "glass transition temperature at p = 0", 0.0, 500.0),
        ("A_1", "K", "viscosity.A_1", "A_1", 0.0, 2000.0),
        ("A_2", "1/Pa", "viscosity.A_2", "A_2", 0.0, 1e-6),
        ("b_1", "1/Pa", "viscosity.b_1", "b_1", 0.0, 1e-6),
        ("b_2", "1", "viscosity.b_2", "b_2", -5.0, 5.0),
        ("C_1", "1", "viscosity.C_1", "C_1", 0.0, 100.0),
        ("C_2", "K", "viscosity.C_2", "C_2", 0.0, 1000.0),
    ),
    (PIEZO_MODEL, 0): (
        ("alpha_p", "1/Pa", "pressure_viscosity.coefficient", "pressure-viscosity coefficient", 0.0, 1e-6),
    ),
    (PIEZO_MODEL, 1): (
        ("gold_s", "1/Pa", "pressure_viscosity.s", "s of alpha = s (nu / 1 mm^2/s)^t", 0.0, 1e-6),
        ("gold_t", "1", "pressure_viscosity.t", "exponent t", -2.0, 2.0),
    ),
    (DENSITY_MODEL, 0): (
        ("rho_ref", "kg/m^3", "density.rho_ref", "density at T_ref, p = 0", 0.0, 30000.0),
        ("T_ref", "K", "density.T_ref", "reference temperature", 0.0, 700.0),
        (
            "thermal_expansion",
            "1/K",
            "density.thermal_expansion",
            "a of rho = rho_ref / (1 + a (T - T_ref))",
            0.0,
            1e-2,
        ),
    ),
    (DENSITY_MODEL, 1): (
        ("rho_R", "kg/m^3", "density.rho_R", "density at T_R, p = 0", 0.0, 30000.0),
        ("T_R", "K", "density.T_R", "reference temperature", 0.0, 700.0),
        ("a_v", "1/K", "density.a_v", "thermal expansion a_v", 0.0, 1e-2),
        ("beta_K", "1/K", "density.beta_K", "temperature coefficient beta_K of the bulk modulus", 0.0, 1.0),
        ("K_MM", "Pa", "density.K_MM", "bulk modulus K_00 at 0 K", 0.0, 1e13),
        ("K_M_prime", "1", "density.K_M_prime", "pressure derivative K' of the bulk modulus", 0.0, 100.0),
    ),
}
LAW_NAMES = {
    (VISCOSITY_MODEL, 0): "constant viscosity",
    (VISCOSITY_MODEL, 1): "Walther viscosity (ASTM D341)",
    (VISCOSITY_MODEL, 2): "WLF viscosity (Yasutomi)",
    (PIEZO_MODEL, 0): "constant pressure-viscosity",
    (PIEZO_MODEL, 1): "Gold et al. 2001 pressure-viscosity",
    (DENSITY_MODEL, 0): "linear density",
    (DENSITY_MODEL, 1): "Murnaghan density",
}
LAW_CHOICES = (
    _choice(
        VISCOSITY_MODEL, "viscosity.model", ("constant", "walther", "wlf"), "viscosity-temperature law", "constant"
    ),
    _choice(
        PIEZO_MODEL,
        "pressure_viscosity.model",
        ("constant", "gold", "wlf"),
        "pressure-viscosity law (wlf: with the wlf viscosity law)",
        "constant",
    ),
    _choice(DENSITY_MODEL, "density.model", ("linear", "murnaghan"), "density law at p = 0", "linear"),
)


def _law_constants(choice):
    """The choice quantity followed by the constants of each of its laws."""
    return (
        choice,
        *(
            _real(
                L + name,
                unit,
                key,
                f"{LAW_NAMES[law]}: {text} (0 when the law is not chosen)",
                low,
                high,
                used_when=law,
            )
            for law, rows in LAWS.items()
            if law[0] == choice.variable.name
            for name, unit, key, text, low, high in rows
        ),
    )


# Declared lower ends of lubricant values whose file bound is open (the file accepts any value above 1, 0, 0): a
# liquid's relative permittivity from 1.5 (below the PFPE oils' 1.9, the lowest of lubricants), a limiting traction
# coefficient from 0.005 (below the water-glycols' and silicones' 0.01-0.03), a traction curve's knee from a
# slide-to-roll ratio of 1e-5 (oils: 1e-3 to 1e-2)
EPS_R_MIN = 1.5
TRACTION_MIN = 0.005
TRACTION_SLIP_MIN = 1e-5
# the lubricant file's values (docs/parameters.md, lubricant file)
LUBRICANT_QUANTITIES = (
    *(quantity for choice in LAW_CHOICES for quantity in _law_constants(choice)),
    _real(L + "eps_r", "1", "electrical.relative_permittivity", "static relative permittivity", EPS_R_MIN, 100.0),
    _real(
        L + "limiting_traction",
        "1",
        "traction.limiting_coefficient",
        "limiting EHL traction coefficient",
        TRACTION_MIN,
        0.2,
        default=TRACTION_LIMIT_DEFAULT,
    ),
    _real(
        L + "traction_slip",
        "1",
        "traction.slip_scale",
        "slide-to-roll ratio of the traction curve's knee",
        TRACTION_SLIP_MIN,
        1.0,
        default=TRACTION_SLIP_DEFAULT,
    ),
    _real(
        L + "T_low",
        "K",
        "temperature_range.T_low",
        "lowest temperature of the data (0, with T_high 0: no range given; below T_high, at most 700 K)",
        0.0,
        699.0,
        absent=0.0,
    ),
    _real(
        L + "T_high",
        "K",
        "temperature_range.T_high",
        "highest temperature of the data (0, with T_low 0: no range given)",
        0.0,
        700.0,
        absent=0.0,
    ),
)

BEARING_FROM_FILE = Variable(
    "bearing_from_file",
    "",
    "true: the bearing's geometry, materials and surfaces come from the catalogue entry or file named by the "
    "parameter bearing; false: from the bearing_data.* parameters",
    "boolean",
    start=True,
)
LUBRICANT_FROM_FILE = Variable(
    "lubricant_from_file",
    "",
    "true: the lubricant's properties come from the catalogue entry or file named by the parameter lubricant; "
    "false: from the lubricant_data.* parameters",
    "boolean",
    start=True,
)
WHERE = {B: "the bearing_data.* parameters", L: "the lubricant_data.* parameters"}


def _file_value(doc, quantity):
    node = doc
    for part in quantity.key.split("."):
        if not isinstance(node, dict) or part not in node:
            return None
        node = node[part]
    return node.get("value") if isinstance(node, dict) else node


def file_values(quantities, doc, derived=None):
    """The parameters' values (name -> value) of a parsed file `doc`: its values; a value it does not give
    is `derived[name]` (a value the reader derived from the others), else the quantity's default, else its
    'not given' value; a choice is the code of the file's text."""
    out = {}
    for q in quantities:
        value = _file_value(doc, q)
        if q.choices:
            value = q.choices.index(q.default if value is None else value)
        elif value is None:
            value = (derived or {}).get(q.variable.name, q.default)
            value = q.absent if value is None else value
            value = 0.0 if value is None else value
        out[q.variable.name] = int(value) if q.variable.kind == "integer" else float(value)
    return out


def document(quantities, values, name):
    """The nested tables of a file holding `values` (name -> value of each parameter of `quantities`): what
    the file's reader parses. Values meaning 'not given' and the constants of laws not chosen are left out."""
    doc = {"meta": {"name": name}}
    for q in quantities:
        value = values[q.variable.name]
        if q.absent is not None and value == q.absent:
            continue
        if q.used_when and values[q.used_when[0]] != q.used_when[1]:
            continue
        *sections, key = q.key.split(".")
        node = doc
        for section in sections:
            node = node.setdefault(section, {})
        if q.choices:
            node[key] = q.choices[int(value)]
        else:
            node[key] = {"value": value, "unit": q.file_unit, "source": f"FMU parameter {q.variable.name}"}
    return doc


def _from_values(reader, quantities, prefix, values):
    """The set `reader` builds from the parameters' values; a refusal names the parameters, not file keys."""
    where = WHERE[prefix]
    try:
        return reader(document(quantities, values, where), where)
    except ParameterError as exc:
        text = str(exc)
        for q in quantities:
            text = text.replace(f"'{q.key}'", q.variable.name)
        raise ParameterError(_in_parameter_terms(quantities, values, text)) from None


def _in_parameter_terms(quantities, values, text):
    """`text` in the parameters' values: a choice shown as its code (name = 1 ('walther')), a value meaning 'not
    given' as the value (name = 0.0 (not given)) and, when it names a constant of a law, the choice that put the law
    in effect: the parameter a master set may be the choice, not the constant."""
    for q in quantities:
        if q.absent is not None:  # a value meaning 'not given' is shown as the parameter's value
            text = text.replace(f"{q.variable.name} = not given", f"{q.variable.name} = {q.absent} (not given)")
        if q.choices:
            code = int(values[q.variable.name])
            text = text.replace(
                f"{q.variable.name} = '{q.choices[code]}'", f"{q.variable.name} = {code} ('{q.choices[code]}')"
            )
    laws = {q.used_when for q in quantities if q.used_when and f"{q.variable.name} = " in text}
    for choice, code in sorted(laws):
        text += f" (a constant of the {LAW_NAMES[choice, code]} law, chosen by {choice} = {code})"
    return text


def bearing_from_values(values):
    """The Bearing of the bearing_data.* parameters' values (name -> value), checked as a bearing file is."""
    return _from_values(bearing_from_document, BEARING_QUANTITIES, B, values)


def lubricant_from_values(values):
    """The Lubricant of the lubricant_data.* parameters' values (name -> value), checked as a lubricant file is."""
    return _from_values(lubricant_from_document, LUBRICANT_QUANTITIES, L, values)


def bearing_values(name_or_path):
    """The bearing_data.* values of a bearing (catalogue name or file): the file's, with the clearance or the
    contact angle it leaves out derived from the other as the reader does."""
    bearing = load_bearing(name_or_path)
    doc = read_toml(_resolve(name_or_path, "bearings"), "bearing")
    return file_values(BEARING_QUANTITIES, doc, {B + "Pd": bearing.Pd, B + "alpha0": bearing.alpha0})


def lubricant_values(name_or_path):
    """The lubricant_data.* values of a lubricant (catalogue name or file)."""
    return file_values(LUBRICANT_QUANTITIES, read_toml(_resolve(name_or_path, "lubricants"), "lubricant"))


def with_starts(quantities, values):
    """The parameters' declarations with `values` (name -> value) as start values."""
    return tuple(replace(q.variable, start=values[q.variable.name]) for q in quantities)


def bearing_parameters(bearing, lubricant):
    """bearing_from_file, lubricant_from_file and the bearing_data.* and lubricant_data.* parameters with the
    values of `bearing` and `lubricant` (catalogue names or files) as start values."""
    return (
        BEARING_FROM_FILE,
        *with_starts(BEARING_QUANTITIES, bearing_values(bearing)),
        LUBRICANT_FROM_FILE,
        *with_starts(LUBRICANT_QUANTITIES, lubricant_values(lubricant)),
    )


def configured(parameters, choices):
    """The declarations `parameters` of a configured FMU: `choices` (bearing, lubricant, race_control: catalogue
    names or files) as the start values of those parameters and the chosen bearing's and lubricant's values as
    the start values of the bearing_data.* and lubricant_data.* parameters, so that either position of
    bearing_from_file and lubricant_from_file gives the chosen set."""
    values = {}
    if "bearing" in choices:
        values.update(bearing_values(choices["bearing"]))
    if "lubricant" in choices:
        values.update(lubricant_values(choices["lubricant"]))
    values.update(choices)
    return tuple(replace(var, start=values[var.name]) if var.name in values else var for var in parameters)
