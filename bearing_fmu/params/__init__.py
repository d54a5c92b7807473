"""Parameter sets: loading, validation and packing into kernel arrays.

A set is named by a catalogue name (a file in bearings/ or lubricants/ beside this module) or by
the path of a TOML file in the same format (docs/parameters.md). Every value is checked for
presence, unit and physical range; a failure raises ParameterError naming the file, the key and
the allowed range. A path that is no file is reported as "file not found", a file of another kind
(a lubricant file given as bearing) as such. Reading and checking the files, and the bearing file
itself, live in bearing_fmu_common (the thermal FMU reads bearing files too); the names are
re-exported here.
"""

from contextlib import contextmanager
from dataclasses import dataclass, field
from pathlib import Path

import numpy as np

from bearing_fmu_common.bearing_file import (  # noqa: F401  (re-exported: the bearing file's API)
    ALPHA_MAX,
    ANGLE_MATCH,
    BALL_DIAMETER_MIN,
    BALL_RING_MODULUS,
    CONFORMITY_MIN,
    DENSITY,
    GROOVE_MAX,
    INNER_DIAMETER_MAX,
    LENGTH,
    MODULUS,
    PITCH_DIAMETER_MIN,
    POISSON,
    ROUGHNESS,
    SHOULDER_KEYS,
    Bearing,
    Material,
    angle_for_clearance,
    bearing_from_document,
    cage_ball_room,
    check_ring_sections,
    check_roughness,
    clearance_for_angle,
    clearance_limits,
    groove_clearance,
    read_bearing,
    shoulder_estimate,
)
from bearing_fmu_common.paramfile import (  # noqa: F401  (re-exported)
    ParameterError,
    Spec,
    read_toml,
    resolve_toml,
)
from bearing_fmu_common.paramfile import checked_value as _value

from ..kernels import lubricant as lk

CATALOGUE = Path(__file__).resolve().parent


# entries (kind, name) -> file that a configured FMU carries in its catalogue, known to the building process while
# it builds that FMU (catalogue_files): the build constructs the FMU's model with them, as the FMU does from its own
# catalogue
_CARRIED = {}


@contextmanager
def catalogue_files(files):
    """Within the block, the catalogue also has the entries `files` ((kind, name) -> path of a TOML file, kind
    'bearings' or 'lubricants'): those a configured FMU carries under their names."""
    _CARRIED.update(files)
    try:
        yield
    finally:
        for key in files:
            _CARRIED.pop(key, None)


def _resolve(name_or_path, kind):
    """Path of a catalogue entry (by name) or of a user TOML file (by path)."""
    carried = _CARRIED.get((kind, str(name_or_path)))
    if carried is not None:
        return carried
    return resolve_toml(name_or_path, CATALOGUE / kind, kind[:-1])


def catalogue(kind):
    """Names of the catalogue entries of a kind ('bearings' or 'lubricants')."""
    return sorted(p.stem for p in (CATALOGUE / kind).glob("*.toml"))


def load_bearing(name_or_path):
    """Bearing set from a catalogue name ('6208', '6306', 'B7214C') or a TOML path; validated. A Bearing
    (e.g. made from the numeric FMU parameters, bearing_fmu_common.numeric) is returned as it is."""
    if isinstance(name_or_path, Bearing):
        return name_or_path
    return read_bearing(_resolve(name_or_path, "bearings"))


@dataclass(frozen=True)
class Lubricant:
    """Lubricant parameters (SI) and their packed kernel array (kernels.lubricant LUB_* layout)."""

    name: str
    path: str
    array: np.ndarray
    reference: dict = field(default_factory=dict)
    traction_limit: float = 0.0  # limiting traction coefficient of the EHL film (-)
    traction_slip: float = 0.0  # slide-to-roll ratio where the traction curve's linear part meets the limit (-)
    T_low: float = None  # temperature range of the file's data (K); None: the file gives none
    T_high: float = None


TEMPERATURE = Spec("K", 150.0, 700.0)
# the EHL traction curve of a file without a [traction] section (docs/parameters.md): a mineral oil's, estimated
TRACTION_LIMIT_DEFAULT = 0.06
TRACTION_SLIP_DEFAULT = 0.001


def load_lubricant(name_or_path):
    """Lubricant set from a catalogue name or a TOML path; validated and packed for the kernels. A Lubricant
    (e.g. made from the numeric FMU parameters) is returned as it is."""
    if isinstance(name_or_path, Lubricant):
        return name_or_path
    path = _resolve(name_or_path, "lubricants")
    return lubricant_from_document(read_toml(path, "lubricant"), path)


