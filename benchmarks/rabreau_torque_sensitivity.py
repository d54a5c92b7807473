"""Why the three kinematic models' torques differ by 3.7 % and not by Rabreau's 2 %: sensitivity of the
torque spread at 10 000 rpm and 800 N to the estimated B7214C geometry and to the reading of the hybrid
model's gyroscopic-moment share (Rabreau's Table 1, missing from the copy of the paper we worked from), and what the one reading
that gives 2 % does to the solution over speed.

Source: Rabreau et al. 2018, Procedia CIRP 77, 622-625, section 6 ('all of the BB torque models
predict almost the same level of the friction torque (matching within 2 %)', Fig. 8, 10 000 rpm, 800 N
spring preload) and section 2.2 (race control: the race with the larger spin moment controls).
Readings of the hybrid share lam_i (lam_o = 2 - lam_i), all with the hybrid pitch angle:
  spin_moments      lam_i = 2C/(1+C), C = ratio of the spin moments (the model's, continuous);
  outer             lam_i = 0 (the outer race takes it all, as under outer-race control);
  inner             lam_i = 2 (the inner race takes it all, as under inner-race control);
  equal             lam_i = 1 (Harris' convention when no race control is assumed; docs/decisions.md, unverified sources);
  controlling_race  lam_i = 2 if C > 1 else 0 (Jones' criterion of section 2.2 applied per ball).
Run: python -m benchmarks.rabreau_torque_sensitivity -> docs/reports/rabreau_torque_sensitivity.md, .png
"""

import math
import re
import tempfile
from pathlib import Path

import numpy as np

from bearing_fmu.kernels import jones_harris as qk
from bearing_fmu.models.quasi_static import HYBRID_SPLITS, QuasiStaticModel, SolverError
from bearing_fmu.params import load_bearing

from .common import REPORTS, write_report
from .rabreau_preload import RPM, scene

SPEED = 10000.0  # rpm
PRELOAD = 800.0  # N
TEMPERATURES = (313.15, 333.15)
CLAIM = 0.02  # Rabreau section 6
LUBRICANT = "iso_vg68_mineral"
# Estimated B7214C geometry (bearing file) and plausible alternatives: (Z, D (m), f_i, f_o). Ball sets
# that fit the 70 x 125 mm section with a cage bar of 1.8-2.7 mm; conformities over the usual 0.515-0.54.
GEOMETRIES = [
    (17, 15.875e-3, 0.52, 0.53),
    (16, 16.669e-3, 0.52, 0.53),
    (18, 15.081e-3, 0.52, 0.53),
    (19, 14.288e-3, 0.52, 0.53),
    (17, 15.875e-3, 0.515, 0.52),
    (17, 15.875e-3, 0.53, 0.54),
    (17, 15.875e-3, 0.52, 0.52),
    (17, 15.875e-3, 0.54, 0.54),
]
SWEEP_RPM = np.arange(3000.0, 4500.0 + 1.0, 10.0)


def geometry_file(folder, Z, D, f_i, f_o):
    """The catalogue B7214C with another internal geometry; P_d keeps the free contact angle at 15 deg."""
    text = Path(load_bearing("B7214C").path).read_text()
    Pd = 2.0 * (f_i + f_o - 1.0) * D * (1.0 - math.cos(math.radians(15.0)))
    for key, value in (
        ("ball_diameter", D),
        ("inner_conformity", f_i),
        ("outer_conformity", f_o),
        ("n_balls", Z),
        ("diametral_clearance", Pd),
    ):
        text, n = re.subn(
            rf"^({key}\s*=\s*{{ value = )[^,]+", lambda m, v=value: m.group(1) + repr(v), text, flags=re.M
        )
        assert n == 1, key
    path = Path(folder) / f"B7214C_Z{Z}_D{D * 1e3:.3f}_fi{f_i}_fo{f_o}.toml"
    path.write_text(text)
    return path


