"""The DEM's ball-race contact law (kernels.ball_dynamics.contact_law) against its twin
(tests/reference/ref_ball_dynamics_contact_law.py), one contact at a time.

States: random contacts of a 6208-sized ball (D = 11.9 mm, K_h of a steel contact) on the inner race of a tilted,
translating, turning ring and on the fixed outer race, in each regime (boundary, mixed, full film), with the
asperities' spring sticking and slipping (a slipping one also reversed), with and without a film, at approaches
from 0.1 to 10 um; and the open contact. The step's own twin (ref_ball_dynamics_integrator.forces) takes the same
function, so the whole step's comparison (test_ball_dynamics.py) covers it in context; here every output is compared
separately, on states that steps rarely reach.

Tolerance: 1e-12 of each output's scale (the largest force, moment or spring length of the contact), the rounding of
two algebras of the same formulas (the kernel takes 1 - exp instead of expm1 and one division for several); the
outputs that follow the sliding velocity (the normal damper, the spring over a step, the film's traction, the
powers) also 1e-14 of the surface speeds times their slope in it: the sliding is a difference of surface speeds
1e7 times larger where the ball sticks, and carries their rounding (1e-16 of them) in both algebras.
"""

import math

import numpy as np
import pytest

from bearing_fmu.kernels.ball_dynamics import contact_law as ck
from bearing_fmu.kernels.ehl import REGIME_BOUNDARY, REGIME_FULL_FILM, REGIME_MIXED
from tests.reference import ref_ball_dynamics_contact_law as ref

D = 0.0119  # m
K_H = 9.0e9  # N/m^1.5, a steel ball on a steel groove (the 6208's inner contact)
DT = 2.0e-6  # s
M_BALL, I_BALL = 6.9e-3, 9.8e-8  # kg, kg.m^2
RHO = 0.0245  # m, radius of the groove-curvature-centre circle
RG = 0.0003  # m, (f - 1/2) D


def _state(rng, race, regime, phi, spring_scale):
    """One random contact: (kernel arguments, twin arguments)."""
    axis = np.array([rng.normal(0, 1e-3), rng.normal(0, 1e-3), 1.0]) if race == 0 else np.array([0.0, 0.0, 1.0])
    axis /= np.linalg.norm(axis)
    centre = np.array([rng.normal(0, 1e-5), rng.normal(0, 1e-5), rng.normal(0, 1e-5)]) if race == 0 else np.zeros(3)
    psi = rng.uniform(0, 2 * math.pi)
    e = np.array([math.cos(psi), math.sin(psi), 0.0])
    e -= np.dot(e, axis) * axis  # in the circle's plane: its nearest point to the ball is centre + RHO e
    e /= np.linalg.norm(e)
    sign = 1.0 if race == 0 else -1.0  # the ball lies outside the inner circle, inside the outer one
    delta_target = 10 ** rng.uniform(-7, -5)
    angle = rng.uniform(-0.5, 0.5)
    n = sign * math.cos(angle) * e + math.sin(angle) * axis
    p = centre + RHO * e + (RG + delta_target) * n
    omega = 1000.0 if race == 0 else 0.0
    v = rng.normal(0, 0.05, 3)
    w = rng.normal(0, 50.0, 3) + np.array([0.0, 0.0, -2000.0])
    w_orbit = 400.0 + rng.normal(0, 5.0)
    old = rng.normal(0, spring_scale, 3)
    v_ring, tilt = rng.normal(0, 0.01, 3), rng.normal(0, 0.5, 2)
    W = omega * axis + np.array([tilt[0], tilt[1], 0.0])
    if spring_scale < 1e-6:  # a sticking contact: the ball turns with the race, its surface slides by um/s at most
        w = W + rng.normal(0, 1e-4, 3)
        v = (v_ring + np.cross(W, p - centre) if race == 0 else np.zeros(3)) + rng.normal(0, 1e-7, 3)
    trib = (0.1 * rng.uniform(0.5, 1.5), phi, 1.0 / rng.uniform(0.01, 0.5), regime, rng.uniform(1e2, 1e4),
            rng.uniform(0.01, 1.0), rng.uniform(1e-5, 1e-3))  # fmt: skip
    law = dict(K_h=K_H, D=D, alpha_e=rng.uniform(0.05, 0.2), kt_ratio=2.0 / 3.0, mu_lim=0.06,
               kappa=7.0 * DT / M_BALL, w_reg=1e-3 / (0.5 * D), rate=I_BALL / (4.0 * DT))  # fmt: skip
    geometry = ck.groove_approach(*p, *centre, *axis, RHO, RG)
    mu, phi_, slip, regime_, c_frozen, f_roll, m_s = trib
    frame = (omega, *v_ring, *centre, K_H, *axis, *tilt)
    steps = (0.5 * D, law["alpha_e"], law["kt_ratio"], 4.0 * DT / I_BALL, law["w_reg"], DT)
    kernel = (race, geometry, (tuple(p), tuple(v), tuple(w), w_orbit), tuple(old), (mu, regime_, c_frozen, f_roll, m_s),
              (phi_, slip, law["mu_lim"], law["kappa"]), frame, steps)  # fmt: skip
    twin = (race, p, v, w, w_orbit, old, trib, (W, v_ring, centre), law, DT)
    # the surface speeds whose difference is the sliding: their rounding (1e-16 of them) bounds the sliding's
    speed = np.linalg.norm(W) * (RHO + D) + np.linalg.norm(w) * 0.5 * D + np.linalg.norm(v) + np.linalg.norm(v_ring)
    return kernel, twin, (p, centre, axis, speed)


