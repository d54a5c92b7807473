"""The DEM fidelity's numeric settings, declared once: each a `Setting` with its name (the DemModel keyword and the
BearingDEM parameter), SI unit, description, allowed range, the entry of params/dem_model.toml that holds its
default (with its source) and where the kernel finds it (a slot of kernels.ball_dynamics.state's parameter array,
or a function that packs what it implies).

From DEM_SETTINGS the FMU parameters are declared (models.declarations.DEM_PARAMETERS), BearingDEM hands each one
to DemModel by name (bearing_fmu.fmu), DemModel checks each against its range (checked_settings) and the facade packs
them into the parameter array (pack_settings, from models.dem.packing). A new setting is one entry here, its default
in params/dem_model.toml, its slot in kernels.ball_dynamics.state and its use in the kernel.
"""

import textwrap
from collections.abc import Callable
from dataclasses import dataclass

from bearing_fmu_common.variables import Variable

from ..kernels.ball_dynamics import state as s
from ..kernels.ehl import friction_coefficient
from ..params import Spec, dem_model_value
from .limits import InputError

TRACTION_LIMIT_MAX = friction_coefficient(0.0)  # a full film carries no more than the boundary regime (0.1)


def pitch_lever(dm):
    """(m^2) A support spread over the pitch circle of diameter dm (m), seen about a diameter: (d_m/2)^2/2 times
    the support's value across the axis gives its value in the tilts."""
    return 0.5 * (0.5 * dm) ** 2


def add_shaft_mass(par, mass):
    """The shaft's modal mass at the seat (kg) moves with the ring: added to its mass in the translations and,
    spread over the pitch circle like the support's spring and damper, m (d_m/2)^2/2, to its tilt inertia; its polar
    inertia and gyroscopic moment stay the ring's (a spinning shaft's gyroscopic coupling is the shaft model's).
    Packed after the ring's own mass and inertia."""
    par[s.P_M_RING] += mass
    par[s.P_I_RING] += pitch_lever(par[s.P_DM]) * mass


@dataclass(frozen=True)
class Setting:
    """A numeric setting of the DEM: a DemModel keyword and a BearingDEM parameter of the same name."""

    name: str
    unit: str  # SI unit; '1' = dimensionless ('-' in params/dem_model.toml)
    description: str  # the FMU parameter's description
    low: float  # allowed range [low, high]
    high: float
    key: str  # entry of params/dem_model.toml holding the default and its source
    limits: str  # why these bounds (the FMU's documentation)
    slot: str = ""  # name of the kernels.ball_dynamics.state parameter slot that takes the value as it is
    pack: Callable = None  # else pack(par, value): writes what the value implies, after the ring's mass and inertia
    hint: str = ""  # appended to a refusal: what the notable values mean
    # the scene drives in which it acts (() = every drive): the ring's support acts on a ring the loads move, not on
    # one whose path is prescribed (there the master's shaft model is the support)
    drives: tuple = ()

    def default(self):
        """The default from params/dem_model.toml, checked against the range."""
        file_unit = "-" if self.unit == "1" else self.unit
        return dem_model_value(self.key, Spec(file_unit, self.low, self.high))

    def checked(self, value):
        """value as a float (None = the default); an InputError naming the setting, the value, its unit and the
        allowed range when it is outside it (or not finite)."""
        if value is None:
            return DEFAULTS[self.name]
        value = float(value)
        if not self.low <= value <= self.high:  # False for NaN
            unit = "" if self.unit == "1" else f" {self.unit}"
            raise InputError(
                f"{self.name} = {value}{unit} is outside the allowed range [{self.low:g}, {self.high:g}]{self.hint}"
            )
        return value

    def parameter(self):
        """The FMU parameter (a Real of this name, unit, range and default)."""
        return Variable(
            self.name, self.unit, self.description, start=DEFAULTS[self.name], min=self.low, max=self.high,
            limits=self.limits, drives=self.drives,
        )  # fmt: skip


