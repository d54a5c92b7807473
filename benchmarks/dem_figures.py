"""Figures of the DEM like the papers' (Guessasma & Machado 2018 Fig. 8-12; Farah et al. 2020 Fig. 8):
the 6208, P_d = 0, F_r = 3 kN, guessasma_oil.

(a) ball spin and cage speed against time through the start-up (5 ms ramp to 500 rad/s);
(b) slide-to-roll ratio of the outer contacts against time (balls accelerated in the ramp, rolling after);
(c) film parameter Lambda and minimum film h_min of a tracked ball against its azimuth over one cage
    revolution in steady rolling (azimuth from the load line: loaded zone around 0);
(d) that ball's capacitance (inner and outer contacts in series) against its azimuth.
Run: python -m benchmarks.dem_figures -> docs/reports/dem_6208.png
"""

import math

import numpy as np

from bearing_fmu.kernels.geometry import BALL_1_AZIMUTH
from bearing_fmu.models.dem import DemModel

from .common import REPORTS

F_R = 3000.0
OMEGA = 500.0


def main():
    model = DemModel("6208", "guessasma_oil")
    model.advance(2e-3, omega=0.0, F_y=F_R)
    ramp = model.record(7e-3, 50e-6, omega=OMEGA, F_y=F_R)
    run = model.record(30e-3, 50e-6, F_y=F_R)
    start = {k: np.concatenate([ramp[k], run[k]]) for k in ramp if k != "contacts"}
    start.update({k: np.concatenate([ramp["contacts"][k], run["contacts"][k]]) for k in ramp["contacts"]})
    revolution = 2.0 * math.pi / 198.0
    record = model.record(model.time + revolution, 10e-6, F_y=F_R)
    steady = record["contacts"]

    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, ax = plt.subplots(2, 2, figsize=(11, 7.5))
    t_ms = start["t"] * 1e3
    ax[0, 0].plot(t_ms, np.abs(start["omega_ball"]), label="ball spin, fixed frame (most loaded ball)")
    ax[0, 0].plot(t_ms, start["omega_cage"], label="cage")
    ax[0, 0].axhline(952.38, ls=":", c="k", lw=0.8)
    ax[0, 0].axhline(198.0, ls=":", c="k", lw=0.8)
    ax[0, 0].set(xlabel="t (ms)", ylabel="rad/s", title="(a) start-up to 500 rad/s (dotted: pure rolling)")
    ax[0, 0].legend(fontsize=8)
    srr = np.where(start["Q_outer"] > 0.0, start["SRR_outer"], np.nan)
    ax[0, 1].semilogy(t_ms, np.nanmax(srr, axis=1), label="largest, loaded outer contacts")
    ax[0, 1].set(xlabel="t (ms)", ylabel="SRR (-)", title="(b) slide-to-roll ratio")
    ax[0, 1].legend(fontsize=8)
    psi = np.degrees(np.angle(np.exp(1j * (steady["psi"][:, 0] - BALL_1_AZIMUTH))))  # from the load line (+y)
    order = np.argsort(psi)
    for race, style in (("inner", "-"), ("outer", "--")):
        lam = np.where(steady["Q_" + race][:, 0] > 0.0, steady["Lambda_" + race][:, 0], np.nan)
        ax[1, 0].plot(psi[order], lam[order], style, label=f"Lambda {race}")
    ax2 = ax[1, 0].twinx()
    h = np.where(steady["Q_outer"][:, 0] > 0.0, steady["h_min_outer"][:, 0], np.nan)
    ax2.plot(psi[order], h[order] * 1e6, ":", c="gray", label="h_min outer (um)")
    ax2.set_ylabel("h_min outer (um)")
    ax[1, 0].set(xlabel="azimuth of ball 0 (deg)", ylabel="Lambda (-)", title="(c) film of a tracked ball")
    ax[1, 0].legend(fontsize=8, loc="upper left")
    c_i, c_o = steady["C_inner"][:, 0], steady["C_outer"][:, 0]
    c_ball = np.where((c_i > 0) & (c_o > 0), c_i * c_o / np.where(c_i + c_o > 0, c_i + c_o, 1.0), 0.0)
    ax[1, 1].plot(psi[order], c_ball[order] * 1e12)
    ax[1, 1].set(
        xlabel="azimuth of ball 0 (deg)",
        ylabel="pF",
        title=f"(d) capacitance of the tracked ball (bearing {record['C_bearing'].mean() * 1e12:.1f} pF)",
    )
    for a in ax.flat:
        a.grid(True, alpha=0.3)
    fig.tight_layout()
    fig.savefig(REPORTS / "dem_6208.png", dpi=110)
    print(f"wrote {REPORTS / 'dem_6208.png'}")


if __name__ == "__main__":
    main()
