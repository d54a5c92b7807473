"""The lubrication methods of the quasi-static fidelity against the SKF friction model, over speed.

Product: QuasiStaticModel with the shipped quasi-static scene (centrifugal, gyroscopic, torque on, outer race
control) and the scene option `lubrication` = flooded | oil_bath | oil_jet | oil_air | grease at its documented
defaults (models.lubrication.METHODS, docs/lubrication_method.md; none fitted to SKF). SKF: benchmarks.skf_friction
(independent reference, its sources and unverified constants there: bare model for flooded; phi_ish, phi_rs with
the method's K_rs for the others; its drag only for the bath).
Cases: 6208 (SKF 62 series) radial F_r = 3000 N, 955-9549 rpm; B7214C (72 series, SKF's 72 B constants: see the
caveat in the report) axial F_a = 800 N (the Rabreau rig's preload), 1000-15000 rpm (d_m n = 1.46e6 mm/min, the
oil-lubricated speed range of a 72-series spindle bearing). Oil iso_vg68_mineral at 40 C; the SKF model gets
the same operating viscosity nu = eta/rho. 'product' is the contact torque (Houpert components with the method's
film factors) without the drag; 'SKF' is phi_ish phi_rs M_rr + M_sl (bare M_rr + M_sl for flooded); ratio =
product / SKF. Exponents: least-squares slope of ln M over ln n on the whole range. Torques in mN.m.
The oil jet's starvation against SKF's form: per speed, the inlet oil layer h_oil at which the product's
Hamrock-Dowson starvation factor of the most loaded inner contact equals SKF's phi_rs (K_rs = 3e-8), found by
bisection in log h_oil over [0.01, 20] um, and the contact torque ratio with it. A constant layer follows SKF's
exponential form over speed only if that layer is about constant.
Run: python -m benchmarks.lubrication_skf -> docs/reports/lubrication_skf.md and .png
"""

import math
from dataclasses import replace
from pathlib import Path

import numpy as np

from bearing_fmu.kernels.lubricant import lubricant_state
from bearing_fmu.models.quasi_static import QuasiStaticModel
from bearing_fmu.params import load_bearing, load_lubricant
from bearing_fmu.scene import Scene

from . import skf_friction as skf
from .render import cli

LUBRICANT = "iso_vg68_mineral"
T_OIL = 313.15
SCENE = Scene.from_toml(Path(__file__).resolve().parent.parent / "bearing_fmu" / "scenes" / "quasi_static.toml")
METHODS = ("flooded", "oil_bath", "oil_jet", "oil_air", "grease")
CASES = (
    {"bearing": "6208", "series": "62", "load": ("F_y", 3000.0), "F_r": 3000.0, "F_a": 0.0,
     "speeds": (955.0, 1910.0, 2865.0, 3820.0, 5730.0, 7640.0, 9549.0)},
    {"bearing": "B7214C", "series": "72 B", "load": ("F_z", 800.0), "F_r": 0.0, "F_a": 800.0,
     "speeds": (1000.0, 2000.0, 4000.0, 6000.0, 8000.0, 10000.0, 12000.0, 15000.0)},
)  # fmt: skip
RPM = math.pi / 30.0
CAVEAT = (
    "Caveat: SKF's general catalogue gives constants for the 72 B series (40 deg contact angle); the B7214C has "
    "15 deg. The SKF column is that series' model at the same size and load, not a model of this bearing."
)


def exponent(n, M):
    """Least-squares slope of ln M over ln n."""
    return float(np.polyfit(np.log(n), np.log(M), 1)[0])


def product(case, method):
    """Per speed: (torque, torque_drag, phi_ish_inner, phi_rs_inner) (N.m, -)."""
    m = QuasiStaticModel(case["bearing"], LUBRICANT, replace(SCENE, lubrication=method))
    rows = []
    for n in case["speeds"]:
        r = m.evaluate(omega=n * RPM, T_oil=T_OIL, **{case["load"][0]: case["load"][1]})
        rows.append((r["torque"], r.get("torque_drag", 0.0), r.get("phi_ish_inner", 1.0), r.get("phi_rs_inner", 1.0)))
    return np.array(rows)


