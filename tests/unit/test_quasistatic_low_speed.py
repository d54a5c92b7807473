"""The quasi-static solver from rest and at low speed, and under zero load inside the clearance.

At low non-zero speed the balls that the load does not press are held on the outer race by a
centrifugal force of nanonewtons; their equilibrium is judged against the bearing-level load per ball
(jones_harris._ball_newton), a warm start where such a ball floated is replaced, and a ring free in its
clearance under zero load sits at the documented position (docs/quasistatic.md section 3). Speeds,
loads and bearings are those with which engineers drive the FMU: a run-up from rest under radial,
axial and moment loads, and a grid of low speeds from 0.1 rpm.
"""

import math

import numpy as np
import pytest

from bearing_fmu import InputError, QuasiStaticModel, Scene
from bearing_fmu.build import SCENES_DIR
from bearing_fmu.kernels import jones_harris
from tests.reference import ref_jones_harris as ref
from tests.unit.test_quasistatic import kernel_solve, pack

RPM = 2.0 * math.pi / 60.0
SCENE = Scene.from_toml(SCENES_DIR / "quasi_static.toml")  # the scene of Bearing.fmu
# loads (N, N.m) of the run-ups and of the grid: radial + axial, radial + moment, pure axial, none
LOADS = {
    "B7214C": (  # a single-row angular-contact bearing: every load with the thrust that keeps it on its shoulder
        dict(F_y=5000.0, F_z=500.0),
        dict(F_x=-2000.0, F_y=5000.0, F_z=2000.0, M_y=60.0),
        dict(F_z=2000.0),
        dict(F_y=3000.0, F_z=1000.0, M_x=40.0),
        {},
    ),
    "6208": (dict(F_x=-2000.0, F_y=5000.0, M_y=60.0), dict(F_y=5000.0, F_z=500.0), dict(F_y=3000.0), {}),
}
LOW_SPEEDS_RPM = (0.1, 0.3, 1.0, 3.0, 10.0, 25.0, 79.0, 116.0, 200.0, 537.0, 600.0)


@pytest.mark.parametrize("bearing", sorted(LOADS))
def test_run_up_from_rest_under_load_refuses_no_step(bearing):
    """0 -> 10 000 rpm in 1 s at 1 ms steps from an equilibrium at rest, for each load: every step
    converges (the solver's own tolerance, scene tolerance 1e-10 of the load) and the work stays small."""
    for load in LOADS[bearing]:
        m = QuasiStaticModel(bearing, scene=SCENE)
        m.evaluate(omega=0.0, **load)
        most = 0
        for k in range(1001):
            m.evaluate(omega=10000.0 * RPM * k / 1000, **load)
            most = max(most, m.status[1])
        assert m.status[0] == jones_harris.QS_OK
        assert most <= 60, (load, most)  # bearing evaluations of the worst step (a full cap would be 100+)


@pytest.mark.parametrize("bearing", sorted(LOADS))
def test_low_speed_grid_refuses_no_step(bearing):
    """Every low speed x load, visited in order (warm starts from the previous case, as in a sweep) and
    each again from a cold model: converged, with the applied loads balanced to the scene tolerance."""
    warm = QuasiStaticModel(bearing, scene=SCENE)
    for rpm in LOW_SPEEDS_RPM:
        for load in LOADS[bearing]:
            for m in (warm, QuasiStaticModel(bearing, scene=SCENE)):
                m.evaluate(omega=rpm * RPM, **load)
                applied = np.array([load.get(n, 0.0) for n in ("F_x", "F_y", "F_z", "M_x", "M_y")])
                scale = np.array([1.0, 1.0, 1.0, 0.5 * m.bearing.dm, 0.5 * m.bearing.dm])
                err = np.max(np.abs(applied - m.F) / scale)
                assert err <= SCENE.tolerance * max(1e-3, np.max(np.abs(applied) / scale)) + 1e-12, (rpm, load)


def _free_cases():
    """Bearings with clearance at zero load, at rest and at low and high speed."""
    deep = ref.params_6208(Pd=20e-6, centrifugal=True, gyroscopic=True)
    angular = ref.params_b7214c(centrifugal=True, gyroscopic=True)
    return [("6208 Pd 20 um", deep), ("B7214C", angular)]


