"""The spindle shaft on two DEM bearings (runs/shaft_transient_dem.toml) against the same shaft on quasi-static
bearings (runs/shaft_transient_qs.toml): the steady state at the seats and the tool tip, the orbits and the spectrum
there, whether a whirl appears, and the cost per simulated second split between the master, the shaft and the
bearings.

Both runs: the Rabreau et al. (2018) rig's estimated shaft on its X pair of B7214C, fixed preload (each bearing's own
axial shift for 800 N at 10 000 rpm: -6.3191 um for the DEM, -6.7537 um quasi-static), 500 N along x on the tool tip,
10 000 rpm, H = 25 us. The DEM run starts from rest and runs up in 0.5 s; the quasi-static one starts at speed.
Steady state: the DEM run's means over its last 0.2 s against the quasi-static run's end (which settles on the
nonlinear static equilibrium within 3e-6, tests/cosim/test_shaft_transient_run.py). Spectrum: the Hann-windowed
amplitude spectrum of the tool tip's x and y over the same window, its strongest lines named by the nearest of the
bearing's own frequencies (the DEM's FTF, BPFO, BPFI, BSF outputs, harmonics and sidebands) and the shaft's modes at speed on the bearings' mean
K (ShaftModel.evaluate), when one is within 5 %. Cost: CPU time of each FMU's doStep (they run in this process) and
the rest of the stepping (the master: transfers, schedules, recording), one run.
Run: python -m benchmarks.shaft_dem -> docs/reports/shaft_dem.md and .png
"""

import time
from pathlib import Path

import numpy as np

from spindle.cosim.master import Master
from spindle.cosim.runfile import load_run
from spindle.shaft import ShaftModel
from spindle.shaft.declarations import SEAT_DAMPING

from .render import cli, metric

ROOT = Path(__file__).resolve().parent.parent
DEM_RUN = ROOT / "runs" / "shaft_transient_dem.toml"
QS_RUN = ROOT / "runs" / "shaft_transient_qs.toml"
STEADY = 0.2  # s: the window of the steady state at the end of the DEM run
TOLERANCE = 0.02  # the seats' displacements against the quasi-static bearings'
MOTION = ("x", "y", "z", "theta_x", "theta_y")
FORCES = ("F_x", "F_y", "F_z", "M_x", "M_y")
LINES = 6  # strongest spectral lines listed per direction
NAMED_WITHIN = 0.05  # a line is named by a frequency this close (relative): the window's resolution is 5 Hz
# the B7214C's ring alone (no shaft) at 10 000 rpm under 800 N whirls at this frequency below 62-70 N.s/m of support
# damping (docs/dem.md, Whirl thresholds); the band where the spectrum is searched for it
RING_WHIRL = 713.0  # Hz
WHIRL_BAND = (600.0, 850.0)  # Hz


def timed_run(path):
    """(columns, result, CPU seconds per instance's doStep) of a run file, every step recorded."""
    spec = load_run(path)
    cpu = {}
    with Master(spec) as master:
        for name, inst in master.instances.items():
            cpu[name] = 0.0
            inst.do_step = _timed(inst.do_step, cpu, name)
        result = master.run()
    if result.status != "ok":
        raise RuntimeError(f"{path.name}: {result.status}: {result.message}")
    return result.columns, result, cpu


def _timed(do_step, cpu, name):
    def step(t, h):
        start = time.process_time()
        try:
            do_step(t, h)
        finally:
            cpu[name] += time.process_time() - start

    return step


def seats(columns, rows):
    """Seat displacements (2, 5) averaged over the rows (bearing frames) and the tool tip's x, y."""
    seat = np.array([[columns[f"shaft.{n}_{s}"][rows].mean() for n in MOTION] for s in (1, 2)])
    return seat, np.array([columns[f"shaft.{n}_tip"][rows].mean() for n in ("x", "y")])


