"""Checks of the inputs whose declared ranges (models.declarations) a bearing narrows: speed, oil temperature and
clearance. Each raises InputError naming the input, its value and the allowed range."""

from ..params import clearance_limits
from .declarations import OMEGA, PD, T_OIL
from .limits import DM_N_LIMIT, InputError


def check_speed(omega, omega_max):
    """Raise InputError unless |omega| (rad/s) <= omega_max (the bearing's d_m n limit) and OMEGA_MAX."""
    OMEGA.check(omega, -omega_max, omega_max, f"d_m n <= {DM_N_LIMIT:.0e} mm.rpm")


def check_oil_temperature(T_oil):
    """Raise InputError unless T_oil (K) is within T_OIL_RANGE."""
    T_OIL.check(T_oil)


def check_clearance(Pd, bearing, given):
    """Raise InputError unless the diametral clearance Pd (m) lies within the geometric limits of the
    bearing (params.clearance_limits: -A <= P_d <= A, A = (f_i + f_o - 1) D, i.e. free contact angle up to
    60 deg) and, when set (given=True: the parameter Pd), within its declared range +-GROOVE_MAX; given
    False: read from the bearing file."""
    low, high = clearance_limits(bearing.D, bearing.f_i, bearing.f_o)
    if given:  # the parameter: also within its declared range
        low, high = max(low, PD.min), min(high, PD.max)
    if not (low <= Pd <= high):  # False for NaN
        origin = "set" if given else f"read from {bearing.path}"
        raise InputError(
            f"Pd = {Pd} m ({origin}) is outside the allowed range [{low:.4g}, {high:.4g}] m "
            f"(|Pd| <= (f_i + f_o - 1) D with f_i = {bearing.f_i}, f_o = {bearing.f_o} and D = {bearing.D} m of "
            f"{named_bearing(bearing)}: a larger clearance puts the free contact angle past 60 deg)"
        )


def named_bearing(bearing):
    """How a message names the bearing: 'bearing <name>' for a file, else where its values came from."""
    return bearing.path if bearing.path == bearing.name else f"bearing '{bearing.name}'"
