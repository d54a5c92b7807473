"""The SKF model for the frictional moment of a ball bearing: an independent reference implementation.

Source: SKF General Catalogue 6000/I EN (2008), section 'Friction', 'The new SKF model for calculation of the
frictional moment' (also SKF Rolling bearings, PUB BU/P1 10000 EN, and skf.com 'The SKF model for calculating the
frictional moment'). What was read, and where:
- verified against the catalogue's text (the yumpu copy of 'SKF - Rolling Bearings', document 55668573, p. 105
  and p. 106): M_sl = G_sl mu_sl, mu_sl = phi_bl mu_bl + (1 - phi_bl) mu_EHL, phi_bl = exp(-2.6e-8 (n nu)^1.4 d_m),
  mu_bl 'generally ~ 0.15', mu_EHL = 0.05 for mineral oils (p. 105); Table 2a, the forms of G_rr and G_sl for deep
  groove ball bearings with F_a = 0 and for angular contact ball bearings with F_g = R3 d_m^4 n^2 and
  F_g = S3 d_m^4 n^2 (p. 106). Later editions give mu_bl = 0.12 for n > 0 (not read here; 0.15 is kept).
- not read in an SKF text (the pages' equations are images, Table 2b and the drag pages were not reachable):
  phi_ish's constants (1.84e-9, 1.28, 0.64; skf.com's 'Inlet shear heating reduction factor' page names the
  terms only), phi_rs with K_rs and K_Z, Table 2b's R_i, S_i and the drag-loss equations. Each value and equation
  here equals its transcription in independent public implementations of the SKF model (GitHub code read for
  this comparison: the 62 series constants and the drag equations in one, the 72 B constants, K_Z = 4.4 and
  K_rs = 3e-8 in another, phi_ish's and phi_rs's forms in both); they stay UNVERIFIED against the catalogue
  (docs/lubrication_method.md, section 5). The drag-loss factor V_M is read from a diagram the catalogue does not
  tabulate: it is an input here, never a fitted number.

Units as the catalogue: n r/min, nu mm^2/s (operating kinematic viscosity), d, D, d_m mm, loads N, moments N.mm.

  M = phi_ish phi_rs M_rr + M_sl + M_seal + M_drag                      (M_seal = 0: open bearings)
  M_rr = G_rr (nu n)^0.6
  M_sl = G_sl mu_sl,  mu_sl = phi_bl mu_bl + (1 - phi_bl) mu_EHL,  phi_bl = exp(-2.6e-8 (n nu)^1.4 d_m),
         mu_bl = 0.15, mu_EHL = 0.05 (mineral oil)
  phi_ish = 1 / (1 + 1.84e-9 (n d_m)^1.28 nu^0.64)
  phi_rs = exp(-K_rs nu n (d + D) sqrt(K_Z / (2 (D - d)))),  K_rs = 3e-8 low-level oil bath and oil jet,
           6e-8 grease and oil-air; K_Z = 3.1 deep groove, 4.4 single-row angular contact
  deep groove (F_a = 0): G_rr = R1 d_m^1.96 F_r^0.54,  G_sl = S1 d_m^-0.26 F_r^(5/3)
  angular contact: G_rr = R1 d_m^1.97 (F_r + F_g + R2 F_a)^0.54, F_g = R3 d_m^4 n^2,
                   G_sl = S1 d_m^0.26 ((F_r + F_g)^(4/3) + S2 F_a^(4/3)), F_g = S3 d_m^4 n^2
  drag (ball bearings, oil bath of level H from the lowest point of the outer raceway):
    M_drag = 0.4 V_M K_ball d_m^5 n^2 + 1.093e-7 n^2 d_m^3 (n d_m^2 f_t / nu)^-1.379 R_s,
    K_ball = i_rw K_Z (d + D)/(D - d) 1e-12,  R_s = 0.36 d_m^2 (t - sin t) f_A,  f_A = 0.05 K_Z (D + d)/(D - d),
    t = 2 acos((0.6 d_m - H)/(0.6 d_m)) for H < 1.2 d_m (2 pi above),  f_t = sin(t/2) for t <= pi (1 above).
"""

import math

# Geometry constants (SKF catalogue Table 2b, 'Geometric constants for rolling and sliding frictional moments';
# unverified against the catalogue, equal to independent public transcriptions, module docstring): deep groove
# 62 series; single-row angular contact 72 B (40 deg contact angle).
SERIES = {
    "62": {"kind": "deep_groove", "R1": 3.9e-7, "R2": 1.7, "S1": 3.23e-3, "S2": 36.5, "K_Z": 3.1},
    "72 B": {
        "kind": "angular_contact",
        "R1": 5.03e-7,
        "R2": 1.97,
        "R3": 1.90e-12,
        "S1": 1.30e-2,
        "S2": 0.68,
        "S3": 1.91e-12,
        "K_Z": 4.4,
    },
}
# K_rs: 3e-8 low-level oil bath and oil jet, 6e-8 grease and oil-air (unverified, module docstring)
K_RS = {"oil_bath": 3e-8, "oil_jet": 3e-8, "oil_air": 6e-8, "grease": 6e-8}
MU_BL = 0.15  # catalogue p. 105 'generally ~ 0.15' (verified)
MU_EHL_MINERAL = 0.05  # catalogue p. 105, mineral oils (verified)


