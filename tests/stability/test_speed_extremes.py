"""Stability cases in speed: rest, reversal, very high speed (d_m n >= 2e6 mm.rpm), beyond the limit.

Each test states the case, the fidelities it covers and the expected outcome: stable and within a
stated tolerance of a reference, or a clear diagnostic (an InputError naming the input, its value
and its allowed range). Low speeds between rest and 600 rpm, where the quasi-static solver once
refused steps, are the run-ups and grids of tests/unit/test_quasistatic_low_speed.py.
"""

import math

import numpy as np
import pytest

from bearing_fmu import AnalyticModel, InputError, QuasiStaticModel, Scene
from bearing_fmu.build import SCENES_DIR
from bearing_fmu.kernels.geometry import ball_mass, centrifugal_force, rolling_kinematics
from bearing_fmu.models.dem import DemModel

RPM = 2.0 * math.pi / 60.0
QS_SCENE = Scene.from_toml(SCENES_DIR / "quasi_static.toml")  # the scene of Bearing.fmu
STRIBECK_ZERO_CLEARANCE = 4.37  # Stribeck's Q_max = 4.37 F_r / Z at P_d = 0 (Harris &
# Kotzalas 2006, Essential Concepts of Bearing Technology, load-distribution chapter)


def finite(outputs):
    return all(np.all(np.isfinite(np.asarray(v, dtype=float))) for v in outputs.values())


def dem_start(model, omega, F_y, settle=2e-3, ramp=5e-3, run_to=0.03):
    """The DEM start-up of the validation tests: settle at rest under a radial F_y (on the line of ball 1,
    docs/conventions.md), ramp to omega, run."""
    model.advance(settle, omega=0.0, F_y=F_y)
    for k in range(1, 21):
        model.advance(settle + ramp * k / 20, omega=omega * k / 20, F_y=F_y)
    return model.advance(run_to, omega=omega, F_y=F_y)


def test_analytic_at_rest_gives_the_static_load_distribution():
    """Case: analytic fidelity at omega = 0 (6208, P_d = 0, F_r = 3 kN). Outcome: finite outputs; no film
    (h = 0, Lambda = 0, boundary regime); Q_max_inner = Stribeck's 4.37 F_r / Z for zero clearance
    (tolerance 0.1 %: 4.37 is the textbook's rounded value of the continuous integral); the capacitance
    is bounded by the scene's film floor, not infinite."""
    out = AnalyticModel("6208").evaluate(omega=0.0, F_y=3000.0, T_oil=313.15)
    assert finite(out)
    assert out["h_min_inner"] == out["h_min_outer"] == out["Lambda_outer"] == 0.0
    assert out["regime"] == 0 and out["omega_cage"] == 0.0
    assert out["Q_max_inner"] == pytest.approx(STRIBECK_ZERO_CLEARANCE * 3000.0 / 9, rel=1e-3)
    assert 0.0 < out["C_bearing"] < 1e-6


@pytest.mark.parametrize("bearing,load", [("B7214C", dict(F_x=3000.0, F_z=800.0)), ("6208", dict(F_x=3000.0))])
def test_quasi_static_at_rest_is_converged_without_torque(bearing, load):
    """Case: quasi-static fidelity exactly at rest, loaded. Outcome: converged (status 0) with finite
    outputs, the load residual within the scene tolerance (1e-10 of the load, relative) and no rolling
    torque (the Houpert losses are rolling and sliding powers: zero at omega = 0)."""
    model = QuasiStaticModel(bearing, scene=QS_SCENE)
    out = model.evaluate(omega=0.0, **load)
    assert finite(out)
    assert model.status[0] == 0
    assert model.status[2] <= 1e-8 * max(abs(v) for v in load.values())
    assert out["torque"] == 0.0 and out["P_loss"] == 0.0


def test_dem_at_rest_carries_the_load_of_the_quasi_static_fidelity():
    """Case: DEM fidelity at rest under 3 kN (6208, 10 ms of settling at the default time step).
    Outcome: no monitor stop, finite outputs, the cage at rest (|omega_cage| < 1e-3 rad/s) and Q_max
    within 2 % of the quasi-static fidelity at rest (the slow-drive agreement validated in
    tests/validation/test_dem_6208.py; the ring settles within a few ms)."""
    model = DemModel("6208", "guessasma_oil")
    out = model.advance(0.010, omega=0.0, F_y=3000.0)
    assert finite(out)
    assert abs(out["omega_cage"]) < 1e-3
    qs = QuasiStaticModel("6208", "guessasma_oil", scene=Scene(name="qs", fidelity="quasi_static", gyroscopic=False))
    reference = qs.evaluate(omega=0.0, F_y=3000.0)
    assert out["Q_max_inner"] == pytest.approx(reference["Q_max_inner"], rel=0.02)


@pytest.mark.parametrize("fidelity", ["analytic", "quasi_static"])
def test_speed_reversal_mirrors_the_solution(fidelity):
    """Case: omega -> -omega (analytic 6208 under F_y; quasi-static B7214C under radial + axial load, at
    10 000 rpm). Outcome: every load, angle, film, torque and heat output identical (the physics is even
    in omega: centrifugal and gyroscopic terms go with omega^2, the torque output is the magnitude of
    the resisting torque), the cage and ball speeds exactly negated."""
    if fidelity == "analytic":
        model = AnalyticModel("6208")
        forward = dict(model.evaluate(omega=1000.0, F_y=3000.0, T_oil=313.15))
        backward = dict(model.evaluate(omega=-1000.0, F_y=3000.0, T_oil=313.15))
    else:
        model = QuasiStaticModel("B7214C", scene=QS_SCENE)
        forward = dict(model.evaluate(omega=10000.0 * RPM, F_x=2000.0, F_z=800.0))
        backward = dict(model.evaluate(omega=-10000.0 * RPM, F_x=2000.0, F_z=800.0))
    speeds = {"omega_cage", "omega_ball"}  # signed; omega_ball_cage and the frequencies are magnitudes
    work = {"iterations"}  # solver work, not physics: the reversed case starts warm from the mirrored one
    for name, value in forward.items():
        if name in work:
            continue
        expected = -value if name in speeds else value
        assert backward[name] == pytest.approx(expected, rel=1e-9, abs=1e-15), name