def steady_rows(dem, rows, qs):
    """Table rows (seat, dof, DEM mean, its peak-to-peak, quasi-static, relative deviation) and the largest relative
    deviation of the displacements the tool-tip force moves radially (x, theta_y at both seats, the tip's x)."""
    d_seat, d_tip = seats(dem, rows)
    q_seat, q_tip = seats(qs, slice(-1, None))
    out, worst = [], 0.0
    for s, name in enumerate(("front (1)", "rear (2)")):
        for i, dof in enumerate(MOTION):
            ptp = np.ptp(dem[f"shaft.{dof}_{s + 1}"][rows])
            dev = (d_seat[s, i] - q_seat[s, i]) / abs(q_seat[s, i]) if abs(q_seat[s, i]) > 1e-9 else None
            out.append([name, dof, d_seat[s, i] * 1e6, ptp * 1e6, q_seat[s, i] * 1e6, dev])
            if dof in ("x", "theta_y"):
                worst = max(worst, abs(dev))
    tip = (d_tip[0] - q_tip[0]) / abs(q_tip[0])
    out += [["tool tip", "x", d_tip[0] * 1e6, np.ptp(dem["shaft.x_tip"][rows]) * 1e6, q_tip[0] * 1e6, tip],
            ["tool tip", "y", d_tip[1] * 1e6, np.ptp(dem["shaft.y_tip"][rows]) * 1e6, q_tip[1] * 1e6, None]]  # fmt: skip
    return out, max(worst, abs(tip))


def load_rows(dem, rows, qs):
    """Table rows (bearing, load, DEM mean, peak-to-peak, quasi-static) of the seats' reaction loads."""
    out = []
    for s in (1, 2):
        for n in FORCES:
            x = dem[f"bearing_{s}.{n}"][rows]
            out.append([f"bearing {s}", n, x.mean(), np.ptp(x), qs[f"bearing_{s}.{n}"][-1]])
    return out


def spectrum(t, x):
    """(frequencies in Hz, single-sided amplitude in m) of x(t) with a Hann window (its coherent gain undone)."""
    x = x - x.mean()
    w = np.hanning(x.size)
    return np.fft.rfftfreq(x.size, t[1] - t[0]), 2.0 * np.abs(np.fft.rfft(x * w)) / w.sum()


def named_frequencies(columns, rows, omega):
    """Frequencies (Hz) a line may belong to: the shaft's speed, the bearing's own frequencies as the DEM outputs them
    (FTF and its harmonics below BPFO, BPFO, BPFI, 2 BSF, the ball passes' harmonics and their sidebands at FTF and at the
    shaft's speed), and the shaft's six modes at speed on the bearings' mean K."""
    f_shaft = omega / (2.0 * np.pi)
    ftf, bpfo, bpfi, bsf = (columns[f"bearing_1.{n}"][rows].mean() for n in ("FTF", "BPFO", "BPFI", "BSF"))
    names = {"1x shaft": f_shaft, "2x shaft": 2.0 * f_shaft, "2 BSF": 2.0 * bsf}
    balls = round(bpfo / ftf)  # BPFO = Z FTF
    names |= {f"{k} FTF" if k > 1 else "FTF": k * ftf for k in range(1, balls)}  # the cage's comb up to BPFO
    for name, f, side, side_name in (("BPFO", bpfo, ftf, "FTF"), ("BPFI", bpfi, f_shaft, "1x shaft")):
        names |= {name: f, f"2 {name}": 2.0 * f, f"{name} - {side_name}": f - side, f"{name} + {side_name}": f + side}
    K = np.array([[[columns[f"bearing_{s}.K[{i},{j}]"][rows].mean() for j in range(1, 6)] for i in range(1, 6)]
                  for s in (1, 2)])  # fmt: skip
    modes = ShaftModel().evaluate(omega, K)
    for k, (f, whirl) in enumerate(zip(modes["frequencies"], modes["whirl"], strict=True), start=1):
        names[f"shaft mode {k} ({'forward' if whirl > 0 else 'backward' if whirl < 0 else 'axial/none'})"] = f
    return names


def line_rows(t, columns, names):
    """The strongest LINES local maxima of the tool tip's x and y spectra, each with the nearest named frequency."""
    rows = []
    for axis in ("x", "y"):
        f, a = spectrum(t, columns[f"shaft.{axis}_tip"])
        peaks = [i for i in range(1, a.size - 1) if a[i] >= a[i - 1] and a[i] > a[i + 1]]
        for i in sorted(sorted(peaks, key=lambda i: -a[i])[:LINES]):
            name, g = min(names.items(), key=lambda kv: abs(kv[1] - f[i]))
            if abs(g - f[i]) > NAMED_WITHIN * f[i]:
                name, g = f"none within {NAMED_WITHIN:.0%}", None
            rows.append([f"tool tip {axis}", f[i], a[i] * 1e9, name, g])
    return rows


