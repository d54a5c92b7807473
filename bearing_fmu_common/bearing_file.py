"""A bearing file (docs/parameters.md): its geometry, materials and surfaces, read and checked.

Shared by the bearing FMUs (bearing_fmu.params.load_bearing resolves a catalogue name and reads the file
here) and the thermal spindle, which needs the rings' geometry and material for their thermal and
centrifugal growth. Standard library only (no kernels), so the thermal FMU ships no bearing model. The
clearance/contact-angle rule is that of Harris & Kotzalas (2006, vol. 1).
"""

import math
from dataclasses import dataclass, field
from pathlib import Path

from .paramfile import ParameterError, Spec, checked_value, read_toml

_value = checked_value

LENGTH = Spec("m", 0.0, 10.0, low_open=True)
MODULUS = Spec("Pa", 1e6, 1e13, low_open=True)  # a cage's material: polymers (PA66 3.3 GPa) to steel and brass
# the balls' and rings' material: rolling-bearing steels (about 200 GPa), titanium alloys (110 GPa) and ceramics
# (silicon nitride 310 GPa, tungsten carbide about 650 GPa); below 10 GPa are polymers, whose contacts the hard
# EHL film formulas and the Hertz pressure limit of the models do not describe
BALL_RING_MODULUS = Spec("Pa", 1e10, 1e12)
# |diametral clearance| (m) a parameter may declare: the groove clearance (f_i + f_o - 1) D of a 0.25 m ball with
# conformities 0.52 (beyond any catalogue ball); the bearing's own groove clearance applies within it
GROOVE_MAX = 1e-2
ROUGHNESS = Spec("m", 0.0, 1e-4)
# Declared ranges of the numeric parameters (FMU parameters) whose file values have an open bound: the file accepts
# any ball diameter, pitch diameter and conformity above 0 (0.5), a declared range is closed, so its end is a value
# some bearing can take. Ball diameters from 0.1 mm (below the balls of the smallest miniature bearings, 0.3 mm),
# pitch diameters from 0.5 mm (room for three 0.1 mm balls), conformities from 0.501 (a groove 0.1 % wider than the
# ball: tighter than any ball bearing's, 0.505-0.53; at 0.5 the groove fits the ball and the contact is the whole
# groove); the bore and the inner lands below 9.99 m, so that a 10 m pitch circle with balls up to 10 mm still
# leaves them room (they lie below the inner groove bottom d_m - D and the pitch circle).
BALL_DIAMETER_MIN = 1e-4
PITCH_DIAMETER_MIN = 5e-4
CONFORMITY_MIN = 0.501
INNER_DIAMETER_MAX = 9.99
POISSON = Spec("-", 0.0, 0.5, low_open=False)
DENSITY = Spec("kg/m^3", 100.0, 30000.0)


@dataclass(frozen=True)
class Material:
    E: float  # Pa
    nu: float  # -
    rho: float  # kg/m^3


@dataclass(frozen=True)
class Bearing:
    """Bearing geometry and materials (SI). Values documented in the TOML file."""

    name: str
    kind: str
    path: str
    D: float  # ball diameter (m)
    dm: float  # pitch diameter (m)
    f_i: float  # inner groove conformity (-)
    f_o: float  # outer groove conformity (-)
    Z: int  # number of balls (-)
    Pd: float  # diametral clearance (m), negative = preload
    alpha0: float  # nominal contact angle (rad): the file's, else the free angle of the clearance
    ball: Material
    ring: Material
    Ra_inner: float  # inner race roughness Ra (m)
    Ra_outer: float  # outer race roughness Ra (m)
    Ra_ball: float  # ball roughness Ra (m)
    cage_ball_radius: float = 0.0  # DEM cage-ball radius (m), 0 if absent
    cage_mass: float = 0.0  # mass of the whole cage (kg), 0 if absent: the DEM's Z cage balls share it
    extras: dict = field(default_factory=dict)
    # land (shoulder) diameters (m): of each ring on its thrust side (the side a ball presses under a thrust +z on
    # the inner ring; both sides of a deep-groove ring) and on the other side; 0 only in a Bearing built by hand
    # (read_bearing always fills them: the file's values, else the estimates of shoulder_estimate)
    shoulder_inner: float = 0.0
    shoulder_outer: float = 0.0
    shoulder_inner_back: float = 0.0
    shoulder_outer_back: float = 0.0
    shoulders_estimated: tuple = ()  # keys of SHOULDER_KEYS the file did not give (estimated by shoulder_estimate)
    # boundary dimensions (m), None where the file gives none (the DEM then estimates the inner ring's mass)
    bore: float = None
    outer_diameter: float = None
    width: float = None
    cage_material: dict = field(default_factory=dict)  # the file's [material.cage] values given: E (Pa), nu, rho


