"""Twin of bearing_fmu.kernels.radial_bearing: the analytic bearing as a plain loop over the balls.

Calls only the other twins (never a kernel). Deep-groove bearing (contact angle 0), outer ring
fixed, radial load along psi = 0 (docs/decisions.md):
1. oil state (ref_lubricant), pure-rolling kinematics (ref_geometry), centrifugal force on the
   outer contacts if switched on;
2. load-deflection constant K of the inner and outer Hertz contacts in series (ref_hertz), radial
   shift delta_r carrying F_r in the continuous Sjovall form (ref_loaddist, quad + brentq);
3. ball j at psi_j = 2 pi j / Z: Q_i = K (delta_r cos psi_j - P_d/2)_+^1.5, Q_o = Q_i + F_c; per
   contact Hertz, EHL film, film parameter and, if loaded, capacitance; ball = inner and outer
   contacts in series, bearing = balls in parallel plus the background term;
4. race summaries over the loaded contacts (minimum film parameter and film thickness; 0 when a
   race has no loaded contact), worst regime, largest loads and pressure, count of balls loaded
   on both races.
Lubrication method (its block at B_LUBRICATION_BLOCK on; ref_lubrication): the flooded films of each loaded contact
times its inlet-shear-heating and starvation factors (those of ball 1, the most loaded, are outputs); the drag of the
Z balls at the cage's orbital speed. Flooded: the factors are 1 and the drag 0 here (the kernel writes neither).
The brg and lub arrays are read through the kernels' layout constants (B_*, LUB_*) only; the Hertz
coefficients (k, E, K) are taken from brg as the kernel does (they are its inputs; the unit test
checks them separately against ref_hertz).
"""

import math

from bearing_fmu.kernels import capacitance as capk  # layout constants (CAP_*) only
from bearing_fmu.kernels import lubricant as lk  # layout constants (LUB_*) only
from bearing_fmu.kernels import lubrication as lmk  # layout constants (LM_*) only
from bearing_fmu.kernels import radial_bearing  # layout constants (B_*) only

from . import (
    ref_capacitance,
    ref_ehl,
    ref_film_correction,
    ref_geometry,
    ref_hertz,
    ref_loaddist,
    ref_lubricant,
    ref_lubrication,
)

BALL_ROWS = ("Q_i", "Q_o", "h_min_i", "h_min_o", "Lambda_i", "Lambda_o", "C_i", "C_o")
# a race's contact constant -> the stem of its slot in the bearing array (B_<stem>_I, B_<stem>_O)
RACE_SLOTS = {"Rx": "RX", "Ry": "RY", "k": "K", "E": "EE", "K": "KK", "sigma": "SIGMA"}
# the lubrication method's and the capacitance submodel's blocks in the bearing array
LM = radial_bearing.B_LUBRICATION_BLOCK
CAP = radial_bearing.B_CAPACITANCE_BLOCK


