"""ShaftTransient (spindle/shaft/transient.py): the shaft's time-domain mode against its modal model.

Checks against ShaftModel.evaluate, which solves the same equations as an eigenproblem:
- free vibration on linear seats (inside the model, and as a bearing coupled through the seat forces, one step
  late) oscillates at the modal frequency: the average-acceleration scheme lengthens a period by (w h)^2 / 12,
  1.3e-3 at 50 steps per period (measured 1.31e-3; the held forces' lag is of second order too: 6.7e-4 at 0.5 of
  the estimated step), asserted within 0.5 %;
- without damping the trapezoidal rule conserves the energy of a linear system exactly: to rounding (measured
  1.4e-13 per step), asserted 1e-9 per step, with and without the gyroscopic term (skew: it does no work);
- a step of 100 of the model's shortest periods stays bounded (unconditional stability);
- under a constant tool-tip force the motion settles on the static compliance (the same linear solve, 1e-6 after the
  damped transient has decayed by more than e^-20);
- bearings whose forces are held over a step decay below the estimated stable step 2 c / k and grow at 4 times it;
  bearings that pass their K with their forces are followed as if their K were inside the model (to rounding, 1e-9
  of the amplitude) at 20 steps per period without damping;
- the seat forces enter in the bearing's frame and sign: a linear bearing's output K d gives the shaft the same
  force as the seat stiffness of the modal model, to rounding;
- with Newmark's gamma above 1/2 each undamped mode of the model at rest follows the scalar oscillator's Newmark map
  (the scheme is linear and the modes decouple: to rounding, 1e-9 of the amplitude), and that map's spectral radius
  tends to Hughes' closed form (3/2 - gamma) / (gamma + 1/2) as omega h grows (T. J. R. Hughes, The Finite Element
  Method, 1987, section 9.1; at omega h = 1e4 measured within 2.4e-8 of it, asserted 1e-6: the limit is approached
  as 1 / (omega h)^2, 2.4e-6 at omega h = 1e3).
"""

import math

import numpy as np
import pytest
import scipy.linalg

from bearing_fmu.build import SCENES_DIR
from bearing_fmu.models.quasi_static import QuasiStaticModel
from bearing_fmu.scene import Scene
from spindle.shaft import ShaftInputError, ShaftModel
from spindle.shaft.declarations import K_START
from spindle.shaft.transient import ShaftTransient
from tests.cases import shaft_beams as sb

OMEGA = 20000.0 * math.pi / 30.0
K_BEARING = np.array([K_START, K_START])  # a B7214C's K in its own frame; the default shaft's front seat faces -z
K_SYMMETRIC = np.array([sb.seat_matrix(2e8, 5e7, 1e5)] * 2)
# a light damping on every seat dof: it holds the modes a bearing coupled one step late would excite (docs/shaft.md)
C_LIGHT = np.array([np.diag([200.0, 200.0, 200.0, 0.02, 0.02])] * 2)


@pytest.fixture(scope="module")
def model():
    return ShaftModel()


def first_mode(model, K_seats):
    """(frequency in Hz, real shape) of the lowest mode of the undamped model at rest with the seats K_seats."""
    K, _ = model.matrices(K_seats)
    w2, V = np.linalg.eig(model._Minv @ K)
    r = int(np.argmin(np.where(w2.real > 0.0, w2.real, np.inf)))
    return math.sqrt(w2[r].real) / (2.0 * math.pi), V[:, r].real / np.max(np.abs(V[:, r].real))


def zero_crossing_frequency(t, x):
    """Frequency (Hz) from the zero crossings of x(t), linearly interpolated between samples."""
    i = np.nonzero(np.sign(x[:-1]) * np.sign(x[1:]) < 0.0)[0]
    times = t[i] - x[i] * (t[i + 1] - t[i]) / (x[i + 1] - x[i])
    return 0.5 * (times.size - 1) / (times[-1] - times[0])


def no_seat_forces(model):
    return np.zeros((len(model.shaft.seat_nodes), 5))