CASES = [
    (race, regime, phi, spring)
    for race in (0, 1)
    for regime, phi in ((REGIME_BOUNDARY, 0.0), (REGIME_MIXED, 0.5), (REGIME_FULL_FILM, 1.0))
    for spring in (1e-9, 1e-5)  # sticking, slipping
]


@pytest.mark.parametrize("race, regime, phi, spring", CASES)
def test_the_contact_law_equals_its_twin(race, regime, phi, spring):
    """Every output of ball_race_contact against the twin, 25 random contacts per case (module docstring)."""
    rng = np.random.default_rng(hash((race, regime, phi, spring)) % 2**32)
    slipped = reversed_seen = 0
    for _ in range(25):
        kernel, twin, (p, centre, axis, speed) = _state(rng, race, regime, phi, spring)
        delta, nx, ny, nz = kernel[1]
        delta_t, *n_t = ref.groove_approach(*p, *centre, *axis, RHO, RG)
        assert delta == pytest.approx(delta_t, abs=1e-15) and delta > 0.0  # 1e-15 m: rounding of |s| ~ 0.3 mm
        assert np.array([nx, ny, nz]) == pytest.approx(np.array(n_t), abs=1e-12)
        out = ck.ball_race_contact(*kernel)
        # the law on the kernel's geometry (compared just above): the approach, a difference of two lengths 1e3-1e4
        # times larger, carries their rounding
        c = ref.ball_race_contact(twin[0], delta, np.array([nx, ny, nz]), *twin[1:])
        # the forces that follow the sliding (damper, spring over a step, film traction) carry the sliding's rounding
        Q = K_H * delta**1.5
        law, trib = twin[8], twin[6]
        slope = max(trib[4], 1.5 * law["alpha_e"] * Q) + law["kt_ratio"] * K_H * math.sqrt(delta) * DT
        slope += law["mu_lim"] * 2.0 * Q * trib[2]
        sliding = 1e-14 * speed * slope  # N
        force = 1e-12 * np.abs(c["force"]).max() + sliding
        moment = 1e-12 * np.abs(c["moment"]).max() + 0.5 * D * sliding
        assert out[0] == delta
        assert np.array(out[1:4]) == pytest.approx(c["force"], abs=force)
        assert np.array(out[4:7]) == pytest.approx(c["moment"], abs=moment)
        # the spring adds the sliding times dt: its rounding is that of the surface speeds, not of the spring
        length = 1e-12 * np.abs(c["spring"]).max() + 1e-14 * speed * DT
        assert np.array(out[7:10]) == pytest.approx(c["spring"], abs=length)
        assert (out[10], out[11]) == (c["slipping"], c["reversed"])
        assert out[12] == pytest.approx(c["power"], abs=force * speed)
        assert np.array(out[13:16]) == pytest.approx(c["dissipating"], abs=force)
        assert np.array(out[16:19]) == pytest.approx(c["r_c"], abs=1e-15)
        slipped += c["slipping"]
        reversed_seen += c["reversed"]
    if phi < 1.0:  # the cases reach the states they are for
        if spring > 1e-6:
            assert slipped >= 20 and reversed_seen > 0, (slipped, reversed_seen)
        else:
            assert slipped <= 5, slipped


def test_an_open_contact_gives_nothing_and_resets_its_spring():
    """A ball 1 um off the race: every force, moment, spring and power 0, in the kernel and the twin."""
    kernel, twin, _ = _state(np.random.default_rng(1), 1, REGIME_BOUNDARY, 0.0, 1e-6)
    n = np.array(kernel[1][1:])
    kernel = (kernel[0], (-1e-6, *n), *kernel[2:])
    out = ck.ball_race_contact(*kernel)
    c = ref.ball_race_contact(1, -1e-6, n, *twin[1:])
    assert out[0] == -1e-6 and not any(out[1:10]) and not out[10] and not out[11] and not any(out[12:])
    assert c["power"] == 0.0 and not c["force"].any() and not c["spring"].any()


@pytest.mark.parametrize("regime", [REGIME_BOUNDARY, REGIME_MIXED])
def test_contact_damping_and_the_spring_equal_their_twins(regime):
    """contact_damping in both laws and tangential_spring sticking and slipping, to rounding."""
    assert ck.contact_damping(regime, 123.0, 0.1, 500.0) == ref.contact_damping(regime, 123.0, 0.1, 500.0)
    n = np.array([0.6, 0.0, 0.8])
    for old, cap in ((np.array([1e-7, 2e-7, -3e-7]), 10.0), (np.array([1e-5, -2e-5, 0.0]), 0.5)):
        sx, sy, sz, fx, fy, fz, slipping, reversed_ = ck.tangential_spring(*old, *n, 0.1, -0.2, 0.05, DT, 1e7, cap)
        xi, f, slipping_t, reversed_t = ref.tangential_spring(old, n, np.array([0.1, -0.2, 0.05]), DT, 1e7, cap)
        assert np.array([sx, sy, sz]) == pytest.approx(xi, abs=1e-12 * np.abs(xi).max())
        assert np.array([fx, fy, fz]) == pytest.approx(f, abs=1e-12 * np.abs(f).max())
        assert (slipping, reversed_) == (slipping_t, reversed_t)
