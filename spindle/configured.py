"""Configured FMUs: `spindle build --config FILE` (docs/parameters.md, "Configured FMUs").

A configured FMU is a generic one whose start values are a chosen bearing, lubricant, race control and spindle
network: the String parameters name them and the numeric parameters (bearing_data.*, lubricant_data.*, the
network's main dimensions) hold their values, so that either position of the *_from_file switches gives the
chosen set and a master that sets no parameter at all (or drops String parameters) runs it. It is named
<Name>_<name>.fmu (e.g. BearingDEM_B7214C.fmu). The configuration file:

    [configuration]
    name = "B7214C"                 # the FMUs' name suffix (letters, digits, _)
    bearing = "B7214C"              # catalogue name or bearing TOML file (the FMU carries the file)
    lubricant = "iso_vg68_mineral"  # catalogue name or lubricant TOML file (the FMU carries the file)
    race_control = "hybrid"         # quasi-static FMUs: outer | inner | hybrid (default: the scene's)
    spindle = "b7214c_x_pair"       # thermal FMUs: a network of the catalogue (spindle/thermal/params)
    shaft = "rabreau_b7214c"        # shaft FMUs: a shaft of the catalogue (spindle/shaft/params)
    fmus = ["BearingDEM", "Bearing", "SpindleThermal"]   # which FMUs; default: every one that takes the choices

A bearing FMU is configured with bearing, lubricant (and race_control), a thermal FMU with spindle, a shaft FMU
with shaft. Without
`fmus`, an FMU whose model refuses the bearing (the analytic fidelity takes deep-groove bearings only) is left
out with a note; named in `fmus`, the refusal is an error.
"""

import re
import tomllib
from pathlib import Path

from bearing_fmu import build as bearing_build
from bearing_fmu.params import ParameterError, catalogue, catalogue_files, load_bearing, load_lubricant
from bearing_fmu.scene import RACE_CONTROLS, Scene
from bearing_fmu_common.variables import InputError

from .all_fmus import SHAFT_FMUS, THERMAL_FMUS, build_shaft_fmu, build_thermal_fmu
from .shaft.params import CATALOGUE as SHAFTS
from .thermal.model import CATALOGUE as NETWORKS

KEYS = ("name", "bearing", "lubricant", "race_control", "spindle", "shaft", "fmus")


def _scene_fmus():
    """FMU name -> scene file of every bearing scene."""
    out = {}
    for path in bearing_build.scene_files():
        with open(path, "rb") as fh:
            out[tomllib.load(fh)["fmu"]["name"]] = path
    return out


class ConfigurationError(ValueError):
    """A configuration file is malformed or names something that does not exist (the message says which)."""


def read_configuration(path):
    """The [configuration] table of a configuration file, checked: known keys, a name usable in a file name,
    a race control of RACE_CONTROLS, a network of the catalogue, FMUs that exist; bearing and lubricant are
    read (a bad file is refused here, naming it)."""
    path = Path(path)
    try:
        with open(path, "rb") as fh:
            table = tomllib.load(fh).get("configuration")
    except (OSError, tomllib.TOMLDecodeError) as exc:
        raise ConfigurationError(f"{path}: {exc}") from None
    if not isinstance(table, dict):
        raise ConfigurationError(f"{path}: needs a [configuration] table (keys: {', '.join(KEYS)})")
    unknown = sorted(set(table) - set(KEYS))
    if unknown:
        raise ConfigurationError(
            f"{path}: unknown key(s) {', '.join(unknown)} in [configuration] (known: {', '.join(KEYS)})"
        )
    name = table.get("name")
    if not isinstance(name, str) or not re.fullmatch(r"[A-Za-z0-9_]+", name):
        raise ConfigurationError(f"{path}: name = {name!r}: the FMUs' name suffix, letters, digits and _ only")
    if table.get("race_control", "outer") not in RACE_CONTROLS:
        raise ConfigurationError(
            f"{path}: race_control = {table['race_control']!r}, allowed: {', '.join(RACE_CONTROLS)}"
        )
    if "spindle" in table and not (NETWORKS / f"{table['spindle']}.toml").is_file():
        networks = ", ".join(sorted(p.stem for p in NETWORKS.glob("*.toml")))
        raise ConfigurationError(
            f"{path}: spindle = {table['spindle']!r} is not a network of the catalogue ({networks})"
        )
    if "shaft" in table and not (SHAFTS / f"{table['shaft']}.toml").is_file():
        shafts = ", ".join(sorted(p.stem for p in SHAFTS.glob("*.toml")))
        raise ConfigurationError(f"{path}: shaft = {table['shaft']!r} is not a shaft of the catalogue ({shafts})")
    known = sorted(_scene_fmus()) + sorted(THERMAL_FMUS) + sorted(SHAFT_FMUS)
    fmus = table.get("fmus", [])
    if not isinstance(fmus, list) or any(f not in known for f in fmus):
        raise ConfigurationError(f"{path}: fmus = {fmus!r}: a list of FMU names among {', '.join(known)}")
    try:
        for key, load in (("bearing", load_bearing), ("lubricant", load_lubricant)):
            if key in table:
                load(_relative(table[key], path))
    except ParameterError as exc:
        raise ConfigurationError(f"{path}: {exc}") from None
    return table


