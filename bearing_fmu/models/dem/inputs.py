"""Checks of the DEM's settings (constructor arguments) and inputs (each call's values and the FMU's communication
step): every refusal is an InputError that names the value and its allowed range."""

import math

from bearing_fmu_common.variables import InputLimits

from ...params import clearance_limits
from ..declarations import (
    DEM_DT_MAX,
    DEM_DT_MIN,
    DEM_INPUTS,
    DEM_LOAD_INPUTS,
    DEM_PATH_INPUTS,
    DEM_REFRESH_MAX,
    DISPLACEMENT_LIMIT,
    PATH_RATE_FREQUENCY,
    T_OIL_START,
)
from ..dem_settings import checked_settings as checked_numeric_settings
from ..limits import DM_N_LIMIT, MATERIAL_LIMIT, InputError
from .packing import CONSTANTS

T_OIL_DEFAULT = T_OIL_START  # K, the oil temperature of a call that gives none
# update()'s communication step is rounded to this grid (s), far below any DEM time step (0.1-10 us)
COMMUNICATION_DIGITS = 12
COMMUNICATION_RESOLUTION = 10.0**-COMMUNICATION_DIGITS


def checked_settings(dt, refresh, safety, refresh_interval, settings, kt_ratio, mass, inertia, drive="load"):
    """Refuse a DemModel setting out of its range (the arguments of DemModel; settings = its keywords of
    models.dem_settings.DEM_SETTINGS, mass and inertia are ring_mass and ring_inertia); returns those settings
    checked (name -> value, the defaults of params/dem_model.toml where absent or None) and kt_ratio, the file's
    where None. drive: the model's (the ring's support is none with a prescribed ring)."""
    if dt is not None and not (math.isfinite(dt) and DEM_DT_MIN <= dt <= DEM_DT_MAX):
        raise InputError(
            f"dt = {dt} s is outside the allowed range [{DEM_DT_MIN:g}, {DEM_DT_MAX:g}] s (in the FMU also 0 = "
            "automatic)"
        )
    if refresh is not None and not (float(refresh) == int(refresh) and 1 <= int(refresh) <= 100000):
        raise InputError(f"refresh = {refresh} steps is outside the allowed range [1, 100000] (a whole number)")
    if not (math.isfinite(safety) and 0.0 < safety <= 1.0):
        raise InputError(f"safety = {safety} is outside the allowed range ]0, 1]")
    # 0 (the declared minimum) refreshes at every step, as any interval below dt does (time_step.refresh_steps)
    if not (math.isfinite(refresh_interval) and 0.0 <= refresh_interval <= DEM_REFRESH_MAX):
        raise InputError(
            f"refresh_interval = {refresh_interval} s is outside the allowed range [0, {DEM_REFRESH_MAX:g}] s "
            "(0 = every DEM step)"
        )
    settings = checked_numeric_settings(settings, drive)
    kt_ratio = CONSTANTS.kt_ratio if kt_ratio is None else kt_ratio
    if not (math.isfinite(kt_ratio) and 0.1 <= kt_ratio <= 1.5):
        raise InputError(f"kt_ratio = {kt_ratio} is outside the allowed range [0.1, 1.5]")
    if mass is not None and not (math.isfinite(mass) and mass > 0.0):
        raise InputError(f"ring_mass = {mass} kg is outside the allowed range ]0, inf[ kg")
    if inertia is not None and not (math.isfinite(inertia) and inertia > 0.0):
        raise InputError(f"ring_inertia = {inertia} kg.m^2 is outside the allowed range ]0, inf[ kg.m^2")
    return settings, kt_ratio


def speed_limit(bearing):
    """Largest inner-ring speed (rad/s): the bearing's d_m n limit."""
    return DM_N_LIMIT / (bearing.dm * 1e3) * 2.0 * math.pi / 60.0


def input_limits(bearing, Pd, load, omega_max):
    """The InputLimits of DEM_LOAD_INPUTS (the load-driven DEM's inputs) narrowed to a bearing of diametral
    clearance Pd (m) with the load limit `load`
    (N) and the speed limit omega_max (rad/s)."""
    narrowed = {name: (-load, load, MATERIAL_LIMIT) for name in ("F_x", "F_y", "F_z")}
    # moments: the load limit at the pitch radius, as the quasi-static fidelity's
    narrowed.update(
        {name: (-load * 0.5 * bearing.dm, load * 0.5 * bearing.dm, MATERIAL_LIMIT) for name in ("M_x", "M_y")}
    )
    narrowed["omega"] = (-omega_max, omega_max, f"d_m n <= {DM_N_LIMIT:.0e} mm.rpm")
    # the clearance in effect, P_d + dPd_thermal, keeps the geometric limits of P_d itself (|P_d| <= A:
    # neither an interference beyond the groove clearance nor a free contact angle beyond 60 deg)
    low, high = clearance_limits(bearing.D, bearing.f_i, bearing.f_o)
    narrowed["dPd_thermal"] = (
        low - Pd,
        high - Pd,
        f"Pd + dPd_thermal within [{low:.4g}, {high:.4g}] m (|Pd| <= (f_i + f_o - 1) D)",
    )
    return InputLimits(DEM_LOAD_INPUTS, narrowed)


