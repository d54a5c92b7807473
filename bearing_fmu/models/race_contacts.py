"""The two race contacts of a bearing as the facades pack them: the free contact angle, the reduced radii,
the Hertz coefficients and modulus, the contact terms the quasi-static (kernels.contact_outputs CP_*) and DEM
(kernels.ball_dynamics.state P_*) parameter arrays share under the same slot names, and the shoulder
truncation parameters every fidelity shares (kernels.truncation TP_*)."""

import math
from typing import NamedTuple

import numpy as np

from ..kernels import ball_traction as bt
from ..kernels import truncation as tk
from ..kernels.geometry import curvature_radii, free_contact_angle
from ..kernels.hertz import hertz_coefficients_approx, hertz_coefficients_exact, hertz_contact, reduced_modulus
from ..kernels.torque import ALPHA_HYSTERESIS_STEEL
from ..scene import FILM_FORMULAS


class RaceContacts(NamedTuple):
    alpha0: float  # rad, free contact angle of the clearance P_d (0 for P_d <= 0)
    Rx_i: float  # m, reduced radii of the inner contact (rolling direction, across the groove)
    Ry_i: float
    Rx_o: float  # m, the same of the outer contact
    Ry_o: float
    ci: tuple  # Hertz coefficients (k, E, K) of the inner contact (kernels.hertz)
    co: tuple  # and of the outer one
    E_red: float  # Pa, reduced modulus of ball and rings


def race_contacts(bearing, scene, Pd):
    """RaceContacts of `bearing` at the diametral clearance Pd (m), with the scene's Hertz coefficients
    (exact or Hamrock-Brewe)."""
    b = bearing
    alpha0 = free_contact_angle(b.D, b.f_i, b.f_o, Pd) if Pd > 0.0 else 0.0
    Rx_i, Ry_i, Rx_o, Ry_o = curvature_radii(b.D, b.dm, b.f_i, b.f_o, alpha0)
    coefficients = hertz_coefficients_exact if scene.hertz == "exact" else hertz_coefficients_approx
    E_red = reduced_modulus(b.ball.E, b.ball.nu, b.ring.E, b.ring.nu)
    return RaceContacts(alpha0, Rx_i, Ry_i, Rx_o, Ry_o, coefficients(Rx_i, Ry_i), coefficients(Rx_o, Ry_o), E_red)


def contact_terms(bearing, scene, rc):
    """Slot name (without its array's prefix) -> value of the contact terms both fidelities' arrays hold:
    radii (m), Hertz coefficients, reduced modulus (Pa), composite roughness (m), film formula (code), hysteresis
    factor, conformities."""
    b = bearing
    return {
        "RX_I": rc.Rx_i,
        "RY_I": rc.Ry_i,
        "K_I": rc.ci[0],
        "EE_I": rc.ci[1],
        "KK_I": rc.ci[2],
        "RX_O": rc.Rx_o,
        "RY_O": rc.Ry_o,
        "K_O": rc.co[0],
        "EE_O": rc.co[1],
        "KK_O": rc.co[2],
        "E_RED": rc.E_red,
        "SIGMA_I": scene.roughness_factor * math.hypot(b.Ra_inner, b.Ra_ball),
        "SIGMA_O": scene.roughness_factor * math.hypot(b.Ra_outer, b.Ra_ball),
        "FILM": FILM_FORMULAS[scene.film],
        "ALPHA_H": ALPHA_HYSTERESIS_STEEL,
        "F_I": b.f_i,
        "F_O": b.f_o,
    }


def traction_block(bearing, scene, rc, lubricant, used=True):
    """kernels.ball_traction TR_* block of the quasi-static race control "traction": per race the Hertz ellipse at
    1 N, its elliptic integral, radii, ellipticity, conformity and composite roughness, then the lubricant's traction
    curve (the DEM's: limiting coefficient and knee), the reduced modulus, the hysteresis factor and the film formula.
    The viscosity and pressure-viscosity slots are the facade's to set at each evaluation's oil temperature. Not
    `used` (a race-control hypothesis, which reads none of it): the null block, all 0."""
    b = bearing
    tr = np.zeros(bt.TR_SIZE)
    if not used:
        return tr
    terms = contact_terms(b, scene, rc)
    for race, (Rx, Ry, c, f, sigma) in enumerate(
        ((rc.Rx_i, rc.Ry_i, rc.ci, b.f_i, terms["SIGMA_I"]), (rc.Rx_o, rc.Ry_o, rc.co, b.f_o, terms["SIGMA_O"]))
    ):
        o = bt.TR_STRIDE * race
        a1, b1 = hertz_contact(1.0, Rx, Ry, rc.E_red, *c)[:2]
        tr[o + bt.TR_A1] = a1
        tr[o + bt.TR_B1] = b1
        tr[o + bt.TR_EE] = c[1]
        tr[o + bt.TR_RX] = Rx
        tr[o + bt.TR_RY] = Ry
        tr[o + bt.TR_K] = c[0]
        tr[o + bt.TR_F] = f
        tr[o + bt.TR_SIGMA] = sigma
    tr[bt.TR_MU_LIM] = lubricant.traction_limit
    tr[bt.TR_S0] = lubricant.traction_slip
    tr[bt.TR_E_RED] = rc.E_red
    tr[bt.TR_ALPHA_H] = terms["ALPHA_H"]
    tr[bt.TR_FILM] = terms["FILM"]
    return tr