def lubricant_from_document(doc, path):
    """Lubricant set from a parsed lubricant file `doc` (nested dicts as tomllib gives them), validated and
    packed; `path` names the file in messages (a Path or the text naming where the values came from)."""
    arr = np.zeros(lk.LUB_SIZE)
    visc = doc.get("viscosity", {}).get("model", "constant")
    piezo = doc.get("pressure_viscosity", {}).get("model", "constant")
    dens = doc.get("density", {}).get("model", "linear")

    _pack_density(doc, arr, path, dens)
    _pack_viscosity(doc, arr, path, visc)
    _pack_pressure_viscosity(doc, arr, path, piezo, visc)

    arr[lk.LUB_EPS_R0] = _value(doc, "electrical.relative_permittivity", Spec("-", 1.0, 100.0, True), path)
    reference = {
        k: v["value"] for k, v in doc.get("reference_313K", {}).items() if isinstance(v, dict) and "value" in v
    }
    traction_limit = _value(
        doc, "traction.limiting_coefficient", Spec("-", 0.0, 0.2, True), path, False, TRACTION_LIMIT_DEFAULT
    )
    traction_slip = _value(doc, "traction.slip_scale", Spec("-", 0.0, 1.0, True), path, False, TRACTION_SLIP_DEFAULT)
    T_low = _value(doc, "temperature_range.T_low", TEMPERATURE, path, False)
    T_high = _value(doc, "temperature_range.T_high", TEMPERATURE, path, False)
    if (T_low is None) != (T_high is None) or (T_low is not None and not T_low < T_high):
        low, high = ("not given" if T is None else f"{T} K" for T in (T_low, T_high))
        raise ParameterError(
            f"{path}: 'temperature_range.T_low' = {low} and 'temperature_range.T_high' = {high} are not allowed: "
            "both given (or neither), with T_low < T_high"
        )
    return Lubricant(
        name=str(doc.get("meta", {}).get("name", Path(path).stem)),
        path=str(path),
        array=arr,
        reference=reference,
        traction_limit=traction_limit,
        traction_slip=traction_slip,
        T_low=T_low,
        T_high=T_high,
    )


def _pack_density(doc, arr, path, dens):
    """The density model `dens` of a lubricant file into its array (kernels.lubricant LUB_*)."""
    if dens == "murnaghan":
        arr[lk.LUB_DENS_MODEL] = lk.DENSITY_MURNAGHAN
        arr[lk.LUB_RHO_REF] = _value(doc, "density.rho_R", DENSITY, path)
        arr[lk.LUB_T_REF] = _value(doc, "density.T_R", TEMPERATURE, path)
        arr[lk.LUB_EXPANSION] = _value(doc, "density.a_v", Spec("1/K", 0.0, 1e-2), path)
        arr[lk.LUB_MURN_BETA_K] = _value(doc, "density.beta_K", Spec("1/K", 0.0, 1.0), path)
        arr[lk.LUB_MURN_K_MM] = _value(doc, "density.K_MM", Spec("Pa", 1e6, 1e13, True), path)
        arr[lk.LUB_MURN_K_PRIME] = _value(doc, "density.K_M_prime", Spec("-", 0.0, 100.0, True), path)
    elif dens == "linear":
        arr[lk.LUB_DENS_MODEL] = lk.DENSITY_LINEAR
        arr[lk.LUB_RHO_REF] = _value(doc, "density.rho_ref", DENSITY, path)
        arr[lk.LUB_T_REF] = _value(doc, "density.T_ref", TEMPERATURE, path)
        arr[lk.LUB_EXPANSION] = _value(doc, "density.thermal_expansion", Spec("1/K", 0.0, 1e-2), path)
    else:
        raise ParameterError(f"{path}: 'density.model' = {dens!r}, allowed: 'linear', 'murnaghan'")


def _pack_viscosity(doc, arr, path, visc):
    """The viscosity model `visc` of a lubricant file into its array."""
    if visc == "constant":
        arr[lk.LUB_VISC_MODEL] = lk.VISCOSITY_CONSTANT
        arr[lk.LUB_ETA_CONST] = _value(doc, "viscosity.dynamic_viscosity", Spec("Pa.s", 0.0, 1e4, True), path)
    elif visc == "walther":
        arr[lk.LUB_VISC_MODEL] = lk.VISCOSITY_WALTHER
        nu_spec = Spec("m^2/s", 2e-6, 1.0)  # ASTM D341 holds for nu >= 2 mm^2/s
        nu1 = _value(doc, "viscosity.nu_1", nu_spec, path)
        T1 = _value(doc, "viscosity.T_1", TEMPERATURE, path)
        nu2 = _value(doc, "viscosity.nu_2", nu_spec, path)
        T2 = _value(doc, "viscosity.T_2", TEMPERATURE, path)
        if not (T2 > T1 and nu2 < nu1):
            raise ParameterError(
                f"{path}: 'viscosity.T_1' = {T1} K, 'viscosity.T_2' = {T2} K, 'viscosity.nu_1' = {nu1} m^2/s and "
                f"'viscosity.nu_2' = {nu2} m^2/s are not allowed: the Walther law needs T_2 > T_1 and nu_2 < nu_1 "
                "(viscosity falls with temperature)"
            )
        arr[lk.LUB_WALTHER_A], arr[lk.LUB_WALTHER_B] = lk.walther_constants(nu1, T1, nu2, T2)
    elif visc == "wlf":
        arr[lk.LUB_VISC_MODEL] = lk.VISCOSITY_WLF
        _pack_wlf(doc, arr, path)
    else:
        raise ParameterError(f"{path}: 'viscosity.model' = {visc!r}, allowed: 'constant', 'walther', 'wlf'")


