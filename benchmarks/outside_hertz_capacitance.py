"""Bearing capacitance with and without the oil around the Hertz ellipses (scene capacitance_region).

For a few bearings and operating points: C_bearing (pF) with the scene's `capacitance_region = "hertz"` (each
contact a parallel plate over its Hertz ellipse at h_c, the default) and with `"lubricated"` at several
oil-availability gaps `oil_gap` (the oil around each contact fills the gap up to that height; the inlet half in
full film, the cavitated outlet half with oil streamers a fraction h_c/h of the gap, docs/decisions.md). Oil at
40 C, no background capacitance, permittivity at the Hertz maximum pressure in the ellipse and at ambient
pressure outside. The operating points are ours: no published measurement of these bearings at these points
could be read (docs/decisions.md, "Capacitance outside the Hertz zone"). Then the same point in the
quasi-static fidelity and at the end of a DEM run, and the cost of the outside term per contact (the kernel
alone, and one analytic evaluation with the option on and off).
Run: python -m benchmarks.outside_hertz_capacitance -> docs/reports/outside_hertz_capacitance.md
"""

import math
import os
import statistics
import time

from bearing_fmu.kernels import capacitance as cap
from bearing_fmu.kernels import hertz as hk
from bearing_fmu.kernels import radial_bearing
from bearing_fmu.models.analytic import AnalyticModel
from bearing_fmu.models.dem import DemModel
from bearing_fmu.models.quasi_static import QuasiStaticModel
from bearing_fmu.scene import Scene

from .common import interleaved_medians, median_time
from .render import cli

RPM = 2.0 * math.pi / 60.0
PF = 1e12
OIL_GAPS = (1e-6, 2e-6, 5e-6, 10e-6, 25e-6)  # m
CASES = [  # (label, fidelity, bearing, lubricant, inputs)
    ("6208, 700 rad/s, F_y = 3 kN, 40 C", "analytic", "6208", "guessasma_oil", dict(omega=700.0, F_y=3000.0)),
    ("6208, 70 rad/s, F_y = 3 kN, 40 C", "analytic", "6208", "guessasma_oil", dict(omega=70.0, F_y=3000.0)),
    ("6208, 700 rad/s, F_y = 500 N, 40 C", "analytic", "6208", "guessasma_oil", dict(omega=700.0, F_y=500.0)),
    ("B7214C, 10 000 rpm, F_z = 800 N + F_x = 1 kN, 40 C", "quasi_static", "B7214C", "iso_vg68_mineral",
     dict(omega=10000 * RPM, F_z=800.0, F_x=1000.0)),
    ("B7214C, 1 000 rpm, F_z = 800 N, 40 C", "quasi_static", "B7214C", "iso_vg68_mineral",
     dict(omega=1000 * RPM, F_z=800.0)),
    ("6306, 1 000 rpm, F_y = 1 kN, 40 C", "analytic", "6306", "mineral_oil_capacitance", dict(omega=1000 * RPM, F_y=1e3)),
]  # fmt: skip
T_OIL = 313.15
KERNEL = dict(load=1000.0, h_c=2e-7, oil_gap=10e-6)  # the kernel timed: 6208 inner contact
BATCH, BATCHES = 200, 21  # analytic evaluations per timed batch, interleaved batches
DEM_GAP, DEM_RUNS = 10e-6, 4  # DEM runs per region, interleaved; the first of each compiles and warms up


def evaluate(fidelity, bearing, lubricant, inputs, **scene):
    """(C_bearing F, h_c inner m, h_c outer m) of one operating point."""
    if fidelity == "analytic":
        out = AnalyticModel(bearing, lubricant, Scene(**scene)).evaluate(inputs["omega"], inputs["F_y"], T_OIL)
    else:
        m = QuasiStaticModel(bearing, lubricant, Scene(name="q", fidelity="quasi_static", **scene))
        out = m.evaluate(T_oil=T_OIL, **inputs)
    return out["C_bearing"], out.get("h_c_inner", math.nan), out.get("h_c_outer", math.nan)


def capacitance_table():
    rows = []
    for label, fidelity, bearing, lubricant, inputs in CASES:
        C0, hi, ho = evaluate(fidelity, bearing, lubricant, inputs)
        row = [label, f"{hi * 1e9:.0f} / {ho * 1e9:.0f}", C0 * PF]
        for g in OIL_GAPS:
            C = evaluate(fidelity, bearing, lubricant, inputs, capacitance_region="lubricated", oil_gap=g)[0]
            row.append(f"{C * PF:.1f} (x{C / C0:.2f})")
        rows.append(row)
    gaps = [f"oil_gap {g * 1e6:g} um (pF, x Hertz)" for g in OIL_GAPS]
    columns = ["case", "h_c inner / outer (nm)", "Hertz only (pF)", *gaps]
    caption = "The factor in brackets is C_bearing over its Hertz-only value."
    return dict(caption=caption, columns=columns, formats=["{}", "{}", "{:.1f}"] + ["{}"] * len(OIL_GAPS), rows=rows)