def analytic_bearing(omega, F_r, T_oil, brg, lub):
    """Returns (out, balls): out maps the lower-case O_* names of kernels.radial_bearing without the
    'O_' prefix (e.g. 'lambda_i' for O_LAMBDA_I) to values; balls maps BALL_ROWS (the rows of the
    kernel's work array, in order) to lists over the balls. 'iter' (the kernel's Newton iteration
    count) has no twin: it is None here."""
    Z = int(brg[radial_bearing.B_Z])
    D, dm, Pd, E_red = (
        brg[radial_bearing.B_D],
        brg[radial_bearing.B_DM],
        brg[radial_bearing.B_PD],
        brg[radial_bearing.B_E_RED],
    )
    # each race's contact constants, from the slots B_RX_I ... B_SIGMA_I and B_RX_O ... B_SIGMA_O
    race = {
        r: {key: brg[getattr(radial_bearing, f"B_{slot}_{r.upper()}")] for key, slot in RACE_SLOTS.items()}
        for r in ("i", "o")
    }
    film_code = int(brg[radial_bearing.B_FILM])
    pressure_choice = int(brg[CAP + capk.CAP_PRESSURE])
    h_floor = brg[CAP + capk.CAP_H_FLOOR]

    eta, xi, rho0 = ref_lubricant.lubricant_state(T_oil, lub)
    K_cm = ref_lubricant.clausius_mossotti_constant(lub[lk.LUB_EPS_R0], lub[lk.LUB_RHO_REF])
    lubricated = brg[LM + lmk.LM_ON] > 0.5
    beta = ref_lubrication.temperature_viscosity_coefficient(T_oil, lub) if lubricated else 0.0
    phis = {"i": (1.0, 1.0), "o": (1.0, 1.0)}
    omega_cage, omega_ball_cage, omega_ball, u = ref_geometry.rolling_kinematics(omega, D, dm, 0.0)
    F_c = (
        ref_geometry.centrifugal_force(brg[radial_bearing.B_M_BALL], dm, omega_cage)
        if brg[radial_bearing.B_CENTRIFUGAL] > 0.5
        else 0.0
    )

    stiff = {s: ref_hertz.hertz_stiffness(c["Rx"], c["Ry"], E_red, c["k"], c["E"], c["K"]) for s, c in race.items()}
    K = ref_hertz.series_stiffness(stiff["i"], stiff["o"])
    delta_r = ref_loaddist.solve_radial_shift(F_r, Pd, K, Z)

    balls = {name: [] for name in BALL_ROWS}
    loaded = {"i": [], "o": []}  # (Lambda, h_min, h_c) of the loaded contacts of each race
    pressures = []
    C_bearing = brg[CAP + capk.CAP_BACKGROUND]
    n_loaded = 0
    for j in range(Z):
        psi = 2.0 * math.pi * j / Z
        compression = delta_r * math.cos(psi) - Pd / 2.0
        # model convention: a compression below 1e-12 (delta_r + |P_d|) is rounding of cos(psi) at
        # 90 deg, not contact (the ball on the edge of the zone carries no load in exact arithmetic)
        if compression <= 1e-12 * (abs(delta_r) + abs(Pd)):
            compression = 0.0
        Q_i = K * compression**1.5 if compression > 0.0 else 0.0
        loads = {"i": Q_i, "o": Q_i + F_c}
        C = {}
        for s, c in race.items():
            Q = loads[s]
            a_y, b_x, _, p_max = ref_hertz.hertz_contact(Q, c["Rx"], c["Ry"], E_red, c["k"], c["E"], c["K"])
            h_c, h_min = ref_film_correction.corrected_film_thickness(
                film_code,
                eta,
                xi,
                E_red,
                u,
                Q,
                c["Rx"],
                c["Ry"],
                c["k"],
                brg[radial_bearing.B_FILM_TABLE :],
                "io".index(s),
            )
            if lubricated and Q > 0.0:
                method = (brg[LM + lmk.LM_K_OIL], brg[LM + lmk.LM_THERMAL], brg[LM + lmk.LM_H_OIL])
                phi = ref_lubrication.film_factors(h_c, h_min, abs(u), p_max, b_x, c["Rx"], E_red, eta, beta, *method)
                h_c, h_min = h_c * phi[0] * phi[1], h_min * phi[0] * phi[2]
                if j == 0:
                    phis[s] = phi[:2]
            lam = ref_ehl.film_parameter(h_min, c["sigma"])
            C[s] = 0.0
            if Q > 0.0:
                C[s] = ref_capacitance.lubricated_contact_capacitance(
                    K_cm,
                    rho0,
                    p_max,
                    pressure_choice,
                    a_y,
                    b_x,
                    h_c,
                    h_floor,
                    E_red,
                    brg[CAP + capk.CAP_OIL_GAP],
                    outside=ref_capacitance.assembly_outside,
                )
                loaded[s].append((lam, h_min, h_c))
            pressures.append(p_max)
            balls[f"h_min_{s}"].append(h_min)
            balls.setdefault(f"h_c_{s}", []).append(h_c)  # (not a kernel row: the tests' bound of C needs it)
            balls[f"Lambda_{s}"].append(lam)
            balls[f"C_{s}"].append(C[s])
            balls[f"Q_{s}"].append(Q)
        if loads["i"] > 0.0 and loads["o"] > 0.0:
            n_loaded += 1
        C_bearing += ref_capacitance.ball_capacitance(C["i"], C["o"])

    def race_minima(s):
        if not loaded[s]:
            return 0.0, 0.0, 0.0  # no loaded contact on this race: no film to speak of
        return tuple(min(values) for values in zip(*loaded[s]))

    lam_i, hmin_i, hc_i = race_minima("i")
    lam_o, hmin_o, hc_o = race_minima("o")
    out = {
        "lambda_i": lam_i,
        "lambda_o": lam_o,
        "hmin_i": hmin_i,
        "hmin_o": hmin_o,
        "regime": ref_ehl.lubrication_regime(min(lam_i, lam_o)),
        "c_bearing": C_bearing,
        "qmax_i": max(balls["Q_i"]),
        "qmax_o": max(balls["Q_o"]),
        "pmax": max(pressures),
        "omega_cage": omega_cage,
        "omega_ball": omega_ball,
        "n_loaded": n_loaded,
        "delta_r": delta_r,
        "eps": ref_loaddist.load_parameter(delta_r, Pd),
        "hc_i": hc_i,
        "hc_o": hc_o,
        "eta": eta,
        "xi": xi,
        "iter": None,
        "omega_ball_cage": abs(omega_ball_cage),
    }
    frequencies = ref_geometry.pass_frequencies(omega, omega_cage, omega_ball_cage, Z)
    out["ftf"], out["bpfo"], out["bpfi"], out["bsf"] = frequencies
    (out["phi_ish_i"], out["phi_rs_i"]), (out["phi_ish_o"], out["phi_rs_o"]) = phis["i"], phis["o"]
    P = 0.0
    if brg[LM + lmk.LM_DRAG] > 0.5:
        rho_e, eta_e = ref_lubrication.mixture(brg[LM + lmk.LM_DRAG_X], rho0, eta)
        P = Z * ref_lubrication.ball_drag_power(omega_cage * dm / 2.0, D, rho_e, eta_e, brg[LM + lmk.LM_DRAG_AREA])
    out["p_drag"] = P
    out["torque_drag"] = P / abs(omega) if omega != 0.0 else 0.0
    return out, balls


# the kernels this module twins (tests/unit/test_every_kernel_has_a_twin.py)
KERNEL_MODULE = "bearing_fmu.kernels.radial_bearing"
TWINS = {"analytic_bearing": analytic_bearing}