def test_free_vibration_on_seat_springs_has_the_modal_frequency(model):
    f1, shape = first_mode(model, K_BEARING)
    assert f1 == pytest.approx(model.evaluate(0.0, K_BEARING)["frequencies"][0], rel=1e-9)
    transient = ShaftTransient(model, 0.0, K_seats=K_BEARING)
    transient.set_state(1e-6 * shape, np.zeros_like(shape))
    h, zero = 1.0 / (50.0 * f1), no_seat_forces(model)
    k = model._tip + int(np.argmax(np.abs(shape[model._tip : model._tip + 2])))  # the tip's x or y: the mode's plane
    x = [transient.q[k]] + [transient.step(h, zero, zero)["tip_displacement"][k - model._tip] for _ in range(1000)]
    assert zero_crossing_frequency(h * np.arange(1001), np.array(x)) == pytest.approx(f1, rel=5e-3)


@pytest.mark.parametrize("omega", [0.0, OMEGA])
def test_energy_is_conserved_without_damping(model, omega):
    transient = ShaftTransient(model, omega, K_seats=K_SYMMETRIC)
    rng = np.random.default_rng(1)
    transient.set_state(1e-6 * rng.standard_normal(model.n_dofs), 1e-3 * rng.standard_normal(model.n_dofs))
    f1, _ = first_mode(model, K_SYMMETRIC)
    zero, energy = no_seat_forces(model), [transient.energy()]
    for _ in range(200):
        transient.step(1.0 / (20.0 * f1), zero, zero)
        energy.append(transient.energy())
    assert np.max(np.abs(np.diff(energy))) <= 1e-9 * energy[0]


def test_a_step_of_a_hundred_shortest_periods_stays_bounded(model):
    K, _ = model.matrices(K_SYMMETRIC)
    shortest = 2.0 * math.pi / math.sqrt(np.max(np.linalg.eigvals(model._Minv @ K).real))
    transient = ShaftTransient(model, 0.0, K_seats=K_SYMMETRIC, substeps=3)
    rng = np.random.default_rng(2)
    transient.set_state(1e-6 * rng.standard_normal(model.n_dofs), 1e-3 * rng.standard_normal(model.n_dofs))
    e0, zero = transient.energy(), no_seat_forces(model)
    for _ in range(300):
        transient.step(300.0 * shortest, zero, zero)  # 3 substeps of 100 shortest periods
        assert transient.energy() == pytest.approx(e0, rel=1e-6)


def scalar_newmark_step(w, h, gamma, q, v):
    """One step of Newmark's scheme (beta = (gamma + 1/2)^2 / 4) on q'' = -w^2 q, written out for a scalar."""
    beta = 0.25 * (gamma + 0.5) ** 2
    a = -w * w * q
    q_star, v_star = q + h * v + (0.5 - beta) * h * h * a, v + (1.0 - gamma) * h * a
    a_new = -w * w * q_star / (1.0 + beta * h * h * w * w)
    return q_star + beta * h * h * a_new, v_star + gamma * h * a_new


