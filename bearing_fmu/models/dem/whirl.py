"""The ring-orbit watch: a self-excited orbit or wobble of the inner ring (whirl) found from the DEM's own steps.

A free or lightly supported inner ring of an angular-contact bearing under heavy thrust at speed can whirl: the
contacts' traction feeds energy into its lowest mode (docs/dem.md, Ring support). The run stays stable, so the
integrator's monitor has nothing to stop, but the torque and the loads then describe a whirling ring. The watch
judges the ring's motion across its axis over windows of at least WINDOW of simulated time, from the kernel's
integrals of x, y, theta_x, theta_y, their squares and the squared speeds (acc[A_XT], acc[A_RING_SQ]):
- the orbit about the window's mean, rms radius r = sqrt(var x + var y), and the tilt rms t likewise; their motion
  at the inner groove circle e = sqrt(r^2 + (rho_i t)^2); its frequency f = v_rms / (2 pi e) (exact for a circular
  orbit, the rms-weighted frequency of a mixture);
- the reference is the elastic approach delta of the most loaded ball-race contact (Hertz, Q = K_h delta^1.5), at
  least DELTA_FLOOR.
A window is a whirl when
- (steady) e > STEADY_FRACTION delta in it and in the window before, not decaying (at least DECAY_RATIO of the
  window before: the settling after a start-up or a load step decays), at a frequency that is not a kinematic one
  (shaft, cage, ball passes: the lines of a healthy bearing's vibration, Randall & Antoni 2011, Mech. Syst. Signal
  Process. 25(2) 485-520, section 2; the variable compliance of a radially loaded bearing moves its ring at those);
  a whirl stays one while e > STEADY_FRACTION delta;
- or (growing) e > GROWTH_FLOOR delta after GROWTH_WINDOWS windows that each grew by GROWTH_RATIO (a transient
  decays; an instability grows).
The thresholds are measured (docs/dem.md, Ring support): a healthy bearing's orbit stays below 5 % of delta once
settled (1.7 % on the 6205 and 6208 under radial loads, 4 % on the lightly loaded 6208 at 10 000 rpm), a whirl
reaches 800-2 000 %; the settling transients decay by half or more per window.

The window's sums live in one float64[WS_SIZE] array, part of the DEM's state (rollback, FMU get/set state).
"""

import math

import numpy as np

from ...kernels.ball_dynamics import state as s
from ...kernels.geometry import pass_frequencies

WINDOW = 0.02  # s: 15-25 periods of a whirl at 750-1200 Hz, two of the ball pass of a small bearing at 1 800 rpm
STEADY_FRACTION = 0.25  # orbit at the groove over the contact deflection that counts as a whirl when it persists
DECAY_RATIO = 0.7  # a persisting orbit that keeps at least this share of the window before is not settling
GROWTH_FLOOR = 0.01  # a growing orbit counts from this fraction of the deflection (round-off orbits grow too)
GROWTH_RATIO = 2.0  # growth of the orbit from one window to the next
GROWTH_WINDOWS = 3  # consecutive windows of such growth
DELTA_FLOOR = 1e-7  # m: the reference deflection of an unloaded bearing (its ring rattles in the clearance)
# a frequency within 2 % (the cage slip) + 0.5 Hz of a kinematic line is kinematic; the fundamentals only: the rms
# frequency of a kinematic vibration is that of its dominant line, and a comb of harmonics would cover the whirls'
# frequencies by chance (the 218's 822 Hz at 12 000 rpm lies 2.8 % from 4 x the shaft's 200 Hz, its 780 Hz at
# 8 000 rpm within 1 % of twice the ball spin, a line of a ball defect, not of a healthy bearing)
KINEMATIC_TOLERANCE = 0.02
KINEMATIC_FLOOR = 0.5  # Hz

# layout of the window array
WS_T = 0  # simulated time in the window (s)
WS_SUM = 1  # integrals of x, y (m.s), theta_x, theta_y (rad.s): 4 entries
WS_SQ = 5  # integrals of their squares and of the squared speeds (acc[A_RING_SQ] layout): 6 entries
WS_START = 11  # x, y, theta_x, theta_y at the window's start: 4 entries
WS_E = 15  # the orbit e of the last GROWTH_WINDOWS + 1 windows, newest first (m)
WS_WHIRL = WS_E + GROWTH_WINDOWS + 1  # 1 while the last window was a whirl
WS_SIZE = WS_WHIRL + 1

