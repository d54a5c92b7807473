"""Houpert friction torque of the quasi-static model vs Palmgren's M0 + M1 (the cross-check of docs/houpert_torque.md).

Houpert: QuasiStaticModel (scene 'qs': centrifugal, gyroscopic, torque on, race control 'outer'),
torque = total contact power / omega, split into EHL rolling, hysteresis, Heathcote and spin
(kernels.torque, docs/houpert_torque.md). Palmgren (note 4d, kernels.torque): M0 (viscous, with
f0 by bearing kind and lubrication) + M1 = f1 P1 dm, f1 = z (P0/C0)^y, C0 from ISO 76
(iso76_static_rating at the nominal contact angle). No model constant is tuned here.

Grid: (a) 6208 deep groove, radial F_y = 500..6000 N, 500..10000 rpm, Palmgren with oil bath
(f0 = 2) and oil mist (f0 = 1); (b) B7214C angular contact, axial F_z = 200..3000 N,
1000..15000 rpm, Palmgren with oil mist / oil-air (f0 = 1.7); lubricant iso_vg68_mineral at
T_oil = 313.15 and 333.15 K (kinematic viscosity eta/rho0 in cSt for Palmgren).
Run: python -m benchmarks.torque_palmgren -> docs/reports/torque_palmgren.md and .png
"""

import math

import numpy as np

from bearing_fmu.kernels import contacts as ck
from bearing_fmu.kernels import torque as tk
from bearing_fmu.kernels.lubricant import lubricant_state
from bearing_fmu.models.quasi_static import QuasiStaticModel
from bearing_fmu.params import load_bearing
from bearing_fmu.scene import Scene

from .common import REPORTS, machine, write_report

LUBRICANT = "iso_vg68_mineral"
TEMPERATURES = (313.15, 333.15)
SCENE = Scene(
    name="qs", fidelity="quasi_static", centrifugal=True, gyroscopic=True, torque=True, stiffness=False, tolerance=1e-10
)
COMPONENTS = ("EHL rolling", "hysteresis", "Heathcote", "spin")

# ISO 76 static equivalent load P0 = max(X0 F_r + Y0 F_a, F_r) (ISO 76 table; estimated, docs/decisions.md, unverified sources):
# single-row deep groove X0 = 0.6, Y0 = 0.5; single-row angular contact 15 deg X0 = 0.5, Y0 = 0.46.
STATIC_FACTORS = {tk.PALMGREN_DEEP_GROOVE: (0.6, 0.5), tk.PALMGREN_ANGULAR_CONTACT: (0.5, 0.46)}
NU_N_LIMIT = 2000.0  # cSt.rpm: below it Palmgren's M0 formula is replaced by its constant floor
DM_N_HIGH_SPEED = 1e6  # mm.rpm: usual threshold of "high-speed" ball bearings (not a Palmgren number)

CASES = (
    {
        "bearing": "6208",
        "load": "F_y",
        "loads": (500.0, 1500.0, 3000.0, 6000.0),
        "speeds": (500.0, 1000.0, 3000.0, 6000.0, 10000.0),
        "kind": tk.PALMGREN_DEEP_GROOVE,
        "f0": {
            "oil bath": tk.palmgren_f0(tk.PALMGREN_DEEP_GROOVE, tk.LUB_OIL_BATH),
            "oil mist": tk.palmgren_f0(tk.PALMGREN_DEEP_GROOVE, tk.LUB_OIL_MIST),
        },
    },
    {
        "bearing": "B7214C",
        "load": "F_z",
        "loads": (200.0, 800.0, 1500.0, 3000.0),
        "speeds": (1000.0, 3000.0, 6000.0, 10000.0, 15000.0),
        "kind": tk.PALMGREN_ANGULAR_CONTACT,
        "f0": {"oil mist/oil-air": tk.palmgren_f0(tk.PALMGREN_ANGULAR_CONTACT, tk.LUB_OIL_MIST)},
    },
)


def static_equivalent_load(kind, F_r, F_a):
    X0, Y0 = STATIC_FACTORS[kind]
    return max(X0 * abs(F_r) + Y0 * abs(F_a), abs(F_r))


