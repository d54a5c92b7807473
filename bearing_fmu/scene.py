"""Scenes: the build-time choice of fidelity, physics options and outputs (docs/architecture.md).

A scene is a small TOML table (or keyword arguments). `Scene.validate()` reports every
incompatible or unknown choice at once. What a scene turns off is neither computed nor exposed.
"""

import tomllib
from dataclasses import dataclass, fields, replace

from .kernels.capacitance import PRESSURE_MAX, PRESSURE_MEAN
from .kernels.ehl import FILM_CHITTENDEN, FILM_HAMROCK_DOWSON, FILM_MASJEDI_KHONSARI

DRIVES = ("load", "displacement", "fixed_axial")  # which DOFs are load- or displacement-controlled
RACE_CONTROLS = ("outer", "inner", "hybrid", "traction")
FILM_FORMULAS = {
    "hamrock_dowson": FILM_HAMROCK_DOWSON,
    "masjedi_khonsari": FILM_MASJEDI_KHONSARI,
    "chittenden": FILM_CHITTENDEN,
}
HERTZ_SOLUTIONS = ("exact", "approximate")
FILM_CORRECTIONS = ("none", "table")  # the film formula as it is, or times the numerical / formula table
SPRING_CONSTANTS = ("hertz", "iso_ts_16281")  # contact load-deflection law of the quasi-static load distribution
PERMITTIVITY_PRESSURES = {"max": PRESSURE_MAX, "mean": PRESSURE_MEAN}
CAPACITANCE_REGIONS = ("hertz", "lubricated")  # the contact's capacitor: its Hertz ellipse, or the oil around it too
# lubrication methods (docs/lubrication_method.md; their defaults in models.lubrication.METHODS)
LUBRICATION_METHODS = ("flooded", "oil_bath", "oil_jet", "oil_air", "grease")
DRAG_METHODS = ("oil_bath", "oil_jet", "oil_air")


_QUASI_STATIC_ONLY = "{option} = {value} needs fidelity = 'quasi_static'"
_IN_THE_DEM = (
    "{option} = {value} is a quasi-static option (the DEM always has the gyroscopic moment, the torque and the "
    "dPd_thermal input)"
)


@dataclass(frozen=True)
class FidelityRules:
    """The scene options a fidelity accepts (its facade: bearing_fmu.fidelities).

    allowed: option -> (the values the fidelity accepts, the message for any other: {option} and {value} are filled);
        an option not listed takes every value the scene allows.
    torque_always: the fidelity computes the friction torque whatever the option `torque` says (the drag of a bath,
        jet or oil-air method is then computed and exposed).
    """

    allowed: dict
    torque_always: bool = False

    def problems(self, scene, refused=()):
        """The scene's options this fidelity does not accept, except those in `refused` (refused for every one)."""
        out = []
        for option, (values, message) in self.allowed.items():
            value = getattr(scene, option)
            if value not in values and option not in refused:
                out.append(message.format(option=option, value=_shown(value)))
        return out


def _shown(value):
    """An option's value as a scene file writes it (true, 'load')."""
    return str(value).lower() if isinstance(value, bool) else repr(value)


# What each fidelity accepts beyond the options every fidelity takes; a new fidelity declares its rules here.
FIDELITY_RULES = {
    "analytic": FidelityRules(
        {
            "spring_constant": (("hertz",), _QUASI_STATIC_ONLY),
            **{option: ((False,), _QUASI_STATIC_ONLY) for option in ("gyroscopic", "torque", "stiffness")},
            "thermal_inputs": ((False,), _QUASI_STATIC_ONLY),
            "drive": (("load",), _QUASI_STATIC_ONLY + " (analytic is load-driven)"),
        },
        torque_always=True,
    ),
    "quasi_static": FidelityRules({}),
    "dem": FidelityRules(
        {
            "spring_constant": (("hertz",), _QUASI_STATIC_ONLY),
            "life": ((False,), "life = true needs fidelity = 'analytic' or 'quasi_static'"),
            **{option: ((False,), _IN_THE_DEM) for option in ("gyroscopic", "torque", "thermal_inputs")},
            "drive": (
                ("load", "displacement"),
                "drive = {value} is not a DEM drive: allowed 'load' or 'displacement' with fidelity = 'dem'",
            ),
            "centrifugal": (
                (True,),
                "centrifugal = false is not possible with fidelity = 'dem' (the balls' orbit makes it)",
            ),
            "lubrication": (
                ("flooded",),
                "lubrication = {value} is not in the DEM yet (docs/lubrication_method.md, the DEM hook): "
                "allowed 'flooded' with fidelity = 'dem'",
            ),
        },
        torque_always=True,
    ),
}
FIDELITIES = tuple(FIDELITY_RULES)


