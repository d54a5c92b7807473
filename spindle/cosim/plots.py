"""Plots of a co-simulation result (matplotlib, optional): temperatures, torque, preload, film, capacitance.

Columns are picked by variable name ('instance.variable'), so the same plot serves every run file:
temperatures = variables starting with T_ (shown in C), torque, axial load (F_z) or contact angle,
Lambda_*, C_bearing. Panels without data are left out.

A run streamed to a CSV file is plotted from the file without reading it whole: the rows are read one
by one and only the plotted columns kept, reduced to at most MAX_BUCKETS buckets of consecutive rows, each
drawn by its smallest and largest value (in time order), so a short spike still shows and the memory of
the plot does not grow with the run's length (docs/architecture.md, master).
"""

import csv
import math
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
MAX_BUCKETS = 4000  # per line: up to 8000 points, several per pixel of the 880-pixel-wide figure


def _plotted(names):
    """[(panel label, [column names], conversion)] of the panels that have data among names."""
    panels = []
    for label, pick, convert in PANELS:
        chosen = [q for q in names if q != "time" and "." in q and pick(q.split(".", 1)[1])]
        if chosen:
            panels.append((label, chosen, convert))
    return panels


def envelope(t, y, size):
    """(t, y) reduced to the smallest and largest y of each bucket of `size` consecutive points, in time
    order (one point where both are the same)."""
    t, y = np.asarray(t, dtype=float), np.asarray(y, dtype=float)
    if size <= 1 or len(y) <= 2:
        return t, y
    keep = []
    for start in range(0, len(y), size):
        block = y[start : start + size]
        keep.extend(sorted({start + int(np.argmin(block)), start + int(np.argmax(block))}))
    return t[keep], y[keep]


def read_plot_columns(path, max_buckets=MAX_BUCKETS):
    """{name: (t, y)} of the plotted columns of a result CSV, each reduced to at most max_buckets buckets
    (envelope), read row by row: the memory is that of the reduced columns and one bucket."""
    from .master import header_names

    with open(path, newline="") as fh:
        n_rows = sum(1 for _ in fh) - 1
    size = max(1, math.ceil(n_rows / max_buckets))
    with open(path, newline="") as fh:
        reader = csv.reader(fh)
        names = [cell.rpartition(" [")[0] or cell for cell in header_names(next(reader))]
        wanted = [q for _, chosen, _ in _plotted(names) for q in chosen]
        at = [0] + [names.index(q) for q in wanted]
        out = {q: ([], []) for q in wanted}
        block = []

        def flush():
            values = np.array(block, dtype=float).reshape(len(block), len(at))
            for k, q in enumerate(wanted, start=1):
                t, y = envelope(values[:, 0], values[:, k], len(block))
                out[q][0].extend(t.tolist())
                out[q][1].extend(y.tolist())
            block.clear()

        for row in reader:
            block.append([row[i] for i in at])
            if len(block) == size:
                flush()
        if block:
            flush()
    return {q: (np.array(t), np.array(y)) for q, (t, y) in out.items()}


def plot_title(stem, description="", overrides=None):
    """Title of a run's plot: the run file's stem and description, and the --set overrides the run had
    (a run at another speed than its description says is titled with the speed it ran at)."""
    title = f"{stem}: {description}" if description else stem
    if overrides:
        title += "\nwith " + ", ".join(f"{key} = {value}" for key, value in overrides.items())
    return title


def plot_run(result, path, title=""):
    """Write a PNG of the recorded trajectories of a RunResult (or any object with .columns), of a run
    streamed to a CSV file (its RunResult, or the file's path: the plot reads the file row by row)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    if isinstance(result, (str, Path)) or not result.columns:
        lines = read_plot_columns(result if isinstance(result, (str, Path)) else result.csv_path)
    else:
        lines = {q: (result.columns["time"], y) for q, y in result.columns.items() if q != "time"}
    panels = _plotted(list(lines))
    t_end = max((t[-1] for t, _ in lines.values() if len(t)), default=0.0)
    scale_t, t_label = (1.0 / 60.0, "time (min)") if t_end > 600 else (1.0, "time (s)")
    fig, axes = plt.subplots(len(panels), 1, figsize=(8, 2.3 * len(panels) + 0.6), sharex=True, squeeze=False)
    for ax, (label, chosen, convert) in zip(axes[:, 0], panels):
        for q in chosen:
            t, y = lines[q]
            ax.plot(np.asarray(t) * scale_t, y if convert is None else convert(np.asarray(y)), label=q, lw=1.2)
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