def palmgren(kind, f0, nu_cSt, n_rpm, F_r, F_a, b):
    """(M0, M1, f1, P0/C0) in N.m for one bearing (alpha: nominal contact angle)."""
    C0 = tk.iso76_static_rating(b.Z, b.D, b.dm, b.alpha0)
    P0 = static_equivalent_load(kind, F_r, F_a)
    P1 = tk.palmgren_equivalent_load(kind, F_r, F_a, b.alpha0)
    f1 = tk.palmgren_f1(kind, P0, C0)
    return (tk.palmgren_viscous_torque(f0, nu_cSt, n_rpm, b.dm), tk.palmgren_load_torque(f1, P1, b.dm), f1, P0 / C0)


def run_case(case):
    rows = []
    model = QuasiStaticModel(case["bearing"], LUBRICANT, SCENE, race_control="outer")
    b = model.bearing
    radial = case["load"] in ("F_x", "F_y")
    for T in TEMPERATURES:
        eta, xi, rho0 = lubricant_state(T, model.lubricant.array)
        nu = eta / rho0 * 1e6  # cSt = mm^2/s
        for F in case["loads"]:
            for n in case["speeds"]:
                omega = n * math.pi / 30.0
                res = model.evaluate(omega=omega, T_oil=T, **{case["load"]: F})
                comps = model.out[ck.CO_P_EHL : ck.CO_P_EHL + tk.TL_SIZE] / omega
                F_r, F_a = (F, 0.0) if radial else (0.0, F)
                row = {
                    "bearing": case["bearing"],
                    "T": T,
                    "nu": nu,
                    "F": F,
                    "n": n,
                    "omega": omega,
                    "nu_n": nu * n,
                    "dm_n": b.dm * 1e3 * n,
                    "M_H": res["torque"],
                    "comps": comps.copy(),
                    "Lambda": min(res["Lambda_inner"], res["Lambda_outer"]),
                    "alpha_i": res["alpha_inner"],
                    "alpha_o": res["alpha_outer"],
                    "n_loaded": res["n_loaded"],
                    "p_max": res["p_max"],
                    "warnings": list(model.warnings),
                    "palmgren": {},
                }
                for label, f0 in case["f0"].items():
                    M0, M1, f1, p0c0 = palmgren(case["kind"], f0, nu, n, F_r, F_a, b)
                    row["palmgren"][label] = (M0, M1)
                    row["f1"], row["P0_C0"] = f1, p0c0
                rows.append(row)
    return rows


def _label(r):
    return f"{r['bearing']} {r['F']:.0f} N {r['n']:.0f} rpm {r['T'] - 273.15:.0f} C"


def in_domain(r):
    """Palmgren's domain as read here: M0 formula branch, not boundary film, moderate speed."""
    return r["nu_n"] >= NU_N_LIMIT and r["Lambda"] > 1.0 and r["dm_n"] <= DM_N_HIGH_SPEED


def diagnose(r, label, ratio, other):
    """Reasons why a point lies outside [0.5, 2] (list of short strings)."""
    M0, M1 = r["palmgren"][label]
    ehl, _, heath, _ = r["comps"]
    why = []
    if r["nu_n"] < NU_N_LIMIT:
        why.append(f"nu n = {r['nu_n']:.0f} < 2000: M0 on its constant floor")
    if ratio < 0.5:
        why.append(
            f"light load (P0/C0 = {r['P0_C0']:.3f}): M0 is {100 * M0 / (M0 + M1):.0f} % of Palmgren and "
            f"load-independent, Houpert's EHL rolling force ~ Q^0.466 (starved-inlet fit) gives "
            f"EHL/M0 = {ehl / M0:.2f}"
        )
    if ratio > 2.0:
        if r["Lambda"] <= 1.0:
            why.append(
                f"boundary film (Lambda_min = {r['Lambda']:.2f} <= 1, mu = 0.1): Heathcote sliding "
                f"{heath:.3f} N.m alone is {heath / M1:.1f} x M1; Palmgren assumes a well-lubricated bearing"
            )
        if r["P0_C0"] > 0.2:
            why.append(f"heavy load (P0/C0 = {r['P0_C0']:.2f})")
    if r["dm_n"] > DM_N_HIGH_SPEED:
        why.append(f"high speed (dm n = {r['dm_n']:.2g} mm.rpm)")
    for olabel, oratio in other.items():
        if 0.5 <= oratio <= 2.0:
            why.append(f"inside with the {olabel} f0 (ratio {oratio:.2f}): f0 uncertainty")
    return why