def _relative(value, config_path):
    """A catalogue name as it is; a file (ending in .toml) relative to the configuration file's folder."""
    return str(config_path.parent / value) if str(value).endswith(".toml") else value


def _choice(kind, value, config_path):
    """((name in the FMU, name or file to read at build), files to bundle) of a bearing or lubricant choice: a
    file is carried in the FMU's catalogue under its file name (stem), which must not name another entry."""
    if not str(value).endswith(".toml"):
        return (value, value), ()
    source = Path(_relative(value, config_path))
    folder = bearing_build.PACKAGE_DIR / "params" / kind
    if source.stem in catalogue(kind) and source.read_bytes() != (folder / f"{source.stem}.toml").read_bytes():
        raise ConfigurationError(
            f"{config_path}: {kind[:-1]} = {value!r}: the catalogue has another entry named '{source.stem}': "
            "rename the file"
        )
    return (source.stem, str(source)), ((source, f"bearing_fmu/params/{kind}/{source.stem}.toml"),)


def build_configured(config_path, out_dir):
    """Build the configured FMUs of the configuration file into out_dir; returns (paths, notes): the FMUs built
    and, for each FMU left out, why."""
    config_path = Path(config_path)
    table = read_configuration(config_path)
    suffix, wanted = table["name"], table.get("fmus", [])
    choices, files, carried = {}, (), {}
    for key, kind in (("bearing", "bearings"), ("lubricant", "lubricants")):
        if key in table:
            choices[key], bundled = _choice(kind, table[key], config_path)
            files += bundled
            if bundled:  # a file: the FMU carries it in its catalogue under its name
                carried[(kind, choices[key][0])] = choices[key][1]
    if "race_control" in table:
        choices["race_control"] = (table["race_control"], table["race_control"])
    paths, notes = [], []
    for fmu_name, scene_file in _scene_fmus().items():
        if wanted and fmu_name not in wanted or not choices:
            continue
        try:
            _check_model(scene_file, choices)
        except (InputError, ParameterError) as exc:
            if wanted:
                raise ConfigurationError(f"{config_path}: {fmu_name} refuses the configuration: {exc}") from None
            notes.append(f"{fmu_name}_{suffix}.fmu not built: {exc}")
            continue
        with catalogue_files(carried):  # the build constructs the FMU's model with the files it carries
            paths.append(bearing_build.build_fmu(scene_file, out_dir, (suffix, choices, files)))
    if "spindle" in table:
        for fmu_name, (_, axial_float) in THERMAL_FMUS.items():
            if not wanted or fmu_name in wanted:
                paths.append(build_thermal_fmu(f"{fmu_name}_{suffix}", table["spindle"], axial_float, out_dir))
    if "shaft" in table:
        for fmu_name in SHAFT_FMUS:
            if not wanted or fmu_name in wanted:
                paths.append(build_shaft_fmu(out_dir, table["shaft"], f"{fmu_name}_{suffix}"))
    return paths, notes


def _check_model(scene_file, choices):
    """Raise the model's refusal of the chosen bearing, lubricant or race control for the scene's fidelity."""
    with open(scene_file, "rb") as fh:
        scene = Scene.from_dict(tomllib.load(fh)["scene"])
    bearing_build.make_model(scene, {key: source for key, (_, source) in choices.items()})