@pytest.mark.parametrize("gamma", [0.55, 0.6, 0.8])
def test_damping_newmark_moves_each_mode_as_the_scalar_scheme(model, gamma):
    K, _ = model.matrices(K_SYMMETRIC)
    w2, V = scipy.linalg.eigh(K, model._M)  # mass-normalised: V.T M V = I
    h = 1.0 / (20.0 * math.sqrt(w2[6]) / (2.0 * math.pi))  # the seventh mode resolved, the highest ones not
    for r in (6, len(w2) // 2, len(w2) - 1):
        transient = ShaftTransient(model, 0.0, K_seats=K_SYMMETRIC, gamma=gamma)
        transient.set_state(V[:, r], np.zeros(model.n_dofs))
        zero = no_seat_forces(model)
        expected = (1.0, 0.0)
        for _ in range(3):
            transient.step(h, zero, zero)
            expected = scalar_newmark_step(math.sqrt(w2[r]), h, gamma, *expected)
        assert V[:, r] @ model._M @ transient.q == pytest.approx(expected[0], abs=1e-9)
        assert h * (V[:, r] @ model._M @ transient.v) == pytest.approx(h * expected[1], abs=1e-9)


@pytest.mark.parametrize("gamma", [0.5, 0.6, 0.8, 1.0])
def test_the_scalar_map_damps_unresolved_modes_as_hughes_states(gamma):
    w, h = 1.0e4, 1.0  # the map on (q, v / w), so that both columns are of order 1
    (q1, v1), (q2, v2) = scalar_newmark_step(w, h, gamma, 1.0, 0.0), scalar_newmark_step(w, h, gamma, 0.0, w)
    radius = max(abs(np.linalg.eigvals(np.array([[q1, q2], [v1 / w, v2 / w]]))))
    assert radius == pytest.approx((1.5 - gamma) / (gamma + 0.5), abs=1e-6)


def settle(transient, force, f1, periods=200):
    """Ramp the tool-tip force from 0 to `force` over 20 periods of the first mode, then hold it; the end state."""
    h, zero = 1.0 / (20.0 * f1), no_seat_forces(transient.model)
    ramp = 400
    for i in range(ramp):
        transient.step(h, zero, zero, external_tip_force=force * (i + 0.5) / ramp)
    for _ in range(periods * 20):
        transient.step(h, zero, zero, external_tip_force=force)
    return transient.outputs()


@pytest.mark.parametrize("omega", [0.0, OMEGA])
@pytest.mark.parametrize("k, output", [(0, "compliance_radial"), (2, "compliance_axial")])
def test_a_constant_tip_force_settles_on_the_static_compliance(model, omega, k, output):
    out = model.evaluate(omega, K_BEARING, C_LIGHT, critical_speeds=False)
    f1, _ = first_mode(model, K_BEARING)
    transient = ShaftTransient(model, omega, K_seats=K_BEARING, C_seats=C_LIGHT * 50.0)
    force = np.zeros(5)
    force[k] = 100.0
    tip = settle(transient, force, f1)["tip_displacement"]
    assert tip[k] == pytest.approx(100.0 * out[output], rel=1e-6)


def coupled_bearings(transient, h, steps, tip_force=None, jacobian=False):
    """Run the shaft with linear bearings of stiffness K_BEARING coupled through the seat forces: each bearing
    outputs K d of the seat displacement at the start of a step (its own frame, as a displacement-driven bearing
    FMU), held over the step, and with jacobian its K too. Returns the tool tip's displacements (steps + 1, 5)."""
    tips = [transient.outputs()["tip_displacement"]]
    for _ in range(steps):
        F = np.einsum("sij,sj->si", K_BEARING, transient.outputs()["seat_displacement"])
        K = K_BEARING if jacobian else None
        tips.append(transient.step(h, F, F, external_tip_force=tip_force, seat_stiffness=K)["tip_displacement"])
    return np.array(tips)


def test_bearings_with_held_forces_give_the_modal_frequency_below_the_estimated_step(model):
    C = C_LIGHT * 10.0
    f1 = model.evaluate(0.0, K_BEARING, C, critical_speeds=False)["frequencies"][0]
    _, shape = first_mode(model, K_BEARING)
    transient = ShaftTransient(model, 0.0, C_seats=C)
    h_max = transient.held_force_step(K_BEARING, C)
    assert h_max == pytest.approx(2.0 * 0.2 / K_START[4][4], rel=1e-12)  # theta_y: the smallest 2 c / k
    transient.set_state(1e-6 * shape, np.zeros_like(shape))
    k = int(np.argmax(np.abs(shape[model._tip : model._tip + 2])))
    tips = coupled_bearings(transient, 0.5 * h_max, 3000)
    assert zero_crossing_frequency(0.5 * h_max * np.arange(3001), tips[:, k]) == pytest.approx(f1, rel=5e-3)
    assert np.max(np.abs(tips[-300:])) < 0.2 * np.max(np.abs(tips[:300]))  # decays (5.4 periods at zeta 0.08: 0.07)
    transient.set_state(1e-6 * shape, np.zeros_like(shape))
    # the estimate is a mass on a spring: the seat's tilt on the flexible shaft starts growing at 2.5 to 3 times it
    tips = coupled_bearings(transient, 4.0 * h_max, 2000)
    assert np.max(np.abs(tips[-100:])) > 1e2 * np.max(np.abs(tips[:100]))


def test_bearings_with_held_forces_settle_on_the_static_compliance(model):
    out = model.evaluate(0.0, K_BEARING, critical_speeds=False)
    f1 = model.evaluate(0.0, K_BEARING, C_LIGHT, critical_speeds=False)["frequencies"][0]
    transient = ShaftTransient(model, 0.0, C_seats=C_LIGHT * 50.0)
    assert 1.0 / (100.0 * f1) < transient.held_force_step(K_BEARING, C_LIGHT * 50.0)
    tips = coupled_bearings(transient, 1.0 / (100.0 * f1), 6000, np.array([100.0, 0.0, 0.0, 0.0, 0.0]))
    assert tips[-1, 0] == pytest.approx(100.0 * out["compliance_radial"], rel=1e-6)


@pytest.mark.parametrize("omega", [0.0, OMEGA])
def test_bearings_passing_their_stiffness_are_followed_without_lag(model, omega):
    """With the bearings' K passed, the shaft integrates each linear bearing exactly: the same motion as with K inside
    the model, at a step of a twentieth of the first period and without damping (held forces alone grow there)."""
    f1, shape = first_mode(model, K_BEARING)
    inside, coupled = ShaftTransient(model, omega, K_seats=K_BEARING), ShaftTransient(model, omega)
    for transient in (inside, coupled):
        transient.set_state(1e-6 * shape, np.zeros_like(shape))
    h, zero = 1.0 / (20.0 * f1), no_seat_forces(model)
    expected = np.array(
        [inside.outputs()["tip_displacement"]] + [inside.step(h, zero, zero)["tip_displacement"] for _ in range(400)]
    )
    tips = coupled_bearings(coupled, h, 400, jacobian=True)
    assert tips == pytest.approx(expected, rel=0.0, abs=1e-9 * np.max(np.abs(expected)))


def test_seat_forces_enter_in_the_bearings_frame_and_sign(model):
    """A linear bearing outputs K d (the load holding its inner ring at d, in its frame); the shaft receives
    -T K T q at the seat, the force of the modal model's seat stiffness (seat_frame: a mirrored front seat)."""
    assert model.shaft.seat_axes == (-1, 1)
    transient = ShaftTransient(model, 0.0)
    rng = np.random.default_rng(3)
    transient.set_state(rng.standard_normal(model.n_dofs), rng.standard_normal(model.n_dofs))
    values = rng.standard_normal((2, 5))
    assert np.array_equal(transient.to_bearing(transient.to_shaft(values)), values)
    assert np.array_equal(transient.to_shaft(values)[0], values[0] * [1, 1, -1, -1, -1])
    d = transient.outputs()["seat_displacement"]
    f = transient.load_vector(np.einsum("sij,sj->si", K_BEARING, d))
    K_with_seats, _ = model.matrices(K_BEARING)
    assert f == pytest.approx(-(K_with_seats - model._K) @ transient.q, rel=1e-12, abs=1e-9 * np.max(np.abs(f)))


def test_substeps_follow_the_seat_forces_linearly(model):
    """Four substeps of a step whose seat forces go from F0 to F1 are four steps of a quarter with the forces in
    between (to rounding: the acceleration at a step's start is recomputed from its forces, not carried)."""
    rng = np.random.default_rng(5)
    F0, F1 = 100.0 * rng.standard_normal((2, 2, 5))
    split, single = (
        ShaftTransient(model, OMEGA, K_seats=K_BEARING, substeps=4),
        ShaftTransient(model, OMEGA, K_seats=K_BEARING),
    )
    h = 2e-4
    end = split.step(h, F0, F1)
    for i in range(4):
        single.step(h / 4, F0 + (F1 - F0) * i / 4, F0 + (F1 - F0) * (i + 1) / 4)
    assert end["seat_displacement"] == pytest.approx(single.outputs()["seat_displacement"], rel=1e-9, abs=1e-20)
    assert np.max(np.abs(end["seat_displacement"])) > 1e-9  # the forces moved the seats
    assert split.time == pytest.approx(single.time, rel=1e-15)


def test_a_displacement_driven_bearing_pushes_the_seat_back(model):
    """The quasi-static B7214C driven by displacement (BearingDisp.fmu's scene) outputs the load holding its inner
    ring, K d: at the rear seat (bearing along +z) displaced by +20 um in y the shaft receives the reverse, a force
    toward -y of the bearing's F_y."""
    bearing = QuasiStaticModel(scene=Scene.from_toml(SCENES_DIR / "quasi_static_displacement.toml"))
    transient = ShaftTransient(model, 0.0)
    q = np.zeros(model.n_dofs)
    q[model._seat_dofs[1, 1]] = 20e-6
    transient.set_state(q, np.zeros_like(q))
    d = transient.outputs()["seat_displacement"]
    F = np.zeros((2, 5))
    out = bearing.evaluate(omega=0.0, **dict(zip(("x", "y", "z", "theta_x", "theta_y"), d[1], strict=True)))
    F[1] = [out[name] for name in ("F_x", "F_y", "F_z", "M_x", "M_y")]
    assert F[1, 1] > 1000.0  # the load holding the ring at +y is along +y
    f = transient.load_vector(F)
    assert f[model._seat_dofs[1, 1]] == -F[1, 1]


def test_bad_inputs_are_refused_with_their_name_and_range(model):
    transient = ShaftTransient(model, 0.0)
    zero = no_seat_forces(model)
    bad = zero.copy()
    bad[1, 2] = math.nan
    with pytest.raises(ShaftInputError, match=r"seat_forces_end\[1\]\[2\] = nan .*\[-1e\+07, 1e\+07\].*rear_bearing"):
        transient.step(1e-4, zero, bad)
    with pytest.raises(ShaftInputError, match=r"h = 0.0 s is outside the allowed range \(0, 1\]"):
        transient.step(0.0, zero, zero)
    with pytest.raises(ShaftInputError, match=r"seat_forces_start: shape \(5,\), expected \(2, 5\)"):
        transient.step(1e-4, zero[0], zero)
    with pytest.raises(ShaftInputError, match=r"external_tip_force\[0\] = inf"):
        transient.step(1e-4, zero, zero, external_tip_force=[math.inf, 0, 0, 0, 0])
    with pytest.raises(ShaftInputError, match=r"substeps = 0 is outside the allowed range \[1, 100000\]"):
        ShaftTransient(model, 0.0, substeps=0)
    with pytest.raises(ShaftInputError, match=r"gamma = 0.4 is outside the allowed range \[0.5, 1.0\]"):
        ShaftTransient(model, 0.0, gamma=0.4)
    with pytest.raises(ShaftInputError, match=r"omega = -1.0 rad/s"):
        ShaftTransient(model, -1.0)
    with pytest.raises(
        ShaftInputError, match=r"seat_stiffness\[0\]\[2,2\] = -1.0 is outside the allowed range \[0, 1e\+13\]"
    ):
        transient.step(1e-4, zero, zero, seat_stiffness=np.where(np.arange(50).reshape(2, 5, 5) == 12, -1.0, 0.0))
    with pytest.raises(ShaftInputError, match=r"v: shape \(3,\), expected \(27,\) finite values"):
        transient.set_state(np.zeros(model.n_dofs), np.zeros(3))
    assert transient.time == 0.0 and not np.any(transient.q)  # a refused step leaves the state
    assert transient.held_force_step(K_BEARING, None) == 0.0  # held forces without damping: no stable step


def test_a_new_speed_acts_as_a_model_built_at_it(model):
    rng = np.random.default_rng(4)
    q, v = 1e-6 * rng.standard_normal(model.n_dofs), 1e-3 * rng.standard_normal(model.n_dofs)
    changed, built = ShaftTransient(model, 0.0, K_seats=K_SYMMETRIC), ShaftTransient(model, OMEGA, K_seats=K_SYMMETRIC)
    zero = no_seat_forces(model)
    changed.step(1e-4, zero, zero)  # the solver of the old speed is kept, then dropped by set_speed
    changed.set_speed(OMEGA)
    for transient in (changed, built):
        transient.set_state(q, v)
    assert np.array_equal(
        changed.step(1e-4, zero, zero)["tip_displacement"], built.step(1e-4, zero, zero)["tip_displacement"]
    )
