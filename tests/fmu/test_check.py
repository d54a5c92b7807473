"""`spindle check`: the README's CI recipe passes for every shipped FMU and fails, naming the output, when a
reference value is altered; the comparison rule of spindle/check.py on hand-made columns."""

import csv
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest

from spindle.check import ATOL_SCALE, RTOL, compare
from tests.conftest import FMU_DIR, ROOT, _fmu

SHIPPED = ["Bearing", "BearingAnalytic", "BearingDEM", "BearingDisp", "BearingFixed"]
THERMAL = ["SpindleThermal", "SpindleThermalFixed", "SpindleShaft"]


def recipe():
    """The shell block between the ci-recipe markers of README.md."""
    text = (ROOT / "README.md").read_text()
    block = re.search(r"<!-- ci-recipe:begin -->\s*```sh\n(.*?)```\s*<!-- ci-recipe:end -->", text, re.S)
    assert block, "README.md has no ci-recipe block"
    return block.group(1)


def run_recipe(folder):
    """The recipe in `folder` (which holds fmus/), with this environment's `spindle` first on PATH."""
    env = {**os.environ, "PATH": f"{Path(sys.executable).parent}{os.pathsep}{os.environ['PATH']}"}
    return subprocess.run(["bash", "-c", recipe()], cwd=folder, env=env, capture_output=True, text=True, timeout=900)


@pytest.fixture(scope="module")
def user_folder(tmp_path_factory, spindle_thermal_fmu, spindle_thermal_fixed_fmu, spindle_shaft_fmu):
    """A user's checkout: fmus/ with every shipped FMU and the files the check reads beside it."""
    scenes = {"Bearing": "quasi_static", "BearingAnalytic": "analytic", "BearingDEM": "dem"}
    scenes |= {"BearingDisp": "quasi_static_displacement", "BearingFixed": "quasi_static_fixed_preload"}
    for name in SHIPPED:
        _fmu(name, f"{scenes[name]}.toml")
    folder = tmp_path_factory.mktemp("user") / "fmus"
    folder.mkdir()
    for name in SHIPPED + THERMAL:
        for suffix in (".fmu", "_ref.csv", "_scene.toml", "_network.toml", "_shaft.toml"):
            if (FMU_DIR / f"{name}{suffix}").is_file():
                shutil.copy(FMU_DIR / f"{name}{suffix}", folder)
    return folder.parent


def test_ci_recipe_passes_for_every_shipped_fmu_and_fails_on_an_altered_reference(user_folder):
    proc = run_recipe(user_folder)
    assert proc.returncode == 0, proc.stdout + proc.stderr
    for name in SHIPPED + THERMAL:
        assert f"{name}.fmu: ok" in proc.stdout, proc.stdout
    # one torque value of Bearing.fmu's reference, 1e-4 relative off (100 x the tolerance)
    ref = user_folder / "fmus" / "Bearing_ref.csv"
    with open(ref, newline="") as fh:
        rows = list(csv.reader(fh))
    column = rows[0].index("torque")
    rows[5][column] = repr(float(rows[5][column]) * (1.0 + 1e-4))  # row 5 of the data (a rotating case)
    with open(ref, "w", newline="") as fh:
        csv.writer(fh).writerows(rows)
    proc = run_recipe(user_folder)
    assert proc.returncode == 4, proc.stdout + proc.stderr
    assert "Bearing.fmu: DIFFERS in 1 output(s)" in proc.stdout
    assert re.search(r"^  torque: row 5 of 21: ", proc.stdout, re.M), proc.stdout
    assert "BearingAnalytic.fmu: ok" in proc.stdout and "SpindleThermal.fmu: ok" in proc.stdout


def test_tolerance_is_relative_with_a_floor_from_the_column():
    """|FMU - reference| <= RTOL max(|ref|, |FMU|) + ATOL_SCALE RTOL max|column|: a difference of 0.9
    tolerance passes, 1.1 tolerance fails and is named with its row; a NaN from the FMU always fails."""
    reference = {"a": np.array([1.0, 100.0]), "b": np.array([0.0, 1e3]), "c": np.array([2.0, 3.0])}
    floor_b = ATOL_SCALE * RTOL * 1e3
    got = {
        "a": np.array([1.0 + 0.9 * RTOL * 1.0, 100.0]),
        "b": np.array([1.1 * floor_b, 1e3]),  # at a zero reference only the floor applies
        "c": np.array([2.0, np.nan]),
    }
    worst, differences = compare(got, reference, ["a", "b", "c"])
    assert [d.split(":")[0] for d in differences] == ["b", "c"]
    assert differences[0].startswith("b: row 1 of 2: ") and differences[1].startswith("c: row 2 of 2: ")
    assert worst == np.inf
    worst, differences = compare({"a": got["a"]}, reference, ["a"])
    tolerance_a = RTOL * (1.0 + 0.9 * RTOL) + ATOL_SCALE * RTOL * 100.0  # at row 1, largest |a| = 100
    assert differences == [] and worst == pytest.approx(0.9 * RTOL / tolerance_a, rel=1e-6)