def _material(doc, section, path):
    return Material(
        E=_value(doc, f"{section}.E", BALL_RING_MODULUS, path),
        nu=_value(doc, f"{section}.nu", POISSON, path),
        rho=_value(doc, f"{section}.rho", DENSITY, path),
    )


# Shoulders (docs/parameters.md, shoulders): file key -> (ring, side). Estimates for a file without them, as
# shoulder heights above the groove bottom of the nominal geometry (d_m -+ D): a deep-groove ring 0.2 D on both
# sides; an angular-contact ring's thrust side the point of the groove 60 deg from its bottom, h = f D (1 - cos 60),
# its other side a low shoulder of 0.1 D.
SHOULDER_KEYS = {
    "inner_shoulder_diameter": ("inner", "thrust"),
    "outer_shoulder_diameter": ("outer", "thrust"),
    "inner_back_shoulder_diameter": ("inner", "back"),
    "outer_back_shoulder_diameter": ("outer", "back"),
}
DEEP_GROOVE_SHOULDER = 0.2  # x D, estimated shoulder height of a deep-groove ring
THRUST_SHOULDER_ANGLE = math.radians(60.0)  # rad, estimated thrust-side shoulder of an angular-contact ring
BACK_SHOULDER = 0.1  # x D, estimated low shoulder of an angular-contact ring


def shoulder_estimate(kind, D, dm, f, ring, side):
    """Estimated land diameter (m) of a ring ('inner' | 'outer') on a side ('thrust' | 'back') of a bearing of
    kind 'deep_groove' | 'angular_contact', ball diameter D (m), pitch diameter dm (m), the ring's groove
    conformity f (-): the groove bottom d_m -+ D raised by the shoulder height h of SHOULDER_KEYS' comment."""
    if kind == "deep_groove":
        h = DEEP_GROOVE_SHOULDER * D
    elif side == "thrust":
        h = f * D * (1.0 - math.cos(THRUST_SHOULDER_ANGLE))
    else:
        h = BACK_SHOULDER * D
    return dm - D + 2.0 * h if ring == "inner" else dm + D - 2.0 * h


def _shoulders(doc, kind, D, dm, f_i, f_o, path):
    """{key: land diameter (m)} of SHOULDER_KEYS and the keys estimated. Given: within the ring's groove, between
    the groove bottom and the pitch circle (inner ]d_m - D, d_m[, outer ]d_m, d_m + D[). Missing: estimated; a
    deep-groove ring's back side is its thrust side's value when that is given (a symmetric ring)."""
    values, estimated = {}, []
    for key, (ring, side) in SHOULDER_KEYS.items():
        low, high = (dm - D, dm) if ring == "inner" else (dm, dm + D)
        value = _value(doc, f"geometry.{key}", LENGTH, path, required=False)
        if value is not None and not low < value < high:
            raise ParameterError(
                f"{path}: 'geometry.{key}' = {value} m is outside the allowed range ]{low:.6g}, {high:.6g}[ m "
                f"(between the {ring} groove bottom d_m {'-' if ring == 'inner' else '+'} D and the pitch circle d_m, "
                f"with 'geometry.pitch_diameter' = {dm} m and 'geometry.ball_diameter' = {D} m)"
            )
        if value is None:
            estimated.append(key)
            if kind == "deep_groove" and side == "back":  # a symmetric ring: the thrust side's (given or estimated)
                value = values[f"{ring}_shoulder_diameter"]
            else:
                value = shoulder_estimate(kind, D, dm, f_i if ring == "inner" else f_o, ring, side)
        values[key] = value
    return values, tuple(estimated)