def breakdown_rows(rows, picks):
    out = []
    for r in rows:
        if (r["bearing"], r["F"], r["n"], r["T"]) in picks:
            out.append(r)
    return out


def main():
    all_rows = [run_case(case) for case in CASES]
    rows6208, rows7214 = all_rows
    C0 = {b.name: tk.iso76_static_rating(b.Z, b.D, b.dm, b.alpha0) for b in map(load_bearing, ("6208", "B7214C"))}
    variants = [
        ("6208", "oil bath", rows6208),
        ("6208", "oil mist", rows6208),
        ("B7214C", "oil mist/oil-air", rows7214),
    ]
    f0s = {("6208", k): v for k, v in CASES[0]["f0"].items()} | {("B7214C", k): v for k, v in CASES[1]["f0"].items()}
    nus = sorted({r["nu"] for r in rows6208})

    lines = [
        "# Houpert friction torque (quasi-static model) vs Palmgren M0 + M1",
        "",
        "Generated by `python -m benchmarks.torque_palmgren` on " + machine() + ". No model constant was tuned "
        "for this comparison.",
        "",
        "## Set-up",
        "",
        "- **Houpert** (the model): `QuasiStaticModel(bearing, 'iso_vg68_mineral', scene, race_control='outer')`, "
        "scene `qs` (quasi-static, centrifugal and gyroscopic on, torque on, tolerance 1e-10). Torque = total "
        "contact power / omega. Components are EHL rolling (Houpert 1987 force, power 2 F_R u), Tabor "
        "hysteresis (alpha_h = 0.007), Heathcote sliding and spin (Coulomb mu(Lambda): 0.1 for Lambda <= 1, "
        "down to 0.01 at Lambda >= 3). There is no cage, drag, churning or seal term "
        "(docs/houpert_torque.md, kernels/torque.py).",
        "- **Palmgren** (note section 4d, `kernels.torque`): M = M0 + M1. M0 = 0.1 f0 (nu n)^(2/3) dm^3 N.m "
        "(nu in cSt, n in rpm, dm in m). M1 = f1 P1 dm, f1 = z (P0/C0)^y (deep groove 0.0005, 0.55; angular "
        "contact 0.001, 0.33). P1 comes from `palmgren_equivalent_load` (F_r for the radial 6208, F_a for the "
        "axial B7214C). P0 is the ISO 76 static equivalent load max(X0 F_r + Y0 F_a, F_r) with X0, Y0 = "
        "0.6, 0.5 (deep groove) and 0.5, 0.46 (angular contact 15 deg), **unverified** (docs/decisions.md, unverified sources). "
        f"C0 = `iso76_static_rating` at the nominal angle: 6208 {C0['6208'] / 1e3:.1f} kN, "
        f"B7214C {C0['B7214C'] / 1e3:.1f} kN. The f0 values, z, y and X0/Y0 are all estimates "
        "(Harris tables, docs/houpert_torque.md section 4d; docs/decisions.md, unverified sources).",
        "- **f0**: 6208 oil bath f0 = {:g} and oil mist f0 = {:g}. B7214C oil mist / oil-air f0 = {:g} (the "
        "Rabreau rig is oil-air). The f0 of a given arrangement is itself uncertain by roughly a factor 2 "
        "(deep groove: 1 for mist, 2 for bath; grease 0.7-2).".format(
            f0s[("6208", "oil bath")], f0s[("6208", "oil mist")], f0s[("B7214C", "oil mist/oil-air")]
        ),
        "- **Oil**: iso_vg68_mineral. Palmgren's viscosity is the kinematic viscosity eta/rho0 of "
        "`lubricant_state`: "
        + ", ".join(f"{nu:.1f} cSt at {T - 273.15:.0f} C" for nu, T in zip(sorted(nus, reverse=True), TEMPERATURES))
        + ".",
        "- Grid: 6208 radial F_y = 500, 1500, 3000, 6000 N x 500, 1000, 3000, 6000, 10000 rpm; B7214C axial "
        "F_z = 200, 800, 1500, 3000 N x 1000, 3000, 6000, 10000, 15000 rpm; both at T_oil = 313.15 and "
        "333.15 K. That makes 40 points per bearing.",
        "",
    ]

    # validity
    lines += [
        "## Where Palmgren applies",
        "",
        "Palmgren's M0 + M1 is an empirical fit to bearings running at **moderate speeds and loads**, "
        "**flooded or well lubricated** (full or near-full film) and run in. Its M0 formula holds for "
        "**nu n >= 2000 cSt.rpm**; below that, M0 is held at its constant value 160e-7 f0 dm^3. f1 needs the "
        "static rating C0 (ISO 76 here). Palmgren has no centrifugal or gyroscopic effect, no lubricant "
        "starvation and no dependence on the film thickness. For counting, its domain is read as three "
        "checkable conditions:",
        "",
        "1. nu n >= 2000 cSt.rpm (M0 formula branch);",
        "2. Lambda_min > 1, so the model's film is not in the boundary regime. This is the "
        "reading of 'well lubricated' used here;",
        "3. dm n <= 1e6 mm.rpm: 'moderate speed', using the usual high-speed threshold for ball bearings "
        "(not a number from Palmgren).",
        "",
        "The thresholds in 2 and 3 are choices made for this report, not values taken from the sources.",
        "",
    ]

    # headline
    lines += [
        "## Summary: ratio Houpert / Palmgren",
        "",
        "| bearing | Palmgren f0 | points | ratio min | ratio max | within [0.5, 2] | in domain | "
        "in domain and within [0.5, 2] |",
        "|---|---|---|---|---|---|---|---|",
    ]
    summary = {}
    for name, label, rows in variants:
        ratios = np.array([r["M_H"] / sum(r["palmgren"][label]) for r in rows])
        dom = np.array([in_domain(r) for r in rows])
        ok = (ratios >= 0.5) & (ratios <= 2.0)
        summary[(name, label)] = (ratios, ok, dom)
        lines.append(
            f"| {name} | {label} ({f0s[(name, label)]:g}) | {len(rows)} | {ratios.min():.2f} | "
            f"{ratios.max():.2f} | {ok.sum()}/{len(rows)} | {dom.sum()} | {(ok & dom).sum()}/{dom.sum()} |"
        )
    # f0 band for the 6208
    band_ok = [
        0.5 * sum(r["palmgren"]["oil mist"]) <= r["M_H"] <= 2.0 * sum(r["palmgren"]["oil bath"]) for r in rows6208
    ]
    nu_n_min = min(r["nu_n"] for r in rows6208 + rows7214)
    lines += [
        "",
        f"- The lowest nu n on the grid is {nu_n_min:.0f} cSt.rpm. Every point is on the M0 formula "
        "branch, so the nu n < 2000 floor never applies.",
        f"- 6208 against the f0 band (Houpert within [0.5 x Palmgren(mist), 2 x Palmgren(bath)]): "
        f"{sum(band_ok)}/{len(rows6208)} points.",
        f"- Over both bearings with the lubrication each was specified for (6208 oil bath, B7214C oil-air): "
        f"{summary[('6208', 'oil bath')][1].sum() + summary[('B7214C', 'oil mist/oil-air')][1].sum()}/80 "
        "within a factor 2. With oil mist for both: "
        f"{summary[('6208', 'oil mist')][1].sum() + summary[('B7214C', 'oil mist/oil-air')][1].sum()}/80.",
        "",
    ]

    # outside points
    lines += ["## Points outside [0.5, 2] and why", ""]
    for name, label, rows in variants:
        ratios, ok, dom = summary[(name, label)]
        bad = [(r, q) for r, q, good in zip(rows, ratios, ok) if not good]
        lines.append(f"**{name}, {label}**: {len(bad)} point(s) outside." + ("" if bad else " None."))
        for r, q in bad:
            other = {ol: r["M_H"] / sum(v) for ol, v in r["palmgren"].items() if ol != label}
            lines.append(
                f"- {_label(r)}: ratio {q:.2f}{'' if in_domain(r) else ' (outside the domain)'}; "
                + "; ".join(diagnose(r, label, q, other))
                + "."
            )
        lines.append("")

    lines += _explanations(rows6208, rows7214)

    # breakdown
    picks = {
        ("6208", 500.0, 500.0, 313.15),
        ("6208", 500.0, 10000.0, 313.15),
        ("6208", 3000.0, 3000.0, 313.15),
        ("6208", 6000.0, 500.0, 313.15),
        ("6208", 6000.0, 10000.0, 333.15),
        ("B7214C", 200.0, 1000.0, 313.15),
        ("B7214C", 200.0, 15000.0, 313.15),
        ("B7214C", 3000.0, 1000.0, 313.15),
        ("B7214C", 3000.0, 15000.0, 313.15),
        ("B7214C", 1500.0, 6000.0, 333.15),
    }
    lines += [
        "## Houpert components at selected points (N.m, share of the Houpert total in brackets)",
        "",
        "| point | Lambda_min | EHL rolling | hysteresis | Heathcote | spin | Houpert total | Palmgren M0 | "
        "Palmgren M1 |",
        "|---|---|---|---|---|---|---|---|---|",
    ]
    for r in breakdown_rows(rows6208 + rows7214, picks):
        label = "oil bath" if r["bearing"] == "6208" else "oil mist/oil-air"
        M0, M1 = r["palmgren"][label]
        cells = " | ".join(f"{c:.4f} ({100 * c / r['M_H']:.0f} %)" for c in r["comps"])
        lines.append(f"| {_label(r)} | {r['Lambda']:.2f} | {cells} | {r['M_H']:.4f} | {M0:.4f} ({label}) | {M1:.4f} |")
    other = [1.0 - r["comps"][0] / r["M_H"] for r in rows7214]
    lines += [
        "",
        "For the 6208 (alpha = 0, outer race control), spin is zero. For the B7214C, hysteresis, Heathcote "
        f"and spin together are {100 * min(other):.0f}-{100 * max(other):.0f} % of the total over the grid "
        "(the most at heavy load and low speed). Its torque is mostly EHL rolling resistance.",
        "",
    ]

    # full tables
    for (name, rows), labels in zip(
        (("6208", rows6208), ("B7214C", rows7214)), (("oil bath", "oil mist"), ("oil mist/oil-air",))
    ):
        lines += [
            f"## All points, {name}",
            "",
            "| T (C) | F (N) | n (rpm) | nu n (cSt.rpm) | Lambda_min | Houpert (N.m) | EHL share | "
            + " | ".join(f"M0 {lb} (N.m)" for lb in labels)
            + " | M1 (N.m) | "
            + " | ".join(f"ratio {lb}" for lb in labels)
            + " | in domain |",
            "|---|---|---|---|---|---|---|" + "---|" * len(labels) + "---|" + "---|" * len(labels) + "---|",
        ]
        for r in rows:
            M1 = r["palmgren"][labels[0]][1]
            m0s = " | ".join(f"{r['palmgren'][lb][0]:.4f}" for lb in labels)
            rat = " | ".join(_mark(r["M_H"] / sum(r["palmgren"][lb])) for lb in labels)
            lines.append(
                f"| {r['T'] - 273.15:.0f} | {r['F']:.0f} | {r['n']:.0f} | {r['nu_n']:.3g} | "
                f"{r['Lambda']:.2f} | {r['M_H']:.4f} | {100 * r['comps'][0] / r['M_H']:.0f} % | {m0s} | "
                f"{M1:.4f} | {rat} | {'yes' if in_domain(r) else 'no'} |"
            )
        lines.append("")
    lines.append("Ratios outside [0.5, 2] are in bold. Plot: `torque_palmgren.png`.")
    warn = [(_label(r), w) for r in rows6208 + rows7214 for w in r["warnings"]]
    if warn:
        lines += ["", "Model warnings: " + "; ".join(f"{p}: {w}" for p, w in warn)]
    write_report("torque_palmgren.md", "\n".join(lines) + "\n")
    _plot(variants, REPORTS / "torque_palmgren.png")


