"""The DEM's parameter array: a bearing file, a lubricant file, a scene and the model's settings packed once into the
float array of kernels.ball_dynamics (state.P_*): contact constants, masses and inertias, the cage balls and their
guide, the ring's support and the monitor's thresholds; with the estimates for what a bearing file leaves out (the
inner ring's mass and inertia, the cage balls)."""

import math

import numpy as np

from ...kernels.ball_dynamics import state as s
from ...kernels.geometry import ball_mass
from ...kernels.hertz import hertz_contact, hertz_stiffness
from ...params import cage_ball_room, load_dem_constants
from ..blocks import capacitance_block, write_blocks
from ..dem_settings import pack_settings, pitch_lever
from ..film_table import film_table_array
from ..limits import P_MAX_ERROR, InputError
from ..race_contacts import contact_terms, pack, race_contacts, truncation_parameters
from .monitor import CHATTER_STEPS, DAMPING_STOP
from .placement import ball_rest_position

# the contact model's constants with their units and sources (params/dem_model.toml): the cage elements' default
# material (the papers' PA66) and pocket play, the hysteretic damping constant alpha_e, the tangential stiffness
# ratio (the defaults of the settings a user changes are read by models.dem_settings)
CONSTANTS = load_dem_constants()
V_REG = 1e-3  # m/s, speed below which the resistances' directions are regularised
# the film's traction is evaluated linearly implicitly in the slip: a force at the surface of a solid sphere
# changes the surface's speed by 3.5/m per newton and second, and a ball has two contacts (docs/dem.md, Tangential)
FILM_RATE = 2.0 * 3.5


def cage_material(bearing):
    """(E, nu, rho) of the cage balls from the bearing file's [material.cage], else PA66 defaults."""
    cage = bearing.cage_material
    return cage.get("E", CONSTANTS.cage_E), cage.get("nu", CONSTANTS.cage_nu), cage.get("rho", CONSTANTS.cage_rho)


def ring_annulus(bearing):
    """(bore, groove bottom, width) in m of the annulus that estimates the inner ring: from the bore to the groove
    bottom over the ring width (shoulders and groove roughly cancel); without bore or width in the file,
    bore = d_m - 2 D, width = 1.5 D."""
    bore = bearing.dm - 2.0 * bearing.D if bearing.bore is None else bearing.bore
    width = 1.5 * bearing.D if bearing.width is None else bearing.width
    return bore, bearing.dm - bearing.D, width


def ring_mass(bearing):
    """Inner-ring mass (kg): a steel annulus (ring_annulus, estimated)."""
    bore, groove_bottom, width = ring_annulus(bearing)
    return bearing.ring.rho * 0.25 * math.pi * (groove_bottom**2 - bore**2) * width


def ring_inertia(bearing, mass):
    """(about a diameter, about the axis) in kg.m^2 of an inner ring of mass `mass` (kg) shaped as the annulus of
    ring_mass (estimated): m ((R^2 + r^2)/4 + w^2/12) and m (R^2 + r^2)/2, R and r the outer and bore radii."""
    bore, groove_bottom, width = ring_annulus(bearing)
    radii = 0.25 * (groove_bottom**2 + bore**2)  # R^2 + r^2
    return mass * (0.25 * radii + width**2 / 12.0), 0.5 * mass * radii