ALPHA_MAX = math.radians(60.0)  # largest free contact angle accepted (rad): P_d <= 2 A (1 - cos 60 deg) = A
ANGLE_MATCH = math.radians(0.05)  # rad: a file's angle and clearance agree when the derived angles differ less


def groove_clearance(D, f_i, f_o):
    """A = (f_i + f_o - 1) D (m): the distance between the groove curvature centres with the ball touching
    both races without load (D in m, conformities -)."""
    return (f_i + f_o - 1.0) * D


def clearance_limits(D, f_i, f_o):
    """Admissible diametral clearance (m) from the geometry: -A <= P_d <= A. Above A the free contact
    angle passes 60 deg (the contact runs to the groove shoulder); an interference beyond A presses
    every ball by more than the whole groove clearance, far past any material limit."""
    A = groove_clearance(D, f_i, f_o)
    return -A, A


def clearance_for_angle(D, f_i, f_o, alpha):
    """Diametral clearance P_d = 2 A (1 - cos alpha) (m) whose free contact angle is alpha (rad)
    (Harris & Kotzalas 2006, vol. 1, free contact angle: cos alpha0 = 1 - P_d / (2 A))."""
    return 2.0 * groove_clearance(D, f_i, f_o) * (1.0 - math.cos(alpha))


def angle_for_clearance(D, f_i, f_o, Pd):
    """Free contact angle alpha0 = arccos(1 - P_d / (2 A)) (rad) of the diametral clearance P_d (m); 0 for
    P_d <= 0 (no clearance or a preload)."""
    return math.acos(1.0 - Pd / (2.0 * groove_clearance(D, f_i, f_o))) if Pd > 0.0 else 0.0


def _check_clearance(Pd, D, f_i, f_o, path):
    """Raise ParameterError unless -A <= P_d <= A (clearance_limits), naming the values A comes from."""
    low, high = clearance_limits(D, f_i, f_o)
    if not low <= Pd <= high:
        raise ParameterError(
            f"{path}: 'geometry.diametral_clearance' = {Pd} m is outside the allowed range [{low:.6g}, {high:.6g}] m: "
            f"|P_d| <= (f_i + f_o - 1) D with 'geometry.inner_conformity' = {f_i}, 'geometry.outer_conformity' = "
            f"{f_o} and 'geometry.ball_diameter' = {D} m (a larger clearance puts the free contact angle past 60 deg, "
            "a larger preload presses every ball by more than the groove clearance)"
        )