def torques(bearing, T_oil):
    """Torque (N.m) of ORC, ORCG and HT under every hybrid reading; and lam_i, C of the default HT."""
    out = {}
    for label, race, gyro in (("ORC", "outer", False), ("ORCG", "outer", True)):
        model = QuasiStaticModel(bearing, LUBRICANT, scene(gyro), race_control=race)
        out[label] = model.evaluate(omega=SPEED * RPM, F_z=PRELOAD, T_oil=T_oil)["torque"]
        out[f"Q_i {label}"] = model.balls[qk.BQ_Q_I, 0]
    for split in HYBRID_SPLITS:
        model = QuasiStaticModel(bearing, LUBRICANT, scene(True), race_control="hybrid", hybrid_split=split)
        out[split] = model.evaluate(omega=SPEED * RPM, F_z=PRELOAD, T_oil=T_oil)["torque"]
        if split == "spin_moments":
            lam_i = model.balls[qk.BQ_LAM_I, 0]
            out["lam_i"], out["C"] = lam_i, lam_i / (2.0 - lam_i)
            out["Q_i HT"] = model.balls[qk.BQ_Q_I, 0]
    return out


def grid_c_hyb():
    """c_hyb = a_i E_i / (a_o E_o) at equal loads of the catalogue B7214C (-)."""
    return QuasiStaticModel("B7214C", LUBRICANT, scene(True), race_control="hybrid").qs[qk.QS_C_HYB]


def spread(t, split):
    values = (t["ORC"], t["ORCG"], t[split])
    return (max(values) - min(values)) / max(values)


def speed_sweep(split):
    """Warm sweep over SWEEP_RPM at 800 N: arrays K_zz (N/um), lam_i, and the spin-moment ratio C of
    the solution; NaN where Newton fails (the model is then rebuilt, the next point starts cold)."""
    rows = []
    model = None
    for rpm in SWEEP_RPM:
        model = model or QuasiStaticModel("B7214C", LUBRICANT, scene(True), race_control="hybrid", hybrid_split=split)
        try:
            res = model.evaluate(omega=rpm * RPM, F_z=PRELOAD, T_oil=TEMPERATURES[0])
            rows.append([res["K[3,3]"] * 1e-6, model.balls[qk.BQ_LAM_I, 0], first_ball_ratio(model)])
        except SolverError:
            rows.append([math.nan] * 3)
            model = None
    return np.array(rows).T


def spin_moment_ratio(split, rpm):
    """C (-) of the first ball of the HT solution with a fixed share at rpm, 800 N (cold solve)."""
    model = QuasiStaticModel("B7214C", LUBRICANT, scene(True), race_control="hybrid", hybrid_split=split)
    model.evaluate(omega=rpm * RPM, F_z=PRELOAD, T_oil=TEMPERATURES[0])
    return first_ball_ratio(model)


def first_ball_ratio(model):
    """Spin-moment ratio C = c_hyb (Q_i/Q_o)^(4/3) (-) of the first ball of a solved model."""
    Q_i, Q_o = model.balls[qk.BQ_Q_I, 0], model.balls[qk.BQ_Q_O, 0]
    return model.qs[qk.QS_C_HYB] * (Q_i / Q_o) ** (4.0 / 3.0)


def crossing_speed(split, C_sweep):
    """Speed (rpm) where C of a fixed share crosses 1, by bisection to 0.01 rpm inside the sweep step."""
    i = int(np.flatnonzero(np.diff(np.sign(C_sweep - 1.0)) != 0)[0])
    lo, hi = SWEEP_RPM[i], SWEEP_RPM[i + 1]
    while hi - lo > 0.01:
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if spin_moment_ratio(split, mid) > 1.0 else (lo, mid)
    return 0.5 * (lo + hi)


