"""The ring-orbit watch (bearing_fmu.models.dem.whirl) on windows whose motion is known in closed form.

The window's sums are filled as the kernel fills acc (integrals over the steps of x, y, theta_x, theta_y, their
squares and the squared speeds), here from sampled analytic motions with the midpoint rule, so the expected orbit,
tilt and frequency are exact up to the sampling (1e-6 with 20 000 samples per window)."""

import math

import numpy as np
import pytest

from bearing_fmu.kernels.ball_dynamics import state as s
from bearing_fmu.models.dem import whirl

RHO_I = 0.05  # m, radius of the inner groove-curvature-centre circle
N = 20000  # samples of a window


def window_of(motion, t0=0.0, T=whirl.WINDOW):
    """A closed window of motion(t) -> (x, y, theta_x, theta_y, vx, vy, wx, wy) over [t0, t0 + T]: the window array
    and the ring at its end."""
    ring = np.zeros(s.R_SIZE)
    x0 = motion(t0)
    ring[s.R_X], ring[s.R_X + 1], ring[s.R_TH], ring[s.R_TH + 1] = x0[:4]
    window = whirl.new_window(ring)
    acc = np.zeros(s.A_SIZE)
    dt = T / N
    for t in t0 + (np.arange(N) + 0.5) * dt:
        x, y, tx, ty, vx, vy, wx, wy = motion(t)
        acc[s.A_XT : s.A_XT + 5] += np.array([x, y, 0.0, tx, ty]) * dt
        acc[s.A_RING_SQ : s.A_RING_SQ + 6] += (
            np.array([x * x, y * y, tx * tx, ty * ty, vx**2 + vy**2, wx**2 + wy**2]) * dt
        )
    whirl.add_call(window, acc, T)
    x1 = motion(t0 + T)
    ring[s.R_X], ring[s.R_X + 1], ring[s.R_TH], ring[s.R_TH + 1] = x1[:4]
    return window, ring


def circular(radius, f, offset=(3e-6, -2e-6), tilt=0.0):
    """A circular orbit of `radius` (m) at f (Hz) about a static offset, with a wobble of `tilt` (rad) at the same
    frequency."""
    w = 2.0 * math.pi * f

    def motion(t):
        c, sn = math.cos(w * t), math.sin(w * t)
        return (
            offset[0] + radius * c,
            offset[1] + radius * sn,
            tilt * c,
            tilt * sn,
            -radius * w * sn,
            radius * w * c,
            -tilt * w * sn,
            tilt * w * c,
        )

    return motion


@pytest.mark.parametrize("radius, f, tilt", [(100e-6, 822.0, 0.0), (2e-6, 107.0, 0.0), (30e-6, 776.0, 1e-3)])
def test_orbit_tilt_and_frequency_of_a_circular_whirl(radius, f, tilt):
    """A whole number of periods of a circular orbit about an offset: r = the radius (the offset is the mean, not
    the orbit), t = the tilt, e = hypot(r, rho_i t), f = v_rms / (2 pi e) the orbit's frequency; within 1e-6."""
    T = round(whirl.WINDOW * f) / f
    window, ring = window_of(circular(radius, f, tilt=tilt), T=T)
    e, r, t, got_f = whirl.orbit(window, ring, RHO_I)
    assert r == pytest.approx(radius, rel=1e-6)
    assert t == pytest.approx(tilt, rel=1e-6, abs=1e-15)
    assert e == pytest.approx(math.hypot(radius, RHO_I * tilt), rel=1e-6)
    assert got_f == pytest.approx(f, rel=1e-6)


def test_a_steady_whirl_is_flagged_from_its_second_window_and_stays_flagged():
    """A 100 um orbit at 822 Hz against a 12.8 um deflection (the 218 at 12 000 rpm on 300 N.s/m): the first window
    is not judged steady (no window before it), the second is, and so are the following ones."""
    motion = circular(100e-6, 822.0)
    window = None
    kinds = []
    for k in range(4):
        w, ring = window_of(motion, t0=k * whirl.WINDOW)
        if window is not None:
            w[whirl.WS_E :] = window[whirl.WS_E :]  # the history and the flag carry over
        verdict = whirl.judge(w, ring, RHO_I, 12.8e-6, [200.0, 85.0, 1360.0, 1840.0])
        kinds.append(verdict.kind)
        window = w
    assert kinds == [None, "steady", "steady", "steady"]


def test_a_decaying_transient_and_a_kinematic_vibration_are_not_flagged():
    """A settling orbit that halves per window (a start-up: the B7214C at 15 000 rpm under 800 N and 300 N went
    1.4, 0.43, 0.23 delta), and a persisting orbit at 2 % of the deflection at BPFO (the 6205 at 1 797 rpm, 1.7 %):
    neither is a whirl. The same persisting orbit at 40 % of the deflection is, unless its frequency is a kinematic
    line (BPFO within 2 % + 0.5 Hz)."""
    delta = 10e-6
    lines = [30.0, 12.0, 107.4, 162.2]

    def sequence(amplitudes, f):
        window = None
        kinds = []
        for k, a in enumerate(amplitudes):
            w, ring = window_of(circular(a, f), t0=k * whirl.WINDOW)
            if window is not None:
                w[whirl.WS_E :] = window[whirl.WS_E :]
            kinds.append(whirl.judge(w, ring, RHO_I, delta, lines).kind)
            window = w
        return kinds

    assert sequence([14e-6, 4.3e-6, 2.3e-6, 0.7e-6], 500.0) == [None] * 4
    assert sequence([0.17e-6] * 4, 107.4) == [None] * 4
    assert sequence([4e-6] * 4, 350.0) == [None, "steady", "steady", "steady"]
    assert sequence([4e-6] * 4, 108.0) == [None] * 4


def test_a_growing_orbit_is_flagged_after_three_doublings_above_the_floor():
    """An orbit that grows by 2.5x per window is flagged once it has grown in GROWTH_WINDOWS consecutive windows
    and passed GROWTH_FLOOR of the deflection, while it is still small against the deflection (before it would be a
    steady whirl); the same growth below the floor (round-off orbits) is not."""
    delta = 10e-6
    amplitudes = [1e-9 * 2.5**k for k in range(9)]
    window = None
    kinds = []
    for k, a in enumerate(amplitudes):
        w, ring = window_of(circular(a, 700.0), t0=k * whirl.WINDOW)
        if window is not None:
            w[whirl.WS_E :] = window[whirl.WS_E :]
        kinds.append(whirl.judge(w, ring, RHO_I, delta, [100.0]).kind)
        window = w
    first = kinds.index("growing")
    assert amplitudes[first] > whirl.GROWTH_FLOOR * delta
    assert amplitudes[first - 1] <= whirl.GROWTH_FLOOR * delta
    assert amplitudes[first] < whirl.STEADY_FRACTION * delta
    assert all(kind is None for kind in kinds[:first])
