"""Input checks shared by the bearing fidelities: clearance, speed, oil temperature and contact-pressure limits.

Every check raises InputError with a message naming the input, its value and the allowed range.
"""

import math

from bearing_fmu_common.variables import InputError, Variable  # noqa: F401  (re-exported for the models)

# Pressures that bound the admissible load (docs/decisions.md):
P_MAX_WARNING = 4.2e9  # Pa, ISO 76 static load rating criterion for ball bearings
P_MAX_ERROR = 6.0e9  # Pa, estimated: far beyond first yield of bearing steel; Hertz is meaningless
DM_N_LIMIT = 4.0e6  # mm.rpm, d_m n beyond any oil-lubricated steel ball bearing (estimated)
T_OIL_RANGE = (233.15, 473.15)  # K, -40..200 C: range of the viscosity laws of mineral and PAO oils


def check_speed(omega, omega_max):
    """Raise InputError unless omega (rad/s) is finite and |omega| <= omega_max (the d_m n limit)."""
    if not (math.isfinite(omega) and abs(omega) <= omega_max):
        raise InputError(
            f"omega = {omega} rad/s is outside the allowed range [{-omega_max:.6g}, {omega_max:.6g}] "
            f"rad/s (d_m n <= {DM_N_LIMIT:.0e} mm.rpm)"
        )


def check_oil_temperature(T_oil):
    """Raise InputError unless T_oil (K) is within T_OIL_RANGE."""
    lo, hi = T_OIL_RANGE
    if not (math.isfinite(T_oil) and lo <= T_oil <= hi):
        raise InputError(f"T_oil = {T_oil} K is outside the allowed range [{lo}, {hi}] K")


def pressure_warnings(p_max, loads):
    """Warnings for a Hertz pressure p_max (Pa) above the ISO 76 limit; InputError above the material
    limit. `loads` names the inputs that caused it (for the message)."""
    if p_max > P_MAX_ERROR:
        raise InputError(
            f"{loads} gives p_max = {p_max / 1e9:.3g} GPa, beyond the material limit "
            f"{P_MAX_ERROR / 1e9:.1f} GPa (allowed: loads giving p_max <= {P_MAX_ERROR / 1e9:.1f} GPa)"
        )
    if p_max > P_MAX_WARNING:
        return [
            f"p_max = {p_max / 1e9:.3g} GPa exceeds {P_MAX_WARNING / 1e9:.1f} GPa "
            f"(ISO 76 static limit): permanent raceway deformation expected"
        ]
    return []


def check_clearance(Pd, bearing, given):
    """Raise InputError unless the diametral clearance Pd (m) lies within the geometric limits of the
    bearing (params.clearance_limits: -A <= P_d <= A, A = (f_i + f_o - 1) D, i.e. free contact angle up to
    60 deg). given: True when Pd was set by the user, False when it was read from the bearing file."""
    from ..params import clearance_limits

    low, high = clearance_limits(bearing.D, bearing.f_i, bearing.f_o)
    if not (math.isfinite(Pd) and low <= Pd <= high):
        origin = "set" if given else f"read from {bearing.path}"
        raise InputError(
            f"Pd = {Pd} m ({origin}) is outside the allowed range [{low:.4g}, {high:.4g}] m "
            f"(|Pd| <= (f_i + f_o - 1) D: free contact angle up to 60 deg)"
        )
