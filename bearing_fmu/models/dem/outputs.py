"""The DEM's outputs in the facade's terms: the bearing outputs as a dict, the state outputs at the end of a call or
averaged over it, the shoulder truncation and its warnings, and the per-contact arrays of contacts()."""

import math

import numpy as np

from ...kernels.ball_dynamics import state as s
from ...kernels.ball_dynamics.outputs import contact_angles, contact_loads, shoulder_truncation
from ..race_contacts import truncation_warnings

# the outputs that averaged_state replaces by their means over the tribology refreshes of a call: (out, acc sum)
AVERAGED_STATE = (
    (s.O_QMAX_I, s.A_S_QMAX_I),
    (s.O_QMAX_O, s.A_S_QMAX_O),
    (s.O_PMAX, s.A_S_PMAX),
    (s.O_LAMBDA_I, s.A_S_LAMBDA_I),
    (s.O_LAMBDA_O, s.A_S_LAMBDA_O),
    (s.O_HMIN_I, s.A_S_HMIN_I),
    (s.O_HMIN_O, s.A_S_HMIN_O),
    (s.O_HC_I, s.A_S_HC_I),
    (s.O_HC_O, s.A_S_HC_O),
)
# contacts(): its per-contact arrays and their rows in the tribology array (None: the current load)
CONTACT_ROWS = {
    "Q": None,
    "h_min": s.T_H_MIN,
    "h_c": s.T_H_C,
    "Lambda": s.T_LAMBDA,
    "regime": s.T_REGIME,
    "mu": s.T_MU,
    "C_n": s.T_C_N,
    "SRR": s.T_SRR,
    "u": s.T_U,
    "C": s.T_CAP,
    "a": s.T_A,
    "b": s.T_B,
}


def outputs_dict(out, capacitance):
    """Bearing-level outputs of the output array out (names as the quasi-static fidelity), SI units; C_bearing
    only with capacitance."""
    o = out
    result = dict(
        omega_cage=o[s.O_OMEGA_CAGE],
        omega_ball=o[s.O_OMEGA_BALL],
        omega_ball_cage=o[s.O_OMEGA_BALL_REL],
        Q_max_inner=o[s.O_QMAX_I],
        Q_max_outer=o[s.O_QMAX_O],
        p_max=o[s.O_PMAX],
        alpha_inner=o[s.O_ALPHA_I],
        alpha_outer=o[s.O_ALPHA_O],
        Lambda_inner=o[s.O_LAMBDA_I],
        Lambda_outer=o[s.O_LAMBDA_O],
        h_min_inner=o[s.O_HMIN_I],
        h_min_outer=o[s.O_HMIN_O],
        h_c_inner=o[s.O_HC_I],
        h_c_outer=o[s.O_HC_O],
        regime=int(o[s.O_REGIME]),
        C_bearing=o[s.O_C_BEARING],
        n_loaded=int(o[s.O_N_LOADED]),
        P_loss=o[s.O_P_LOSS],
        Q_inner_ring=o[s.O_Q_INNER_RING],
        Q_outer_ring=o[s.O_Q_OUTER_RING],
        torque=o[s.O_TORQUE],
        cage_slip=o[s.O_CAGE_SLIP],
        SRR_max=o[s.O_SRR_MAX],
        kinetic_energy=o[s.O_KINETIC],
        x=o[s.O_X],
        y=o[s.O_X + 1],
        z=o[s.O_X + 2],
        theta_x=o[s.O_X + 3],
        theta_y=o[s.O_X + 4],
    )
    if not capacitance:
        del result["C_bearing"]
    return result


def state_outputs(out, acc, ring, interval, averaged_state):
    """The ring's displacement and tilts into out[O_X:O_X + 5]: at the end of the interval (s), or with averaged_state
    their means over the interval's steps (the call's sums acc), and then also the loads, pressure and films as means
    over its tribology refreshes (a call without a refresh keeps the end values)."""
    o = out
    if not averaged_state or interval <= 0.0:
        o[s.O_X : s.O_X + 3] = ring[s.R_X : s.R_X + 3]
        o[s.O_X + 3 : s.O_X + 5] = ring[s.R_TH : s.R_TH + 2]
        return
    o[s.O_X : s.O_X + 5] = acc[s.A_XT : s.A_XT + 5] / interval
    samples = acc[s.A_SAMPLES]
    if samples > 0.0:
        for out_slot, sum_slot in AVERAGED_STATE:
            o[out_slot] = acc[sum_slot] / samples


def truncation_outputs(balls, ring, par, truncation, Q, signed_alpha, trunc, truncated):
    """The contact ellipses against the shoulders in the end state (balls, ring) into trunc (kernels.truncation
    TR_*), with the shoulders' parameters `truncation` and the scratch arrays Q, signed_alpha (2, Z); returns the
    warnings of a race newly truncated or whose truncation has doubled since its last warning, truncated (2,) keeping
    each race's truncated fraction at its last warning (0: not truncated)."""
    shoulder_truncation(balls, ring, par, truncation, Q, signed_alpha, trunc)
    fractions = [float(v) for v in truncated]
    warnings = truncation_warnings(truncation, trunc, Q, 0, signed_alpha, 0, fractions)
    truncated[:] = fractions
    return warnings


def contact_arrays(balls, ring, trib, par, Q, alpha):
    """DemModel.contacts() of the state (balls, ring, trib); Q and alpha (2, Z) take the current loads and angles."""
    contact_loads(balls, ring, par, Q)
    contact_angles(balls, ring, par, alpha)
    x, y = balls[s.B_X], balls[s.B_X + 1]
    r2 = x * x + y * y
    result = {
        "psi": np.mod(np.arctan2(y, x), 2.0 * math.pi),
        "omega_orbit": (x * balls[s.B_VX + 1] - y * balls[s.B_VX]) / r2,
        "omega_spin": np.linalg.norm(balls[s.B_WX : s.B_WX + 3], axis=0),
    }
    for race, suffix in ((0, "_inner"), (1, "_outer")):
        for name, row in CONTACT_ROWS.items():
            result[name + suffix] = Q[race].copy() if row is None else trib[row, race].copy()
        result["delta" + suffix] = (Q[race] / par[s.P_KH_I + race]) ** (2.0 / 3.0)
        result["alpha" + suffix] = alpha[race].copy()
    return result
