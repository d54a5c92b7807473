"""Fixtures of the co-simulation tests: the FMUs of the closed-loop run files and a clock probe FMU."""
import subprocess
import sys
from pathlib import Path

import pytest


@pytest.fixture(scope="session")
def closed_loop_fmus(bearing_fmu, bearing_fixed_fmu, spindle_thermal_fmu, spindle_thermal_fixed_fmu):
    """The four FMUs runs/closed_loop_*.toml load from fmus/ (built or rebuilt if stale)."""
    return {"Bearing": bearing_fmu, "BearingFixed": bearing_fixed_fmu, "SpindleThermal": spindle_thermal_fmu,
            "SpindleThermalFixed": spindle_thermal_fixed_fmu}


@pytest.fixture(scope="session")
def clock_fmu(tmp_path_factory):
    """ClockSlave.fmu built from tests/cosim/clock_slave.py (see its docstring)."""
    out = tmp_path_factory.mktemp("clock")
    proc = subprocess.run([sys.executable, "-m", "pythonfmu", "build", "-f",
                           str(Path(__file__).with_name("clock_slave.py")), "-d", str(out)],
                          capture_output=True, text=True, timeout=120)
    assert proc.returncode == 0, proc.stderr
    return out / "ClockSlave.fmu"