DRIVES = ("load", "displacement")  # DemModel's drive: the loads move the inner ring, or its path is prescribed
PATH_NAMES = tuple(v.name for v in DEM_PATH_INPUTS)


def checked_drive(drive):
    """The drive of a DemModel, refused unless one of DRIVES."""
    if drive not in DRIVES:
        raise InputError(f"drive = {drive!r} is not one of the allowed {list(DRIVES)}")
    return drive


def path_limits(bearing):
    """The InputLimits of DEM_PATH_INPUTS narrowed to the bearing: displacements within half its groove clearance
    A = (f_i + f_o - 1) D, their rates within that amplitude vibrating at PATH_RATE_FREQUENCY."""
    bound = DISPLACEMENT_LIMIT * (bearing.f_i + bearing.f_o - 1.0) * bearing.D
    why = "|d| <= 0.5 (f_i + f_o - 1) D: beyond it past any material limit"
    narrowed = {name: (-bound, bound, why) for name in PATH_NAMES[:3]}
    rate = bound * 2.0 * math.pi * PATH_RATE_FREQUENCY
    narrowed |= {name: (-rate, rate, f"{why}, vibrating at 10 kHz") for name in PATH_NAMES[5:8]}
    return InputLimits(DEM_PATH_INPUTS, narrowed)


DZ_THERMAL = next(v for v in DEM_INPUTS if v.name == "dz_thermal")


def shift_limits(bearing):
    """The InputLimits of dz_thermal narrowed to the bearing: |dz_thermal| <= 0.02 D, the quasi-static fidelity's."""
    limit = 0.02 * bearing.D
    return InputLimits((DZ_THERMAL,), {"dz_thermal": (-limit, limit, "|value| <= 0.02 D")})


def shifted(end, dz_thermal, limits, displacement_driven):
    """The path's end values `end` (x ... theta_y, then their rates; SI) with dz_thermal (m, checked against limits:
    shift_limits) added to z; z_rate unchanged (the shift is constant). Refused non-zero when the model is
    load-driven."""
    if dz_thermal != 0.0 and not displacement_driven:
        raise InputError(
            f"dz_thermal = {dz_thermal} is an input of drive = 'displacement' only (this model is load-driven: "
            "give F_z)"
        )
    limits.check((dz_thermal,))
    if dz_thermal == 0.0:
        return end
    return (*end[:2], end[2] + dz_thermal, *end[3:])


def path_values(limits, motion, displacement_driven):
    """The prescribed ring's end values of a call (x ... theta_y, then their rates; SI) from the keywords `motion`
    (name -> value, absent = 0), checked against limits (path_limits). Refused when the model is load-driven, or
    for a name that is not one of PATH_NAMES."""
    unknown = sorted(set(motion) - set(PATH_NAMES))
    if unknown:
        raise InputError(f"unknown input(s) {unknown}: allowed the loads, or with drive = 'displacement' {PATH_NAMES}")
    if motion and not displacement_driven:
        raise InputError(
            f"{sorted(motion)[0]} = {motion[sorted(motion)[0]]} is an input of drive = 'displacement' only (this "
            "model is load-driven: give F_x ... M_y)"
        )
    values = tuple(float(motion.get(name, 0.0)) for name in PATH_NAMES)
    limits.check(values)
    return values


def check_no_loads(loads):
    """A ring on a prescribed path takes no loads (the shaft holds it): refuse a non-zero one."""
    for name, value in zip(("F_x", "F_y", "F_z", "M_x", "M_y"), loads):
        if value != 0.0:
            raise InputError(
                f"{name} = {value} is outside the allowed range [0, 0] with drive = 'displacement' (the ring's "
                "path is prescribed: its reaction loads are outputs)"
            )


def check_inputs(limits, t, t_end, omega, loads, T_oil, dPd_thermal):
    """Refuse a call from time t (s) to t_end (s) that does not go forward, or an input outside limits
    (input_limits)."""
    if not (math.isfinite(t_end) and t_end > t):
        raise InputError(f"t_end = {t_end} s is outside the allowed range ]{t:.9g}, inf[ s (after the current time)")
    limits.check((omega, *loads, T_oil, dPd_thermal))  # the order of DEM_LOAD_INPUTS


def communication_interval(interval):
    """The communication step interval (s) on the grid of COMMUNICATION_RESOLUTION; refused below it."""
    if not (math.isfinite(interval) and interval >= COMMUNICATION_RESOLUTION):
        raise InputError(
            f"communication step = {interval} s is outside the allowed range [{COMMUNICATION_RESOLUTION:g}, inf[ s"
        )
    # on a grid of 1 ps: masters that hand the same nominal step in different roundings (libcosim counts
    # integer nanoseconds, fmpy multiplies n H) then take the same DEM steps, bit for bit
    return round(interval, COMMUNICATION_DIGITS)