def pack_parameters(bearing, scene, lubricant, Pd, settings, kt_ratio, mass=None, inertia=None, film_tables=None):
    """The parameter array (float64[P_SIZE]) of a bearing with diametral clearance Pd (m) and the model's settings
    (checked: settings = name -> value of models.dem_settings.DEM_SETTINGS, kt_ratio; the ring's mass (kg) and
    inertia about a diameter (kg.m^2), None = estimated; film_tables: the directory of an FMU's own film tables, None
    = the cache, models.film_table); returns it with the shoulders' truncation parameters
    (models.race_contacts.truncation_parameters) and the balls' rest position (placement.ball_rest_position).
    Raises InputError when estimated cage balls find no room between the balls."""
    b, sc = bearing, scene
    D = b.D
    rc = race_contacts(b, sc, Pd)
    alpha0, Rx_i, Ry_i, Rx_o, Ry_o, ci, co, E_red = rc
    truncation = truncation_parameters(b, rc, Pd)
    p = np.zeros(s.P_SIZE)
    p[s.P_Z] = b.Z
    p[s.P_D] = D
    p[s.P_DM] = b.dm
    p[s.P_ALPHA0] = alpha0
    p[s.P_M_BALL] = ball_mass(D, b.ball.rho)
    p[s.P_I_BALL] = 0.1 * p[s.P_M_BALL] * D * D
    # groove-curvature-centre circles as in the quasi-static model: the inner one seen from the outer one
    # at (A sin alpha0, A - P_d/2) (axial, radial) for an angular-contact bearing, (0, A - P_d/2) otherwise
    A = (b.f_i + b.f_o - 1.0) * D
    A_axial = A * math.sin(alpha0) if b.kind == "angular_contact" else 0.0
    A_radial = A - 0.5 * Pd
    p[s.P_RHO_I] = 0.5 * b.dm + (b.f_i - 0.5) * D * math.cos(alpha0)
    p[s.P_Z_I] = A_axial
    p[s.P_RHO_O] = p[s.P_RHO_I] - A_radial
    p[s.P_Z_O] = 0.0
    p[s.P_RG_I] = (b.f_i - 0.5) * D
    p[s.P_RG_O] = (b.f_o - 0.5) * D
    p[s.P_KH_I] = hertz_stiffness(Rx_i, Ry_i, E_red, *ci)
    p[s.P_KH_O] = hertz_stiffness(Rx_o, Ry_o, E_red, *co)
    pack(p, s, "P_", contact_terms(b, sc, rc))
    p[s.P_ALPHA_E] = CONSTANTS.alpha_e
    p[s.P_KT_RATIO] = kt_ratio
    p[s.P_V_REG] = V_REG
    rest = ball_rest_position(b, Pd, p[s.P_KH_I], p[s.P_KH_O])
    _pack_cage(p, b, rest)
    p[s.P_M_RING] = ring_mass(b) if mass is None else float(mass)
    p[s.P_I_RING], p[s.P_IP_RING] = ring_inertia(b, p[s.P_M_RING])
    if inertia is not None:
        p[s.P_I_RING] = float(inertia)
    pack_settings(p, settings)  # after the ring's own mass and inertia, which the shaft's modal mass adds to
    # the support in the tilts: its spring and damper spread over the pitch circle
    lever = pitch_lever(b.dm)
    p[s.P_KT_SUPPORT] = lever * p[s.P_K_SUPPORT]
    p[s.P_CT_SUPPORT] = lever * p[s.P_C_SUPPORT]
    _pack_hertz_scales(p, rc)
    p[s.P_CHATTER] = CHATTER_STEPS
    p[s.P_DAMPING_STOP] = DAMPING_STOP
    write_blocks(
        p,
        (
            (s.P_FILM_TABLE, film_table_array(b, lubricant, sc.film_correction, film_tables)),
            (s.P_CAPACITANCE_BLOCK, capacitance_block(sc)),
        ),
    )
    p[s.P_MU_LIM] = lubricant.traction_limit
    p[s.P_S_TRACTION] = lubricant.traction_slip
    p[s.P_FILM_RATE] = FILM_RATE
    p[s.P_REFRESH] = 1
    return p, truncation, rest