def pack(array, slots, prefix, terms):
    """array[slots.<prefix><name>] = value for each term (slots: the module that names the array's slots)."""
    for name, value in terms.items():
        array[getattr(slots, prefix + name)] = value


def groove_centre_radii(bearing, Pd):
    """Radii (m) of the inner and outer groove-curvature-centre circles of the unloaded, centred bearing at the
    diametral clearance Pd (m), as the quasi-static and DEM geometries place them: rho_i = d_m/2 + (f_i - 1/2) D
    cos alpha0, rho_o = rho_i - (A - P_d/2), A = (f_i + f_o - 1) D (docs/quasistatic.md section 1)."""
    b = bearing
    alpha0 = free_contact_angle(b.D, b.f_i, b.f_o, Pd) if Pd > 0.0 else 0.0
    rho_i = 0.5 * b.dm + (b.f_i - 0.5) * b.D * math.cos(alpha0)
    return rho_i, rho_i - ((b.f_i + b.f_o - 1.0) * b.D - 0.5 * Pd)


def truncation_parameters(bearing, rc, Pd):
    """kernels.truncation TP_* array of `bearing` at the clearance Pd (m): per race the semi-major axis at 1 N
    (m) of the contacts RaceContacts rc, the groove radius f D (m) and the angles (rad) of the thrust-side and
    other shoulder edges from the groove-curvature centre. The shoulders move with their ring: a thermal
    clearance change leaves these angles as they are."""
    b = bearing
    tp = np.zeros(tk.TP_SIZE)
    rho = groove_centre_radii(b, Pd)
    races = (
        (rc.Rx_i, rc.Ry_i, rc.ci, b.f_i, b.shoulder_inner, b.shoulder_inner_back),
        (rc.Rx_o, rc.Ry_o, rc.co, b.f_o, b.shoulder_outer, b.shoulder_outer_back),
    )
    for race, (Rx, Ry, c, f, thrust, back) in enumerate(races):
        o = tk.TP_STRIDE * race
        r = f * b.D
        tp[o + tk.TP_A1] = hertz_contact(1.0, Rx, Ry, rc.E_red, *c)[0]
        tp[o + tk.TP_R] = r
        tp[o + tk.TP_THRUST] = tk.shoulder_angle(rho[race], r, thrust, race)
        tp[o + tk.TP_BACK] = tk.shoulder_angle(rho[race], r, back, race)
    return tp


RACES = ("inner", "outer")
TRUNCATION_GROWTH = 2.0  # a truncated race is warned again each time its truncated fraction has doubled


def truncation_warnings(tp, tr, loads, load_row, angles, angle_row, truncated):
    """Warnings for the races whose contact ellipse has just become truncated by a shoulder (kernels.truncation:
    tr[TR_*] filled by race_truncation from the same loads and signed angles): one per entry, naming the race,
    the ball, its contact angle, where its ellipse reaches and the shoulder it passes, and again each time the
    truncated fraction has grown TRUNCATION_GROWTH times since the race's last warning. truncated: the two races'
    truncated fractions at their last warning (0: not truncated), updated in place (a race leaving truncation is
    warned again at its next entry)."""
    inner, outer = float(tr[tk.TR_INNER]), float(tr[tk.TR_OUTER])
    if inner == 0.0 and outer == 0.0 and not (truncated[0] or truncated[1]):  # the usual case, at every step
        return []
    warnings = []
    for race, t in enumerate((inner, outer)):
        warned = float(truncated[race])
        if t > 0.0 and (warned == 0.0 or t >= TRUNCATION_GROWTH * warned):
            o = tk.TP_STRIDE * race
            j = int(tr[tk.TR_BALL_INNER + race])
            alpha = float(angles[angle_row + race, j])
            a = tp[o + tk.TP_A1] * float(loads[load_row + race, j]) ** (1.0 / 3.0)
            theta = math.asin(min(1.0, a / tp[o + tk.TP_R]))  # the semi-major axis seen from the groove centre
            thrust, back = tp[o + tk.TP_THRUST], tp[o + tk.TP_BACK]
            if thrust - alpha <= back + alpha:  # the nearer edge (in angle) is the one passed
                side, edge, limit = "thrust-side", alpha + theta, thrust
            else:
                side, edge, limit = "other", alpha - theta, -back
            warnings.append(
                f"contact ellipse truncated by the {RACES[race]} ring's {side} shoulder: ball {j + 1}'s {RACES[race]} "
                f"contact at {math.degrees(alpha):.1f} deg reaches {math.degrees(edge):.1f} deg, past the shoulder "
                f"edge at {math.degrees(limit):.1f} deg ({100.0 * t:.3g} % of the semi-major axis beyond it); its "
                f"load, stresses and film are computed as if the groove went on (output truncation_{RACES[race]})"
                + (f"; grown from {100.0 * warned:.3g} % at the last warning" if warned > 0.0 else "")
            )
            truncated[race] = t
        elif t == 0.0:
            truncated[race] = 0.0
    return warnings
