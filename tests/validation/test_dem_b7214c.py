"""The DEM fidelity on the spindle bearing B7214C of Rabreau et al. (2018): 10 000 rpm, 800 N axial preload,
iso_vg68_mineral at 313 K. The internal geometry is estimated (bearing file), so are its cage balls (1.0 mm
radius, sharing the estimated 14 g of the cage: the default time step is 4.8 us at speed).

The DEM imposes no race-control law: the balls' spin axes follow from the contact friction and inertia.
Against the three quasi-static hypotheses (Rabreau 2018; Harris & Kotzalas 2006 vol. 2): with the default
tangential law (the film's EHL traction curve) the DEM is outer-race controlled. With the papers' Coulomb
spring at mu(Lambda) = 0.01 in full film (traction_limit = 0.01) the balls need ~0.4 s to reach rolling speed;
after it every ball slides at both races (the friction cannot hold the gyroscopic moment) and the contact angles
swing (alpha_i 23.0-24.4 deg, alpha_o 7.9-10.4 deg) with an ~800 Hz axial motion of the ring (+-7.4 um) and the
balls that the sliding Coulomb contacts do not damp; its mean angles are 23.6 deg and 9.3 deg (docs/dem.md).
"""

import math

import numpy as np
import pytest

from bearing_fmu.kernels.ball_dynamics import state as s
from bearing_fmu.models.dem import DemModel
from bearing_fmu.models.quasi_static import QuasiStaticModel
from bearing_fmu.scene import Scene

OMEGA = 10000.0 * 2.0 * math.pi / 60.0
F_AXIAL = 800.0


PAPERS_LAW = 0.01  # traction_limit of the papers' mu(Lambda): a Coulomb spring capped at 0.01 F_n in a full film


@pytest.fixture(scope="module")
def rolling():
    """With the papers' law, the state after 0.5 s: 10 ms speed ramp, then the balls' slow acceleration to rolling
    speed."""
    model = DemModel("B7214C", "iso_vg68_mineral", traction_limit=PAPERS_LAW)
    model.advance(2e-3, omega=0.0, F_z=F_AXIAL)
    for k in range(1, 21):
        model.advance(2e-3 + 10e-3 * k / 20, omega=OMEGA * k / 20, F_z=F_AXIAL)
    model.advance(0.5, omega=OMEGA, F_z=F_AXIAL)
    return model.get_state()


@pytest.fixture(scope="module")
def steady(rolling):
    model = DemModel("B7214C", "iso_vg68_mineral", traction_limit=PAPERS_LAW)
    model.set_state(rolling)
    samples = [model.advance(0.5 + 0.02 * k, omega=OMEGA, F_z=F_AXIAL) for k in range(1, 6)]
    return {key: float(np.mean([o[key] for o in samples])) for key in samples[0]}


