"""The quasi-static facade's output array, filled in declaration order in one compiled call.

quasi_static_outputs() takes the solver's arrays (kernels.jones_harris: displacements d, reactions F,
stiffness K, per-ball results) and the contact outputs (kernels.contact_outputs CO_*) and writes each output
slot from the source named by models.declarations, after deriving the outputs that summarise the
ball set:
- the most loaded ball: the ball with the largest inner contact load (the largest outer contact load
  if no ball touches the inner race); its inner and outer contact angles (rad);
- the cage speed (rad/s): orbital speed of the balls, mean weighted by inner contact load (plain mean
  when no ball is loaded on the inner race);
- the ball's angular speed in the fixed frame (rad/s): the magnitude of the spin w_R about the axis
  pitched by beta plus the orbital speed w_m about the bearing axis, |(w_R cos beta + w_m, w_R sin beta)|
  (Harris and Kotzalas 2007, ball kinematics), of the most loaded ball, with the sign of omega; 0 at rest;
- the ball's angular speed relative to the cage: |w_R| of the most loaded ball (rad/s);
- the defect frequencies FTF, BPFO, BPFI, BSF (Hz, kernels.geometry.pass_frequencies) from the cage speed
  and that relative ball speed: the operating contact angles and the race-control hypothesis are in them;
- the largest traction coefficient the race control asks of an inner and of an outer contact (-).
"""

import math

from bearing_fmu_common.jit import kernel
from bearing_fmu_common.layout import Layout

from .geometry import pass_frequencies
from .jones_harris import BQ_A_I, BQ_A_O, BQ_BETA, BQ_MU_REQ_I, BQ_MU_REQ_O, BQ_Q_I, BQ_Q_O, BQ_W_M, BQ_W_R

# source codes of an output slot (models.declarations `source` arrays)
SRC_OUT = 0  # the contact kernel's output array (kernels.contact_outputs CO_*)
SRC_D = 1  # the solver's displacements
SRC_F = 2  # the solver's reactions
SRC_K = 3  # the stiffness matrix, flattened row by row
SRC_BALL_SET = 4  # the ball-set summary below (BS_*)
SRC_TRUNC = 5  # the shoulder truncation of the contact ellipses (kernels.truncation TR_*)
# the ball-set summary
_BS_SLOTS = Layout()
BS_ALPHA_I = _BS_SLOTS.slot()  # inner contact angle of the most loaded ball (rad)
BS_ALPHA_O = _BS_SLOTS.slot()  # outer contact angle of the most loaded ball (rad)
BS_CAGE = _BS_SLOTS.slot()  # cage speed (rad/s)
BS_BALL = _BS_SLOTS.slot()  # ball angular speed in the fixed frame (rad/s)
BS_ITERATIONS = _BS_SLOTS.slot()  # Newton iterations of the solve (-)
BS_BALL_CAGE = _BS_SLOTS.slot()  # ball angular speed relative to the cage (rad/s, magnitude)
BS_FTF = _BS_SLOTS.slot()  # defect frequencies (Hz) from the cage speed and BS_BALL_CAGE: fundamental train (cage) ...
BS_BPFO = _BS_SLOTS.slot()  # ... ball pass outer race
BS_BPFI = _BS_SLOTS.slot()  # ... ball pass inner race
BS_BSF = _BS_SLOTS.slot()  # ... ball spin
BS_MU_REQ_I = _BS_SLOTS.slot()  # largest traction coefficient the race control asks of an inner contact (-)
BS_MU_REQ_O = _BS_SLOTS.slot()  # ... of an outer contact (-)
BS_SIZE = _BS_SLOTS.size


@kernel
def ball_set_summary(balls, omega, iterations, summary):
    """Fill summary[BS_*] from the per-ball results `balls` (BQ_* rows, one column per ball), the
    inner-ring speed omega (rad/s) and the solver's iteration count."""
    Z = balls.shape[1]
    total = 0.0
    weighted = 0.0
    j = 0
    mu_i = 0.0
    mu_o = 0.0
    for k in range(Z):
        q = balls[BQ_Q_I, k]
        total += q
        weighted += q * balls[BQ_W_M, k]
        if q > balls[BQ_Q_I, j]:
            j = k
        mu_i = max(mu_i, balls[BQ_MU_REQ_I, k])
        mu_o = max(mu_o, balls[BQ_MU_REQ_O, k])
    summary[BS_MU_REQ_I] = mu_i
    summary[BS_MU_REQ_O] = mu_o
    if total > 0.0:
        cage = weighted / total
    else:  # no ball on the inner race: most loaded on the outer race, plain mean orbital speed
        cage = 0.0
        for k in range(Z):
            cage += balls[BQ_W_M, k]
            if balls[BQ_Q_O, k] > balls[BQ_Q_O, j]:
                j = k
        cage /= Z
    w_m, w_r, beta = balls[BQ_W_M, j], balls[BQ_W_R, j], balls[BQ_BETA, j]
    spin = math.hypot(w_r * math.cos(beta) + w_m, w_r * math.sin(beta))
    summary[BS_ALPHA_I] = balls[BQ_A_I, j]
    summary[BS_ALPHA_O] = balls[BQ_A_O, j]
    summary[BS_CAGE] = cage
    summary[BS_BALL] = math.copysign(spin, omega) if omega != 0.0 else 0.0
    summary[BS_ITERATIONS] = iterations
    summary[BS_BALL_CAGE] = abs(w_r)
    summary[BS_FTF], summary[BS_BPFO], summary[BS_BPFI], summary[BS_BSF] = pass_frequencies(omega, cage, w_r, Z)


@kernel
def quasi_static_outputs(balls, omega, iterations, out, d, F, K_flat, trunc, source, index, summary, values):
    """Fill values[k] = (source array source[k])[index[k]] for every output slot k (SRC_* codes), after
    ball_set_summary(); returns the first slot whose value is not finite, -1 if every value is."""
    ball_set_summary(balls, omega, iterations, summary)
    bad = -1
    for k in range(values.shape[0]):
        code, i = source[k], index[k]
        if code == SRC_OUT:
            v = out[i]
        elif code == SRC_D:
            v = d[i]
        elif code == SRC_F:
            v = F[i]
        elif code == SRC_K:
            v = K_flat[i]
        elif code == SRC_TRUNC:
            v = trunc[i]
        else:
            v = summary[i]
        values[k] = v
        if bad < 0 and not math.isfinite(v):
            bad = k
    return bad