def whirl_band(t, dem, rows):
    """(largest amplitude in WHIRL_BAND, largest amplitude anywhere; nm) of the tool tip's and the seats' x and y."""
    in_band = strongest = 0.0
    for name in ("x_tip", "y_tip", "x_1", "y_1", "x_2", "y_2"):
        f, a = spectrum(t, dem[f"shaft.{name}"][rows])
        inside = (f >= WHIRL_BAND[0]) & (f <= WHIRL_BAND[1])
        in_band, strongest = max(in_band, a[inside].max()), max(strongest, a[1:].max())
    return in_band * 1e9, strongest * 1e9


def cost_rows(result, cpu, simulated):
    """(rows: part, CPU s, share, CPU s per simulated s) of one run's stepping."""
    parts = {"bearings (2 DEM FMUs)": cpu["bearing_1"] + cpu["bearing_2"], "shaft FMU": cpu["shaft"]}
    parts["master (transfers, schedules, recording)"] = result.cpu_time - sum(parts.values())
    rows = [[k, v, v / result.cpu_time, v / simulated] for k, v in parts.items()]
    return rows + [["whole run", result.cpu_time, 1.0, result.cpu_time / simulated]]


def measure():
    dem, result, cpu = timed_run(DEM_RUN)
    qs, _, _ = timed_run(QS_RUN)
    spec = load_run(DEM_RUN)
    t = dem["time"]
    rows = slice(int(np.searchsorted(t, t[-1] - STEADY)), None)
    omega = float(dem["shaft.omega"][-1])
    table, worst = steady_rows(dem, rows, qs)
    names = named_frequencies(dem, rows, omega)
    lines = line_rows(t[rows], {k: dem[k][rows] for k in ("shaft.x_tip", "shaft.y_tip")}, names)
    orbit = max(np.ptp(dem[f"shaft.{n}_{s}"][rows]) for n in ("x", "y") for s in (1, 2))
    costs = cost_rows(result, cpu, t[-1] - t[0])
    band = whirl_band(t[rows], dem, rows)
    values = dict(worst=worst, tolerance=TOLERANCE, steady=STEADY, orbit=orbit * 1e9, stop=t[-1],
                  per_second=costs[-1][3], dem_share=costs[0][2], shaft_share=costs[1][2], master_share=costs[2][2],
                  wall=result.wall_time, steps=result.n_steps, step=spec.step * 1e6, whirl=RING_WHIRL,
                  band_low=WHIRL_BAND[0], band_high=WHIRL_BAND[1], in_band=band[0], strongest=band[1],
                  verdict="no whirl appears" if band[0] < 0.1 * band[1] else "a line in the whirl's band (see the spectrum)",
                  damping=spec.instances["shaft"].parameters.get("c_radial_1", SEAT_DAMPING[0][2]))  # fmt: skip
    blocks = [
        dict(text=SUMMARY, values=values),
        dict(table=dict(caption="## Steady state at the seats and the tool tip (um, urad; bearing frames at the seats)",
                        columns=["where", "dof", "DEM mean", "DEM peak-to-peak", "quasi-static", "deviation"],
                        rows=table, formats=[None, None, "{:.4f}", "{:.4f}", "{:.4f}", "{:+.2%}"])),
        dict(table=dict(caption="## The bearings' reaction loads (N, N.m)",
                        columns=["bearing", "load", "DEM mean", "DEM peak-to-peak", "quasi-static"],
                        rows=load_rows(dem, rows, qs), formats=[None, None, "{:.2f}", "{:.2f}", "{:.2f}"])),
        dict(text=STEADY_TEXT, values=values),
        dict(table=dict(caption=f"## The strongest lines of the tool tip's motion over the last {STEADY:g} s",
                        columns=["signal", "frequency (Hz)", "amplitude (nm)", "nearest named frequency", "at (Hz)"],
                        rows=lines, formats=[None, "{:.1f}", "{:.3f}", None, "{:.1f}"])),
        dict(text=WHIRL_TEXT, values=values),
        dict(figure=figure(dem, rows, names)),
        dict(table=dict(caption="## Cost of the DEM run (CPU time of the stepping, one run)",
                        columns=["part", "CPU (s)", "share", "CPU s per simulated s"], rows=costs,
                        formats=[None, "{:.1f}", "{:.1%}", "{:.1f}"])),
        dict(text=COST_TEXT, values=values),
    ]  # fmt: skip
    metrics = [
        metric("shaft on DEM bearings: seat x, theta_y and tip x against quasi-static bearings", worst, "1",
               "difference", TOLERANCE),
        metric("shaft on DEM bearings: CPU per simulated second", values["per_second"], "s/s", "timing"),
    ]  # fmt: skip
    return dict(name="shaft_dem", title="The spindle shaft on two DEM bearings", about=__doc__.split("Run:")[0],
                blocks=blocks, metrics=metrics)  # fmt: skip