def main():
    with tempfile.TemporaryDirectory() as folder:
        grid = {(g, T): torques(geometry_file(folder, *g), T) for g in GEOMETRIES for T in TEMPERATURES}
    sweeps = {split: speed_sweep(split) for split in HYBRID_SPLITS}
    base = grid[(GEOMETRIES[0], TEMPERATURES[0])]

    lines = [
        "# Rabréau's 2 % torque agreement: sensitivity to the geometry and to the hybrid moment share",
        "",
        "Source: Rabréau et al. 2018, Procedia CIRP 77, 622-625, "
        "section 6: at 10 000 rpm and 800 N 'all of the BB torque models predict almost "
        "the same level of the friction torque (matching within 2 %)'. Generated by "
        "`python -m benchmarks.rabreau_torque_sensitivity`.",
        "",
        f"Our B7214C gives ORC / ORCG / HT = {base['ORC']:.4f} / {base['ORCG']:.4f} / "
        f"{base['spin_moments']:.4f} N·m at {TEMPERATURES[0]} K, a spread of "
        f"{100 * spread(base, 'spin_moments'):.1f} % (docs/reports/rabreau_preload.md). The loss is "
        "dominated by the EHL rolling resistance, F_R ∝ Q^0.466, so the spread follows the contact loads. HT "
        f"sends part of the gyroscopic moment to the inner race (λ_i = {base['lam_i']:.2f} here); the "
        "friction force there carries part of the thrust, and Q_i is "
        f"{100 * (base['Q_i HT'] / base['Q_i ORCG'] - 1):+.1f} % against ORCG. "
        "How HT shares the moment is Rabréau's Table 1, missing from the copy of the paper we worked from; the internal geometry of "
        "the B7214C is estimated. This report varies both. Every HT reading keeps the hybrid pitch angle.",
        "",
        "Readings of the inner-race share λ_i (λ_o = 2 − λ_i):",
        "",
        "- `spin_moments` (the model): λ_i = 2C/(1+C), C the ratio of the inner to the outer spin moment;",
        "- `outer`: λ_i = 0, the outer race takes all, as under outer-race control;",
        "- `inner`: λ_i = 2, the inner race takes all, as under inner-race control;",
        "- `equal`: λ_i = 1, Harris' convention when no race control is assumed (Harris & Kotzalas 2006, "
        "unverified: docs/decisions.md, unverified sources);",
        "- `controlling_race`: λ_i = 2 if C > 1 else 0, Jones' criterion (Rabréau section 2.2: the race "
        "with the larger spin moment controls) applied per ball.",
        "",
        "![sensitivity](rabreau_torque_sensitivity.png)",
        "",
        f"## Spread (max − min)/max of ORC, ORCG and HT at {SPEED:.0f} rpm, {PRELOAD:.0f} N",
        "",
        "| Z | D (mm) | f_i | f_o | T_oil (K) | C | λ_i (model) | ORC (N·m) | ORCG vs ORC | "
        + " | ".join(f"HT `{s}`" for s in HYBRID_SPLITS)
        + " |",
        "|---" * (9 + len(HYBRID_SPLITS)) + "|",
    ]
    for (g, T), t in grid.items():
        Z, D, f_i, f_o = g
        lines.append(
            f"| {Z} | {D * 1e3:.3f} | {f_i} | {f_o} | {T} | {t['C']:.3f} | {t['lam_i']:.3f} | "
            f"{t['ORC']:.4f} | {100 * (t['ORCG'] / t['ORC'] - 1):+.2f} % | "
            + " | ".join(f"{100 * spread(t, s):.2f} %" for s in HYBRID_SPLITS)
            + " |"
        )
    ranges = {
        s: (min(spread(t, s) for t in grid.values()), max(spread(t, s) for t in grid.values())) for s in HYBRID_SPLITS
    }
    lines += ["", "Range over the 8 geometries and 2 oil temperatures:", ""]
    lines += [
        f"- `{s}`: {100 * lo:.2f} – {100 * hi:.2f} %"
        + (" (meets 2 % everywhere)" if hi <= CLAIM else " (above 2 % everywhere)" if lo > CLAIM else "")
        for s, (lo, hi) in ranges.items()
    ]
    # interpolate the spread against lam_i (outer: 0, model: lam_i, equal: 1) for the base geometry
    lam = np.array([0.0, base["lam_i"], 1.0])
    spr = np.array([spread(base, "outer"), spread(base, "spin_moments"), spread(base, "equal")])
    lam_2 = float(np.interp(CLAIM, spr, lam))
    lines += [
        "",
        f"The geometry moves the spread by about ±0.5 %; the moment share moves it from "
        f"{100 * spr[0]:.1f} % (λ_i = 0) to {100 * spr[2]:.1f} % (λ_i = 1). For the estimated geometry "
        f"the spread reaches 2 % at λ_i ≈ {lam_2:.2f} (linear interpolation between the three readings, "
        f"monotone: {bool(np.all(np.diff(spr) > 0))}). Only a reading that puts (nearly) all of the moment "
        f"on the outer race at C = {base['C']:.2f} reproduces Rabréau's 2 %: `outer` or `controlling_race`, "
        f"which coincide here because C < 1. (`inner` puts it all on the inner race and spreads most.)",
    ]

    # -- the speed sweep
    k_ctl, lam_ctl, _ = sweeps["controlling_race"]
    failed = SWEEP_RPM[np.isnan(k_ctl)]
    ok = ~np.isnan(k_ctl)
    switch = np.flatnonzero(np.diff(lam_ctl[ok]) != 0.0)
    k_model = sweeps["spin_moments"][0]
    C_outer, C_inner = sweeps["outer"][2], sweeps["inner"][2]
    outer_consistent = crossing_speed("outer", C_outer)  # lam_i = 0 agrees with the criterion above
    inner_consistent = crossing_speed("inner", C_inner)  # lam_i = 2 agrees with it below
    lines += [
        "",
        f"## Over speed: {SWEEP_RPM[0]:.0f}–{SWEEP_RPM[-1]:.0f} rpm in {SWEEP_RPM[1] - SWEEP_RPM[0]:.0f} rpm "
        f"steps, {PRELOAD:.0f} N, warm-started",
        "",
        f"At rest the inner spin moment is the larger (C = c_hyb = {grid_c_hyb():.2f} for equal loads: the inner "
        "contact ellipse is longer), so `controlling_race` puts the moment on the inner race at low speed "
        "and on the outer race once centrifugal force has raised Q_o enough. C of the fixed shares:",
        "",
        f"- `outer` (λ_i = 0): C < 1, i.e. consistent with the criterion, above {outer_consistent:.2f} rpm;",
        f"- `inner` (λ_i = 2): C > 1, consistent, below {inner_consistent:.2f} rpm (crossings by bisection "
        f"to 0.01 rpm).",
        (
            f"- Between {outer_consistent:.2f} and {inner_consistent:.2f} rpm both states satisfy the criterion: "
            "two equilibria at the same speed and load."
            if inner_consistent > outer_consistent
            else f"- Between {inner_consistent:.2f} and {outer_consistent:.2f} rpm neither state satisfies it: "
            "no equilibrium."
        ),
    ]
    if len(failed):
        C_in_band = C_outer[np.isin(SWEEP_RPM, failed)]
        lines.append(
            f"- `controlling_race`: **Newton fails** at {len(failed)} speeds, {failed.min():.0f}–"
            f"{failed.max():.0f} rpm, although the λ_i = 0 equilibrium is consistent there (its C = "
            f"{C_in_band.min():.4f}–{C_in_band.max():.4f}): C lies within 0.3 % of the switch, where the share "
            f"and the loads jump and the Jacobian (zero derivative of the step) says nothing of it; Newton "
            f"stops at its iteration cap with a SolverError (no NaN, no hang)."
        )
    else:
        lines.append("- `controlling_race`: Newton converged at every speed of the sweep.")
    if len(switch):
        i = switch[0]
        before, after = SWEEP_RPM[ok][i], SWEEP_RPM[ok][i + 1]
        jump = k_ctl[ok][i + 1] / k_ctl[ok][i] - 1.0
        lines.append(
            f"- Across its switch ({before:.0f} → {after:.0f} rpm, converged neighbours) K_zz jumps by "
            f"{100 * jump:+.1f} %; the model's `spin_moments` share changes K_zz by "
            f"{100 * (k_model[SWEEP_RPM == after][0] / k_model[SWEEP_RPM == before][0] - 1):+.2f} % over "
            f"the same interval."
        )
    for split in HYBRID_SPLITS:
        k = sweeps[split][0]
        good = k[~np.isnan(k)]
        step = np.max(np.abs(np.diff(good) / good[:-1]))
        lines.append(
            f"- `{split}`: {int(np.isnan(k).sum())} failures; largest relative change of K_zz "
            f"between neighbouring converged speeds {100 * step:.2f} %."
        )
    lines += [
        "",
        "## Conclusion",
        "",
        "- The 3.7 % is not a geometry effect: over 8 plausible internal geometries and two oil temperatures "
        f"the model's share gives {100 * ranges['spin_moments'][0]:.1f}–{100 * ranges['spin_moments'][1]:.1f} %.",
        "- It is the moment share. Rabréau's 2 % is reproduced by a share that leaves (nearly) the whole "
        "gyroscopic moment on the outer race. Of the readings tried, `outer` does that by decree, which "
        "makes HT's 'distribution of gyroscopic moments' the same as ORCG's; `controlling_race` does it "
        "by Jones' criterion, but its stiffness jumps by about 11 % at the switching speed, two "
        "equilibria coexist next to it and our Newton fails in a band beside it: not fit for a model that "
        "must run through speed ramps, and smoothing the switch would be a rule of our own again.",
        "- The model keeps `spin_moments`: continuous, and the same blend of outer and inner control that "
        "the hybrid pitch-angle law makes. Rabréau's 2 % stays unreproduced until Table 1 (or refs. 8, 11, "
        "12) can be read; the other readings are available as `QuasiStaticModel(..., hybrid_split=...)` "
        "for studies.",
    ]
    write_report("rabreau_torque_sensitivity.md", "\n".join(lines) + "\n")
    _plot(grid, sweeps, REPORTS / "rabreau_torque_sensitivity.png")