def _pack_pressure_viscosity(doc, arr, path, piezo, visc):
    """The pressure-viscosity model `piezo` of a lubricant file into its array (WLF needs the WLF viscosity)."""
    if piezo == "constant":
        arr[lk.LUB_PIEZO_MODEL] = lk.PIEZO_CONSTANT
        arr[lk.LUB_XI_CONST] = _value(doc, "pressure_viscosity.coefficient", Spec("1/Pa", 0.0, 1e-6, True), path)
    elif piezo == "gold":
        arr[lk.LUB_PIEZO_MODEL] = lk.PIEZO_GOLD
        arr[lk.LUB_GOLD_S] = _value(doc, "pressure_viscosity.s", Spec("1/Pa", 0.0, 1e-6, True), path)
        arr[lk.LUB_GOLD_T] = _value(doc, "pressure_viscosity.t", Spec("-", -2.0, 2.0), path)
    elif piezo == "wlf":
        if visc != "wlf":
            raise ParameterError(f"{path}: 'pressure_viscosity.model' = 'wlf' needs 'viscosity.model' = 'wlf'")
        arr[lk.LUB_PIEZO_MODEL] = lk.PIEZO_WLF
    else:
        raise ParameterError(f"{path}: 'pressure_viscosity.model' = {piezo!r}, allowed: 'constant', 'gold', 'wlf'")


def _pack_wlf(doc, arr, path):
    arr[lk.LUB_WLF_MU_G] = _value(doc, "viscosity.mu_G", Spec("Pa.s", 0.0, 1e20, True), path)
    arr[lk.LUB_WLF_TG0] = _value(doc, "viscosity.T_g0", Spec("K", 0.0, 500.0, True), path)
    arr[lk.LUB_WLF_A1] = _value(doc, "viscosity.A_1", Spec("K", 0.0, 2000.0), path)
    arr[lk.LUB_WLF_A2] = _value(doc, "viscosity.A_2", Spec("1/Pa", 0.0, 1e-6), path)
    arr[lk.LUB_WLF_B1] = _value(doc, "viscosity.b_1", Spec("1/Pa", 0.0, 1e-6), path)
    arr[lk.LUB_WLF_B2] = _value(doc, "viscosity.b_2", Spec("-", -5.0, 5.0), path)
    arr[lk.LUB_WLF_C1] = _value(doc, "viscosity.C_1", Spec("-", 0.0, 100.0, True), path)
    arr[lk.LUB_WLF_C2] = _value(doc, "viscosity.C_2", Spec("K", 0.0, 1000.0, True), path)


@dataclass(frozen=True)
class DemConstants:
    """Contact-model constants of the DEM fidelity (params/dem_model.toml), SI."""

    cage_E: float  # Pa, the cage elements' default Young's modulus
    cage_nu: float  # -, their Poisson's ratio
    cage_rho: float  # kg/m^3, their density
    cage_pocket_play: float  # -, pocket play of an estimated cage ball over the ball diameter
    alpha_e: float  # s/m, hysteretic damping constant (C_hyst = 1.5 alpha_e Q)
    kt_ratio: float  # -, tangential over secant normal stiffness of the asperities' spring


def load_dem_constants(path=CATALOGUE / "dem_model.toml"):
    """The DEM's contact-model constants, checked as the other parameter files' values are."""
    doc = read_toml(Path(path))
    return DemConstants(
        cage_E=_value(doc, "cage_material.E", Spec("Pa", 0.0, 1e13, True), path),
        cage_nu=_value(doc, "cage_material.nu", Spec("-", 0.0, 0.5), path),
        cage_rho=_value(doc, "cage_material.rho", DENSITY, path),
        cage_pocket_play=_value(doc, "cage.pocket_play", Spec("-", 0.0, 0.1), path),
        alpha_e=_value(doc, "contact.alpha_e", Spec("s/m", 0.0, 10.0), path),
        kt_ratio=_value(doc, "contact.kt_ratio", Spec("-", 0.1, 1.5), path),
    )


def dem_model_value(key, spec, path=CATALOGUE / "dem_model.toml"):
    """Entry `key` of the DEM's constants file (e.g. 'ring_support.damping'), checked against spec (its unit and
    range): the defaults of the DEM's settings (models.dem_settings)."""
    return _value(read_toml(Path(path)), key, spec, path)