def cost():
    """(kernel us per contact, analytic evaluation us off, on) on the 6208 inner contact."""
    off = AnalyticModel("6208", "guessasma_oil", Scene())
    b = off.brg
    geometry = [
        b[i]
        for i in (
            radial_bearing.B_RX_I,
            radial_bearing.B_RY_I,
            radial_bearing.B_E_RED,
            radial_bearing.B_K_I,
            radial_bearing.B_EE_I,
            radial_bearing.B_KK_I,
        )
    ]
    a, bb, _, p = hk.hertz_contact(KERNEL["load"], *geometry)
    args = (2.2, a, bb, p, b[radial_bearing.B_E_RED], KERNEL["h_c"], KERNEL["oil_gap"], 1e-8)
    kernel = median_time(cap.outside_hertz_capacitance, *args, number=2000)
    on = AnalyticModel("6208", "guessasma_oil", Scene(capacitance_region="lubricated", oil_gap=10e-6))
    u = (700.0, 3000.0, T_OIL)

    def batch(model):
        return lambda: [model.update(u) for _ in range(BATCH)]

    t = interleaved_medians({"off": batch(off), "on": batch(on)}, repeats=BATCHES)
    return kernel * 1e6, t["off"] / BATCH * 1e6, t["on"] / BATCH * 1e6


def dem_run(region):
    """DEM 6208, guessasma_oil, 1 ms at rest then a ramp to 300 rad/s over 5 ms under F_y = 3 kN, held to 20 ms:
    (C_bearing at the end F, wall time of the 20 ms s)."""
    m = DemModel("6208", "guessasma_oil", scene=Scene(name="dem", fidelity="dem", capacitance_region=region))
    t0 = time.perf_counter()
    m.advance(1e-3, omega=0.0, F_y=3000.0)
    m.advance(6e-3, omega=300.0, F_y=3000.0)
    out = m.advance(20e-3, omega=300.0, F_y=3000.0)
    return out["C_bearing"], time.perf_counter() - t0


def dem_table():
    """The same point in the quasi-static fidelity and in the DEM, 'hertz' and 'lubricated'."""
    qs = [
        evaluate("quasi_static", "6208", "guessasma_oil", dict(omega=300.0, F_y=3000.0), **kw)[0]
        for kw in ({}, dict(capacitance_region="lubricated", oil_gap=DEM_GAP))
    ]
    runs = {"hertz": [], "lubricated": []}
    for _ in range(DEM_RUNS):
        for region, r in runs.items():
            r.append(dem_run(region))
    (c0, w0), (c1, w1) = ((r[-1][0], statistics.median(w for _, w in r[1:])) for r in runs.values())
    return dict(
        columns=["fidelity", "Hertz only (pF)", f"oil_gap {DEM_GAP * 1e6:g} um (pF, x Hertz)",
                 "wall time of 20 ms simulated (s)"],
        rows=[["quasi-static", f"{qs[0] * PF:.1f}", f"{qs[1] * PF:.1f} (x{qs[1] / qs[0]:.2f})", None],
              ["DEM (end of the run)", f"{c0 * PF:.1f}", f"{c1 * PF:.1f} (x{c1 / c0:.2f})", f"{w0:.3f} / {w1:.3f}"]],
    )  # fmt: skip


DEM_TEXT = (
    "The 6208 (guessasma_oil, 40 C) at 300 rad/s under F_y = 3 kN in the quasi-static fidelity and at the end of a DEM "
    "run (1 ms at rest, a ramp to 300 rad/s over 5 ms, held to 20 ms; default time step and tribology refresh), with "
    "the wall time of each DEM run ('hertz' / 'lubricated', median of {median_of} after a warm-up run):"
)
READING = (
    "The outside term grows with the logarithm of the oil gap (each doubling adds about eps_0 (eps_r + 1)/2 2 pi "
    "sqrt(Rx Ry) ln 2 per contact, tests/unit/test_capacitance.py), so it matters most where the Hertz-zone term is "
    "small: thick films (high speed, cold oil) and light loads."
)
COST = (
    "Cost: the outside term of one contact (kernel `outside_hertz_capacitance`, 6208 inner contact at {load:g} N, "
    "h_c = {h_c:g} nm, oil_gap {gap:g} um) {kernel:.1f} us per call from Python; one analytic evaluation of the 6208 "
    "(700 rad/s, 3 kN): {off:.1f} us with 'hertz', {on:.1f} us with 'lubricated' (medians of {batches} interleaved "
    "batches of {batch} calls; 1-min load average {load_avg:.1f} at the end of the run)."
)


def measure():
    table, dem = capacitance_table(), dem_table()
    kernel_us, off_us, on_us = cost()
    values = dict(load=KERNEL["load"], h_c=KERNEL["h_c"] * 1e9, gap=KERNEL["oil_gap"] * 1e6, kernel=kernel_us,
                  off=off_us, on=on_us, batches=BATCHES, batch=BATCH, load_avg=os.getloadavg()[0])  # fmt: skip
    blocks = [{"table": table}, {"text": DEM_TEXT, "values": dict(median_of=DEM_RUNS - 1)}, {"table": dem},
              {"text": READING}, {"text": COST, "values": values}]  # fmt: skip
    title, about = "Bearing capacitance with the oil around the contacts", __doc__.split("\n\n")[1].split("Then ")[0]
    return dict(name="outside_hertz_capacitance", title=title, about=about, blocks=blocks, metrics=[])


def main(argv=None):
    cli(measure, "outside_hertz_capacitance")


if __name__ == "__main__":
    main()
