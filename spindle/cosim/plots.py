"""Plots of a co-simulation result (matplotlib, optional): temperatures, torque, preload, film, capacitance.

Columns are picked by variable name ('instance.variable'), so the same plot serves every run file:
temperatures = variables starting with T_ (shown in C), torque, axial load (F_z) or contact angle,
Lambda_*, C_bearing. Panels without data are left out.
"""

from pathlib import Path

import numpy as np

PANELS = (
    ("temperature (C)", lambda v: v.startswith("T_"), lambda x: x - 273.15),
    ("friction torque (N.m)", lambda v: v == "torque", None),
    ("axial load / preload (N)", lambda v: v in ("F_z", "F_axial"), None),
    ("outer contact angle (deg)", lambda v: v == "alpha_outer", np.degrees),
    ("film parameter Lambda (-)", lambda v: v.startswith("Lambda_"), None),
    ("capacitance (pF)", lambda v: v == "C_bearing", lambda x: x * 1e12),
)


def plot_run(result, path, title=""):
    """Write a PNG of the recorded trajectories of a RunResult (or any object with .columns), of a run
    streamed to a CSV file (its RunResult, or the file's path: the plot reads the file)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    from .master import read_csv

    if isinstance(result, (str, Path)):
        cols = read_csv(result)[0]
    else:
        cols = result.columns or read_csv(result.csv_path)[0]
    t = cols["time"]
    scale_t, t_label = (1.0 / 60.0, "time (min)") if t[-1] > 600 else (1.0, "time (s)")
    panels = []
    for label, pick, convert in PANELS:
        chosen = [q for q in cols if q != "time" and pick(q.split(".", 1)[1])]
        if chosen:
            panels.append((label, chosen, convert))
    fig, axes = plt.subplots(len(panels), 1, figsize=(8, 2.3 * len(panels) + 0.6), sharex=True, squeeze=False)
    for ax, (label, chosen, convert) in zip(axes[:, 0], panels):
        for q in chosen:
            y = cols[q] if convert is None else convert(np.asarray(cols[q]))
            ax.plot(t * scale_t, y, label=q, lw=1.2)
        ax.set_ylabel(label)
        ax.grid(alpha=0.3)
        ax.legend(fontsize=7, ncol=2 if len(chosen) > 3 else 1)
    axes[-1, 0].set_xlabel(t_label)
    if title:
        axes[0, 0].set_title(title, fontsize=9)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
    return path