def test_dem_speed_reversal_runs_through_zero():
    """Case: DEM 6208 at 3 kN, steady at +500 rad/s, speed ramped to -500 rad/s in 20 ms (the ring
    passes through rest while loaded). Outcome: no monitor stop, finite outputs, and 80 ms after the
    ramp the cage turns backwards at its kinematic speed within 1 % (the steady-state tolerance of the
    forward case in tests/validation/test_dem_6208.py)."""
    model = DemModel("6208", "guessasma_oil")
    dem_start(model, 500.0, 3000.0)
    t0 = model.time
    for k in range(1, 21):
        model.advance(t0 + 0.020 * k / 20, omega=500.0 - 1000.0 * k / 20, F_y=3000.0)
    out = model.advance(t0 + 0.1, omega=-500.0, F_y=3000.0)
    assert finite(out)
    cage = rolling_kinematics(-500.0, 12.6e-3, 60.6e-3, 0.0)[0]
    assert out["omega_cage"] == pytest.approx(cage, rel=0.01)


def test_quasi_static_at_very_high_speed_is_centrifugal_dominated():
    """Case: quasi-static B7214C at 25 000 rpm under 800 N axial (d_m n = 97.5 mm x 25 000 rpm = 2.4e6
    mm.rpm). Outcome: converged; the outer contacts carry the centrifugal force (Q_max_outer > 10 Q_max_inner,
    alpha_outer < alpha_inner); per ball the axial inner-contact loads carry the thrust exactly
    (Z Q_i sin alpha_i = F_a, 1e-6 relative: the solver's tolerance) and the radial ball balance
    Q_o cos alpha_o - Q_i cos alpha_i = F_c holds within the radial share of the outer-race friction
    force that carries the gyroscopic moment, F_f sin alpha_o with F_f <= 2 M_g / D,
    M_g <= J omega_ball omega_cage (J = m D^2 / 10)."""
    model = QuasiStaticModel("B7214C", scene=QS_SCENE)
    out = model.evaluate(omega=25000.0 * RPM, F_z=800.0)
    assert finite(out) and model.status[0] == 0
    b = model.bearing
    Qi, Qo, ai, ao = out["Q_max_inner"], out["Q_max_outer"], out["alpha_inner"], out["alpha_outer"]
    assert Qo > 10.0 * Qi and ao < ai
    assert b.Z * Qi * math.sin(ai) == pytest.approx(800.0, rel=1e-6)
    m = ball_mass(b.D, 7850.0)  # bearing steel, the file's rho
    Fc = centrifugal_force(m, b.dm, out["omega_cage"])
    friction = 2.0 * (0.1 * m * b.D**2) * abs(out["omega_ball"] * out["omega_cage"]) / b.D
    assert abs(Qo * math.cos(ao) - Qi * math.cos(ai) - Fc) <= friction * math.sin(ao) + 1e-9 * Fc


@pytest.mark.parametrize("omega", [3500.0, 5000.0])
def test_dem_at_very_high_speed_is_stable_and_slips(omega):
    """Case: DEM 6208 at 3 kN driven to 3500 and 5000 rad/s (d_m n = 2.0e6 and 2.9e6 mm.rpm; centrifugal
    force 0.4 and 0.8 of the mean ball load) in 5 ms. Outcome: no monitor stop over 0.2 s, finite outputs,
    the outer contacts more loaded than the inner ones, and the cage accelerating towards its kinematic
    speed without passing it (gross slip: the traction of the lightly loaded, well-lubricated contacts
    limits the cage's acceleration)."""
    model = DemModel("6208", "guessasma_oil")
    early = dem_start(model, omega, 3000.0)
    late = model.advance(0.2, omega=omega, F_y=3000.0)
    assert finite(early) and finite(late)
    assert late["Q_max_outer"] > late["Q_max_inner"]
    cage = rolling_kinematics(omega, 12.6e-3, 60.6e-3, 0.0)[0]
    assert early["omega_cage"] < late["omega_cage"] <= cage


@pytest.mark.parametrize("fidelity", ["analytic", "quasi_static", "dem"])
def test_speed_beyond_the_limit_is_refused(fidelity):
    """Case: a speed beyond d_m n = 4e6 mm.rpm (beyond any oil-lubricated steel ball bearing). Outcome:
    InputError naming omega, its value and the allowed range; nothing computed."""
    if fidelity == "analytic":
        model = AnalyticModel("6208")
        call = lambda w: model.evaluate(omega=w, F_y=3000.0, T_oil=313.15)  # noqa: E731
    elif fidelity == "quasi_static":
        model = QuasiStaticModel("6208", scene=QS_SCENE)
        call = lambda w: model.evaluate(omega=w, F_x=3000.0)  # noqa: E731
    else:
        model = DemModel("6208", "guessasma_oil")
        call = lambda w: model.advance(1e-4, omega=w, F_y=3000.0)  # noqa: E731
    too_fast = 1.01 * 4.0e6 / 60.6 * RPM
    with pytest.raises(InputError) as info:
        call(too_fast)
    message = str(info.value)
    assert "omega" in message and f"{too_fast}" in message and "allowed range" in message
