"""DemModel: facade of the DEM (ball dynamics) fidelity, kernels.ball_dynamics.

Guessasma & Machado (2018) and Farah et al. (2020): Z steel balls and Z PA66 cage balls, inner ring
with translational DOF x, y, z, tilts theta_x, theta_y and prescribed rotation omega(t), fixed outer ring;
per-contact EHL film, regime-dependent damping and friction, Houpert rolling resistances, capacitance. SI units.

The whole state lives in numpy arrays (get_state/set_state copy all of them, for FMU rollback).
advance(t_end, ...) runs every step of the interval in one jitted call; the inner-ring speed goes
linearly from its previous value to the given one over the interval (a start-up ramp is a sequence
of calls), loads and oil temperature are held. The bodies start at rest in their geometric positions
(balls touching the outer race, cage balls midway between them on the pitch circle).

Settling aids for quasi-static comparisons (Guessasma 2018 appendix A): drive slowly (omega = 1 rad/s)
so that centrifugal and film effects vanish; the ring's response to a load step decays in about a
millisecond (hysteretic damping); compare after a few milliseconds.

The modules, one responsibility each:

- ``model``: DemModel, its state arrays, the kernel calls of a call (with the automatic step's retries and
  the rollback to the call's start) and the FMU protocol (update, evaluate, get_state/set_state).
- ``packing``: bearing, lubricant, scene and settings into the kernels' parameter array; the estimates of
  the inner ring's mass and inertia and of the cage balls; the load limit.
- ``placement``: the bodies' rest positions at the start.
- ``time_step``: the stability limit, the automatic step, the steps of a call and the refresh interval.
- ``inputs``: checks of the settings, of each call's inputs and of the FMU's communication step.
- ``monitor``: the monitor's thresholds, the kinetic-energy bound of a call, DemUnstableError and its message.
- ``outputs``: the output dict, the averaged state outputs, the shoulder truncation, the per-contact arrays.
- ``whirl``: the ring-orbit watch (a self-excited orbit of the ring on its support: monitor code 6, a warning).
"""

from ..dem_settings import TRACTION_LIMIT_MAX
from .inputs import COMMUNICATION_DIGITS, COMMUNICATION_RESOLUTION, T_OIL_DEFAULT
from .model import REFRESH_INTERVAL, DemModel
from .monitor import CHATTER_STEPS, DAMPING_PLAN, DAMPING_STOP, ENERGY_FACTOR, STATUS_WORDS, DemUnstableError
from .outputs import AVERAGED_STATE
from .packing import CONSTANTS, FILM_RATE, V_REG
from .time_step import AUTO_STEP_HALVINGS, MU_BOUNDARY, SAFETY

__all__ = [
    "AUTO_STEP_HALVINGS",
    "AVERAGED_STATE",
    "CHATTER_STEPS",
    "COMMUNICATION_DIGITS",
    "COMMUNICATION_RESOLUTION",
    "CONSTANTS",
    "DAMPING_PLAN",
    "DAMPING_STOP",
    "ENERGY_FACTOR",
    "FILM_RATE",
    "MU_BOUNDARY",
    "REFRESH_INTERVAL",
    "SAFETY",
    "STATUS_WORDS",
    "T_OIL_DEFAULT",
    "TRACTION_LIMIT_MAX",
    "V_REG",
    "DemModel",
    "DemUnstableError",
]