def skf_rows(case, method, nu_cSt, level_mm):
    """Per speed: (phi_ish phi_rs M_rr + M_sl, drag R_s term, drag per unit V_M (N.m), phi_ish, phi_rs)."""
    b = load_bearing(case["bearing"])
    args = (nu_cSt, b.bore * 1e3, b.outer_diameter * 1e3, case["F_r"], case["F_a"])
    terms = [skf.frictional_moment(case["series"], n, *args, None if method == "flooded" else method, level_mm)
             for n in case["speeds"]]  # fmt: skip
    return np.array([(1e-3 * (s["rolling"] + s["sl"]), 1e-3 * s["drag_rs"], 1e-3 * s["drag_per_VM"], s["phi_ish"],
                      s["phi_rs"]) for s in terms])  # fmt: skip


def compare(case, method, nu):
    """Table rows of one bearing and method over speed, its summary row and its two plotted series."""
    n = np.array(case["speeds"])
    level_mm = 0.5 * load_bearing(case["bearing"]).D * 1e3  # the bath's default level: centre of the lowest ball
    p, s = product(case, method), skf_rows(case, method, nu, level_mm)
    contact = p[:, 0] - p[:, 1]
    ratio = contact / s[:, 0]
    rows = []
    for k, speed in enumerate(n):
        if method == "oil_bath":
            drag = [1e3 * p[k, 1], 1e3 * s[k, 1], (p[k, 1] - s[k, 1]) / s[k, 2]]
        else:
            drag = [1e3 * p[k, 1] if p[k, 1] > 0.0 else None, None, None]
        rows.append([method, speed, 1e3 * contact[k], 1e3 * s[k, 0], ratio[k], f"{p[k, 2]:.3f} / {s[k, 3]:.3f}",
                     f"{p[k, 3]:.3f} / {s[k, 4]:.3f}"] + drag)  # fmt: skip
    e_d = exponent(n, p[:, 1]) if p[-1, 1] > 0.0 else None
    summary = [case["bearing"], method, ratio.min(), ratio.max(), ratio[-1], exponent(n, contact)]
    summary += [exponent(n, s[:, 0]), e_d]
    color = f"C{METHODS.index(method)}"
    series = [dict(x=n.tolist(), y=(1e3 * m).tolist(), style=color + style, label=f"{who} {method}")
              for m, style, who in ((contact, "--", "product"), (s[:, 0], "-", "SKF"))]  # fmt: skip
    return rows, summary, series


COLUMNS = ["method", "n (rpm)", "product", "SKF", "ratio", "phi_ish product / SKF", "phi_rs product / SKF",
           "drag product", "SKF drag R_s term", "V_M equivalent"]  # fmt: skip
SUMMARY = ["bearing", "method", "ratio min", "ratio max", "ratio at top speed", "exponent product", "exponent SKF",
           "exponent of the product's drag"]  # fmt: skip
DRAG = (
    "The drag: SKF's V_M term needs the drag-loss factor V_M of a catalogue diagram (not read here), so the table "
    "gives the V_M at which SKF's drag equals the product's (Harris ball drag at the default level, the centre of the "
    "lowest ball): compare it with the diagram's V_M at H/d_m of the case. SKF's R_s term alone is listed beside it."
)


LAYER_RANGE = (1e-8, 20e-6)  # m: the bisection's bracket of the inlet oil layer


def phi_rs_at(case, layer, n):
    """The product's oil-jet starvation factor (inner, most loaded) and contact torque (N.m) at inlet layer `layer`
    (m) and speed n (rpm)."""
    m = QuasiStaticModel(case["bearing"], LUBRICANT, replace(SCENE, lubrication="oil_jet", inlet_oil_layer=layer))
    r = m.evaluate(omega=n * RPM, T_oil=T_OIL, **{case["load"][0]: case["load"][1]})
    return r["phi_rs_inner"], r["torque"] - r["torque_drag"]