# the options with a set of choices, and those choices (a dict's keys are shown sorted)
SCENE_CHOICES = {
    "film": FILM_FORMULAS,
    "film_correction": FILM_CORRECTIONS,
    "hertz": HERTZ_SOLUTIONS,
    "permittivity_pressure": PERMITTIVITY_PRESSURES,
    "drive": DRIVES,
    "race_control": RACE_CONTROLS,
    "spring_constant": SPRING_CONSTANTS,
    "lubrication": LUBRICATION_METHODS,
}


class SceneError(ValueError):
    """One or more scene options are unknown or incompatible (all are listed in the message)."""


@dataclass(frozen=True)
class Scene:
    """Build-time model options.

    fidelity: 'analytic' (Stribeck/Sjovall + Hertz + EHL) |
        'quasi_static' (Jones/Harris 5-DOF ball equilibrium, docs/quasistatic.md) |
        'dem' (ball dynamics, docs/dem.md: load- or displacement-driven; the gyroscopic and centrifugal effects,
        the friction torque and the thermal clearance input come from the dynamics, so the options that switch them
        are quasi-static ones; film, film_correction, hertz, roughness_factor and the capacitance options apply).
    drive (quasi_static, dem): 'load' (loads in, displacements out), 'displacement' (displacements in,
        reaction loads out; in the DEM the inner ring's path, its displacements and their rates at each step's end)
        or 'fixed_axial' (quasi_static only: radial loads and tilting moments in, axial position in: a
        fixed-preload bearing).
    race_control (quasi_static): default of the FMU parameter race_control, 'outer' | 'inner' | 'hybrid' | 'traction'.
    gyroscopic (quasi_static): ball gyroscopic moment on.
    torque (quasi_static): friction torque, power loss and ring heat outputs (Houpert components).
    stiffness (quasi_static, dem): the 5x5 stiffness outputs K[i,j].
    thermal_inputs (quasi_static): inputs dPd_thermal (and dz_thermal when z is imposed).
    film: EHL film formula, 'hamrock_dowson' (default, as Guessasma 2018 and Farah 2020) | 'masjedi_khonsari' |
        'chittenden'.
    film_correction: 'none' (default: the formula's film) | 'table' (the formula's h_c and h_min times the ratios of
        the numerical EHL solution to it, interpolated in the bearing and lubricant's film table, which
        `spindle film-table BEARING --lubricant OIL` builds once; docs/film_correction.md).
    hertz: 'exact' (complete elliptic integrals, default) | 'approximate' (Hamrock-Brewe).
    centrifugal: ball centrifugal force on the outer contacts.
    capacitance: compute and expose the bearing capacitance C_bearing.
    permittivity_pressure: lubricant permittivity at the Hertz 'max' (default) or 'mean' pressure.
    roughness_factor: sigma = factor x sqrt(Ra_race^2 + Ra_ball^2) (1.25: Ra -> Rq of a Gaussian
        surface, Guessasma 2018 eq. 7).
    film_floor: film thickness (m) below which the capacitance is bounded (estimated, docs/decisions.md).
    background_capacitance: ring/background capacitance (F) added to the balls (Farah adds ~30 pF; off = 0).
    capacitance_region: 'hertz' (default: each contact is a parallel plate over its Hertz ellipse at h_c) |
        'lubricated' (plus the oil-filled gap around the ellipse up to oil_gap, kernels.capacitance.
        outside_hertz_capacitance; docs/decisions.md).
    oil_gap: the oil-availability gap (m) of capacitance_region = 'lubricated': oil fills the gap around a
        contact where it is at most oil_gap (the meniscus). Recommended values per lubrication method in
        docs/parameters.md (estimated).
    life (analytic, quasi_static): rating-life outputs L10, L10_h (ISO 281 basic rating life) and L10r, L10r_h
        (reference rating life from the contact loads, ISO/TS 16281 manner), docs/rating_life.md.
    spring_constant (quasi_static): contact load-deflection constants of the load distribution, 'hertz' (exact
        Hertz with the bearing file's materials, default) | 'iso_ts_16281' (the standard's point-contact form,
        for comparison with tools that use it; kernels.rating_life.iso16281_spring_constant).
    lubrication (analytic, quasi_static): the lubrication method, docs/lubrication_method.md: 'flooded' (default:
        isothermal, fully flooded contacts without drag, the results of the model before the option bit for bit)
        | 'oil_bath' | 'oil_jet' | 'oil_air' | 'grease'. Every other method reduces the film by inlet shear heating
        and by starvation of the inlet (outputs phi_ish_*, phi_rs_*; Lambda, regime, mu, capacitance and the EHL
        rolling force follow), and bath, jet and oil-air add the drag of the balls in the oil (torque_drag, P_drag;
        quasi-static: with torque on). The DEM has the hook, not yet the method (flooded only).
    oil_level (oil_bath): oil level above the lowest point of the outer raceway, in ball diameters (default 0.5:
        the centre of the lowest ball at rest).
    inlet_oil_layer: oil layer (m, both surfaces) on the track ahead of a contact, from which the starvation
        follows (default by method: bath and jet 20e-6, oil-air 2e-6, grease 1e-6; estimated).
    cavity_oil_fraction (oil_jet, oil_air): oil-volume fraction of the oil-air mixture the balls move through
        (default: jet 0.01, oil-air 1e-4; estimated).
    tolerance: relative tolerance of the load equilibrium (-).
    max_iterations: iteration cap of the quasi-static Newton solver (never a hang).
    """

    name: str = "analytic"
    fidelity: str = "analytic"
    film: str = "hamrock_dowson"
    film_correction: str = "none"
    hertz: str = "exact"
    centrifugal: bool = True
    capacitance: bool = True
    permittivity_pressure: str = "max"
    roughness_factor: float = 1.25
    film_floor: float = 10e-9
    background_capacitance: float = 0.0
    capacitance_region: str = "hertz"
    oil_gap: float = 10e-6
    tolerance: float = 1e-12
    drive: str = "load"
    race_control: str = "outer"
    gyroscopic: bool = False
    torque: bool = False
    stiffness: bool = False
    thermal_inputs: bool = False
    max_iterations: int = 100
    life: bool = False
    spring_constant: str = "hertz"
    lubrication: str = "flooded"
    oil_level: float = None
    inlet_oil_layer: float = None
    cavity_oil_fraction: float = None

    @property
    def lubricated(self):
        """A lubrication method other than flooded: the film factors phi_ish_*, phi_rs_* exist."""
        return self.lubrication != "flooded"

    @property
    def drag(self):
        """The drag of the balls is computed and exposed (torque_drag, P_drag): a bath, jet or oil-air method, in
        the analytic fidelity or with the quasi-static torque."""
        return self.lubrication in DRAG_METHODS and (FIDELITY_RULES[self.fidelity].torque_always or self.torque)

    def problems(self):
        """List of human-readable problems (empty when the scene is valid)."""
        out = []
        if self.fidelity not in FIDELITIES:
            out.append(f"fidelity = {self.fidelity!r}: available {list(FIDELITIES)}")
        out += self._choice_problems(("film", "film_correction", "hertz", "permittivity_pressure"))
        if not 1.0 <= self.roughness_factor <= 2.0:
            out.append(f"roughness_factor = {self.roughness_factor}: allowed [1, 2]")
        if not 0.0 < self.film_floor <= 1e-6:
            out.append(f"film_floor = {self.film_floor} m: allowed ]0, 1e-6] m")
        if not 0.0 <= self.background_capacitance <= 1e-6:
            out.append(f"background_capacitance = {self.background_capacitance} F: allowed [0, 1e-6] F")
        if self.capacitance_region not in CAPACITANCE_REGIONS:
            out.append(f"capacitance_region = {self.capacitance_region!r}: allowed {list(CAPACITANCE_REGIONS)}")
        elif self.capacitance_region != "hertz" and not self.capacitance:
            out.append(f"capacitance_region = {self.capacitance_region!r} needs capacitance = true")
        if not 0.0 < self.oil_gap <= 50e-6:  # the paraboloid gap: about 0.3 D across the groove at 50 um
            out.append(f"oil_gap = {self.oil_gap} m: allowed ]0, 5e-5] m")
        if not 1e-15 <= self.tolerance <= 1e-3:
            out.append(f"tolerance = {self.tolerance}: allowed [1e-15, 1e-3]")
        out += self._choice_problems(("drive", "race_control", "spring_constant"))
        if not 5 <= self.max_iterations <= 1000:
            out.append(f"max_iterations = {self.max_iterations}: allowed [5, 1000]")
        if self.fidelity in FIDELITY_RULES:
            refused = [
                name for name in ("spring_constant", "lubrication") if getattr(self, name) not in SCENE_CHOICES[name]
            ]
            out += FIDELITY_RULES[self.fidelity].problems(self, refused)
        out += self._lubrication_problems()
        if self.background_capacitance > 0.0 and not self.capacitance:
            out.append("background_capacitance > 0 needs capacitance = true")
        return out

    def _choice_problems(self, options):
        """The named options whose value is not one of their choices (SCENE_CHOICES), in the given order."""
        out = []
        for option in options:
            choices = SCENE_CHOICES[option]
            value = getattr(self, option)
            if value not in choices:
                shown = sorted(choices) if isinstance(choices, dict) else list(choices)
                out.append(f"{option} = {value!r}: allowed {shown}")
        return out

    def _lubrication_problems(self):
        out = []
        if self.lubrication not in LUBRICATION_METHODS:
            return self._choice_problems(("lubrication",))
        checks = (
            ("oil_level", "", 0.0, 20.0, ("oil_bath",)),
            ("inlet_oil_layer", " m", 1e-8, 1e-2, LUBRICATION_METHODS[1:]),
            ("cavity_oil_fraction", "", 0.0, 1.0, ("oil_jet", "oil_air")),
        )
        for name, unit, low, high, methods in checks:
            value = getattr(self, name)
            if value is None:
                continue
            if self.lubrication not in methods:
                out.append(f"{name} = {value} needs lubrication in {list(methods)}")
            elif not (isinstance(value, (int, float)) and low <= value <= high):
                out.append(f"{name} = {value}{unit}: allowed [{low:g}, {high:g}]{unit}")
        return out

    def validate(self):
        """Raise SceneError listing every problem at once; return self when valid."""
        problems = self.problems()
        if problems:
            raise SceneError(f"scene '{self.name}': " + "; ".join(problems))
        return self

    @classmethod
    def from_dict(cls, data):
        known = {f.name for f in fields(cls)}
        unknown = sorted(set(data) - known)
        if unknown:
            raise SceneError(f"unknown scene option(s) {unknown}: allowed {sorted(known)}")
        return replace(cls(), **data).validate()

    @classmethod
    def from_toml(cls, path):
        with open(path, "rb") as fh:
            data = tomllib.load(fh)
        return cls.from_dict(data.get("scene", data))