@pytest.mark.parametrize("label, p", _free_cases(), ids=[c[0] for c in _free_cases()])
@pytest.mark.parametrize("rpm", [0.0, 1.0, 10000.0])
def test_zero_load_in_clearance_gives_the_centre_whatever_the_history(label, p, rpm):
    """Zero load with clearance: any position inside the clearance balances it. The solver returns the
    twin's documented centre (x = y = 0, no tilt, z = -A sin(alpha0)), bit for bit the same from warm
    starts on either side of the clearance and from a loaded state."""
    p = dict(p, omega=rpm * RPM)
    qs = pack(p)
    centre = ref.solve_loads(np.zeros(5), p)
    assert np.array_equal(centre, ref.zero_load_position(p))
    start = np.array([3e-6, -1e-6, 7e-6, 1e-4, -1e-4])  # the kernel's rule on all five DOFs load-controlled
    A1_0 = jones_harris.qs_geometry(qs, 0.0)[3]
    assert jones_harris._free_ring_start(
        np.zeros(5), np.arange(5), 5, A1_0, start, np.zeros((jones_harris.CS_SIZE, p["Z"]))
    )
    assert np.array_equal(start, ref.zero_load_position(p))
    A = (p["f_i"] + p["f_o"] - 1.0) * p["D"]
    results = []
    for d0 in (None, (0.0, 0.0, 20e-6, 0.0, 0.0), (0.0, 0.0, -0.3 * A, 0.0, 0.0), (5e-6, -3e-6, 0.0, 1e-4, 0.0)):
        status, d, F, *_ = kernel_solve(qs, np.zeros(5), p["omega"], d0=d0)
        assert status == jones_harris.QS_OK
        results.append(d)
    for d in results:
        assert np.array_equal(d, centre)
    # the same through the facade after a load history (the issue's +74 / -74 / 0 um)
    m = QuasiStaticModel("B7214C" if p["angular"] else "6208", scene=SCENE, Pd=p["Pd"])
    seen = []
    # (an angular-contact bearing takes thrust in +z only: its histories differ in size and direction)
    histories = (dict(F_z=1000.0), dict(F_y=2000.0, F_z=3000.0)) if p["angular"] else (dict(F_z=1000.0), dict(F_z=-1e3))
    for history in (*histories, {}):
        m.evaluate(omega=rpm * RPM, **history)
        seen.append(m.evaluate(omega=rpm * RPM)["z"])
    assert seen[0] == seen[1] == seen[2]


def test_low_speed_solution_matches_twin():
    """6208 at 1 rpm under 5 kN + 2 kN + 60 N.m (a case refused before for every ball's tiny centrifugal
    load): displacements equal the twin's (scipy root on the same equations) to 1e-6 relative."""
    p = ref.params_6208(centrifugal=True, gyroscopic=True, omega=1.0 * RPM)
    # 5 kN along the line of ball 1 (+y), 2 kN across it (-x), 60 N.m about the y axis (docs/conventions.md)
    F_applied = (-2000.0, 5000.0, 0.0, 0.0, 60.0)
    status, d, *_ = kernel_solve(pack(p, tol=1e-10), F_applied, p["omega"])
    assert status == jones_harris.QS_OK
    d_ref = ref.solve_loads(F_applied, p)
    scale = np.array([1, 1, 1, p["dm"] / 2, p["dm"] / 2])
    assert np.max(np.abs((d - d_ref) * scale)) <= 1e-6 * np.max(np.abs(d_ref * scale))


@pytest.mark.parametrize("load", [dict(F_z=-100.0), dict(F_x=-2000.0, F_y=5000.0, M_y=60.0)])
def test_reverse_thrust_on_single_angular_contact_bearing_is_refused(load):
    """A single-row angular-contact bearing has its thrust shoulder on one side: a reverse thrust, or a
    radial load and moment without the thrust that keeps every loaded ball on that shoulder, is refused
    with the reason (no result computed on a shoulder that does not exist); the model keeps its state."""
    m = QuasiStaticModel("B7214C", scene=SCENE)
    m.evaluate(F_z=800.0)
    state = m.get_state()
    with pytest.raises(InputError, match="single-row angular-contact bearing.*missing shoulder"):
        m.evaluate(**load)
    assert m.get_state() == state