WATCHED = (s.R_X, s.R_X + 1, s.R_TH, s.R_TH + 1)  # the ring's slots across its axis


def new_window(ring):
    """A window array starting at the ring's current position."""
    window = np.zeros(WS_SIZE)
    window[WS_START : WS_START + 4] = ring[list(WATCHED)]
    return window


def add_call(window, acc, interval):
    """Add the kernel call's integrals (acc, over `interval` s) to the window."""
    window[WS_T] += interval
    window[WS_SUM : WS_SUM + 2] += acc[s.A_XT : s.A_XT + 2]
    window[WS_SUM + 2 : WS_SUM + 4] += acc[s.A_XT + 3 : s.A_XT + 5]
    window[WS_SQ : WS_SQ + 6] += acc[s.A_RING_SQ : s.A_RING_SQ + 6]


def orbit(window, ring, rho_i):
    """(e (m), r (m), t (rad), f (Hz)) of a window: the rms motion at the inner groove circle of radius rho_i (m),
    the orbit's and the tilt's rms about the window's means and the motion's rms frequency; ring at its end."""
    T = window[WS_T]
    mean = window[WS_SUM : WS_SUM + 4] / T
    var = np.maximum(window[WS_SQ : WS_SQ + 4] / T - mean**2, 0.0)
    drift = (ring[list(WATCHED)] - window[WS_START : WS_START + 4]) / T  # mean velocities over the window
    v2 = max(window[WS_SQ + 4] / T - drift[0] ** 2 - drift[1] ** 2, 0.0)
    w2 = max(window[WS_SQ + 5] / T - drift[2] ** 2 - drift[3] ** 2, 0.0)
    r = math.sqrt(var[0] + var[1])
    t = math.sqrt(var[2] + var[3])
    e = math.hypot(r, rho_i * t)
    f = math.sqrt(v2 + rho_i**2 * w2) / (2.0 * math.pi * e) if e > 0.0 else 0.0
    return e, r, t, f


def kinematic_lines(omega, omega_cage, omega_ball_rel, Z):
    """The kinematic frequencies (Hz) of a healthy turning bearing's vibration: shaft, FTF, BPFO, BPFI."""
    ftf, bpfo, bpfi, _ = pass_frequencies(omega, omega_cage, omega_ball_rel, Z)
    return [f for f in (abs(omega) / (2.0 * math.pi), ftf, bpfo, bpfi) if f > 0.0]


def is_kinematic(f, lines):
    """Whether f (Hz) lies on one of the kinematic lines (Hz)."""
    return any(abs(f - line) <= KINEMATIC_TOLERANCE * line + KINEMATIC_FLOOR for line in lines)


class Verdict:
    """A window's judgement: kind None (no whirl), 'steady' or 'growing'; the orbit's e, r (m), t (rad), f (Hz) and
    the reference deflection delta (m)."""

    def __init__(self, kind, e, r, t, f, delta):
        self.kind, self.e, self.r, self.t, self.f, self.delta = kind, e, r, t, f, delta


def judge(window, ring, rho_i, delta, lines):
    """Close the window (ring at its end, delta the reference deflection (m), lines the kinematic frequencies (Hz)):
    shift the orbit history, set WS_WHIRL, restart the sums; returns its Verdict."""
    e, r, t, f = orbit(window, ring, rho_i)
    delta = max(delta, DELTA_FLOOR)
    history = window[WS_E : WS_E + GROWTH_WINDOWS + 1]
    previous = history[0]
    history[1:] = history[:-1].copy()
    history[0] = e
    kind = None
    large = STEADY_FRACTION * delta
    if window[WS_WHIRL] > 0.0 and e > large:
        kind = "steady"
    elif e > large and previous > large and e >= DECAY_RATIO * previous and not is_kinematic(f, lines):
        kind = "steady"
    # (a window not yet closed counts 0: a run's first windows have no growth to show)
    elif e > GROWTH_FLOOR * delta and all(
        0.0 < GROWTH_RATIO * history[k + 1] < history[k] for k in range(GROWTH_WINDOWS)
    ):
        kind = "growing"
    window[WS_WHIRL] = 0.0 if kind is None else 1.0
    window[WS_T] = 0.0
    window[WS_SUM : WS_SQ + 6] = 0.0
    window[WS_START : WS_START + 4] = ring[list(WATCHED)]
    return Verdict(kind, e, r, t, f, delta)