SUMMARY = """The shaft on two DEM bearings runs up from rest to 10 000 rpm and settles: over the last {steady:g} s \
the seats' radial motion spans at most {orbit:.1f} nm peak to peak. The displacements the tool-tip force causes \
(x and theta_y at both seats, the tool tip's x) are within **{worst:.2%}** of the same shaft on quasi-static \
bearings (tolerance {tolerance:.0%})."""

STEADY_TEXT = """What the quasi-static bearing does not have: the DEM ring sits sideways (y, theta_x at both seats, \
the tool tip's y) with almost no lateral reaction, the contacts' traction holding it there, and the axial shift \
the radial load causes (z) differs, with the axial loads: these are differences of the two bearing models, the \
shaft and the coupling being the same in both runs."""

WHIRL_TEXT = """The ring alone (no shaft) of this bearing at this speed whirls at about {whirl:.0f} Hz when its \
support damping is low (docs/dem.md, Whirl thresholds). On the shaft, whose seats carry {damping:.0f} N.s/m and the \
shaft's mass and stiffness, the seats' and the tool tip's spectra between {band_low:.0f} and {band_high:.0f} Hz peak \
at {in_band:.3f} nm, against {strongest:.3f} nm for their strongest line: the lines are the bearing's own frequencies \
(table above): {verdict}."""

COST_TEXT = """{per_second:.1f} s of CPU per simulated second ({steps} steps of {step:.0f} us; {wall:.0f} s wall on the \
shared machine): the two DEM bearings {dem_share:.0%}, the shaft {shaft_share:.0%}, the master \
{master_share:.0%}."""


def figure(dem, rows, names):
    """Run-up, orbits at the seats and the tool tip's spectrum."""
    t = dem["time"]
    stride = 20
    runup = [dict(x=list(t[::stride]), y=list(dem[f"shaft.x_{s}"][::stride] * 1e6), label=f"seat {s}: x", style="-")
             for s in (1, 2)]  # fmt: skip
    runup.append(dict(x=list(t[::stride]), y=list(dem["shaft.x_tip"][::stride] * 1e6), label="tool tip: x", style="-"))
    orbits = []  # about the mean position, which the table gives
    for s in (1, 2):
        x, y = dem[f"shaft.x_{s}"][rows], dem[f"shaft.y_{s}"][rows]
        orbits.append(dict(x=list((x - x.mean()) * 1e9), y=list((y - y.mean()) * 1e9), label=f"seat {s}", style="-"))
    loads = [dict(x=list(t[::stride]), y=list(dem[f"bearing_{s}.F_z"][::stride]), label=f"bearing {s}: F_z", style="-")
             for s in (1, 2)]  # fmt: skip

    spectra = []
    for axis in ("x", "y"):
        f, a = spectrum(t[rows], dem[f"shaft.{axis}_tip"][rows])
        keep = (f > 0.0) & (f < 5000.0)
        spectra.append(dict(x=list(f[keep]), y=list(a[keep] * 1e9), label=f"tool tip {axis}", style="-"))
    panels = [
        dict(xlabel="time (s)", ylabel="um", title="seats and tool tip, x (bearing frames)", series=runup),
        dict(
            xlabel="x - mean (nm)",
            ylabel="y - mean (nm)",
            title=f"orbits at the seats, last {STEADY:g} s",
            series=orbits,
            aspect="equal",
        ),
        dict(xlabel="time (s)", ylabel="N", title="axial loads (the fixed preload through the run-up)", series=loads),
        dict(xlabel="frequency (Hz)", ylabel="nm", yscale="log", title="tool tip's amplitude spectrum", series=spectra),
    ]
    return dict(file="shaft_dem.png", caption=CAPTION, title=TITLE, size=(13, 9), panels=panels)


CAPTION = "the shaft on two DEM bearings: run-up, orbits at the seats, the tool tip's spectrum"
TITLE = "shaft_transient_dem.toml: rest to 10 000 rpm in 0.5 s, 500 N on the tool tip, H = 25 us"


def main(argv=None):
    cli(measure, "shaft_dem")


if __name__ == "__main__":
    main()