def test_radial_load_with_a_clearance_of_half_the_groove_matches_the_twin():
    """A clearance of half the groove clearance (P_d = 0.5 A, free angle 41 deg): under a radial load at
    speed the unloaded balls rest on the outer race beyond the inner curvature centre (cos a_i < 0), where
    the cage speed of the race-control kinematics is singular at a_i = pi; their kinematics take the outer
    angle (docs/quasistatic.md). Kernel and twin (scipy root on the same equations) agree to 1e-6 of the
    displacement, as for the ordinary cases above."""
    p = ref.params_6208(centrifugal=True, gyroscopic=True, omega=500.0)
    A = (p["f_i"] + p["f_o"] - 1.0) * p["D"]
    p = ref.params_6208(centrifugal=True, gyroscopic=True, omega=500.0, Pd=0.5 * A)
    F_applied = (0.0, 3000.0, 0.0, 0.0, 0.0)
    status, d, *_ = kernel_solve(pack(p, tol=1e-10), F_applied, p["omega"])
    assert status == jones_harris.QS_OK
    d_ref = ref.solve_loads(F_applied, p)
    scale = np.array([1, 1, 1, p["dm"] / 2, p["dm"] / 2])
    assert np.max(np.abs((d - d_ref) * scale)) <= 1e-6 * np.max(np.abs(d_ref * scale))


@pytest.mark.parametrize("share", [0.3, 0.5, 0.9])
def test_deep_groove_bearing_with_a_large_clearance_converges_under_radial_load(share):
    """The 6208 with P_d = 0.3, 0.5 and 0.9 A (free angles 32-58 deg, far beyond any clearance class) under
    300 N and 3 kN radial at 50-1500 rad/s: converged, finite, the ring centred axially (a symmetric deep
    groove under a radial load) and the cage between rest and the inner ring's speed."""
    b = QuasiStaticModel("6208", scene=SCENE).bearing
    A = (b.f_i + b.f_o - 1.0) * b.D  # m
    for omega in (50.0, 500.0, 1500.0):
        for F_y in (300.0, 3000.0):
            m = QuasiStaticModel("6208", scene=SCENE, Pd=share * A)
            out = m.evaluate(omega=omega, F_y=F_y)
            assert m.status[0] == jones_harris.QS_OK
            assert all(np.all(np.isfinite(np.asarray(v, dtype=float))) for v in out.values())
            assert abs(out["z"]) <= 1e-9 * A
            assert 0.0 < out["omega_cage"] < omega


def test_radial_load_alone_on_a_single_angular_contact_bearing_is_refused_every_time():
    """A free single-row angular-contact bearing under a radial load without thrust slides axially until its
    loaded balls touch the groove bottoms (contact angle 0), where nothing locates it axially and it is
    nearly free to tilt. The solver returns that angle to its rounding (~1e-12 rad, either sign): the case is
    refused every time with the reason (not accepted or refused by the sign of a rounding error), at its own
    and at three times its clearance, from rest to speed; a thrust makes the same radial load computable."""
    for Pd in (None, 3 * 54.09e-6):
        kwargs = {} if Pd is None else dict(Pd=Pd)
        for omega in (0.0, 50.0, 500.0, 1500.0):
            m = QuasiStaticModel("B7214C", scene=SCENE, **kwargs)
            with pytest.raises(InputError, match="groove bottom with nothing to locate it axially"):
                m.evaluate(omega=omega, F_y=3000.0)
            m.evaluate(omega=omega, F_y=3000.0, F_z=1000.0)
            assert m.status[0] == jones_harris.QS_OK


@pytest.mark.parametrize("F_y", [10.0, 30.0, 100.0])
def test_light_radial_load_alone_on_a_single_angular_contact_bearing_is_refused_with_the_reason(F_y):
    """Under a light radial load without thrust the nearly free ring (slide and tilt) can stall the solver
    before it reaches the groove bottom; the refusal still names the physical reason, not the solver's."""
    for omega in (0.0, 1.0, 100.0):
        m = QuasiStaticModel("B7214C", scene=SCENE)
        with pytest.raises(InputError, match="missing shoulder.*groove bottom with nothing to locate it axially"):
            m.evaluate(omega=omega, F_y=F_y)