def _clearance_and_angle(doc, D, f_i, f_o, kind, path):
    """(P_d (m), contact angle (rad): the file's nominal one, else the free one) from the file's
    'geometry.diametral_clearance' and/or 'geometry.contact_angle' (docs/parameters.md, clearance and
    contact angle): one gives the other by cos alpha0 = 1 - P_d/(2A); given both, they must agree to
    ANGLE_MATCH. A deep-groove file's contact angle 0 is its nominal (radial) angle and leaves the
    clearance free."""
    Pd = _value(doc, "geometry.diametral_clearance", Spec("m", -math.inf, math.inf), path, required=False)
    if Pd is not None:
        _check_clearance(Pd, D, f_i, f_o, path)
    alpha = _value(doc, "geometry.contact_angle", Spec("rad", 0.0, ALPHA_MAX), path, required=False)
    if Pd is None and alpha is None:
        raise ParameterError(
            f"{path}: give 'geometry.diametral_clearance' (m) or 'geometry.contact_angle' (rad, the nominal "
            f"contact angle), or both"
        )
    if Pd is None:
        return clearance_for_angle(D, f_i, f_o, alpha), alpha
    free = angle_for_clearance(D, f_i, f_o, Pd)
    if alpha is not None and (alpha > 0.0 or kind == "angular_contact") and abs(free - alpha) > ANGLE_MATCH:
        raise ParameterError(
            f"{path}: 'geometry.contact_angle' = {alpha} rad ({math.degrees(alpha):.3f} deg) and "
            f"'geometry.diametral_clearance' = {Pd} m (free contact angle {math.degrees(free):.3f} deg) disagree: "
            f"the clearance for {math.degrees(alpha):.3f} deg is {clearance_for_angle(D, f_i, f_o, alpha):.6g} m "
            f"(cos alpha0 = 1 - P_d / (2 (f_i + f_o - 1) D) with 'geometry.inner_conformity' = {f_i}, "
            f"'geometry.outer_conformity' = {f_o} and 'geometry.ball_diameter' = {D} m); give one of them, or both "
            "consistent"
        )
    return Pd, free if alpha is None else alpha


def check_roughness(Ra_inner, Ra_outer, Ra_ball, path):
    """Raise ParameterError unless each race's contact has a composite roughness sqrt(Ra_race^2 + Ra_ball^2) > 0
    (m; Ra >= 0 each): every fidelity's film parameter is Lambda = h_min / sigma. `path` names where the values came
    from; the message names the keys of the bearing file's [surface]."""
    for race, Ra in (("inner", Ra_inner), ("outer", Ra_outer)):
        if not math.hypot(Ra, Ra_ball) > 0.0:
            high = f"{ROUGHNESS.high:g}"
            raise ParameterError(
                f"{path}: 'surface.{race}_race_Ra' = {Ra} m and 'surface.ball_Ra' = {Ra_ball} m give the {race} "
                f"contacts no roughness: the film parameter Lambda = h_min / sigma needs a composite roughness "
                f"sigma = sqrt(Ra_race^2 + Ra_ball^2) > 0 (allowed: 'surface.{race}_race_Ra' in ]0, {high}] m, or "
                f"'surface.ball_Ra' in ]0, {high}] m)"
            )


def cage_ball_room(D, dm, Z):
    """Largest radius (m) of a cage ball half a pitch ahead of each of Z balls of diameter D (m) on a circle of
    diameter dm (m): touching both neighbouring balls, d_m sin(pi / (2 Z)) - D / 2 (centre to centre along the
    chord of half a pitch)."""
    return dm * math.sin(0.5 * math.pi / Z) - 0.5 * D


def _check_cage(cage_ball_radius, D, dm, Z, path):
    """Refuse a given cage-ball radius (m; 0 = not given) that overlaps the balls on the pitch circle."""
    room = cage_ball_room(D, dm, Z)
    if cage_ball_radius > room:
        fit = (
            f"at most {room:.6g} m fits (d_m sin(pi / (2 Z)) - D/2, touching both balls): give a smaller "
            f"'cage.ball_radius' or leave it out (0) for the DEM's estimate"
            if room > 0.0
            else "no cage ball fits between the balls: give fewer balls"
        )
        raise ParameterError(
            f"{path}: 'cage.ball_radius' = {cage_ball_radius} m and 'geometry.n_balls' = {Z} overlap: the cage balls "
            f"sit half a pitch between {Z} balls of {D} m on the pitch circle d_m = {dm} m, where {fit}"
        )


def groove_bottoms(D, dm, Pd):
    """(inner, outer) groove-bottom diameters (m) that the ring sections are checked against: the nominal d_m -+ D,
    widened by half a clearance P_d > 0 as the thermal model's groove diameters d_m -+ (D + P_d / 2) are (the
    DEM's inner-ring mass takes the nominal one); D, dm, Pd in m."""
    half = 0.5 * max(Pd, 0.0)
    return dm - D - half, dm + D + half


