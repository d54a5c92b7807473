"""Twin of bearing_fmu.kernels.contact_outputs: every ball-race contact of a solved bearing as a plain loop.

Calls only the other twins (never a kernel). For each ball j and race (inner, outer), with the contact
load Q, rolling speed u and spin speed of the per-ball rows (kernels.jones_harris BQ_*):
1. Hertz contact (ref_hertz) with the curvature and elliptic constants of the free contact angle;
2. EHL film (ref_ehl) at the oil state (ref_lubricant), film parameter Lambda = h_min/sigma;
3. if loaded and the capacitance submodel is on: permittivity at the Hertz pressure (Clausius-Mossotti
   at the Dowson-Higginson density) and the contact capacitance (ref_capacitance);
4. if loaded and the loss submodel is on: the four Houpert loss components (ref_torque) with the
   friction coefficient of Lambda; the heat goes to the ring of the contact.
Summaries (docs/quasistatic.md): minimum Lambda and h_min over the loaded contacts of each race and the
central film h_c of its most loaded contact (0 when a race has none), regime of the worse race, largest
loads and pressure, balls loaded on both races, bearing capacitance = background + balls (inner and outer
contacts in series) in parallel, power loss = both rings' heats, torque = power / |omega| (0 at rest).
Lubrication method (its block at CP_LUBRICATION_BLOCK on; ref_lubrication): the flooded films of a loaded contact
times the inlet-shear-heating and starvation factors before Lambda, mu, capacitance; the EHL loss times the
rolling-force factor; the factors of the most loaded contact of each race; with the losses, the drag of every ball
at its orbital speed, half its heat to each ring.
The cp, lub and balls arrays are read through the kernels' layout constants only. A submodel that is
off is a null submodel: its outputs are NaN here (the kernel does not write them).
"""

import numpy as np

from bearing_fmu.kernels import capacitance as capk  # layout constants (CAP_*) only
from bearing_fmu.kernels import contact_outputs as ck  # layout constants (CP_*, CO_*, PC_*) only
from bearing_fmu.kernels import jones_harris  # layout constants (BQ_*) only
from bearing_fmu.kernels import lubricant as lk  # layout constants (LUB_*) only
from bearing_fmu.kernels import lubrication as lmk  # layout constants (LM_*) only

from . import ref_capacitance, ref_ehl, ref_film_correction, ref_hertz, ref_lubricant, ref_lubrication, ref_torque

RACES = (  # (name, cp offsets of Rx, Ry, k, E, K; sigma; conformity; load, rolling, spin rows; ring heat)
    ("inner", (ck.CP_RX_I, ck.CP_RY_I, ck.CP_K_I, ck.CP_EE_I, ck.CP_KK_I), ck.CP_SIGMA_I, ck.CP_F_I,
     jones_harris.BQ_Q_I, jones_harris.BQ_U_I, jones_harris.BQ_SPIN_I),
    ("outer", (ck.CP_RX_O, ck.CP_RY_O, ck.CP_K_O, ck.CP_EE_O, ck.CP_KK_O), ck.CP_SIGMA_O, ck.CP_F_O,
     jones_harris.BQ_Q_O, jones_harris.BQ_U_O, jones_harris.BQ_SPIN_O),
)  # fmt: skip
# the lubrication method's and the capacitance submodel's blocks in the contact array
LM = ck.CP_LUBRICATION_BLOCK
CAP = ck.CP_CAPACITANCE_BLOCK


def contact(Q, u, spin, Rx, Ry, k, ell_E, ell_K, sigma, f, cp, race, eta, xi, rho0, lub, capacitance, torque, beta):
    """One contact of race 0 (inner) or 1 (outer): dict with p_max, h_min, Lambda, C (F), the loss components (W,
    ref_torque TL_* order) and the lubrication method's factors phi (ish, rs_c)."""
    E_red = cp[ck.CP_E_RED]
    a, b, _, p_max = ref_hertz.hertz_contact(Q, Rx, Ry, E_red, k, ell_E, ell_K)
    h_c, h_min = ref_film_correction.corrected_film_thickness(
        int(cp[ck.CP_FILM]), eta, xi, E_red, u, Q, Rx, Ry, k, cp[ck.CP_FILM_TABLE :], race
    )
    phi = (1.0, 1.0, 1.0)
    if cp[LM + lmk.LM_ON] > 0.5 and Q > 0.0:
        args = (
            abs(u),
            p_max,
            b,
            Rx,
            E_red,
            eta,
            beta,
            cp[LM + lmk.LM_K_OIL],
            cp[LM + lmk.LM_THERMAL],
            cp[LM + lmk.LM_H_OIL],
        )
        phi = ref_lubrication.film_factors(h_c, h_min, *args)
        h_c, h_min = h_c * phi[0] * phi[1], h_min * phi[0] * phi[2]
    lam = ref_ehl.film_parameter(h_min, sigma)
    C = 0.0
    losses = [0.0] * ref_torque.TL_SIZE
    if Q > 0.0 and capacitance:
        K_cm = ref_lubricant.clausius_mossotti_constant(lub[lk.LUB_EPS_R0], lub[lk.LUB_RHO_REF])
        C = ref_capacitance.lubricated_contact_capacitance(
            K_cm,
            rho0,
            p_max,
            int(cp[CAP + capk.CAP_PRESSURE]),
            a,
            b,
            h_c,
            cp[CAP + capk.CAP_H_FLOOR],
            E_red,
            cp[CAP + capk.CAP_OIL_GAP],
            outside=ref_capacitance.assembly_outside,
        )
    if Q > 0.0 and torque:
        mu = ref_ehl.friction_coefficient(lam)
        args = (Q, u, spin, Rx, Ry, a, b, ell_E, f, cp[ck.CP_D], E_red, eta, xi, mu, cp[ck.CP_ALPHA_H])
        ref_torque.contact_losses(*args, losses)
        if cp[LM + lmk.LM_ON] > 0.5:
            losses[ref_torque.TL_EHL] *= ref_lubrication.rolling_force_factor(phi[0], phi[1])
    return {"p_max": p_max, "h_c": h_c, "h_min": h_min, "Lambda": lam, "C": C, "losses": losses, "phi": phi[:2]}