def _mark(q):
    return f"{q:.2f}" if 0.5 <= q <= 2.0 else f"**{q:.2f}**"


def _explanations(rows6208, rows7214):
    """Reading of the comparison; every number quoted is computed from the grid."""

    def q(r, label):
        return r["M_H"] / sum(r["palmgren"][label])

    def span(values):
        return f"{min(values):.2f}-{max(values):.2f}"

    spread = [(F, [q(r, "oil mist") for r in rows6208 if r["F"] == F and r["T"] == 313.15]) for F in (500.0, 6000.0)]
    light = [r for r in rows7214 if r["F"] == 200.0 and r["T"] == 313.15]
    lam = [r for r in rows6208 if r["Lambda"] <= 1.0]
    e = [r["comps"][0] / r["palmgren"]["oil bath"][0] for r in rows6208]
    light6208 = [r for r in rows6208 if r["F"] == 500.0]
    heavy = [r for r in rows6208 if r["F"] == 6000.0]
    heath_max = max(r["comps"][2] for r in heavy)
    M1_heavy = heavy[0]["palmgren"]["oil bath"][1]
    mist_bad = [r for r in rows6208 if not 0.5 <= q(r, "oil mist") <= 2.0]
    m1_share = [r["palmgren"]["oil mist/oil-air"][1] / sum(r["palmgren"]["oil mist/oil-air"]) for r in rows7214]
    flood = [q(r, "oil bath") * (1.0 + 0.4 * r["comps"][0] / r["M_H"]) for r in light6208]
    dom = {key: [r for r in rows if in_domain(r)] for key, rows in (("6208", rows6208), ("B7214C", rows7214))}
    dom_ok = {
        lb: sum(0.5 <= q(r, lb) <= 2.0 for r in dom[name])
        for name, lb in (("6208", "oil bath"), ("6208", "oil mist"), ("B7214C", "oil mist/oil-air"))
    }
    return [
        "## Reading",
        "",
        "- **Speed and viscosity scale alike.** Houpert's EHL force goes as (eta u)^0.656, and Palmgren's M0 as "
        "(nu n)^(2/3). At a fixed load, the ratio therefore hardly depends on speed or temperature. For the "
        f"6208 with oil mist at 40 C, over 500-10000 rpm, it spans {span(spread[0][1])} at "
        f"{spread[0][0]:.0f} N and {span(spread[1][1])} at {spread[1][0]:.0f} N. The comparison is governed "
        "by **load**.",
        "- **Load dependence differs by construction.** Palmgren's M0 does not depend on load. Houpert has "
        "no load-independent term: its EHL rolling force grows as Q^0.466 per contact. So Houpert/Palmgren "
        f"rises with load. For the 6208, EHL/M0(bath) runs from {min(e):.2f} to {max(e):.2f} over the grid. "
        f"At the lightest 6208 load (500 N, P0/C0 = {light6208[0]['P0_C0']:.3f}), Houpert is "
        f"{span([q(r, 'oil bath') for r in light6208])} x Palmgren with the oil-bath f0 = 2. Two things cause "
        "this. The bath f0 includes churning and drag of a flooded bearing, which the contact model does not "
        "compute. And the Houpert 1987 force is a moderately starved-inlet fit: Biboulet & Houpert 2010 put "
        "fully flooded forces about 1.4x higher (note 2.4). Scaling only the EHL part by 1.4 would give "
        f"{span(flood)} (an illustration; not applied to the model). With the oil-mist f0 the same points "
        f"give {span([q(r, 'oil mist') for r in light6208])}.",
        f"- **Boundary film at low speed on the 6208.** {len(lam)} of {len(rows6208)} 6208 points have "
        "Lambda_min <= 1 (Ra 0.3 um races, sigma = 0.375 um). There the model's Coulomb mu is 0.1, and "
        "Heathcote sliding becomes the largest load-dependent loss, up to "
        f"{heath_max:.3f} N.m at 6000 N against M1 = {M1_heavy:.3f} N.m. This accounts for the "
        f"{len(mist_bad)} oil-mist points just above 2 ("
        + ", ".join(f"{_label(r)}: {q(r, 'oil mist'):.2f}" for r in mist_bad)
        + f"), at P0/C0 = {heavy[0]['P0_C0']:.2f}, a heavy load. Palmgren's M1 = f1 P1 dm assumes a "
        "well-lubricated bearing and has no film dependence.",
        "- **B7214C (oil-air).** Every point lies within a factor 2 "
        f"({span([q(r, 'oil mist/oil-air') for r in rows7214])}). At 200 N and 40 C the ratio climbs from "
        f"{q(light[0], 'oil mist/oil-air'):.2f} at 1000 rpm to {q(light[-1], 'oil mist/oil-air'):.2f} at "
        "15000 rpm. The ball centrifugal force loads the outer contacts, and the contact angles split "
        f"(inner {np.degrees(light[-1]['alpha_i']):.0f} deg, outer {np.degrees(light[-1]['alpha_o']):.1f} deg "
        "at 15000 rpm). The outer EHL losses therefore grow with speed on top of the applied load, which "
        f"Palmgren does not represent. Palmgren M1 is {100 * min(m1_share):.1f}-{100 * max(m1_share):.0f} % of "
        "Palmgren's total here, and hysteresis, Heathcote and spin are at most "
        f"{100 * max(1 - r['comps'][0] / r['M_H'] for r in rows7214):.0f} % of Houpert's. The B7214C "
        "comparison is therefore essentially Houpert EHL rolling against Palmgren M0 with f0 = 1.7, which is "
        "a low-confidence value. That Houpert 1987 is a starved fit suits the oil-air rig.",
        "- **Within a factor 2 where Palmgren applies.** Inside the domain defined above, "
        f"{dom_ok['oil mist']}/{len(dom['6208'])} 6208 points are within [0.5, 2] with the oil-mist f0, "
        f"{dom_ok['oil bath']}/{len(dom['6208'])} with the oil-bath f0, and "
        f"{dom_ok['oil mist/oil-air']}/{len(dom['B7214C'])} B7214C points with oil-air. With the oil-bath f0, "
        "the 500 N points fall below 0.5, and no domain condition excludes them. They show that the bath's "
        "load-independent drag is missing from the model, and they lie within the f0 uncertainty band "
        "(f0 = 1-2). The claim therefore holds for oil mist/oil-air, and for the f0 band. It does not hold "
        "for a light-loaded 6208 in an oil bath.",
        "",
    ]