def check_ring_sections(D, dm, Pd, bore=None, outer_diameter=None, names=None, where=""):
    """Raise ParameterError unless each ring has material under its groove: bore < inner groove bottom and
    outer diameter > outer groove bottom (groove_bottoms; bore < outer diameter follows). None = not given.
    `names` maps 'bore', 'outer_diameter', 'D', 'd_m', 'Pd' to the names the message gives them (default: the
    bearing file's keys); `where` prefixes the message (the file)."""
    names = {**SECTION_NAMES, **(names or {})}
    inner, outer = groove_bottoms(D, dm, Pd)
    groove = f"{names['d_m']} = {dm} m, {names['D']} = {D} m, {names['Pd']} = {Pd} m"
    if bore is not None and not bore < inner:
        raise ParameterError(
            f"{where}{names['bore']} = {bore} m leaves the inner ring no material under its groove: allowed below "
            f"the inner groove bottom d_m - D - max(P_d, 0)/2 = {inner:.6g} m ({groove})"
        )
    if outer_diameter is not None and not outer_diameter > outer:
        raise ParameterError(
            f"{where}{names['outer_diameter']} = {outer_diameter} m leaves the outer ring no material under its "
            f"groove: allowed above the outer groove bottom d_m + D + max(P_d, 0)/2 = {outer:.6g} m ({groove})"
        )


SECTION_NAMES = {
    "bore": "'geometry.bore'",
    "outer_diameter": "'geometry.outer_diameter'",
    "D": "'geometry.ball_diameter'",
    "d_m": "'geometry.pitch_diameter'",
    "Pd": "'geometry.diametral_clearance'",
}


def groove_width(D, dm, f, ring, lands):
    """Axial width (m) of a ring's groove between its two lands (diameters `lands`, m): the groove, a circle of
    radius f D (f the conformity) from the nominal groove bottom d_m -+ D, is sqrt(h (2 f D - h)) wide on each side
    at a land of height h above the bottom; ring 'inner' | 'outer'."""
    bottom = dm - D if ring == "inner" else dm + D
    r = f * D
    return sum(math.sqrt(h * (2.0 * r - h)) for h in (0.5 * abs(land - bottom) for land in lands))


def _check_width(bearing, path):
    """Refuse a given ring width (m) narrower than either ring's groove between its lands (shoulder diameters):
    the shoulders, whose edges truncate the contact ellipses, lie on the ring."""
    b = bearing
    for ring, f, lands in (
        ("inner", b.f_i, (b.shoulder_inner, b.shoulder_inner_back)),
        ("outer", b.f_o, (b.shoulder_outer, b.shoulder_outer_back)),
    ):
        needed = groove_width(b.D, b.dm, f, ring, lands)
        if not b.width >= needed:
            keys = [key for key in SHOULDER_KEYS if key.startswith(ring)]
            estimated = [key for key in keys if key in b.shoulders_estimated]
            shown = " and ".join(f"'geometry.{key}' = {land:.6g} m" for key, land in zip(keys, lands))
            raise ParameterError(
                f"{path}: 'geometry.width' = {b.width} m is narrower than the {ring} ring's groove between its lands: "
                f"allowed from {needed:.6g} m, the width of the groove (radius f D from the groove bottom) at the land "
                f"diameters {shown}"
                + (" (estimated where not given: docs/parameters.md, Shoulders)" if estimated else "")
            )


CAGE_MATERIAL = {"E": MODULUS, "nu": POISSON, "rho": DENSITY}


def read_bearing(path):
    """Bearing set from the bearing file at path (a lubricant or spindle file is refused as such); validated."""
    path = Path(path)
    return bearing_from_document(read_toml(path, "bearing"), path)


