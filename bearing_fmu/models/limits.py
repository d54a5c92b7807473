"""Input checks shared by the bearing fidelities: clearance, speed, oil temperature and contact-pressure limits.

Every check raises InputError with a message naming the input, its value and the allowed range. The
static bounds below are the declared ranges (FMI min/max) of the inputs and parameters
(models.declarations); the checks (here and in models.input_checks, which reads the declarations) narrow them
where the limit depends on the bearing (d_m n, the material load limit, the groove clearance).
"""

from bearing_fmu_common.bearing_file import GROOVE_MAX  # noqa: F401  (re-exported for the models)
from bearing_fmu_common.variables import (  # noqa: F401  (re-exported for the models)
    LOAD_MAX,
    OMEGA_MAX,
    THERMAL_SHIFT_MAX,
    InputError,
    Variable,
)

# Pressures that bound the admissible load (docs/decisions.md):
P_MAX_WARNING = 4.2e9  # Pa, ISO 76 static load rating criterion for ball bearings
P_MAX_ERROR = 6.0e9  # Pa, estimated: far beyond first yield of bearing steel; Hertz is meaningless
DM_N_LIMIT = 4.0e6  # mm.rpm, d_m n beyond any oil-lubricated steel ball bearing (estimated)
T_OIL_RANGE = (233.15, 473.15)  # K, -40..200 C: range of the viscosity laws of mineral and PAO oils
# Static bounds (declared ranges; the bearing-dependent limit applies within them):
# OMEGA_MAX (rad/s) and LOAD_MAX (N) are bearing_fmu_common.variables' (the thermal FMU uses them too)
MOMENT_MAX = 1e8  # N.m: LOAD_MAX at 1 m
# GROOVE_MAX (m, |clearance|) is the bearing file's (bearing_fmu_common.bearing_file: the thermal FMU declares it too)
TILT_LIMIT = 0.01  # rad: imposed tilt, over 3 x the largest misalignment ball-bearing catalogues permit
# THERMAL_SHIFT_MAX (m, thermal clearance or axial change) is bearing_fmu_common.variables' (the thermal FMU's bound)
OMEGA_LIMITS = f"|omega| <= {OMEGA_MAX:g} rad/s and d_m n <= {DM_N_LIMIT:.0e} mm.rpm of the bearing"
LOAD_LIMITS = "static bound; the bearing's material limit (p_max = 6 GPa with the load on all balls) applies within"
MATERIAL_LIMIT = (
    f"the material limit: beyond it even shared equally by all balls the load gives p_max > {P_MAX_ERROR / 1e9:.1f} GPa"
)
T_OIL_LIMITS = "-40..200 C: range of the viscosity laws of mineral and PAO oils"


def material_load_limit(Z, E_red, contacts):
    """Largest admissible load (N): all Z balls at the contact load giving p_max = P_MAX_ERROR on the worse
    of the contacts ((Rx, Ry, k, E, K) per race: curvature radii in m and Hertz coefficients), reduced
    modulus E_red (Pa). p_max ~ Q^(1/3), so Q_lim = (P_MAX_ERROR / p(1 N))^3; no load distribution shares a
    load better than equally over all balls, so a larger load certainly passes the material limit."""
    from ..kernels.hertz import hertz_contact

    return Z * min(
        (P_MAX_ERROR / hertz_contact(1.0, Rx, Ry, E_red, k, ee, kk)[3]) ** 3 for Rx, Ry, k, ee, kk in contacts
    )


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


class OilTemperatureWatch:
    """Warns once per entry when the oil temperature leaves the range that the lubricant file's data support
    (its [temperature_range]; none for a file without one, e.g. constant properties given for one state): the
    viscosity, pressure-viscosity and density laws are then extrapolated. The input range T_OIL_RANGE is checked
    separately (an error beyond it)."""

    def __init__(self, lubricant):
        self.name = lubricant.name
        self.low, self.high = lubricant.T_low, lubricant.T_high
        self.outside = False

    def warnings(self, T_oil):
        """[] or the one warning of an entry into the extrapolated range at T_oil (K)."""
        if self.low is None:
            return []
        outside = not (self.low <= T_oil <= self.high)
        entered = outside and not self.outside
        self.outside = outside
        if not entered:
            return []
        return [
            f"T_oil = {T_oil:.5g} K is outside the temperature range of the data of lubricant '{self.name}' "
            f"[{self.low:.5g}, {self.high:.5g}] K: its viscosity, pressure-viscosity and density are extrapolated "
            "(the lubricant file's [temperature_range])"
        ]