def _plot(grid, sweeps, path):
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(12, 4.5))
    for i, split in enumerate(HYBRID_SPLITS):
        values = [100 * spread(t, split) for t in grid.values()]
        ax1.plot([i] * len(values), values, "o", alpha=0.6, label=split)
    ax1.axhline(100 * CLAIM, color="k", ls="--", lw=1, label="Rabréau: within 2 %")
    ax1.set_xticks(range(len(HYBRID_SPLITS)), list(HYBRID_SPLITS))
    ax1.set_ylabel("torque spread ORC/ORCG/HT (%)")
    ax1.set_title(f"{SPEED:.0f} rpm, {PRELOAD:.0f} N: 8 geometries x 2 oil temperatures")
    ax1.legend(fontsize=8)
    for split, (k, _, _) in sweeps.items():
        style = dict(color="k", ls="--", lw=1.2) if split == "controlling_race" else {}
        ax2.plot(SWEEP_RPM, k, label=split, **style)
    k_ctl = sweeps["controlling_race"][0]
    for rpm in SWEEP_RPM[np.isnan(k_ctl)]:
        ax2.axvspan(rpm - 5, rpm + 5, color="red", alpha=0.2, lw=0)
    ax2.set_xlabel("speed (rpm)")
    ax2.set_ylabel("K_zz (N/µm)")
    ax2.set_title("HT axial stiffness at 800 N (red: Newton fails, controlling_race)")
    ax2.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    print(f"wrote {path}")


if __name__ == "__main__":
    main()