def contact_outputs(omega, T_oil, cp, lub, balls):
    """Returns (out, per_contact): arrays in the kernel's CO_* and PC_* layouts (NaN where a submodel is off)."""
    capacitance = cp[CAP + capk.CAP_ON] > 0.5
    torque = cp[ck.CP_TORQUE] > 0.5
    eta, xi, rho0 = ref_lubricant.lubricant_state(T_oil, lub)
    lubricated = cp[LM + lmk.LM_ON] > 0.5
    beta = ref_lubrication.temperature_viscosity_coefficient(T_oil, lub) if lubricated else 0.0
    Z = balls.shape[1]
    res = {}  # (race name, j) -> contact dict
    for j in range(Z):
        for race, (name, geo, sigma, f, q_row, u_row, spin_row) in enumerate(RACES):
            Rx, Ry, k, ell_E, ell_K = (cp[i] for i in geo)
            Q, u, spin = balls[q_row, j], balls[u_row, j], balls[spin_row, j]
            state = (eta, xi, rho0, lub, capacitance, torque, beta)
            res[name, j] = dict(contact(Q, u, spin, Rx, Ry, k, ell_E, ell_K, cp[sigma], cp[f], cp, race, *state), Q=Q)

    out = np.full(ck.CO_SIZE, np.nan)
    per_contact = np.full((ck.PC_SIZE, Z), np.nan)
    for race, (name, *_) in enumerate(RACES):
        loaded = [res[name, j] for j in range(Z) if res[name, j]["Q"] > 0.0]
        out[ck.CO_LAMBDA_I + race] = min((c["Lambda"] for c in loaded), default=0.0)
        out[ck.CO_HMIN_I + race] = min((c["h_min"] for c in loaded), default=0.0)
        out[ck.CO_QMAX_I + race] = max((c["Q"] for c in loaded), default=0.0)
        # central film of the most loaded contact: the first ball of the largest load
        out[ck.CO_HC_I + race] = max(loaded, key=lambda c: c["Q"])["h_c"] if loaded else 0.0
        if lubricated:
            phi = max(loaded, key=lambda c: c["Q"])["phi"] if loaded else (1.0, 1.0)
            out[ck.CO_PHI_ISH_I + race], out[ck.CO_PHI_RS_I + race] = phi
        for j in range(Z):
            per_contact[ck.PC_HMIN_I + race, j] = res[name, j]["h_min"]
            per_contact[ck.PC_LAMBDA_I + race, j] = res[name, j]["Lambda"]
            if capacitance:
                per_contact[ck.PC_C_I + race, j] = res[name, j]["C"]
            if torque:
                per_contact[ck.PC_P_I + race, j] = sum(res[name, j]["losses"])
    out[ck.CO_REGIME] = ref_ehl.lubrication_regime(min(out[ck.CO_LAMBDA_I], out[ck.CO_LAMBDA_O]))
    everything = [res[key] for key in res if res[key]["Q"] > 0.0]
    out[ck.CO_PMAX] = max((c["p_max"] for c in everything), default=0.0)
    out[ck.CO_N_LOADED] = sum(1 for j in range(Z) if res["inner", j]["Q"] > 0.0 and res["outer", j]["Q"] > 0.0)
    if capacitance:
        out[ck.CO_C_BEARING] = ref_capacitance.bearing_capacitance(
            [res["inner", j]["C"] for j in range(Z)],
            [res["outer", j]["C"] for j in range(Z)],
            cp[CAP + capk.CAP_BACKGROUND],
        )
    if torque:
        for t in range(ref_torque.TL_SIZE):
            out[ck.CO_P_EHL + t] = sum(c["losses"][t] for c in everything)
        out[ck.CO_Q_INNER_RING] = sum(sum(res["inner", j]["losses"]) for j in range(Z))
        out[ck.CO_Q_OUTER_RING] = sum(sum(res["outer", j]["losses"]) for j in range(Z))
        if cp[LM + lmk.LM_DRAG] > 0.5:
            rho_e, eta_e = ref_lubrication.mixture(cp[LM + lmk.LM_DRAG_X], rho0, eta)
            P = sum(
                ref_lubrication.ball_drag_power(
                    balls[jones_harris.BQ_W_M, j] * cp[ck.CP_DM] / 2.0,
                    cp[ck.CP_D],
                    rho_e,
                    eta_e,
                    cp[LM + lmk.LM_DRAG_AREA],
                )
                for j in range(Z)
            )
            out[ck.CO_P_DRAG] = P
            out[ck.CO_TORQUE_DRAG] = P / abs(omega) if omega != 0.0 else 0.0
            out[ck.CO_Q_INNER_RING] += P / 2.0
            out[ck.CO_Q_OUTER_RING] += P / 2.0
        out[ck.CO_P_LOSS] = out[ck.CO_Q_INNER_RING] + out[ck.CO_Q_OUTER_RING]
        out[ck.CO_TORQUE] = out[ck.CO_P_LOSS] / abs(omega) if omega != 0.0 else 0.0
    out[ck.CO_ETA] = eta
    out[ck.CO_XI] = xi
    return out, per_contact


# the kernels this module twins (tests/unit/test_every_kernel_has_a_twin.py)
KERNEL_MODULE = "bearing_fmu.kernels.contact_outputs"
TWINS = {"contact_outputs": contact_outputs}