def equivalent_layer(case, n, target):
    """(layer (m), contact torque (N.m)) at which the product's phi_rs equals `target`, or None above the bracket."""
    low, high = (math.log(x) for x in LAYER_RANGE)
    if phi_rs_at(case, math.exp(high), n)[0] < target:
        return None
    for _ in range(40):  # 1e-5 of the log bracket
        mid = 0.5 * (low + high)
        if phi_rs_at(case, math.exp(mid), n)[0] < target:
            low = mid
        else:
            high = mid
    return math.exp(high), phi_rs_at(case, math.exp(high), n)[1]


def jet_layer_rows(case, nu):
    """Per speed: n, SKF's phi_rs, the product's at the default layer, the equivalent layer (um), the torque ratio
    to SKF with it."""
    s = skf_rows(case, "oil_jet", nu, None)
    rows = []
    for k, n in enumerate(case["speeds"]):
        default = phi_rs_at(case, 20e-6, n)[0]
        found = equivalent_layer(case, n, s[k, 4])
        layer, ratio = (None, None) if found is None else (1e6 * found[0], found[1] / s[k, 0])
        rows.append([case["bearing"], n, s[k, 4], default, layer, ratio])
    return rows


def measure():
    eta, _, rho = lubricant_state(T_OIL, load_lubricant(LUBRICANT).array)
    nu = eta / rho * 1e6
    blocks = [{"text": "Operating viscosity nu = {nu:.1f} mm^2/s for both.", "values": {"nu": nu}}]
    summaries, panels = [], []
    formats = ["{}", "{:.0f}", "{:.1f}", "{:.1f}", "{:.2f}", "{}", "{}", "{:.3f}", "{:.3f}", "{:.2e}"]
    for case in CASES:
        rows, series = [], []
        for method in METHODS:
            r, summary, s = compare(case, method, nu)
            rows, series, summaries = rows + r, series + s, summaries + [summary]
        caption = f"{case['bearing']} (SKF {case['series']}), {case['load'][0]} = {case['load'][1]:.0f} N."
        caption += " " + CAVEAT if case["series"] == "72 B" else ""
        blocks.append({"table": dict(caption=caption, columns=COLUMNS, formats=formats, rows=rows)})
        panels.append(dict(title=f"{case['bearing']}: contact torque, product (--) vs SKF (-)", xlabel="n (rpm)",
                           ylabel="M (mN.m)", xscale="log", yscale="log", series=series))  # fmt: skip
    jet = [row for case in CASES for row in jet_layer_rows(case, nu)]
    jet_caption = (
        "Oil jet: the inlet layer at which the product's phi_rs (most loaded inner contact) equals SKF's, and the "
        "contact torque ratio product / SKF with it (the default layer is 20 um)."
    )
    jet_columns = ["bearing", "n (rpm)", "SKF phi_rs", "product phi_rs at 20 um", "equivalent layer (um)",
                   "ratio with it"]  # fmt: skip
    jet_formats = ["{}", "{:.0f}", "{:.3f}", "{:.3f}", "{:.3g}", "{:.2f}"]
    blocks.append({"table": dict(caption=jet_caption, columns=jet_columns, formats=jet_formats, rows=jet)})
    caption = "Summary: ratios product / SKF (without drag) and speed exponents."
    blocks += [{"table": dict(caption=caption, columns=SUMMARY, formats=["{}"] * 2 + ["{:.2f}"] * 6, rows=summaries)},
               {"text": DRAG}, {"figure": dict(file="lubrication_skf.png", caption="torque over speed", panels=panels,
                                               size=(12, 4.8))}]  # fmt: skip
    title, about = "Lubrication methods against the SKF friction model", __doc__.split("\n\n")[1].split("Run:")[0]
    return dict(name="lubrication_skf", title=title, about=about, blocks=blocks, metrics=[])


def main(argv=None):
    cli(measure, "lubrication_skf")


if __name__ == "__main__":
    main()