def bearing_from_document(doc, path):
    """Bearing set from a parsed bearing file `doc` (nested dicts as tomllib gives them), validated; `path`
    names the file in messages and is the record's path (a Path or the text naming where the values came
    from)."""
    meta = doc.get("meta", {})
    kind = meta.get("kind", "deep_groove")
    if kind not in ("deep_groove", "angular_contact"):
        raise ParameterError(f"{path}: 'meta.kind' = {kind!r}, allowed: 'deep_groove', 'angular_contact'")
    D = _value(doc, "geometry.ball_diameter", Spec("m", 0.0, 1.0, True), path)
    dm = _value(doc, "geometry.pitch_diameter", Spec("m", 0.0, 10.0, True), path)
    if dm <= D:
        raise ParameterError(
            f"{path}: 'geometry.pitch_diameter' = {dm} m must exceed the ball diameter 'geometry.ball_diameter' = {D} m"
        )
    conf = Spec("-", 0.5, 1.0, low_open=True)
    Z = _value(doc, "geometry.n_balls", Spec("-", 3, 200), path)
    if Z != int(Z):
        raise ParameterError(f"{path}: 'geometry.n_balls' = {Z} must be a whole number in [3, 200]")
    f_i = _value(doc, "geometry.inner_conformity", conf, path)
    f_o = _value(doc, "geometry.outer_conformity", conf, path)
    Pd, alpha0 = _clearance_and_angle(doc, D, f_i, f_o, kind, path)
    shoulders, shoulders_estimated = _shoulders(doc, kind, D, dm, f_i, f_o, path)
    bearing = Bearing(
        name=str(meta.get("name", Path(path).stem)),
        kind=kind,
        path=str(path),
        D=D,
        dm=dm,
        f_i=f_i,
        f_o=f_o,
        Z=int(Z),
        Pd=Pd,
        alpha0=alpha0,
        ball=_material(doc, "material.ball", path),
        ring=_material(doc, "material.ring", path),
        Ra_inner=_value(doc, "surface.inner_race_Ra", ROUGHNESS, path),
        Ra_outer=_value(doc, "surface.outer_race_Ra", ROUGHNESS, path),
        Ra_ball=_value(doc, "surface.ball_Ra", ROUGHNESS, path),
        cage_ball_radius=_value(doc, "cage.ball_radius", Spec("m", 0.0, 1.0, True), path, required=False, default=0.0),
        cage_mass=_value(doc, "cage.mass", Spec("kg", 0.0, 1e3, True), path, required=False, default=0.0),
        shoulder_inner=shoulders["inner_shoulder_diameter"],
        shoulder_outer=shoulders["outer_shoulder_diameter"],
        shoulder_inner_back=shoulders["inner_back_shoulder_diameter"],
        shoulder_outer_back=shoulders["outer_back_shoulder_diameter"],
        shoulders_estimated=shoulders_estimated,
        bore=_value(doc, "geometry.bore", LENGTH, path, required=False),
        outer_diameter=_value(doc, "geometry.outer_diameter", LENGTH, path, required=False),
        width=_value(doc, "geometry.width", LENGTH, path, required=False),
        cage_material={
            key: _value(doc, f"material.cage.{key}", spec, path)
            for key, spec in CAGE_MATERIAL.items()
            if key in doc.get("material", {}).get("cage", {})
        },
    )
    if math.pi * dm < bearing.Z * D:
        raise ParameterError(
            f"{path}: 'geometry.n_balls' = {bearing.Z} balls of 'geometry.ball_diameter' = {D} m do not fit on the "
            f"pitch circle of 'geometry.pitch_diameter' = {dm} m: allowed at most {math.floor(math.pi * dm / D)} "
            "balls (pi d_m / D)"
        )
    check_roughness(bearing.Ra_inner, bearing.Ra_outer, bearing.Ra_ball, path)
    _check_cage(bearing.cage_ball_radius, D, dm, bearing.Z, path)
    check_ring_sections(D, dm, Pd, bearing.bore, bearing.outer_diameter, where=f"{path}: ")
    if bearing.width is not None:
        _check_width(bearing, path)
    return bearing