DEM_SETTINGS = (
    Setting(
        "traction_limit",
        "1",
        "tangential law of the ball-race contacts: 0 = the film's share of the force follows the lubricant's EHL "
        "traction curve of the slide-to-roll ratio (the asperities' share a spring capped at 0.1); > 0 = override, "
        "a spring alone capped at this value in a full film, ramped from 0.1 at Lambda = 1 (0.01 = the papers' "
        "mu(Lambda))",
        0.0,
        TRACTION_LIMIT_MAX,
        "contact.traction_limit",
        "0 = the EHL traction curve; at most the boundary regime's 0.1",
        slot="P_TRACTION",
        hint=" (0 = the lubricant's EHL traction curve; 0.01 = the papers' mu(Lambda))",
    ),
    # the inner ring's support: a shaft's bending stiffness at a seat is 1e7-1e9 N/m; beyond these bounds the ring
    # would be welded to the ground (the automatic step follows the support, so any value in range is stable)
    Setting(
        "support_stiffness",
        "N/m",
        "stiffness of the inner ring's support (the shaft) to its rest position across the axis (x, y); in the tilts "
        "k (d_m/2)^2/2. 0 = a free ring: the balls alone carry the loads",
        0.0,
        1e10,
        "ring_support.stiffness",
        "a shaft's stiffness at a seat is 1e7-1e9 N/m; the automatic step follows the support",
        slot="P_K_SUPPORT",
        drives=("load",),
    ),
    Setting(
        "support_damping",
        "N.s/m",
        "damping of the inner ring's support (the shaft) across the axis (x, y); in the tilts c (d_m/2)^2/2. "
        "Estimated default (a spindle shaft at a bearing seat); changes no steady state. Below about 300 N.s/m the "
        "free ring of a heavily thrust-loaded angular-contact bearing can whirl at speed (docs/dem.md, Ring support)",
        0.0,
        1e6,
        "ring_support.damping",
        "0 = none; the automatic step follows the support",
        slot="P_C_SUPPORT",
        drives=("load",),
    ),
    Setting(
        "support_axial_damping",
        "N.s/m",
        "damping of the inner ring's support along the bearing axis (z). 0 = none: the bearing alone holds the ring "
        "axially (a single angular-contact bearing takes the thrust); give the seat's axial damping when the "
        "master's shaft model does not carry it. Changes no steady state",
        0.0,
        1e6,
        "ring_support.axial_damping",
        "0 = none; the automatic step follows the support",
        slot="P_C_SUPPORT_AXIAL",
        drives=("load",),
    ),
    # a spindle shaft's modal mass at a seat is a few kilograms; 1000 kg bounds a machine's whole rotor
    Setting(
        "support_mass",
        "kg",
        "the shaft's modal mass at the seat, moving with the inner ring: added to its mass in x, y, z and, spread over "
        "the pitch circle (m (d_m/2)^2/2), to its tilt inertia. 0 = the ring alone. Set it with the shaft's modal "
        "stiffness in support_stiffness: a mass on the damper alone lowers the damping below which the ring whirls "
        "(docs/dem.md, Ring support)",
        0.0,
        1000.0,
        "ring_support.mass",
        "a spindle shaft's modal mass at a seat is 2-10 kg; 0 = the ring alone",
        pack=add_shaft_mass,
        drives=("load",),
    ),
)

DEFAULTS = {setting.name: setting.default() for setting in DEM_SETTINGS}


def checked_settings(values, drive="load"):
    """The settings given as keywords (name -> value; a missing one or None = its default), checked, as a dict in
    the order of DEM_SETTINGS. An unknown name is refused as Python refuses an unknown keyword (TypeError). A setting
    that does not act in `drive` (the DemModel's drive) is 0, and refused unless absent, None or 0."""
    known = {setting.name: setting for setting in DEM_SETTINGS}
    unknown = sorted(set(values) - set(known))
    if unknown:
        raise TypeError(f"DemModel() got an unexpected keyword argument {unknown[0]!r}")
    out = {}
    for name, setting in known.items():
        if not setting.drives or drive in setting.drives:
            out[name] = setting.checked(values.get(name))
        elif values.get(name) in (None, 0.0):
            out[name] = 0.0
        else:
            raise InputError(
                f"{name} = {values[name]} {setting.unit} is outside the allowed range [0, 0] with drive = {drive!r} "
                "(the ring's path is prescribed: its support is the caller's shaft model)"
            )
    return out


def pack_settings(par, settings):
    """Write the checked settings into the parameter array par: a slot's value as it is, a derived one by its
    packing function (call it once the ring's own mass and inertia are in par)."""
    for setting in DEM_SETTINGS:
        value = settings[setting.name]
        if setting.pack is None:
            par[getattr(s, setting.slot)] = value
        else:
            setting.pack(par, value)


def settings_doc():
    """The settings as text for DemModel's docstring: name (unit), range, default, description."""
    lines = ["    Numeric settings (keywords; None or absent = the default of params/dem_model.toml):"]
    for st in DEM_SETTINGS:
        text = f"{st.name} ({st.unit}, [{st.low:g}, {st.high:g}], default {DEFAULTS[st.name]:g}): {st.description}."
        lines += textwrap.wrap(text, 116, initial_indent="    ", subsequent_indent="        ")
    return "\n".join(lines) + "\n"