def phi_ish(n, dm, nu):
    """Inlet shear heating reduction factor (-)."""
    return 1.0 / (1.0 + 1.84e-9 * (n * dm) ** 1.28 * nu**0.64)


def phi_rs(n, nu, d, D, K_Z, K_rs):
    """Kinematic replenishment / starvation reduction factor (-)."""
    return math.exp(-K_rs * nu * n * (d + D) * math.sqrt(K_Z / (2.0 * (D - d))))


def rolling_sliding(series, n, nu, d, D, F_r, F_a, mu_ehl=MU_EHL_MINERAL):
    """(M_rr, M_sl) (N.mm) of an open bearing of the series at n (r/min), nu (mm^2/s), loads F_r, F_a (N)."""
    c = SERIES[series]
    dm = 0.5 * (d + D)
    if c["kind"] == "deep_groove":
        if F_a != 0.0:
            raise ValueError("deep groove: only the radial form (F_a = 0) is written here")
        G_rr = c["R1"] * dm**1.96 * F_r**0.54
        G_sl = c["S1"] * dm**-0.26 * F_r ** (5.0 / 3.0)
    else:
        F_g_rr = c["R3"] * dm**4 * n**2
        F_g_sl = c["S3"] * dm**4 * n**2
        G_rr = c["R1"] * dm**1.97 * (F_r + F_g_rr + c["R2"] * F_a) ** 0.54
        G_sl = c["S1"] * dm**0.26 * ((F_r + F_g_sl) ** (4.0 / 3.0) + c["S2"] * F_a ** (4.0 / 3.0))
    phi_bl = math.exp(-2.6e-8 * (n * nu) ** 1.4 * dm)
    mu_sl = phi_bl * MU_BL + (1.0 - phi_bl) * mu_ehl
    return G_rr * (nu * n) ** 0.6, G_sl * mu_sl


def drag(series, n, nu, d, D, H, V_M, rows=1):
    """(first term / V_M, second term) of M_drag (N.mm): the V_M term per unit V_M and the R_s term, oil level H (mm)."""
    K_Z = SERIES[series]["K_Z"]
    dm = 0.5 * (d + D)
    K_ball = rows * K_Z * (d + D) / (D - d) * 1e-12
    if H < 1.2 * dm:
        t = 2.0 * math.acos((0.6 * dm - H) / (0.6 * dm))
    else:
        t = 2.0 * math.pi
    f_t = math.sin(0.5 * t) if t <= math.pi else 1.0
    f_A = 0.05 * K_Z * (D + d) / (D - d)
    R_s = 0.36 * dm**2 * (t - math.sin(t)) * f_A
    second = 1.093e-7 * n**2 * dm**3 * (n * dm**2 * f_t / nu) ** -1.379 * R_s if H > 0.0 else 0.0
    return 0.4 * K_ball * dm**5 * n**2, second


def frictional_moment(series, n, nu, d, D, F_r, F_a, method=None, H=0.0, V_M=None):
    """Dict of the SKF terms (N.mm): rr (bare M_rr), sl, phi_ish, phi_rs, rolling (phi_ish phi_rs M_rr), drag_rs
    (the drag's R_s term), drag_per_VM (its V_M term per unit V_M), total (rolling + sl, + drag with V_M given).
    method None: the bare model (phi_ish = phi_rs = 1, no drag), as the product's flooded method."""
    M_rr, M_sl = rolling_sliding(series, n, nu, d, D, F_r, F_a)
    dm = 0.5 * (d + D)
    out = {"rr": M_rr, "sl": M_sl, "phi_ish": 1.0, "phi_rs": 1.0, "drag_rs": 0.0, "drag_per_VM": 0.0}
    if method is not None:
        out["phi_ish"] = phi_ish(n, dm, nu)
        out["phi_rs"] = phi_rs(n, nu, d, D, SERIES[series]["K_Z"], K_RS[method])
    if method == "oil_bath":
        out["drag_per_VM"], out["drag_rs"] = drag(series, n, nu, d, D, H, V_M)
    out["rolling"] = out["phi_ish"] * out["phi_rs"] * M_rr
    out["total"] = out["rolling"] + M_sl + (out["drag_rs"] + V_M * out["drag_per_VM"] if V_M is not None else 0.0)
    return out
