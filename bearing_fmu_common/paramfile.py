"""Parameter files (TOML, docs/parameters.md): finding, reading and checking them, for every FMU.

A parameter set is named by a catalogue name (a file `<name>.toml` in a catalogue folder) or by the path
of a TOML file in the same format. Every physical value is an inline table `{ value, unit, source }`;
`checked_value` reads one and checks its presence, unit and range. Three kinds of file exist (bearing,
lubricant, spindle network): a file given for the wrong parameter is named as such instead of failing
on the first key it lacks. A failure raises ParameterError naming the parameter or the file, the key,
the value and the allowed range. Only the standard library: the thermal FMU reads bearing files with
this module and ships no bearing model.
"""

import math
import tomllib
from dataclasses import dataclass
from pathlib import Path


class ParameterError(ValueError):
    """A parameter file is missing, malformed, of the wrong kind or holds a non-physical value."""


@dataclass(frozen=True)
class Spec:
    unit: str
    low: float
    high: float
    low_open: bool = False  # True: value must be > low (not >=)


# the sections that tell a file's kind (the bearing and lubricant files' [meta] does not say it)
KIND_SECTIONS = {
    "spindle": ("node", "link", "boundary"),  # a thermal network: [[node]], [[link]], [[boundary]]
    "bearing": ("geometry",),
    "lubricant": ("viscosity", "pressure_viscosity", "density"),
}


KIND_NAMES = {"spindle": "spindle network", "bearing": "bearing", "lubricant": "lubricant"}


def is_file(path):
    """Path.is_file(), False for a name the system cannot even look up (too long, a NUL byte)."""
    try:
        return path.is_file()
    except (OSError, ValueError):
        return False


def resolve_toml(name_or_path, folder, what):
    """Path of a catalogue entry `folder/<name>.toml` (by name) or of a user TOML file (by path);
    `what` is the parameter ('bearing', 'lubricant', 'spindle'), named in the error message: a value
    ending in .toml that is no file is 'file not found', any other unknown value an unknown name."""
    text = str(name_or_path)
    candidate = Path(folder) / f"{text}.toml"
    if is_file(candidate):
        return candidate
    path = Path(text).expanduser()
    if path.suffix == ".toml":
        if is_file(path):
            return path
        return _not_found(text, path, what)
    names = ", ".join(sorted(p.stem for p in Path(folder).glob("*.toml")))
    raise ParameterError(f"unknown {what} '{text}': give a catalogue name ({names}) or the path of a .toml file")


def _not_found(text, path, what):
    try:
        where = path.absolute()
        exists = path.exists()
    except (OSError, ValueError):
        where, exists = path, False
    problem = "is not a file" if exists else "file not found"
    raise ParameterError(f"{what} = '{text}': {problem} ({where})")


def file_kind(doc):
    """The kind of a parsed parameter file ('bearing', 'lubricant', 'spindle') from its sections, or None."""
    for kind, sections in KIND_SECTIONS.items():
        if any(section in doc for section in sections):
            return kind
    return None


def read_toml(path, what=None):
    """The parsed TOML file at path; with `what` (the parameter it was given for), a file of another kind
    is refused naming the parameter, the file and both kinds."""
    try:
        with open(path, "rb") as fh:
            doc = tomllib.load(fh)
    except tomllib.TOMLDecodeError as exc:
        raise ParameterError(f"{path}: not valid TOML ({exc})") from None
    kind = file_kind(doc)
    if what is not None and kind is not None and kind != what:
        sections = ", ".join(f"[{s}]" for s in KIND_SECTIONS[kind] if s in doc)
        raise ParameterError(
            f"{what} = '{path}' is a {KIND_NAMES[kind]} file, not a {KIND_NAMES[what]} file (it has {sections}): "
            f"give it as `{kind}`, or give a {KIND_NAMES[what]} file as `{what}`"
        )
    return doc


def checked_value(doc, dotted, spec, path, required=True, default=None):
    """Checked value of entry `dotted` (e.g. 'geometry.ball_diameter') of a parsed file (path: for messages)."""
    node = doc
    for part in dotted.split("."):
        if not isinstance(node, dict) or part not in node:
            if required:
                raise ParameterError(f"{path}: missing key '{dotted}' ({spec.unit})")
            return default
        node = node[part]
    if not isinstance(node, dict) or "value" not in node:
        raise ParameterError(
            f"{path}: '{dotted}' must be a table {{ value = ..., unit = \"{spec.unit}\", source = ... }}"
        )
    unit = node.get("unit")
    if unit != spec.unit:
        raise ParameterError(f"{path}: '{dotted}' has unit '{unit}', expected '{spec.unit}'")
    if "source" not in node:
        raise ParameterError(f"{path}: '{dotted}' has no 'source'")
    value = node["value"]
    if isinstance(value, bool) or not isinstance(value, (int, float)) or not math.isfinite(value):
        raise ParameterError(f"{path}: '{dotted}' = {value!r} is not a finite number")
    low_ok = value > spec.low if spec.low_open else value >= spec.low
    if not (low_ok and value <= spec.high):
        bracket = "]" if spec.low_open else "["
        raise ParameterError(
            f"{path}: '{dotted}' = {value} {spec.unit} is outside the allowed range {bracket}{spec.low}, {spec.high}]"
        )
    return float(value)