def _ring_motion(model, duration, samples=400):
    """(half the peak-to-peak axial inner-ring displacement (m), largest tilt (rad)) over the last half of
    `duration` (s)."""
    t0 = model.time
    z, tilt = [], []
    for k in range(1, samples + 1):
        model.advance(t0 + duration * k / samples, omega=OMEGA, F_z=F_AXIAL)
        z.append(model.ring[s.R_X + 2])
        tilt.append(math.hypot(model.ring[s.R_TH], model.ring[s.R_TH + 1]))
    tail = z[samples // 2 :]
    return 0.5 * (max(tail) - min(tail)), max(tilt[samples // 2 :])


def test_papers_law_oscillation_comes_with_sliding_at_both_contacts(rolling):
    """With mu = 0.01 (full film) every ball slides at both races, each tangential force at its Coulomb limit (the
    gyroscopic moment of outer-race control exceeds what the friction can hold), and a sliding Coulomb force does
    not grow with the sliding speed, so it does not damp the ring's motion: the ~800 Hz axial oscillation of ring
    and balls of docs/dem.md, 7.38 um half peak-to-peak over 0.51-0.52 s (7.2-7.4 um whatever dt, refresh, k_t
    ratio, cage damping, hysteresis and v_reg). The ring's support (across the axis only) leaves it axial: the
    tilts stay at round-off (measured 3e-15 rad); without the support the same motion goes into a 1.0 mrad wobble
    of the free ring (docs/dem.md, Ring support). Asserted: more than 5 um axial, below 1 urad of tilt."""
    model = DemModel("B7214C", "iso_vg68_mineral", traction_limit=PAPERS_LAW)
    model.set_state(rolling)
    contacts = model.contacts()
    for race, suffix in ((0, "_inner"), (1, "_outer")):
        k_t = model.par[s.P_KT_RATIO] * model.par[s.P_KH_I + race] * np.sqrt(contacts["delta" + suffix])
        force = k_t * np.linalg.norm(model.spring[3 * race : 3 * race + 3], axis=0)
        # at the limit mu F_n; F_n = Q + C_n v_n differs from the elastic Q by the damping (< 0.1 %)
        assert force == pytest.approx(model.trib[s.T_MU, race] * contacts["Q" + suffix], rel=1e-3)
    axial, tilt = _ring_motion(model, 0.02)
    assert axial > 5e-6 and tilt < 1e-6


@pytest.fixture(scope="module")
def hypotheses():
    scene = Scene(name="qs", fidelity="quasi_static", gyroscopic=True, torque=True)
    return {
        rc: QuasiStaticModel("B7214C", "iso_vg68_mineral", scene=scene, race_control=rc).evaluate(
            omega=OMEGA, F_z=F_AXIAL
        )
        for rc in ("outer", "hybrid", "inner")
    }


def test_papers_law_runs_stably_and_rolls_close_to_outer_race_control(steady, hypotheses):
    """The papers' law: 0.6 s at the default time step without a monitor stop; cage speed within 1 % of outer-race
    control (measured +0.6 %), friction torque from the contact power within 15 % of its Houpert torque (measured
    +1.7 %); the contact angles lie between the outer- and the inner-race-control angles (3 % margin), as
    expected of a spin axis that no race-control law imposes."""
    orc, irc = hypotheses["outer"], hypotheses["inner"]
    print(
        f"B7214C DEM: cage {steady['omega_cage']:.2f} rad/s, torque {steady['torque']:.4f} N.m, alpha_i "
        f"{math.degrees(steady['alpha_inner']):.2f} deg, alpha_o {math.degrees(steady['alpha_outer']):.2f} deg; "
        + "; ".join(
            f"{rc}: cage {r['omega_cage']:.2f}, torque {r['torque']:.4f}, "
            f"alpha_i {math.degrees(r['alpha_inner']):.2f}, alpha_o {math.degrees(r['alpha_outer']):.2f}"
            for rc, r in hypotheses.items()
        )
    )
    assert steady["omega_cage"] == pytest.approx(orc["omega_cage"], rel=0.01)
    assert steady["torque"] == pytest.approx(orc["torque"], rel=0.15)
    for name in ("alpha_inner", "alpha_outer"):
        low, high = sorted((orc[name], irc[name]))
        assert 0.97 * low <= steady[name] <= 1.03 * high


def _check_outer_race_control(model, n_samples, hypotheses, torque_rel):
    """Run the model up to 10 000 rpm (10 ms ramp) and 0.3 s at speed, then n_samples 10 ms averages; assert
    outer-race control with the gyroscopic moment: cage within 1 %, both contact angles within 3 % (the acceptance of
    the DEM fidelity against the closest quasi-static hypothesis), torque within torque_rel, alpha_o within 0.5 deg
    over the samples (no 800 Hz swing), and the cage slip, against pure rolling at the operating contacts and spin
    axes, below 0.5 % as the cage speed is (against the free angle's kinematics it read -3.9 %)."""
    model.advance(2e-3, omega=0.0, F_z=F_AXIAL)
    for k in range(1, 21):
        model.advance(2e-3 + 10e-3 * k / 20, omega=OMEGA * k / 20, F_z=F_AXIAL)
    model.advance(0.3, omega=OMEGA, F_z=F_AXIAL)
    samples = [model.advance(0.3 + 0.01 * k, omega=OMEGA, F_z=F_AXIAL) for k in range(1, n_samples + 1)]
    mean = {
        key: float(np.mean([o[key] for o in samples])) for key in ("omega_cage", "torque", "alpha_inner", "alpha_outer")
    }
    orc = hypotheses["outer"]
    print(
        f"B7214C DEM, traction_limit {model.settings['traction_limit']}: cage {mean['omega_cage']:.2f} rad/s, torque "
        f"{mean['torque']:.4f} N.m, alpha_i {math.degrees(mean['alpha_inner']):.2f} deg, alpha_o "
        f"{math.degrees(mean['alpha_outer']):.2f} deg, cage slip {samples[-1]['cage_slip']:.4f}"
    )
    assert mean["omega_cage"] == pytest.approx(orc["omega_cage"], rel=0.01)
    assert mean["alpha_inner"] == pytest.approx(orc["alpha_inner"], rel=0.03)
    assert mean["alpha_outer"] == pytest.approx(orc["alpha_outer"], rel=0.03)
    assert mean["torque"] == pytest.approx(orc["torque"], rel=torque_rel)
    alpha_o = [math.degrees(o["alpha_outer"]) for o in samples]
    assert max(alpha_o) - min(alpha_o) < 0.5
    assert abs(samples[-1]["cage_slip"]) < 0.005


def test_with_a_full_film_that_can_hold_the_gyroscopic_moment_it_is_outer_race_control(hypotheses):
    """traction_limit = 0.05 (the balls' tangential force may reach 0.05 F_n in a full film instead of the papers'
    0.01; of the order of an EHL limiting traction coefficient, a value for the test, not a measured one; the
    Houpert spin and Heathcote terms keep the papers' mu): the friction can hold the gyroscopic moment of
    outer-race control (0.074 N.m, docs/dem.md), the contacts stick and the DEM reproduces that hypothesis.
    Measured (0.3-0.6 s, means of 10 ms averages; the same to 1e-4 at dt = 1, 2 and 4.8 us): cage 455.05 rad/s,
    alpha_i 24.51 deg, alpha_o 7.78 deg, torque 1.319 N.m: -0.05 %, +0.4 %, -2.4 %, +0.2 % from outer-race
    control with the gyroscopic moment. Asserted: cage within 1 %, both contact angles within 3 % (the
    acceptance of the DEM fidelity against the closest quasi-static hypothesis), torque within 15 %, and the
    800 Hz swing gone: alpha_o within 0.5 deg over the samples (measured 0.06 deg; 7.9-10.4 deg with 0.01)."""
    _check_outer_race_control(DemModel("B7214C", "iso_vg68_mineral", traction_limit=0.05), 30, hypotheses, 0.15)


def test_with_the_ehl_traction_curve_it_is_outer_race_control(hypotheses):
    """The default tangential law (the film's EHL traction curve of iso_vg68_mineral: limiting coefficient 0.06,
    knee s_0 = 0.1 % slide-to-roll ratio, both estimated; docs/dem.md) holds the gyroscopic moment of outer-race
    control, and the DEM reproduces that hypothesis (Jones 1960; Harris & Kotzalas 2006 vol. 2; the quasi-static
    fidelity with the gyroscopic moment). Acceptance of the DEM fidelity against the closest quasi-static
    hypothesis: contact angles within 3 %, cage speed within 1 %, torque within 5 % (the Houpert terms are the
    same; the film's slip adds its traction losses). Measured (0.3-0.5 s, means of 10 ms averages): cage -0.27 %,
    torque +0.08 %, alpha_i -0.20 %, alpha_o +1.04 %; the 800 Hz swing of the papers' law is gone (alpha_o within
    0.01 deg over the samples; asserted 0.5 deg as for the 0.05 override). How the result depends on the estimated
    knee (docs/dem.md): s_0 = 0.3 % gives alpha_o +3.2 %, 1 % gives +13 % (the balls then hold part of the moment at
    the inner race)."""
    _check_outer_race_control(DemModel("B7214C", "iso_vg68_mineral"), 20, hypotheses, 0.05)
