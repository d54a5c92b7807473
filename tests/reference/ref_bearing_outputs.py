"""Twin of bearing_fmu.kernels.bearing_outputs: the ball-set summary and the output fill, in plain Python.

Written from the definitions in the kernel module's docstring (and models.declarations' sources),
not from its loops: the most loaded ball is found with max() over (load, -position) so that the
first of equal loads wins, the weighted mean is math.fsum of the products over math.fsum of the loads
(exactly rounded sums, so the kernel's ball-order sums agree to rounding, not bit for bit), the
ball's speed in the fixed frame is the norm of its angular-velocity vector written in components.
"""

import math

from . import ref_geometry

SRC_OUT, SRC_D, SRC_F, SRC_K, SRC_BALL_SET, SRC_TRUNC = 0, 1, 2, 3, 4, 5
BS_ALPHA_I, BS_ALPHA_O, BS_CAGE, BS_BALL, BS_ITERATIONS = 0, 1, 2, 3, 4
BS_BALL_CAGE, BS_FTF, BS_BPFO, BS_BPFI, BS_BSF = 5, 6, 7, 8, 9
BS_MU_REQ_I, BS_MU_REQ_O, BS_SIZE = 10, 11, 12
# rows of the per-ball array (kernels.jones_harris BQ_*)
BQ_Q_I, BQ_Q_O, BQ_A_I, BQ_A_O, BQ_BETA, BQ_W_M, BQ_W_R = 0, 1, 2, 3, 4, 5, 6
BQ_MU_REQ_I, BQ_MU_REQ_O = 18, 19


def _most_loaded(loads):
    """Index of the largest load, the first one among equals."""
    return max(range(len(loads)), key=lambda k: (loads[k], -k))


def ball_set_summary(balls, omega, iterations, summary):
    q_i = list(balls[BQ_Q_I])
    w_m = list(balls[BQ_W_M])
    if sum(q_i) > 0.0:
        j = _most_loaded(q_i)
        cage = math.fsum(q * w for q, w in zip(q_i, w_m)) / math.fsum(q_i)
    else:
        j = _most_loaded(list(balls[BQ_Q_O]))
        cage = math.fsum(w_m) / len(w_m)
    # angular velocity of ball j in the fixed frame: spin w_R about the axis pitched by beta in the
    # ball's plane, plus the orbital speed w_m about the bearing axis
    beta, w_r = balls[BQ_BETA, j], balls[BQ_W_R, j]
    along_axis = w_r * math.cos(beta) + balls[BQ_W_M, j]
    across = w_r * math.sin(beta)
    speed = math.sqrt(along_axis**2 + across**2)
    summary[BS_ALPHA_I] = balls[BQ_A_I, j]
    summary[BS_ALPHA_O] = balls[BQ_A_O, j]
    summary[BS_CAGE] = cage
    summary[BS_BALL] = 0.0 if omega == 0.0 else (speed if omega > 0.0 else -speed)
    summary[BS_ITERATIONS] = iterations
    # relative to the cage the ball turns at w_R alone (the orbital speed is the cage's own)
    summary[BS_BALL_CAGE] = abs(w_r)
    frequencies = ref_geometry.pass_frequencies(omega, cage, w_r, len(q_i))
    summary[BS_FTF], summary[BS_BPFO], summary[BS_BPFI], summary[BS_BSF] = frequencies
    # the largest required traction coefficient of each race (0 when no ball asks any)
    summary[BS_MU_REQ_I] = max([0.0, *balls[BQ_MU_REQ_I]])
    summary[BS_MU_REQ_O] = max([0.0, *balls[BQ_MU_REQ_O]])


def quasi_static_outputs(balls, omega, iterations, out, d, F, K_flat, trunc, source, index, summary, values):
    ball_set_summary(balls, omega, iterations, summary)
    arrays = {SRC_OUT: out, SRC_D: d, SRC_F: F, SRC_K: K_flat, SRC_BALL_SET: summary, SRC_TRUNC: trunc}
    for k, (code, i) in enumerate(zip(source, index)):
        values[k] = arrays[int(code)][int(i)]
    bad = [k for k in range(len(values)) if not math.isfinite(values[k])]
    return bad[0] if bad else -1


KERNEL_MODULE = "bearing_fmu.kernels.bearing_outputs"
TWINS = {"ball_set_summary": ball_set_summary, "quasi_static_outputs": quasi_static_outputs}