def _plot(variants, path):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    import matplotlib.ticker  # noqa: F401

    fig, axes = plt.subplots(1, len(variants), figsize=(15, 4.6), sharey=True)
    for ax, (name, label, rows) in zip(axes, variants):
        loads = sorted({r["F"] for r in rows})
        colors = plt.cm.viridis(np.linspace(0.0, 0.85, len(loads)))
        for F, c in zip(loads, colors):
            for T, style in zip(TEMPERATURES, ("-o", "--s")):
                sel = [r for r in rows if r["F"] == F and r["T"] == T]
                ax.plot(
                    [r["n"] for r in sel],
                    [r["M_H"] / sum(r["palmgren"][label]) for r in sel],
                    style,
                    color=c,
                    ms=4,
                    label=f"{F:.0f} N, {T - 273.15:.0f} C",
                )
        ax.axhspan(0.5, 2.0, color="grey", alpha=0.15, lw=0)
        ax.axhline(1.0, color="grey", lw=0.8)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_ylim(0.1, 4.0)
        ax.yaxis.set_minor_formatter(matplotlib.ticker.NullFormatter())
        ax.set_yticks([0.125, 0.25, 0.5, 1, 2, 4])
        ax.set_yticklabels(["0.125", "0.25", "0.5", "1", "2", "4"])
        ax.set_xlabel("speed n (rpm)")
        ax.set_title(f"{name}: Palmgren with {label} f0")
        ax.legend(fontsize=7, ncol=2, loc="lower center")
    axes[0].set_ylabel("Houpert / Palmgren (M0 + M1)")
    fig.suptitle("Houpert torque of the quasi-static model vs Palmgren; band = factor 2", fontsize=10)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    print(f"wrote {path}")


if __name__ == "__main__":
    main()
