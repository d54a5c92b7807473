"""The quasi-static solver at large free contact angles: every point of the documented grid converges or is
refused with its physical reason (docs/quasistatic.md section 3, "Large free contact angles").

Grid: the B7214C and the 6208 with P_d = 0.3, 0.4, 0.5, 0.59, 0.7, 0.8, 0.85, 0.9, 0.95 and 1.0 A
(A = (f_i + f_o - 1) D; free contact angles 32-60 deg), under 3 kN radial with 0, 100 and 500 N thrust and
a thrust-dominated 500 N radial + 3 kN thrust, each alone and with a 50 N.m moment M_x, at 0, 50, 500 and
1000 rad/s, each point solved from a fresh model (cold start) with the scene of Bearing.fmu (tolerance 1e-10
of the load). 640 points; measured: 435 converge, 134 single angular-contact cases are refused because their
loaded balls need the missing shoulder or sit at the groove bottom, and 71 (all at speed) because a ball lies
beyond the centre of curvature of its inner groove. A damped Newton with line search alone ends 127 points
in "no convergence" (a SolverError without a physical reason).

Converged points balance the applied loads to the scene tolerance of the larger of the applied load and the
mean ball load (the solver's own criterion, moments divided by d_m/2); every thrust-dominated point converges.
"""

import numpy as np
import pytest

from bearing_fmu import InputError, QuasiStaticModel, Scene
from bearing_fmu.build import SCENES_DIR
from bearing_fmu.kernels import jones_harris
from bearing_fmu.models.declarations import LOAD_NAMES

SCENE = Scene.from_toml(SCENES_DIR / "quasi_static.toml")  # the scene of Bearing.fmu
SHARES = (0.3, 0.4, 0.5, 0.59, 0.7, 0.8, 0.85, 0.9, 0.95, 1.0)  # P_d / A
RADIAL = (dict(F_y=3000.0), dict(F_y=3000.0, F_z=100.0), dict(F_y=3000.0, F_z=500.0))
THRUST = dict(F_y=500.0, F_z=3000.0)
MOMENT = dict(M_x=50.0)
SPEEDS = (0.0, 50.0, 500.0, 1000.0)  # rad/s
# the physical reasons of a refusal (models/quasi_static.py)
SHOULDER = "single-row angular-contact bearing"
BEYOND_CENTRE = "beyond the centre of curvature of its inner groove"


def grid_loads():
    """Every load of the grid: the three radial loads and the thrust-dominated one, each alone and with M_x."""
    return [dict(load, **extra) for load in (*RADIAL, THRUST) for extra in ({}, MOMENT)]


@pytest.mark.parametrize("omega", SPEEDS)
@pytest.mark.parametrize("bearing", ["B7214C", "6208"])
def test_every_grid_point_converges_or_is_refused_for_a_physical_reason(bearing, omega):
    """Case: every clearance and load of the grid (module docstring) at one speed, from a fresh model. Outcome:
    converged with the loads balanced to the scene tolerance, or an InputError naming a physical reason (a
    ball beyond the centre of its inner groove; for the single angular-contact bearing, the missing shoulder
    or the groove bottom); every thrust-dominated point converges."""
    b = QuasiStaticModel(bearing, scene=SCENE).bearing
    A = (b.f_i + b.f_o - 1.0) * b.D  # m
    scale = np.array([1.0, 1.0, 1.0, 0.5 * b.dm, 0.5 * b.dm])
    unexplained = []
    for share in SHARES:
        for load in grid_loads():
            m = QuasiStaticModel(bearing, scene=SCENE, Pd=share * A)
            try:
                m.evaluate(omega=omega, **load)
            except InputError as error:
                message = str(error)
                physical = BEYOND_CENTRE in message or (b.kind == "angular_contact" and SHOULDER in message)
                if not physical or load.get("F_z") == THRUST["F_z"]:
                    unexplained.append((share, load, message[:160]))
                continue
            applied = np.array([load.get(n, 0.0) for n in LOAD_NAMES])
            error = np.max(np.abs(applied - m.F) / scale)
            assert m.status[0] == jones_harris.QS_OK
            load_scale = max(
                np.max(np.abs(applied) / scale), np.mean(m.balls[jones_harris.BQ_Q_I])
            )  # the solver's scale
            assert error <= SCENE.tolerance * load_scale, (share, load, error)
    assert not unexplained, unexplained
