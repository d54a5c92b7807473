"""Speed outputs and their frames, defect frequencies and central films through the three facades.

Every angular speed is about the bearing axis in the fixed frame unless said otherwise (docs/conventions.md):
omega_cage (fixed frame), omega_ball (the ball in the fixed frame), omega_ball_cage (the ball relative to the
cage); FTF = |omega_cage|/2 pi, BPFO = Z FTF, BPFI = Z |omega - omega_cage|/2 pi, BSF = omega_ball_cage/2 pi.
"""

import math

import pytest

from bearing_fmu.kernels.geometry import rolling_kinematics
from bearing_fmu.models.analytic import AnalyticModel
from bearing_fmu.models.dem import DemModel
from bearing_fmu.models.quasi_static import QuasiStaticModel
from bearing_fmu.scene import Scene
from tests.reference import ref_ball_dynamics_outputs as ref_outputs

TWO_PI = 2.0 * math.pi
RPM = TWO_PI / 60.0


def check_frequencies(out, omega, Z, rel=1e-13):
    """The defect frequencies are the solved speeds counted per second (definitions of the module docstring)."""
    ftf = abs(out["omega_cage"]) / TWO_PI
    assert out["FTF"] == pytest.approx(ftf, rel=rel)
    assert out["BPFO"] == pytest.approx(Z * ftf, rel=rel)
    assert out["BPFI"] == pytest.approx(Z * abs(omega - out["omega_cage"]) / TWO_PI, rel=rel)
    assert out["BSF"] == pytest.approx(out["omega_ball_cage"] / TWO_PI, rel=rel)


def test_analytic_ball_speed_in_the_fixed_frame_is_not_the_ball_spin_frequency():
    """6208 at 500 rad/s (contact angle 0: the ball's spin axis is parallel to the bearing axis, so the fixed-frame
    speed is the speed relative to the cage minus the cage's own, in the opposite sense): omega_ball = 952.38 rad/s,
    omega_ball_cage = 1150.4 rad/s (Guessasma & Machado 2018, section 3.1, printed digits); reading omega_ball as
    2 pi BSF is 17 % off."""
    out = AnalyticModel("6208", "guessasma_oil").evaluate(500.0, 3000.0, 313.15)
    assert out["omega_ball_cage"] - out["omega_ball"] == pytest.approx(out["omega_cage"], rel=1e-12)
    assert out["omega_ball"] == pytest.approx(952.38, abs=0.005)
    assert out["omega_ball_cage"] == pytest.approx(1150.4, abs=0.05)
    assert 1.0 - out["omega_ball"] / out["omega_ball_cage"] == pytest.approx(0.172, abs=0.001)
    check_frequencies(out, 500.0, 9)
    assert out["h_c_inner"] > out["h_min_inner"] > 0.0 and out["h_c_outer"] > out["h_min_outer"] > 0.0


@pytest.mark.parametrize("omega", [10000 * RPM, -10000 * RPM])
def test_quasi_static_frequencies_come_from_the_solved_speeds(omega):
    """B7214C (15 deg nominal) at 10 000 rpm, 2 kN thrust and 1 kN radial with the gyroscopic moment: the
    frequencies follow the solved cage and ball speeds (operating contact angles, outer-race control), not the
    pure-rolling speeds at the nominal angle; magnitudes in both senses of rotation; central films above the
    minimum films."""
    scene = Scene(name="qs", fidelity="quasi_static", gyroscopic=True)
    qs = QuasiStaticModel("B7214C", scene=scene)
    out = qs.evaluate(omega=omega, F_z=2000.0, F_y=1000.0)
    b = qs.bearing
    check_frequencies(out, omega, b.Z)
    nominal_cage = rolling_kinematics(omega, b.D, b.dm, b.alpha0)[0]
    assert abs(out["omega_cage"] / nominal_cage - 1.0) > 1e-3  # the operating state, not the nominal one
    assert out["FTF"] > 0.0 and out["BSF"] > 0.0
    assert out["h_c_inner"] > out["h_min_inner"] > 0.0 and out["h_c_outer"] > out["h_min_outer"] > 0.0


def test_quasi_static_at_rest_has_no_frequencies():
    out = QuasiStaticModel("6208", "guessasma_oil").evaluate(omega=0.0, F_y=1000.0)
    assert (out["FTF"], out["BPFO"], out["BPFI"], out["BSF"], out["omega_ball_cage"]) == (0.0, 0.0, 0.0, 0.0, 0.0)


def test_dem_frequencies_carry_the_cage_slip():
    """DEM 6208 spun up to 300 rad/s under 3 kN: the cage speed is solved dynamically, so FTF = (1 - cage_slip)
    times the pure-rolling cage speed of the loaded balls at their current contacts and spin axes (the twin's
    2x2 solve, tests/reference/ref_ball_dynamics_outputs.py), and the frequencies follow the solved speeds."""
    model = DemModel("6208", "guessasma_oil")
    model.evaluate(1e-3, F_y=3000.0)
    for k in range(1, 6):
        out = model.evaluate(1e-3 + k * 1e-3, omega=60.0 * k, F_y=3000.0)
    b = model.bearing
    check_frequencies(out, 300.0, b.Z)
    Q = ref_outputs.contact_loads(model.balls, model.ring, model.par)
    pure = ref_outputs.pure_rolling_cage_speed(model.balls, model.ring, model.par, 300.0, Q) / TWO_PI
    assert out["FTF"] == pytest.approx((1.0 - out["cage_slip"]) * pure, rel=1e-9)
    assert out["cage_slip"] != 0.0
    # a radial bearing's balls spin about the bearing axis with radial contacts: the classic (1 - gamma)/2
    assert pure == pytest.approx(rolling_kinematics(300.0, b.D, b.dm, 0.0)[0] / TWO_PI, rel=2e-3)
    assert out["h_c_inner"] > 0.0 and out["h_c_outer"] > 0.0
