"""Bearing defect frequencies against the published table of a test rig.

Source: Case Western Reserve University Bearing Data Center, "Bearing Information"
(https://engineering.case.edu/bearingdatacenter/bearing-information): the drive-end 6205-2RS JEM SKF and fan-end
6203-2RS JEM SKF deep-groove bearings of the CWRU rig, their size in inches and their defect frequencies as
multiples of the running speed (tests/validation/data/cwru_bearing_frequencies.csv, transcribed as printed).
The table's "rolling element" frequency is the rate at which a ball defect strikes the races, once per race per
ball revolution relative to the cage: 2 BSF.

Tolerance: the table's frequencies come from the exact geometry, ours from the printed one (ball diameter to
1e-4 in, pitch diameter to 1e-3 in). Half a unit of each printed digit, e = dD/D + dd_m/d_m, carried to first
order through gamma = D/d_m: FTF and BPFO ~ (1 - gamma) move by gamma/(1 - gamma) e, BPFI ~ (1 + gamma) by
gamma/(1 + gamma) e, BSF ~ (d_m/D)(1 - gamma^2) by (1 + 2 gamma^2/(1 - gamma^2)) e; plus half a unit of the
table's last printed digit (the table's own uncertainty).
"""

import csv
import math
import tempfile
from pathlib import Path

from bearing_fmu.models.analytic import AnalyticModel
from bearing_fmu.models.quasi_static import QuasiStaticModel
from bearing_fmu.scene import Scene

from .comparison import DATA, Comparison, ReferenceCase, half_unit

TEMPLATE = Path(__file__).resolve().parents[2] / "bearing_fmu" / "params" / "bearings" / "6208.toml"
INCH = 25.4e-3  # m
RPM = 2.0 * math.pi / 60.0
SPEEDS = (1797.0, 1730.0)  # rpm, the rig's fastest and slowest motor speeds (0 and 3 hp)
F_R, T_OIL = 1000.0, 313.15  # N, K
PUBLISHED = {  # output: (table column, strikes per period)
    "FTF": ("cage_train", 1.0),
    "BPFO": ("outer_ring", 1.0),
    "BPFI": ("inner_ring", 1.0),
    "BSF": ("rolling_element", 2.0),  # a ball defect strikes both races per revolution
}


def rows():
    with (DATA / "cwru_bearing_frequencies.csv").open() as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))


def bearing_file(row, folder):
    """A bearing file of the rig's bearing: the 6208 file with the CWRU size (the frequencies depend on D, d_m, Z
    only; materials, conformity and roughness are those of the template; the template's shoulders and cage-ball
    radius are left out, so the loader estimates the rig bearing's own shoulders and the DEM its cage balls from
    their pockets, docs/parameters.md: the 6208's cage balls do not fit between the rig bearing's balls)."""
    values = {
        "ball_diameter": float(row["ball_diameter_in"]) * INCH,
        "pitch_diameter": float(row["pitch_diameter_in"]) * INCH,
        "n_balls": int(row["Z"]),
        "bore": float(row["bore_in"]) * INCH,
        "outer_diameter": float(row["outer_diameter_in"]) * INCH,
        "width": float(row["width_in"]) * INCH,
    }
    lines = []
    for line in TEMPLATE.read_text().splitlines():
        key = line.split("=")[0].strip()
        if key.endswith("shoulder_diameter") or key == "ball_radius":
            continue
        if key == "name":
            line = f'name = "{row["bearing"]}"'
        elif key in values:
            unit = "-" if key == "n_balls" else "m"
            line = f'{key} = {{ value = {values[key]!r}, unit = "{unit}", source = "CWRU" }}'
        lines.append(line)
    path = Path(folder) / f"cwru_{row['position']}.toml"
    path.write_text("\n".join(lines) + "\n")
    return path


def geometry_tolerances(row):
    """Relative tolerance of FTF, BPFO, BPFI and BSF from the rounding of the printed geometry."""
    D, dm = (float(row[k]) for k in ("ball_diameter_in", "pitch_diameter_in"))
    e = half_unit(row["ball_diameter_in"]) / D + half_unit(row["pitch_diameter_in"]) / dm
    g = D / dm
    return {
        "FTF": g / (1 - g) * e,
        "BPFO": g / (1 - g) * e,
        "BPFI": g / (1 + g) * e,
        "BSF": (1 + 2 * g * g / (1 - g * g)) * e,
    }


def make_model(path, fidelity):
    if fidelity == "analytic":
        return AnalyticModel(str(path), "guessasma_oil")
    return QuasiStaticModel(str(path), "guessasma_oil", Scene(name="qs", fidelity="quasi_static"))


def evaluate(model, rpm):
    if isinstance(model, AnalyticModel):
        return model.evaluate(rpm * RPM, F_R, T_OIL)
    return model.evaluate(omega=rpm * RPM, F_y=F_R, T_oil=T_OIL)


def row_comparisons(row, fidelity, folder):
    """FTF, BPFO, BPFI and 2 BSF over the shaft frequency against the table, at both motor speeds, 1 kN radial at
    40 C. Analytic: pure rolling; quasi-static (outer-race control, no gyroscopic moment): the solved cage and
    ball speeds, which at contact angle 0 are those of pure rolling, so the same tolerance holds."""
    model = make_model(bearing_file(row, folder), fidelity)
    geometry = geometry_tolerances(row)
    result = []
    for rpm in SPEEDS:
        out = evaluate(model, rpm)
        for name, (column, strikes) in PUBLISHED.items():
            value = float(row[column])
            rounding = half_unit(row[column]) / value
            measured = strikes * out[name] / (rpm / 60.0)
            quantity = f"{row['position']} {name} at {rpm:g} rpm"
            result.append(Comparison(quantity, measured, value, rounding, geometry[name] + rounding))
    return result


def compare(fidelity):
    with tempfile.TemporaryDirectory() as folder:
        return [c for row in rows() for c in row_comparisons(row, fidelity, folder)]


def evaluation(fidelity):
    with tempfile.TemporaryDirectory() as folder:
        model = make_model(bearing_file(rows()[0], folder), fidelity)  # the file is read here, once
    return lambda: evaluate(model, SPEEDS[0])


def case(fidelity, label):
    return ReferenceCase(
        f"cwru_{fidelity}",
        label,
        "defect frequencies FTF, BPFO, BPFI, 2 BSF",
        "CWRU Bearing Data Center, Bearing Information table",
        lambda: compare(fidelity),
        lambda: evaluation(fidelity),
    )


CASES = (case("analytic", "analytic"), case("quasi_static", "quasi-static"))
