"""Campbell diagram of a shaft model (docs/shaft.md, "Campbell diagram"): the natural frequencies of
ShaftModel.evaluate over a range of speeds, with their whirl and damping, and the synchronous critical speeds where a
forward whirl frequency crosses the 1x line f = Omega / 2 pi.

The seats' stiffness is a function of the speed: held (the classical diagram, K of one operating point) or
recomputed at each speed by a bearing model; the caller supplies it, so this module needs no bearing model.

A critical speed is found where the number of forward modes below the 1x line changes between two speeds of the
grid, then bisected on that number to SPEED_TOLERANCE: a bracket, no iteration that can fail to converge, and the
same answer whether the seats' K is held or follows the speed. Two crossings within one step of the grid that
cancel are not seen: the grid is the diagram's resolution.
"""

import math
from dataclasses import dataclass

import numpy as np

from .model import N_FREQUENCIES, WHIRL_AXIAL, WHIRL_BACKWARD, WHIRL_FORWARD, WHIRL_NONE

SPEED_TOLERANCE = 1e-3  # rad/s: width of the bracket a critical speed is bisected to (1e-6 of a spindle's speed)
# |f - Omega / 2 pi| / (Omega / 2 pi) above which a change of the count at the end of a bisection is not a crossing
# (a mode's whirl sense changing, or a mode leaving the six reported), so not a critical speed
CROSSING_MATCH = 1e-3
WHIRL_WORDS = {WHIRL_FORWARD: "forward", WHIRL_BACKWARD: "backward", WHIRL_NONE: "none", WHIRL_AXIAL: "axial"}


@dataclass
class CampbellDiagram:
    """The diagram: at each speed (rad/s) the first six natural frequencies (Hz), their whirl (model.WHIRL_*) and
    damping ratios; the forward critical speeds (rad/s) within the speeds' range, rising."""

    speeds: np.ndarray
    frequencies: np.ndarray  # (n_speeds, 6)
    whirl: np.ndarray  # (n_speeds, 6) int
    damping_ratios: np.ndarray  # (n_speeds, 6)
    critical_speeds: np.ndarray


def forward_below(out, omega):
    """How many forward modes of evaluate()'s outputs `out` at speed omega (rad/s) lie below the 1x line."""
    below = out["frequencies"] < omega / (2.0 * math.pi)
    return int(np.count_nonzero(below & (out["whirl"] == WHIRL_FORWARD)))


def on_the_line(out, omega):
    """Whether a forward mode of `out` lies on the 1x line at omega (within CROSSING_MATCH)."""
    f1x = omega / (2.0 * math.pi)
    forward = out["frequencies"][out["whirl"] == WHIRL_FORWARD]
    return bool(forward.size) and float(np.min(np.abs(forward - f1x))) <= CROSSING_MATCH * f1x


def campbell(model, speeds, stiffness, C_seats=None, tolerance=SPEED_TOLERANCE):
    """The Campbell diagram of ShaftModel `model` over `speeds` (rad/s, rising) with seat stiffness
    `stiffness(omega)` (an array (n_seats, 5, 5), as ShaftModel.evaluate takes it) and seat damping C_seats (None:
    undamped); critical speeds bisected to `tolerance` (rad/s)."""
    speeds = np.asarray(speeds, dtype=float)
    if speeds.ndim != 1 or speeds.size < 2 or np.any(np.diff(speeds) <= 0.0):
        raise ValueError(f"speeds: {speeds.size} values, expected at least 2, rising")

    def point(omega):
        return model.evaluate(omega, stiffness(omega), C_seats, critical_speeds=False)

    outs = [point(omega) for omega in speeds]
    counts = [forward_below(out, omega) for out, omega in zip(outs, speeds, strict=True)]
    critical = []
    for k in range(speeds.size - 1):
        critical += _crossings(point, speeds[k], speeds[k + 1], counts[k], counts[k + 1], tolerance)
    return CampbellDiagram(
        speeds=speeds,
        frequencies=np.array([out["frequencies"] for out in outs]),
        whirl=np.array([out["whirl"] for out in outs]),
        damping_ratios=np.array([out["damping_ratios"] for out in outs]),
        critical_speeds=np.array(critical),
    )


def _crossings(point, a, b, count_a, count_b, tolerance):
    """The speeds in [a, b] (rad/s) where the count of forward modes below the 1x line changes, each bisected to a
    bracket narrower than `tolerance` and kept when a forward mode lies on the line there."""
    if count_a == count_b:
        return []
    middle = 0.5 * (a + b)
    out = point(middle)
    if b - a <= tolerance:
        return [middle] if on_the_line(out, middle) else []
    count = forward_below(out, middle)
    return _crossings(point, a, middle, count_a, count, tolerance) + _crossings(
        point, middle, b, count, count_b, tolerance
    )


def rows(diagram):
    """The diagram as table rows: header, then per speed the speed (rpm, rad/s), each mode's frequency (Hz), whirl
    (a word) and damping ratio."""
    modes = range(1, N_FREQUENCIES + 1)
    header = ["speed_rpm", "omega_rad_s"]
    header += [f"f_{k}_Hz" for k in modes] + [f"whirl_{k}" for k in modes] + [f"zeta_{k}" for k in modes]
    table = [header]
    for i, omega in enumerate(diagram.speeds):
        row = [f"{omega * 30.0 / math.pi:.10g}", repr(float(omega))]
        row += [repr(float(f)) for f in diagram.frequencies[i]]
        row += [WHIRL_WORDS[int(w)] for w in diagram.whirl[i]]
        row += [repr(float(z)) for z in diagram.damping_ratios[i]]
        table.append(row)
    return table