def _pack_cage(p, bearing, rest):
    """The cage balls and their guide into p (the balls' mass and Hertz constants already in it); rest = the balls'
    (radius, z) at rest, whose circle the guide holds the cage balls on."""
    b = bearing
    D = b.D
    E_c, nu_c, rho_c = cage_material(b)
    pitch = rest[0]
    # a given radius fits between the balls on the pitch circle (the bearing file's reader checks it); an estimated
    # one leaves the pocket play on the circle of the balls at rest
    room = cage_ball_room(D, 2.0 * pitch, b.Z)
    R_z = b.cage_ball_radius if b.cage_ball_radius > 0.0 else room - CONSTANTS.cage_pocket_play * D
    if R_z <= 0.0:
        raise InputError(
            f"bearing '{b.name}': no room for cage balls between {b.Z} balls of {D} m "
            f"(estimated cage-ball radius {R_z:.3g} m)"
        )
    E_star = 1.0 / ((1.0 - b.ball.nu**2) / b.ball.E + (1.0 - nu_c**2) / E_c)
    R_eq = 0.5 * D * R_z / (0.5 * D + R_z)
    # the cage's inertia: a file that gives the cage's mass shares it over the Z cage balls (their contacts
    # keep the cage balls' radius and material); otherwise solid cage balls of the cage material (seeds)
    p[s.P_M_CAGE] = b.cage_mass / b.Z if b.cage_mass > 0.0 else rho_c * 4.0 / 3.0 * math.pi * R_z**3
    p[s.P_R_CAGE] = R_z
    p[s.P_K_CB] = 4.0 / 3.0 * E_star * math.sqrt(R_eq)
    p[s.P_K_GUIDE] = 4.0 / 3.0 * E_star * math.sqrt(R_z)
    p[s.P_R_GUIDE] = pitch
    p[s.P_Z_GUIDE] = rest[1]
    p[s.P_GUIDE_GAP] = 0.0
    p[s.P_ZETA_CAGE] = 1.0  # critically damped contacts (docs/dem.md, Cage)
    m_eff = p[s.P_M_BALL] * p[s.P_M_CAGE] / (p[s.P_M_BALL] + p[s.P_M_CAGE])
    p[s.P_C_CB] = 2.0 * p[s.P_ZETA_CAGE] * math.sqrt(1.5 * p[s.P_K_CB] * m_eff)
    p[s.P_C_GUIDE] = 2.0 * p[s.P_ZETA_CAGE] * math.sqrt(1.5 * p[s.P_K_GUIDE] * p[s.P_M_CAGE])


def _pack_hertz_scales(p, race_contacts):
    """Per race into p: the physical penetration limit (the approach at which the Hertz pressure reaches the
    material limit) and the Hertz semi-axes and pressure at 1 N, which the kernel scales by
    Q^(1/3) = K_h^(1/3) delta^(1/2); p holds the Hertz constants K_h already."""
    _, Rx_i, Ry_i, Rx_o, Ry_o, ci, co, E_red = race_contacts
    for race, (Rx, Ry, c) in enumerate(((Rx_i, Ry_i, ci), (Rx_o, Ry_o, co))):
        q_lim = (P_MAX_ERROR / hertz_contact(1.0, Rx, Ry, E_red, *c)[3]) ** 3
        p[s.P_DELTA_LIM_I + race] = (q_lim / p[s.P_KH_I + race]) ** (2.0 / 3.0)
    for race, (Rx, Ry, c) in enumerate(((Rx_i, Ry_i, ci), (Rx_o, Ry_o, co))):
        a1, b1, _, p1 = hertz_contact(1.0, Rx, Ry, E_red, *c)
        cube = p[s.P_KH_I + race] ** (1.0 / 3.0)
        p[s.P_HA_I + s.P_HERTZ_SCALE_STRIDE * race] = a1 * cube
        p[s.P_HB_I + s.P_HERTZ_SCALE_STRIDE * race] = b1 * cube
        p[s.P_HP_I + s.P_HERTZ_SCALE_STRIDE * race] = p1 * cube


def load_limit(par, Z):
    """Largest admissible load (N): the Z balls each at the contact load of the penetration limit of par
    (p_max = 6 GPa); no load distribution shares a load better than equally over all balls."""
    q = min((par[s.P_KH_I + r] * par[s.P_DELTA_LIM_I + r] ** 1.5) for r in (0, 1))
    return Z * q
